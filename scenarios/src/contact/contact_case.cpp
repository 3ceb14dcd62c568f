// Contact case files (YAML) for `ferrodyn contact curve|patch`.
#include "ferro/scenarios/contact_case.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/normal/hertz.hpp"
#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios {
namespace {

double positive(MapReader& r, const std::string& key) {
  const double v = r.number(key);
  if (!(v > 0.0)) r.fail(key, fmt::format("must be > 0, got {}", v));
  return v;
}

double positive_or(MapReader& r, const std::string& key, double fallback) {
  r.allow(key);
  return r.has(key) ? positive(r, key) : fallback;
}

// A free-form map of option: value, checked by the model registry afterwards.
contact::ModelOptions options_of(MapReader& parent, const std::string& key) {
  contact::ModelOptions o;
  MapReader m = parent.map_or_empty(key);
  for (const auto& kv : m.yaml()) {
    const std::string name = kv.first.Scalar();
    m.allow(name);
    if (!kv.second.IsScalar()) m.fail(name, "expected a single value (option: value)");
    o[name] = kv.second.Scalar();
  }
  return o;
}

// A model given as a bare name or as {name, options}.
NamedModel named_model(const YAML::Node& n, const std::string& file, const std::string& path) {
  NamedModel m;
  if (n.IsScalar()) {
    m.name = n.Scalar();
    return m;
  }
  MapReader r(n, file, path);
  m.name = r.string("name");
  m.options = options_of(r, "options");
  r.finish();
  return m;
}

contact::Material material_of(MapReader r) {
  const double nu = r.number("poisson");
  contact::Material m;
  if (r.has("young") && r.has("shear_modulus")) {
    r.fail("shear_modulus", "give 'young' or 'shear_modulus', not both");
  }
  if (r.has("young")) {
    m = contact::Material::from_young(positive(r, "young"), nu);
  } else if (r.has("shear_modulus")) {
    m = contact::Material{positive(r, "shear_modulus"), nu};
  } else {
    r.fail("young", "needs 'young' or 'shear_modulus' [Pa]");
  }
  r.allow("young");
  r.allow("shear_modulus");
  try {
    m.validate(r.path());
  } catch (const std::invalid_argument& e) {
    r.fail("poisson", e.what());
  }
  r.finish();
  return m;
}

// Radius -> half curvature 1/(2R); absent, 0 or .inf means flat.
double half_curvature(MapReader& r, const std::string& key) {
  const double radius = r.number_or(key, 0.0, true);
  if (radius == 0.0 || std::isinf(radius)) return 0.0;
  if (!(radius > 0.0)) r.fail(key, fmt::format("must be > 0 m (0 or .inf: flat), got {}", radius));
  return 0.5 / radius;
}

CurveRequest curve_of(MapReader& parent, const std::string& key) {
  CurveRequest c;
  if (!parent.has(key)) {
    parent.allow(key);
    return c;
  }
  MapReader r = parent.map(key);
  c.enabled = true;
  c.max = positive(r, "max");
  c.points = static_cast<int>(r.integer_or("points", c.points));
  if (c.points < 3 || c.points > 100001) {
    r.fail("points", fmt::format("must lie in [3, 100001], got {}", c.points));
  }
  c.angle_deg = r.number_or("angle_deg", c.angle_deg);
  r.finish();
  return c;
}

std::vector<double> number_list(MapReader& r, const std::string& key) {
  const YAML::Node n = r.node(key);
  if (!n.IsSequence()) r.fail(key, "expected a list of numbers");
  std::vector<double> out;
  for (const auto& item : n) {
    double v = 0.0;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, v) || !std::isfinite(v)) {
      r.fail(key, fmt::format("expected finite numbers; item {} is not", out.size()));
    }
    out.push_back(v);
  }
  return out;
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

namespace {

// The geometry block: curvatures (or radii), and for semi_hertz a gap from wells or samples.
void read_case_geometry(MapReader& root, ContactCase& c, const std::string& path) {
  MapReader g = root.map("geometry");
  c.normal.curvature_x = positive_or(g, "curvature_x", c.normal.curvature_x);
  c.normal.curvature_y = positive_or(g, "curvature_y", c.normal.curvature_y);
  if (g.has("radii")) {
    MapReader r = g.map("radii");
    c.normal.curvature_x = half_curvature(r, "body1_x") + half_curvature(r, "body2_x");
    c.normal.curvature_y = half_curvature(r, "body1_y") + half_curvature(r, "body2_y");
    r.finish();
  }
  g.allow("radii");
  if (g.has("wells")) {
    // Gap z(y) = min over wells of curvature (y - y_w)^2 + depth, sampled on [y_min, y_max].
    const double y0 = g.number("y_min");
    const double y1 = g.number("y_max");
    const long n = g.integer_or("samples", 1201);
    if (!(y1 > y0)) g.fail("y_max", "must be > y_min");
    if (n < 3 || n > 1'000'000) g.fail("samples", "must lie in [3, 1000000]");
    const YAML::Node w = g.node("wells");
    if (!w.IsSequence() || w.size() == 0)
      g.fail("wells", "expected a list of {y, curvature, depth}");
    struct Well {
      double y, curvature, depth;
    };
    std::vector<Well> wells;
    for (std::size_t k = 0; k < w.size(); ++k) {
      MapReader wr(w[k], path, fmt::format("geometry.wells[{}]", k));
      wells.push_back({wr.number("y"), positive(wr, "curvature"), wr.number_or("depth", 0.0)});
      wr.finish();
    }
    for (long i = 0; i < n; ++i) {
      const double y = y0 + (y1 - y0) * static_cast<double>(i) / static_cast<double>(n - 1);
      double z = INFINITY;
      for (const Well& well : wells) {
        z = std::min(z, well.curvature * (y - well.y) * (y - well.y) + well.depth);
      }
      c.normal.gap_y.push_back(y);
      c.normal.gap_z.push_back(z);
    }
  }
  g.allow("wells");
  if (g.has("gap_y") || g.has("gap_z")) {
    c.normal.gap_y = number_list(g, "gap_y");
    c.normal.gap_z = number_list(g, "gap_z");
    if (c.normal.gap_y.size() != c.normal.gap_z.size()) {
      g.fail("gap_z", fmt::format("must have as many values as gap_y ({}), got {}",
                                  c.normal.gap_y.size(), c.normal.gap_z.size()));
    }
  }
  g.allow("gap_y");
  g.allow("gap_z");
  g.finish();
  if (!(c.normal.curvature_x > 0.0)) {
    g.fail("curvature_x", "missing or not > 0 (A [1/m], or radii)");
  }
  if (c.normal_model == "hertz" && !(c.normal.curvature_y > 0.0)) {
    g.fail("curvature_y", "hertz needs B > 0 [1/m] (or radii)");
  }
  if (c.normal_model == "semi_hertz" && c.normal.gap_y.size() < 3) {
    g.fail("wells", "semi_hertz needs 'wells' or 'gap_y'/'gap_z'");
  }
}

// The load block: normal force or (Hertz) approach.
void read_case_load(MapReader& root, ContactCase& c) {
  MapReader load = root.map("load");
  if (load.has("normal_force") && load.has("approach")) {
    load.fail("approach", "give normal_force [N] or approach [m], not both");
  }
  if (load.has("normal_force")) {
    c.normal.normal_force = positive(load, "normal_force");
  } else if (load.has("approach")) {
    c.approach = positive(load, "approach");
    if (c.normal_model != "hertz") load.fail("approach", "only with normal_model hertz");
  } else {
    load.fail("normal_force", "needs normal_force [N] or approach [m]");
  }
  load.allow("normal_force");
  load.allow("approach");
  load.finish();
}

// The tangential models to compare, each checked by building it.
void read_case_models(MapReader& root, ContactCase& c, const std::string& path) {
  const YAML::Node models = root.node("models");
  if (!models.IsSequence() || models.size() == 0) {
    root.fail("models", "expected a non-empty list of {name, options}");
  }
  for (std::size_t i = 0; i < models.size(); ++i) {
    const std::string key = fmt::format("models[{}]", i);
    NamedModel m = named_model(models[i], path, key);
    try {
      (void)contact::make_tangential_model(m.name, m.options);
    } catch (const std::invalid_argument& e) {
      const auto [l, col] = position_of(models[i]);
      throw YamlInputError(path, l, col, key, e.what());
    }
    c.models.push_back(std::move(m));
  }
}

// The curves and the patch picture asked for.
void read_case_outputs(MapReader& root, ContactCase& c) {
  // Curves and patch picture.
  if (root.has("curves")) {
    MapReader cv = root.map("curves");
    c.longitudinal = curve_of(cv, "longitudinal");
    c.lateral = curve_of(cv, "lateral");
    c.spin = curve_of(cv, "spin");
    c.combined = curve_of(cv, "combined");
    cv.finish();
  }
  root.allow("curves");
  if (root.has("patch")) {
    MapReader p = root.map("patch");
    c.patch_model.name = p.string_or("model", c.patch_model.name);
    if (p.has("options")) c.patch_model.options = options_of(p, "options");
    p.allow("options");
    if (p.has("creepage")) {
      MapReader cr = p.map("creepage");
      c.patch_creepage.longitudinal = cr.number_or("xi_x", c.patch_creepage.longitudinal);
      c.patch_creepage.lateral = cr.number_or("xi_y", c.patch_creepage.lateral);
      c.patch_creepage.spin = cr.number_or("phi", c.patch_creepage.spin);
      cr.finish();
    }
    p.allow("creepage");
    p.finish();
  }
  root.allow("patch");
}

}  // namespace

ContactCase load_contact_case(const std::string& path) {
  const YamlFile file = load_yaml_file(path);
  MapReader root(file.root, path, "");
  ContactCase c;
  if (!root.has("schema_version")) {
    root.fail("schema_version", fmt::format("missing; this program reads schema_version {}",
                                            ContactCase::kSchemaVersion));
  }
  const long version = root.integer_or("schema_version", -1);
  if (version != ContactCase::kSchemaVersion) {
    root.fail("schema_version", fmt::format("unsupported version {}; supported: {}", version,
                                            ContactCase::kSchemaVersion));
  }
  c.name = root.string_or("name", "contact_case");
  // Normal model.
  if (root.has("normal_model")) {
    const NamedModel n = named_model(root.node("normal_model"), path, "normal_model");
    c.normal_model = n.name;
    c.normal_options = n.options;
  }
  root.allow("normal_model");
  try {
    (void)contact::make_normal_model(c.normal_model, c.normal_options);
  } catch (const std::invalid_argument& e) {
    root.fail("normal_model", e.what());
  }
  read_case_geometry(root, c, path);
  read_case_load(root, c);
  // Materials, friction, K_ij.
  {
    MapReader bodies = root.map("bodies");
    c.normal.body1 = material_of(bodies.map("wheel"));
    c.normal.body2 = material_of(bodies.map("rail"));
    bodies.finish();
  }
  c.friction = positive(root, "friction");
  if (root.has("reduction")) {
    MapReader k = root.map("reduction");
    if (k.has("k")) c.reduction = contact::ReductionFactors::uniform(positive(k, "k"));
    c.reduction.k11 = positive_or(k, "k11", c.reduction.k11);
    c.reduction.k22 = positive_or(k, "k22", c.reduction.k22);
    // K23 = K22 unless given (Toumi 2016, section 4.2.4).
    if (k.has("k22") && !k.has("k23") && !k.has("k")) c.reduction.k23 = c.reduction.k22;
    c.reduction.k23 = positive_or(k, "k23", c.reduction.k23);
    c.reduction.k33 = positive_or(k, "k33", c.reduction.k33);
    k.allow("k");
    k.finish();
  }
  root.allow("reduction");
  read_case_models(root, c, path);
  read_case_outputs(root, c);
  root.finish();
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
