// Contact case files (YAML) for `ferrodyn contact curve|patch`.
#include "ferro/scenarios/contact_case.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <stdexcept>

#include "ferro/contact/hertz.hpp"

namespace ferro::scenarios {
namespace {

[[noreturn]] void bad(const std::string& path, const std::string& key, const std::string& what) {
  throw std::invalid_argument(fmt::format("{}: key '{}': {}", path, key, what));
}

double number(const YAML::Node& n, const std::string& path, const std::string& key) {
  try {
    return n.as<double>();
  } catch (const YAML::Exception&) {
    bad(path, key, fmt::format("expected a number (line {})", n.Mark().line + 1));
  }
}

double positive(const YAML::Node& n, const std::string& path, const std::string& key) {
  const double v = number(n, path, key);
  if (!(v > 0.0) || !std::isfinite(v))
    bad(path, key, fmt::format("must be finite and > 0, got {}", v));
  return v;
}

contact::ModelOptions options_of(const YAML::Node& n, const std::string& path,
                                 const std::string& key) {
  contact::ModelOptions o;
  if (!n) return o;
  if (!n.IsMap()) bad(path, key, "expected a map of option: value");
  for (const auto& kv : n) o[kv.first.as<std::string>()] = kv.second.as<std::string>();
  return o;
}

contact::Material material_of(const YAML::Node& n, const std::string& path,
                              const std::string& key) {
  if (!n || !n.IsMap())
    bad(path, key, "expected a map with 'poisson' and 'young' or 'shear_modulus' [Pa]");
  if (!n["poisson"]) bad(path, key + ".poisson", "missing");
  const double nu = number(n["poisson"], path, key + ".poisson");
  contact::Material m;
  if (n["young"]) {
    m = contact::Material::from_young(positive(n["young"], path, key + ".young"), nu);
  } else if (n["shear_modulus"]) {
    m = contact::Material{positive(n["shear_modulus"], path, key + ".shear_modulus"), nu};
  } else {
    bad(path, key, "needs 'young' or 'shear_modulus' [Pa]");
  }
  m.validate(path + ": " + key);
  return m;
}

// Radius -> half curvature 1/(2R); 0 or .inf means flat.
double half_curvature(const YAML::Node& n, const std::string& path, const std::string& key) {
  if (!n) return 0.0;
  const double r = number(n, path, key);
  if (r == 0.0 || std::isinf(r)) return 0.0;
  return 0.5 / r;
}

CurveRequest curve_of(const YAML::Node& n, const std::string& path, const std::string& key) {
  CurveRequest c;
  if (!n) return c;
  c.enabled = true;
  if (!n["max"]) bad(path, key + ".max", "missing (largest |creepage|)");
  c.max = positive(n["max"], path, key + ".max");
  if (n["points"]) c.points = n["points"].as<int>();
  if (c.points < 3 || c.points > 100001) bad(path, key + ".points", "must lie in [3, 100001]");
  if (n["angle_deg"]) c.angle_deg = number(n["angle_deg"], path, key + ".angle_deg");
  return c;
}

}  // namespace

std::string NamedModel::label() const {
  std::string s = name;
  if (!options.empty()) {
    s += "(";
    bool first = true;
    for (const auto& [k, v] : options) {
      s += first ? "" : ",";
      s += k;
      s += '=';
      s += v;
      first = false;
    }
    s += ")";
  }
  return s;
}

ContactCase load_contact_case(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw std::invalid_argument(fmt::format("{}: cannot open the case file", path));
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(fmt::format("{}: YAML error: {}", path, e.what()));
  }
  ContactCase c;
  if (!root["schema_version"] || root["schema_version"].as<int>() != ContactCase::kSchemaVersion) {
    bad(path, "schema_version", fmt::format("must be {}", ContactCase::kSchemaVersion));
  }
  c.name = root["name"] ? root["name"].as<std::string>() : std::string("contact_case");
  // Normal model.
  if (const auto n = root["normal_model"]) {
    if (n.IsMap()) {
      c.normal_model = n["name"].as<std::string>();
      c.normal_options = options_of(n["options"], path, "normal_model.options");
    } else {
      c.normal_model = n.as<std::string>();
    }
  }
  (void)contact::make_normal_model(c.normal_model, c.normal_options);  // validates name/options
  // Geometry.
  const YAML::Node g = root["geometry"];
  if (!g || !g.IsMap()) bad(path, "geometry", "missing (curvatures, radii or gap)");
  if (g["curvature_x"])
    c.normal.curvature_x = positive(g["curvature_x"], path, "geometry.curvature_x");
  if (g["curvature_y"])
    c.normal.curvature_y = positive(g["curvature_y"], path, "geometry.curvature_y");
  if (const auto r = g["radii"]) {
    c.normal.curvature_x = half_curvature(r["body1_x"], path, "geometry.radii.body1_x") +
                           half_curvature(r["body2_x"], path, "geometry.radii.body2_x");
    c.normal.curvature_y = half_curvature(r["body1_y"], path, "geometry.radii.body1_y") +
                           half_curvature(r["body2_y"], path, "geometry.radii.body2_y");
  }
  if (const auto w = g["wells"]) {
    // Gap z(y) = min over wells of curvature (y - y_w)^2 + depth, sampled on [y_min, y_max].
    const double y0 = number(g["y_min"], path, "geometry.y_min");
    const double y1 = number(g["y_max"], path, "geometry.y_max");
    const int n = g["samples"] ? g["samples"].as<int>() : 1201;
    if (!(y1 > y0) || n < 3) bad(path, "geometry", "needs y_min < y_max and samples >= 3");
    for (int i = 0; i < n; ++i) {
      const double y = y0 + (y1 - y0) * i / (n - 1);
      double z = INFINITY;
      for (std::size_t k = 0; k < w.size(); ++k) {
        const std::string key = fmt::format("geometry.wells[{}]", k);
        const double yw = number(w[k]["y"], path, key + ".y");
        const double cw = positive(w[k]["curvature"], path, key + ".curvature");
        const double dw = w[k]["depth"] ? number(w[k]["depth"], path, key + ".depth") : 0.0;
        z = std::min(z, cw * (y - yw) * (y - yw) + dw);
      }
      c.normal.gap_y.push_back(y);
      c.normal.gap_z.push_back(z);
    }
  }
  if (g["gap_y"] || g["gap_z"]) {
    c.normal.gap_y = g["gap_y"].as<std::vector<double>>();
    c.normal.gap_z = g["gap_z"].as<std::vector<double>>();
  }
  if (!(c.normal.curvature_x > 0.0))
    bad(path, "geometry.curvature_x", "missing or not > 0 (A [1/m])");
  if (c.normal_model == "hertz" && !(c.normal.curvature_y > 0.0)) {
    bad(path, "geometry.curvature_y", "hertz needs B > 0 [1/m]");
  }
  if (c.normal_model == "semi_hertz" && c.normal.gap_y.size() < 3) {
    bad(path, "geometry", "semi_hertz needs 'wells' or 'gap_y'/'gap_z'");
  }
  // Load.
  const YAML::Node load = root["load"];
  if (!load) bad(path, "load", "missing (normal_force [N] or approach [m])");
  if (load["normal_force"]) {
    c.normal.normal_force = positive(load["normal_force"], path, "load.normal_force");
  } else if (load["approach"]) {
    c.approach = positive(load["approach"], path, "load.approach");
    if (c.normal_model != "hertz") bad(path, "load.approach", "only with normal_model hertz");
  } else {
    bad(path, "load", "needs normal_force [N] or approach [m]");
  }
  // Materials, friction, K_ij.
  const YAML::Node bodies = root["bodies"];
  if (!bodies) bad(path, "bodies", "missing (wheel, rail)");
  c.normal.body1 = material_of(bodies["wheel"], path, "bodies.wheel");
  c.normal.body2 = material_of(bodies["rail"], path, "bodies.rail");
  if (!root["friction"]) bad(path, "friction", "missing (mu [-])");
  c.friction = positive(root["friction"], path, "friction");
  if (const auto k = root["reduction"]) {
    if (k["k"])
      c.reduction = contact::ReductionFactors::uniform(positive(k["k"], path, "reduction.k"));
    if (k["k11"]) c.reduction.k11 = positive(k["k11"], path, "reduction.k11");
    if (k["k22"]) c.reduction.k22 = positive(k["k22"], path, "reduction.k22");
    // K23 = K22 unless given (Toumi 2016, section 4.2.4).
    if (k["k22"] && !k["k23"] && !k["k"]) c.reduction.k23 = c.reduction.k22;
    if (k["k23"]) c.reduction.k23 = positive(k["k23"], path, "reduction.k23");
    if (k["k33"]) c.reduction.k33 = positive(k["k33"], path, "reduction.k33");
  }
  // Models.
  const YAML::Node models = root["models"];
  if (!models || !models.IsSequence() || models.size() == 0) {
    bad(path, "models", "expected a non-empty list of {name, options}");
  }
  for (std::size_t i = 0; i < models.size(); ++i) {
    const std::string key = fmt::format("models[{}]", i);
    NamedModel m;
    m.name = models[i].IsMap() ? models[i]["name"].as<std::string>() : models[i].as<std::string>();
    if (models[i].IsMap()) m.options = options_of(models[i]["options"], path, key + ".options");
    try {
      (void)contact::make_tangential_model(m.name, m.options);
    } catch (const std::invalid_argument& e) {
      bad(path, key, e.what());
    }
    c.models.push_back(std::move(m));
  }
  // Curves and patch picture.
  if (const auto cv = root["curves"]) {
    c.longitudinal = curve_of(cv["longitudinal"], path, "curves.longitudinal");
    c.lateral = curve_of(cv["lateral"], path, "curves.lateral");
    c.spin = curve_of(cv["spin"], path, "curves.spin");
    c.combined = curve_of(cv["combined"], path, "curves.combined");
  }
  if (const auto p = root["patch"]) {
    if (p["model"]) c.patch_model.name = p["model"].as<std::string>();
    if (p["options"]) c.patch_model.options = options_of(p["options"], path, "patch.options");
    if (const auto cr = p["creepage"]) {
      if (cr["xi_x"])
        c.patch_creepage.longitudinal = number(cr["xi_x"], path, "patch.creepage.xi_x");
      if (cr["xi_y"]) c.patch_creepage.lateral = number(cr["xi_y"], path, "patch.creepage.xi_y");
      if (cr["phi"]) c.patch_creepage.spin = number(cr["phi"], path, "patch.creepage.phi");
    }
  }
  return c;
}

contact::NormalSolution solve_case_normal(ContactCase& c) {
  if (c.approach > 0.0) {
    // Hertz: delta ~ F^(2/3), so F = F_ref (delta / delta_ref)^(3/2).
    const double e_star = contact::combine(c.normal.body1, c.normal.body2).contact_modulus;
    const double f_ref = 1e4;
    const contact::HertzSolution h =
        contact::hertz_solve(c.normal.curvature_x, c.normal.curvature_y, f_ref, e_star);
    c.normal.normal_force = f_ref * std::pow(c.approach / h.approach, 1.5);
  }
  return contact::make_normal_model(c.normal_model, c.normal_options)->solve(c.normal);
}

}  // namespace ferro::scenarios
