// K_ij tables from offline contact computations: configuration, journal, curves, table (see
// the header).
#include "ferro/scenarios/fe_kij_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ferro/contact/mim/mim.hpp"
#include "ferro/fe_contact/kij_sweep.hpp"
#include "ferro/scenarios/yaml_reader.hpp"
#include "yaml_values.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

// A non-empty list; the layer's yield shear may be .inf (a layer that never yields).
std::vector<double> nonempty_number_list(MapReader& r, const std::string& key) {
  std::vector<double> v = detail::number_list(r, key, key == "layer_yield_shear");
  if (v.empty()) r.fail(key, "must be a non-empty list of numbers");
  return v;
}

struct FeKijConfig {
  fe_contact::KijSweepSpec spec;
  std::string output;
  bool plots = true;
};

FeKijConfig read_config(const std::string& path) {
  const scenarios::YamlFile file = scenarios::load_yaml_file(path);
  MapReader top(file.root, path, "");
  if (top.integer_or("schema_version", -1) != 1) {
    top.fail("schema_version", "must be 1");
  }
  FeKijConfig cfg;
  fe_contact::KijSweepSpec& s = cfg.spec;
  {
    MapReader c = top.map("contact");
    s.contact.reference_force = c.number("reference_force");
    s.contact.reference_semi_axis_x = c.number("semi_axis_x");
    s.contact.reference_semi_axis_y = c.number("semi_axis_y");
    s.contact.normal_force = c.number_or("normal_force", s.contact.reference_force);
    s.contact.body = contact::Material::from_young(c.number("young_modulus"), c.number("poisson"));
    s.contact.friction = c.number("friction");
    const long elements = c.integer_or("elements_minor", 24);
    // Work bounded up front: the MIM grid of the largest patch of the sweep.
    const int most = contact::mim::max_elements_minor(s.contact.reference_semi_axis_x,
                                                      s.contact.reference_semi_axis_y);
    if (elements < 8 || elements > most) {
      c.fail("elements_minor",
             fmt::format("must lie in 8..{} (MIM grids are capped at 2^18 elements), got {}",
                         most, elements));
    }
    s.contact.elements_minor = static_cast<int>(elements);
    s.contact.margin = c.number_or("margin", 0.15);
    c.finish();
  }
  {
    MapReader l = top.map_or_empty("layer");
    s.layer.thickness = l.number_or("thickness", 0.0);
    s.layer.shear_modulus = l.number_or("shear_modulus", fe_contact::kNaN, true);
    s.layer.yield_shear = l.number_or("yield_shear", std::numeric_limits<double>::infinity(), true);
    l.finish();
  }
  {
    MapReader a = top.map("axes");
    for (const std::string& name : fe_contact::sweep_axis_names()) {
      a.allow(name);
      if (!a.has(name)) continue;
      s.axis_names.push_back(name);
      s.axes.push_back(nonempty_number_list(a, name));
    }
    a.finish();
    if (s.axis_names.empty()) {
      top.fail("axes",
               "give at least one of normal_force, layer_thickness, "
               "layer_shear_modulus, layer_yield_shear, yield_stress");
    }
  }
  {
    MapReader pl = top.map_or_empty("plastic");
    fe_contact::ElastoplasticKijSpec& e = s.plastic;
    e.elements_per_semi_axis = static_cast<int>(pl.integer_or("elements_per_semi_axis", 4));
    e.load_steps = static_cast<int>(pl.integer_or("load_steps", 6));
    e.unload_steps = static_cast<int>(pl.integer_or("unload_steps", 0));
    e.hardening_modulus = pl.number_or("hardening_modulus", 0.0);
    e.growth = pl.number_or("growth", 1.6);
    e.extent = pl.number_or("extent", 12.0);
    pl.finish();
  }
  {
    MapReader so = top.map_or_empty("solver");
    s.slope.mim.tangential.tolerance = so.number_or("tolerance", 1.0e-6);
    s.slope.probe_creepage = so.number_or("probe_creepage", 1.0e-6);
    s.slope.probe_spin_times_a = so.number_or("probe_spin_times_a", 1.0e-6);
    so.finish();
  }
  {
    MapReader cu = top.map_or_empty("curves");
    if (cu.has("creepages")) s.curve_creepages = nonempty_number_list(cu, "creepages");
    cu.finish();
  }
  const std::string out = top.string_or("output", "kij.h5");
  cfg.output = fs::path(out).is_absolute() ? out : (fs::path(path).parent_path() / out).string();
  cfg.plots = top.boolean_or("plots", true);
  top.finish();
  // The spec's own checks, located at the key they name ("<section>.<key>: ...").
  try {
    s.validate("");
  } catch (const scenarios::YamlInputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    const auto colon = msg.find(": ");
    std::string field = colon == std::string::npos ? std::string() : msg.substr(0, colon);
    if (!field.empty() && field.front() == '.') field.erase(0, 1);
    const auto dot = field.find('.');
    std::string section = field.substr(0, dot);
    if (section == "slope") section = "solver";
    if (section == "curve_creepages") section = "curves";
    const std::string key = dot == std::string::npos ? std::string() : field.substr(dot + 1);
    const std::string text = colon == std::string::npos ? msg : msg.substr(colon + 2);
    if (top.has(section) && top.yaml()[section].IsMap()) {
      MapReader part = top.map(section);
      const std::string leaf = key.substr(0, key.find_first_of(".["));
      part.fail(!leaf.empty() && part.has(leaf) ? leaf : std::string(), text);
    }
    top.fail(top.has(section) ? section : std::string(), text);
  }
  return cfg;
}

// The grid of the last point computed (provenance).
struct GridNote {
  int nx = 0, ny = 0;
  double element = 0.0;
};

// Journal of finished points: one text file per point, written to a temporary name and renamed.
std::string journal_name(const fs::path& dir, std::size_t i) {
  return (dir / fmt::format("point_{:05d}.txt", i)).string();
}

// Elasto-plastic rail: the first-pass K and the load cycle of a point (Table 3.9 quantities).
struct PlasticRecord {
  contact::ReductionFactors first_pass;
  std::vector<double> cycle;  // p0, u_loaded, u_residual, eps_p, depth, flowing, reverse, cpu
};
constexpr const char* kCycleColumns =
    "peak_pressure_Pa,displacement_loaded_m,displacement_residual_m,max_plastic_strain,"
    "depth_max_plastic_strain_m,flowing_points,reverse_flowing_points,cycle_cpu_s";

bool positive(const contact::ReductionFactors& k) {
  return k.k11 > 0.0 && k.k22 > 0.0 && k.k23 > 0.0 && k.k33 > 0.0;
}

bool read_journal(const fs::path& dir, std::size_t i, contact::ReductionFactors& k,
                  PlasticRecord* plastic) {
  std::ifstream in(journal_name(dir, i));
  if (!in) return false;
  std::string tag;
  in >> tag >> k.k11 >> k.k22 >> k.k23 >> k.k33;
  if (!in || tag != "K" || !positive(k)) return false;
  if (plastic == nullptr) return true;
  // Elasto-plastic points also need their first-pass and cycle lines.
  std::string line;
  bool first = false, cycle = false;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    ls >> tag;
    if (tag == "KFP") {
      contact::ReductionFactors& f = plastic->first_pass;
      ls >> f.k11 >> f.k22 >> f.k23 >> f.k33;
      first = static_cast<bool>(ls) && positive(f);
    } else if (tag == "cycle") {
      // Tokens through strtod: an elastic point has no plastic-strain depth ("nan").
      plastic->cycle.assign(8, 0.0);
      cycle = true;
      for (double& v : plastic->cycle) {
        std::string token;
        ls >> token;
        char* end = nullptr;
        v = std::strtod(token.c_str(), &end);
        cycle = cycle && !token.empty() && end == token.c_str() + token.size();
      }
    }
  }
  return first && cycle;
}

void write_journal(const fs::path& dir, std::size_t i, const fe_contact::KijPoint& p) {
  const std::string name = journal_name(dir, i);
  const std::string tmp = name + ".tmp";
  {
    std::ofstream out(tmp);
    const contact::ReductionFactors& k = p.slopes.k;
    out << fmt::format("K {:.17g} {:.17g} {:.17g} {:.17g}\n", k.k11, k.k22, k.k23, k.k33);
    out << fmt::format("grid {} {} {:.17g}\n", p.nx, p.ny, p.element_size);
    if (p.has_first_pass) {
      const contact::ReductionFactors& f = p.first_pass.k;
      const fe_contact::ElastoplasticResult& c = p.cycle;
      out << fmt::format("KFP {:.17g} {:.17g} {:.17g} {:.17g}\n", f.k11, f.k22, f.k23, f.k33);
      out << fmt::format("cycle {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {} {} {:.6g}\n",
                         c.peak_pressure, c.displacement_loaded, c.displacement_residual,
                         c.max_plastic_strain, c.depth_max_plastic_strain, c.flowing_points,
                         c.reverse_flowing_points, c.cpu_seconds);
    }
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write", tmp));
  }
  fs::rename(tmp, name);
}

void write_curves(const fs::path& dir, std::size_t i, const std::vector<double>& coords,
                  const std::vector<std::string>& names, const fe_contact::KijPoint& p) {
  std::ofstream out(dir / fmt::format("curves_{:05d}.csv", i));
  std::string title;
  for (std::size_t a = 0; a < names.size(); ++a) {
    title += fmt::format("{}{}={:g}", a ? " " : "", names[a], coords[a]);
  }
  out << "# " << title << "\n";
  out << "creepage,Fx_N,Ax_N,Fy_N,Ay_N,Fx_half_space_N,Ax_half_space_N,Fy_half_space_N,"
         "Ay_half_space_N\n";
  for (std::size_t j = 0; j < p.curve_x.creepage.size(); ++j) {
    out << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n",
                       p.curve_x.creepage[j], p.curve_x.force[j], p.curve_x.derivative[j],
                       p.curve_y.force[j], p.curve_y.derivative[j], p.reference_curve_x.force[j],
                       p.reference_curve_x.derivative[j], p.reference_curve_y.force[j],
                       p.reference_curve_y.derivative[j]);
  }
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write creep curves", dir.string()));
}

// Runs point i, records it in the journal (and its curves), keeps its K and load cycle.
void compute_point(const FeKijConfig& cfg, const fs::path& work, std::size_t i,
                   contact::ReductionFactors& k, PlasticRecord* record, GridNote& grid) {
  const fe_contact::KijSweepSpec& spec = cfg.spec;
  const fe_contact::KijPoint p = fe_contact::compute_point(spec, i);
  if (!p.slopes.converged) {
    throw std::runtime_error(fmt::format("configuration {}: the MIM solves did not converge", i));
  }
  write_journal(work, i, p);
  if (!spec.curve_creepages.empty()) {
    write_curves(work, i, spec.coordinates(i), spec.axis_names, p);
  }
  k = p.slopes.k;
  if (record != nullptr) {
    const fe_contact::ElastoplasticResult& c = p.cycle;
    record->first_pass = p.first_pass.k;
    record->cycle = {c.peak_pressure,
                     c.displacement_loaded,
                     c.displacement_residual,
                     c.max_plastic_strain,
                     c.depth_max_plastic_strain,
                     static_cast<double>(c.flowing_points),
                     static_cast<double>(c.reverse_flowing_points),
                     c.cpu_seconds};
  }
  grid = {p.nx, p.ny, p.element_size};
}

// Load-cycle quantities per point (thesis Table 3.9), with the axis values and both K.
void write_elastoplastic_csv(const fe_contact::KijSweepSpec& spec, const fs::path& work,
                             const std::vector<contact::ReductionFactors>& k,
                             const std::vector<PlasticRecord>& records) {
  std::ofstream csv(work / "elastoplastic.csv");
  for (const std::string& name : spec.axis_names) csv << name << ",";
  csv << kCycleColumns
      << ",K11_first_pass,K22_first_pass,K23_first_pass,K33_first_pass,K11,K22,K23,K33\n";
  for (std::size_t i = 0; i < k.size(); ++i) {
    for (double x : spec.coordinates(i)) csv << fmt::format("{:.9g},", x);
    for (double v : records[i].cycle) csv << fmt::format("{:.9g},", v);
    const contact::ReductionFactors& f = records[i].first_pass;
    csv << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", f.k11, f.k22,
                       f.k23, f.k33, k[i].k11, k[i].k22, k[i].k23, k[i].k33);
  }
  if (!csv)
    throw std::runtime_error(fmt::format("{}: cannot write elastoplastic.csv", work.string()));
}

std::map<std::string, std::string> provenance(const fe_contact::KijSweepSpec& spec,
                                              const std::string& config_path,
                                              const GridNote& grid) {
  std::map<std::string, std::string> prov;
  prov["method"] =
      "ratio of initial creep-curve slopes of two steady-rolling MIM runs on the same grid "
      "(half-space + interfacial layer vs half-space)";
  // The configuration as named by the caller (a machine-independent path when run from the
  // repository, as the shipped tables were).
  prov["config"] = fs::path(config_path).lexically_normal().string();
  prov["elements_minor"] = std::to_string(spec.contact.elements_minor);
  if (grid.nx > 0)
    prov["grid_last_point"] =
        fmt::format("{} x {}, dx = dy = {:.6g} m", grid.nx, grid.ny, grid.element);
  prov["mesh_sizes"] = "none (half-space + interfacial layer; no finite-element mesh)";
  if (spec.elastoplastic()) {
    prov["method"] =
        "ratio of initial creep-curve slopes of two steady-rolling MIM runs on the same grid "
        "(elasto-plastic rail + elastic half-space wheel vs half-space pair)";
    prov["mesh_sizes"] = fmt::format(
        "J2 rail block, trilinear hexahedra: {} cells across min(a, b) = the MIM grid elements, "
        "growth {:g}, extent {:g} max(a, b); {} load steps up, {} down; hardening modulus {:g} "
        "Pa",
        spec.plastic.elements_per_semi_axis, spec.plastic.growth, spec.plastic.extent,
        spec.plastic.load_steps,
        spec.plastic.unload_steps > 0 ? spec.plastic.unload_steps : spec.plastic.load_steps,
        spec.plastic.hardening_modulus);
    prov["range"] =
        "K11..K33: shaken down (elastic rail about its residual state, residual dent in the "
        "gap); K*_first_pass: first pass (frozen elasto-plastic tangent of the rail under the "
        "peak load)";
  }
  prov["solver_tolerance"] = fmt::format("{:g}", spec.slope.mim.tangential.tolerance);
  prov["normal_tolerance"] = fmt::format("{:g}", spec.slope.mim.normal.tolerance);
  prov["probe_creepage"] = fmt::format("{:g}", spec.slope.probe_creepage);
  prov["probe_spin_times_a"] = fmt::format("{:g}", spec.slope.probe_spin_times_a);
  if (!spec.elastoplastic())
    prov["range"] = "single-valued (elastic layer; no first-pass/shakedown range)";
  return prov;
}

}  // namespace

struct FeKijStudy::Impl {
  std::string config_path;
  FeKijConfig cfg;
  std::string work;
  std::vector<contact::ReductionFactors> k;
  std::vector<PlasticRecord> records;
  std::vector<bool> done;
  std::size_t resumed = 0;
};

FeKijStudy::FeKijStudy(const std::string& config_path, bool restart)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.config_path = config_path;
  s.cfg = read_config(config_path);
  const fe_contact::KijSweepSpec& spec = s.cfg.spec;
  const fs::path work = s.cfg.output + ".d";
  s.work = work.string();
  if (restart && fs::exists(work)) fs::remove_all(work);
  fs::create_directories(work);
  const std::size_t n = spec.points();
  const bool plastic = spec.elastoplastic();
  s.k.resize(n);
  s.records.resize(plastic ? n : 0);
  s.done.assign(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    s.done[i] = read_journal(work, i, s.k[i], plastic ? &s.records[i] : nullptr);
    s.resumed += s.done[i] ? 1 : 0;
  }
}

FeKijStudy::~FeKijStudy() = default;

std::size_t FeKijStudy::points() const {
  return impl_->done.size();
}
std::size_t FeKijStudy::resumed() const {
  return impl_->resumed;
}
const std::string& FeKijStudy::output() const {
  return impl_->cfg.output;
}
const std::string& FeKijStudy::work_dir() const {
  return impl_->work;
}
bool FeKijStudy::wants_curve_plots() const {
  return impl_->cfg.plots && !impl_->cfg.spec.curve_creepages.empty();
}

FeKijReport FeKijStudy::run(const FeKijRunOptions& options) {
  Impl& s = *impl_;
  const fe_contact::KijSweepSpec& spec = s.cfg.spec;
  const fs::path work = s.work;
  const std::size_t n = points();
  const bool plastic = spec.elastoplastic();
  FeKijReport report;
  const std::clock_t cpu0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  GridNote grid;
  for (std::size_t i = 0; i < n; ++i) {
    if (options.should_stop && options.should_stop()) {
      report.interrupted = true;
      report.finished = static_cast<std::size_t>(std::count(s.done.begin(), s.done.end(), true));
      return report;
    }
    if (!s.done[i]) {
      compute_point(s.cfg, work, i, s.k[i], plastic ? &s.records[i] : nullptr, grid);
      s.done[i] = true;
    }
    if (options.progress) options.progress(i + 1, n);
  }
  report.finished = n;
  report.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<contact::ReductionFactors> first_pass;
  if (plastic) {
    for (const PlasticRecord& r : s.records) first_pass.push_back(r.first_pass);
    write_elastoplastic_csv(spec, work, s.k, s.records);
  }
  const contact::KijTable table =
      fe_contact::make_table(spec, s.k, provenance(spec, s.config_path, grid), first_pass);
  table.write_hdf5(options.table_path.empty() ? s.cfg.output : options.table_path);
  return report;
}

}  // namespace ferro::scenarios
