// K_ij reduction factors: constants and HDF5 tables (layout in docs/KIJ_TABLE.md).
//
// References: Toumi (2016) eq. (156).
// Known deviations: multilinear interpolation, clamped at the axis ends.
#include "ferro/contact/reduction_factors.hpp"
#include "quiet_hdf5.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

namespace ferro::contact {

void ReductionFactors::validate(const char* where) const {
  const std::pair<double, const char*> f[] = {
      {k11, "k11"}, {k22, "k22"}, {k23, "k23"}, {k33, "k33"}};
  for (const auto& [v, field] : f) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("{}.{}: must be finite and > 0, got {}", where, field, v));
    }
  }
}

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
    double v = point[i];
    if (!std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("K_ij table: axis '{}' value is not finite", names_[i]));
    }
    if (v < ax.front() || v > ax.back()) clamped = true;
    v = std::clamp(v, ax.front(), ax.back());
    if (ax.size() == 1) {
      lower[i] = 0;
      weight[i] = 0.0;
      continue;
    }
    std::size_t j =
        static_cast<std::size_t>(std::upper_bound(ax.begin(), ax.end(), v) - ax.begin());
    j = std::clamp<std::size_t>(j, 1, ax.size() - 1);
    lower[i] = j - 1;
    weight[i] = (v - ax[j - 1]) / (ax[j] - ax[j - 1]);
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

namespace {

using detail::QuietHdf5;

struct Handle {
  hid_t id = -1;
  herr_t (*close)(hid_t) = nullptr;
  Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
  ~Handle() {
    if (id >= 0 && close) close(id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
};

std::vector<double> read_dataset(hid_t file, const std::string& path, const std::string& name,
                                 std::vector<hsize_t>* dims_out) {
  Handle d(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (d.id < 0) throw std::invalid_argument(fmt::format("{}: missing dataset '{}'", path, name));
  Handle sp(H5Dget_space(d.id), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(sp.id);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(sp.id, dims.data(), nullptr);
  std::size_t count = 1;
  for (hsize_t v : dims) count *= static_cast<std::size_t>(v);
  std::vector<double> values(count);
  if (H5Dread(d.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw std::invalid_argument(fmt::format("{}: cannot read dataset '{}' as float64", path, name));
  }
  if (dims_out) *dims_out = dims;
  return values;
}

}  // namespace

KijTable KijTable::read_hdf5(const std::string& path) {
  QuietHdf5 quiet;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file.id < 0)
    throw std::invalid_argument(fmt::format("{}: cannot open as an HDF5 file", path));
  // Schema version.
  {
    Handle attr(H5Aopen(file.id, "schema_version", H5P_DEFAULT), H5Aclose);
    int version = 0;
    if (attr.id < 0 || H5Aread(attr.id, H5T_NATIVE_INT, &version) < 0) {
      throw std::invalid_argument(fmt::format("{}: missing root attribute 'schema_version'", path));
    }
    if (version != 1 && version != kSchemaVersion) {
      throw std::invalid_argument(fmt::format(
          "{}: schema_version {} not supported (expected 1 or {})", path, version, kSchemaVersion));
    }
  }
  Handle group(H5Gopen2(file.id, "axes", H5P_DEFAULT), H5Gclose);
  if (group.id < 0) throw std::invalid_argument(fmt::format("{}: missing group '/axes'", path));
  H5G_info_t info;
  H5Gget_info(group.id, &info);
  const auto n = static_cast<std::size_t>(info.nlinks);
  if (n == 0) throw std::invalid_argument(fmt::format("{}: group '/axes' is empty", path));
  std::vector<std::string> names(n);
  std::vector<std::vector<double>> axes(n);
  std::vector<bool> seen(n, false);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len =
        H5Lget_name_by_idx(group.id, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    std::string name(static_cast<std::size_t>(len), '\0');
    H5Lget_name_by_idx(group.id, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(),
                       static_cast<std::size_t>(len) + 1, H5P_DEFAULT);
    const std::string dpath = "axes/" + name;
    std::vector<hsize_t> dims;
    std::vector<double> values = read_dataset(file.id, path, dpath, &dims);
    Handle d(H5Dopen2(file.id, dpath.c_str(), H5P_DEFAULT), H5Dclose);
    Handle attr(H5Aopen(d.id, "index", H5P_DEFAULT), H5Aclose);
    int index = -1;
    if (attr.id < 0 || H5Aread(attr.id, H5T_NATIVE_INT, &index) < 0) {
      throw std::invalid_argument(
          fmt::format("{}: dataset '/{}' has no integer attribute 'index'", path, dpath));
    }
    if (index < 0 || static_cast<std::size_t>(index) >= n ||
        seen[static_cast<std::size_t>(index)]) {
      throw std::invalid_argument(fmt::format(
          "{}: dataset '/{}' attribute 'index' = {} is out of range or repeated (0..{})", path,
          dpath, index, n - 1));
    }
    seen[static_cast<std::size_t>(index)] = true;
    names[static_cast<std::size_t>(index)] = name;
    axes[static_cast<std::size_t>(index)] = std::move(values);
  }
  auto read_k = [&](const char* name, bool optional) -> std::vector<double> {
    if (optional && H5Lexists(file.id, name, H5P_DEFAULT) <= 0) return {};
    std::vector<hsize_t> dims;
    std::vector<double> v = read_dataset(file.id, path, name, &dims);
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
  if (H5Lexists(file.id, "K11_first_pass", H5P_DEFAULT) > 0) {
    table.set_first_pass(read_k("K11_first_pass", false), read_k("K22_first_pass", false),
                         read_k("K23_first_pass", false), read_k("K33_first_pass", true));
  }
  if (H5Lexists(file.id, "provenance", H5P_DEFAULT) > 0) {
    Handle prov(H5Gopen2(file.id, "provenance", H5P_DEFAULT), H5Gclose);
    if (prov.id < 0) {
      throw std::invalid_argument(fmt::format("{}: cannot open group '/provenance'", path));
    }
    std::vector<std::string> keys;
    auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
      static_cast<std::vector<std::string>*>(data)->emplace_back(name);
      return 0;
    };
    hsize_t idx = 0;
    H5Aiterate2(prov.id, H5_INDEX_NAME, H5_ITER_INC, &idx, collect, &keys);
    std::map<std::string, std::string> entries;
    for (const std::string& key : keys) {
      Handle attr(H5Aopen(prov.id, key.c_str(), H5P_DEFAULT), H5Aclose);
      Handle type(H5Aget_type(attr.id), H5Tclose);
      if (H5Tget_class(type.id) != H5T_STRING || H5Tis_variable_str(type.id) > 0) {
        throw std::invalid_argument(fmt::format(
            "{}: '/provenance' attribute '{}' must be a fixed-length string", path, key));
      }
      std::string value(H5Tget_size(type.id), '\0');
      if (H5Aread(attr.id, type.id, value.data()) < 0) {
        throw std::invalid_argument(
            fmt::format("{}: cannot read '/provenance' attribute '{}'", path, key));
      }
      value = value.substr(0, value.find('\0'));
      entries[key] = value;
    }
    table.set_provenance(std::move(entries));
  }
  return table;
}

void KijTable::write_hdf5(const std::string& path) const {
  QuietHdf5 quiet;
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (file.id < 0) throw std::runtime_error(fmt::format("{}: cannot create HDF5 file", path));
  {
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attr(
        H5Acreate2(file.id, "schema_version", H5T_NATIVE_INT, space.id, H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    const int version = kSchemaVersion;
    H5Awrite(attr.id, H5T_NATIVE_INT, &version);
  }
  Handle group(H5Gcreate2(file.id, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  auto write = [&](hid_t where, const std::string& name, const std::vector<double>& v,
                   const std::vector<hsize_t>& dims) -> hid_t {
    Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    const hid_t d = H5Dcreate2(where, name.c_str(), H5T_IEEE_F64LE, space.id, H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT);
    if (d < 0 || H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
      throw std::runtime_error(fmt::format("{}: cannot write dataset '{}'", path, name));
    }
    return d;
  };
  std::vector<hsize_t> dims;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    Handle d(write(group.id, names_[i], axes_[i], {axes_[i].size()}), H5Dclose);
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attr(H5Acreate2(d.id, "index", H5T_NATIVE_INT, space.id, H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
    const int index = static_cast<int>(i);
    H5Awrite(attr.id, H5T_NATIVE_INT, &index);
    dims.push_back(axes_[i].size());
  }
  Handle d11(write(file.id, "K11", k11_, dims), H5Dclose);
  Handle d22(write(file.id, "K22", k22_, dims), H5Dclose);
  Handle d23(write(file.id, "K23", k23_, dims), H5Dclose);
  if (!k33_.empty()) Handle d33(write(file.id, "K33", k33_, dims), H5Dclose);
  if (has_first_pass()) {
    Handle f11(write(file.id, "K11_first_pass", k11_first_, dims), H5Dclose);
    Handle f22(write(file.id, "K22_first_pass", k22_first_, dims), H5Dclose);
    Handle f23(write(file.id, "K23_first_pass", k23_first_, dims), H5Dclose);
    if (!k33_first_.empty()) Handle f33(write(file.id, "K33_first_pass", k33_first_, dims), H5Dclose);
  }
  Handle prov(H5Gcreate2(file.id, "provenance", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (prov.id < 0) throw std::runtime_error(fmt::format("{}: cannot create '/provenance'", path));
  for (const auto& [key, value] : provenance_) {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.id, std::max<std::size_t>(value.size(), 1));
    H5Tset_strpad(type.id, H5T_STR_NULLPAD);
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attr(H5Acreate2(prov.id, key.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
    const std::string stored = value.empty() ? std::string(1, '\0') : value;
    if (attr.id < 0 || H5Awrite(attr.id, type.id, stored.data()) < 0) {
      throw std::runtime_error(
          fmt::format("{}: cannot write '/provenance' attribute '{}'", path, key));
    }
  }
}

}  // namespace ferro::contact
