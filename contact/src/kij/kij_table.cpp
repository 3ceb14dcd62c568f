// K_ij reduction-factor tables: HDF5 layout (docs/KIJ_TABLE.md), interpolation, patch look-up.
//
// References: Toumi (2016) eq. (156).
// Known deviations: multilinear interpolation, clamped at the axis ends.
#include "ferro/contact/kij/kij_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>

#include "ferro/io/hdf5.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {

KijTable::KijTable(std::vector<std::string> axis_names, std::vector<std::vector<double>> axes,
                   std::vector<double> k11, std::vector<double> k22, std::vector<double> k23,
                   std::vector<double> k33)
    : names_(std::move(axis_names)),
      axes_(std::move(axes)),
      k11_(std::move(k11)),
      k22_(std::move(k22)),
      k23_(std::move(k23)),
      k33_(std::move(k33)) {
  if (names_.empty() || names_.size() != axes_.size()) {
    throw std::invalid_argument(
        fmt::format("K_ij table: need >= 1 axis and one name per axis, got {} names for {} axes",
                    names_.size(), axes_.size()));
  }
  std::size_t nodes = 1;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    const auto& ax = axes_[i];
    if (ax.empty())
      throw std::invalid_argument(fmt::format("K_ij table axis '{}': empty", names_[i]));
    for (std::size_t j = 0; j + 1 < ax.size(); ++j) {
      if (!(ax[j + 1] > ax[j])) {
        throw std::invalid_argument(
            fmt::format("K_ij table axis '{}': values must be strictly increasing (index {})",
                        names_[i], j + 1));
      }
    }
    nodes *= ax.size();
  }
  auto check = [&](const std::vector<double>& v, const char* field, bool optional) {
    if (optional && v.empty()) return;
    if (v.size() != nodes) {
      throw std::invalid_argument(
          fmt::format("K_ij table {}: expected {} values (product of the axis lengths), got {}",
                      field, nodes, v.size()));
    }
    for (double x : v) {
      if (!(x > 0.0) || !std::isfinite(x)) {
        throw std::invalid_argument(
            fmt::format("K_ij table {}: values must be finite and > 0", field));
      }
    }
  };
  check(k11_, "K11", false);
  check(k22_, "K22", false);
  check(k23_, "K23", false);
  check(k33_, "K33", true);
}

ReductionFactors KijTable::at(const std::map<std::string, double>& point) const {
  for (const auto& kv : point) {
    if (std::find(names_.begin(), names_.end(), kv.first) == names_.end()) {
      std::string list;
      for (const std::string& n : names_) list += (list.empty() ? "" : ", ") + n;
      throw std::invalid_argument(
          fmt::format("K_ij table: unknown axis '{}'; the table's axes: {}", kv.first, list));
    }
  }
  std::vector<double> values(names_.size());
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const auto it = point.find(names_[i]);
    if (it == point.end()) {
      throw std::invalid_argument(
          fmt::format("K_ij table: no value given for axis '{}'", names_[i]));
    }
    values[i] = it->second;
  }
  return at(values);
}

ReductionFactors KijTable::at_patch(const ContactPatch& patch,
                                    std::map<std::string, double> point) const {
  for (const std::string& name : names_) {
    if (point.count(name) != 0) continue;
    if (name == "normal_force") point[name] = patch.normal_force;
    if (name == "peak_pressure") point[name] = patch.peak_pressure;
  }
  return at(point);
}

ReductionFactors KijTable::at(const std::vector<double>& point) const {
  return interpolate(point, k11_, k22_, k23_, k33_);
}

void KijTable::set_first_pass(std::vector<double> k11, std::vector<double> k22,
                              std::vector<double> k23, std::vector<double> k33) {
  // Same checks as the main set: a table built from them must be valid.
  const KijTable check(names_, axes_, k11, k22, k23, k33);
  k11_first_ = std::move(k11);
  k22_first_ = std::move(k22);
  k23_first_ = std::move(k23);
  k33_first_ = std::move(k33);
}

ReductionFactors KijTable::first_pass_at(const std::vector<double>& point) const {
  if (!has_first_pass()) throw std::logic_error("K_ij table: no first-pass factors");
  return interpolate(point, k11_first_, k22_first_, k23_first_, k33_first_);
}

ReductionFactors KijTable::interpolate(const std::vector<double>& point,
                                       const std::vector<double>& k11,
                                       const std::vector<double>& k22,
                                       const std::vector<double>& k23,
                                       const std::vector<double>& k33) const {
  const std::size_t n = axes_.size();
  if (point.size() != n) {
    throw std::invalid_argument(
        fmt::format("K_ij table: expected {} coordinates, got {}", n, point.size()));
  }
  // Per axis: lower index and weight of the upper node.
  std::vector<std::size_t> lower(n);
  std::vector<double> weight(n);
  std::vector<std::size_t> stride(n);
  bool clamped = false;
  std::size_t s = 1;
  for (std::size_t i = n; i-- > 0;) {
    stride[i] = s;
    s *= axes_[i].size();
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto& ax = axes_[i];
    const double v = point[i];
    if (!std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("K_ij table: axis '{}' value is not finite", names_[i]));
    }
    if (v < ax.front() || v > ax.back()) clamped = true;
    if (ax.size() == 1) {
      lower[i] = 0;
      weight[i] = 0.0;
      continue;
    }
    const numerics::AxisCell cell = numerics::locate(ax, v);
    lower[i] = cell.index;
    weight[i] = cell.t;
  }
  if (clamped) ++clamped_;
  ReductionFactors out{0.0, 0.0, 0.0, 0.0};
  for (std::size_t corner = 0; corner < (std::size_t{1} << n); ++corner) {
    double w = 1.0;
    std::size_t index = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool upper = (corner >> i) & 1U;
      if (upper && axes_[i].size() == 1) {
        w = 0.0;
        break;
      }
      w *= upper ? weight[i] : 1.0 - weight[i];
      index += (lower[i] + (upper ? 1 : 0)) * stride[i];
    }
    if (w == 0.0) continue;
    out.k11 += w * k11[index];
    out.k22 += w * k22[index];
    out.k23 += w * k23[index];
    out.k33 += w * (k33.empty() ? 1.0 : k33[index]);
  }
  return out;
}

KijTable KijTable::read_hdf5(const std::string& path) {
  const io::H5File file = io::H5File::open_input(path, "K_ij table");
  const auto dataset = [&](const std::string& name, io::Dims* dims) {
    if (!file.exists(name))
      throw std::invalid_argument(fmt::format("{}: missing dataset '{}'", path, name));
    try {
      return file.read_array(name, dims);
    } catch (const io::Hdf5Error&) {
      throw std::invalid_argument(
          fmt::format("{}: cannot read dataset '{}' as float64", path, name));
    }
  };
  const auto integer = [&](const std::string& object, const char* name) -> std::optional<long> {
    if (!file.has_attribute(object, name)) return std::nullopt;
    try {
      return file.integer_attribute(object, name);
    } catch (const io::Hdf5Error&) {
      return std::nullopt;
    }
  };
  // Schema version.
  const auto version = integer("/", "schema_version");
  if (!version)
    throw std::invalid_argument(fmt::format("{}: missing root attribute 'schema_version'", path));
  if (*version != 1 && *version != kSchemaVersion) {
    throw std::invalid_argument(fmt::format(
        "{}: schema_version {} not supported (expected 1 or {})", path, *version, kSchemaVersion));
  }
  if (!file.exists("/axes"))
    throw std::invalid_argument(fmt::format("{}: missing group '/axes'", path));
  const std::vector<std::string> members = file.members("/axes");
  const std::size_t n = members.size();
  if (n == 0) throw std::invalid_argument(fmt::format("{}: group '/axes' is empty", path));
  std::vector<std::string> names(n);
  std::vector<std::vector<double>> axes(n);
  std::vector<bool> seen(n, false);
  for (const std::string& name : members) {
    const std::string dpath = "axes/" + name;
    io::Dims dims;
    std::vector<double> values = dataset(dpath, &dims);
    const auto index = integer(dpath, "index");
    if (!index) {
      throw std::invalid_argument(
          fmt::format("{}: dataset '/{}' has no integer attribute 'index'", path, dpath));
    }
    if (*index < 0 || static_cast<std::size_t>(*index) >= n ||
        seen[static_cast<std::size_t>(*index)]) {
      throw std::invalid_argument(fmt::format(
          "{}: dataset '/{}' attribute 'index' = {} is out of range or repeated (0..{})", path,
          dpath, *index, n - 1));
    }
    seen[static_cast<std::size_t>(*index)] = true;
    names[static_cast<std::size_t>(*index)] = name;
    axes[static_cast<std::size_t>(*index)] = std::move(values);
  }
  auto read_k = [&](const char* name, bool optional) -> std::vector<double> {
    if (optional && !file.exists(name)) return {};
    io::Dims dims;
    std::vector<double> v = dataset(name, &dims);
    bool ok = dims.size() == n;
    for (std::size_t i = 0; ok && i < n; ++i) ok = dims[i] == axes[i].size();
    if (!ok) {
      throw std::invalid_argument(fmt::format(
          "{}: dataset '/{}' must have one dimension per axis, in axis index order, with the "
          "axis lengths",
          path, name));
    }
    return v;
  };
  KijTable table(names, axes, read_k("K11", false), read_k("K22", false), read_k("K23", false),
                 read_k("K33", true));
  // Version 2 additions (absent in version 1 files).
  if (file.exists("K11_first_pass")) {
    table.set_first_pass(read_k("K11_first_pass", false), read_k("K22_first_pass", false),
                         read_k("K23_first_pass", false), read_k("K33_first_pass", true));
  }
  if (file.exists("/provenance")) {
    std::map<std::string, std::string> entries;
    try {
      for (const std::string& key : file.attribute_names("/provenance")) {
        entries[key] = file.string_attribute("/provenance", key);
      }
    } catch (const io::Hdf5Error& e) {
      throw std::invalid_argument(fmt::format(
          "{}: '/provenance' attributes must be fixed-length strings ({})", path, e.what()));
    }
    table.set_provenance(std::move(entries));
  }
  return table;
}

void KijTable::write_hdf5(const std::string& path) const {
  io::H5File file = io::H5File::create(path);
  file.set_attribute("/", "schema_version", kSchemaVersion);
  file.ensure_group("/axes");
  io::Dims dims;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    const std::string name = "/axes/" + names_[i];
    file.write_array(name, axes_[i], {axes_[i].size()});
    file.set_attribute(name, "index", static_cast<int>(i));
    dims.push_back(axes_[i].size());
  }
  file.write_array("/K11", k11_, dims);
  file.write_array("/K22", k22_, dims);
  file.write_array("/K23", k23_, dims);
  if (!k33_.empty()) file.write_array("/K33", k33_, dims);
  if (has_first_pass()) {
    file.write_array("/K11_first_pass", k11_first_, dims);
    file.write_array("/K22_first_pass", k22_first_, dims);
    file.write_array("/K23_first_pass", k23_first_, dims);
    if (!k33_first_.empty()) file.write_array("/K33_first_pass", k33_first_, dims);
  }
  file.ensure_group("/provenance");
  for (const auto& [key, value] : provenance_) file.set_attribute("/provenance", key, value);
  file.close();
}

KijPatchLookup::KijPatchLookup(const KijTable& table, const std::map<std::string, double>& fixed) {
  const auto& names = table.axis_names();
  for (const auto& [name, value] : fixed) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      throw std::invalid_argument(
          fmt::format("K_ij table: no axis '{}'; its axes: {}", name, fmt::join(names, ", ")));
    }
    (void)value;
  }
  std::vector<std::size_t> patch_axis_index;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (fixed.count(names[i]) != 0) continue;
    if (names[i] == "normal_force" || names[i] == "peak_pressure") {
      patch_axis_index.push_back(i);
      pressure_axis_.push_back(names[i] == "peak_pressure");
      axes_.push_back(table.axes()[i]);
    } else {
      throw std::invalid_argument(fmt::format(
          "K_ij table: axis '{}' needs a value (only normal_force and peak_pressure come from "
          "the contact patch)",
          names[i]));
    }
  }
  std::map<std::string, double> point = fixed;
  const std::size_t n0 = axes_.empty() ? 1 : axes_[0].size();
  const std::size_t n1 = axes_.size() < 2 ? 1 : axes_[1].size();
  for (std::size_t i = 0; i < n0; ++i) {
    for (std::size_t j = 0; j < n1; ++j) {
      if (!axes_.empty()) point[names[patch_axis_index[0]]] = axes_[0][i];
      if (axes_.size() > 1) point[names[patch_axis_index[1]]] = axes_[1][j];
      const ReductionFactors k = table.at(point);
      values_.push_back({k.k11, k.k22, k.k23, k.k33});
    }
  }
}

ReductionFactors KijPatchLookup::at(const ContactPatch& patch) const {
  // Cell and weight along each patch axis (clamped at the ends).
  std::array<std::size_t, 2> cell{0, 0};
  std::array<double, 2> frac{0.0, 0.0};
  std::array<std::size_t, 2> size{1, 1};
  for (std::size_t a = 0; a < axes_.size(); ++a) {
    const std::vector<double>& x = axes_[a];
    size[a] = x.size();
    const double v = pressure_axis_[a] ? patch.peak_pressure : patch.normal_force;
    if (x.size() < 2) continue;
    const numerics::AxisCell c = numerics::locate(x, v);
    cell[a] = c.index;
    frac[a] = c.t;
  }
  std::array<double, 4> k{0.0, 0.0, 0.0, 0.0};
  for (int c = 0; c < 4; ++c) {
    const std::size_t di = (c & 1) != 0 ? 1 : 0, dj = (c & 2) != 0 ? 1 : 0;
    if ((di == 1 && size[0] < 2) || (dj == 1 && size[1] < 2)) continue;
    const double w = (di == 1 ? frac[0] : 1.0 - frac[0]) * (dj == 1 ? frac[1] : 1.0 - frac[1]);
    const std::array<double, 4>& v = values_[(cell[0] + di) * size[1] + cell[1] + dj];
    for (int q = 0; q < 4; ++q)
      k[static_cast<std::size_t>(q)] += w * v[static_cast<std::size_t>(q)];
  }
  return {k[0], k[1], k[2], k[3]};
}

}  // namespace ferro::contact
