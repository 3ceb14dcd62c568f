// The contact layer from Python: every tangential and normal model on NumPy arrays of cases (the
// loop runs in C++), profiles, and the wheel-rail contact geometry (point search, tables).
// SI units throughout; forces and moment are those of the rail on the wheel.
#include <fmt/format.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "common.hpp"
#include "ferro/contact/geometry/contact_table.hpp"
#include "ferro/contact/geometry/profile.hpp"
#include "ferro/contact/normal/normal_model.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/contact_eval.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/pose_search.hpp"

namespace ferro::python {
namespace {

namespace fc = ferro::contact;
using Column = py::array_t<double, py::array::c_style | py::array::forcecast>;

fc::ModelOptions model_options(const py::object& options) {
  fc::ModelOptions o;
  if (options.is_none()) return o;
  for (const auto& [k, v] : options.cast<py::dict>()) {
    o[py::str(k)] = py::isinstance<py::str>(v) ? v.cast<std::string>()
                                               : py::str(v).cast<std::string>();
  }
  return o;
}

// The input columns (1-D; scalars as one value) and the number of cases.
std::size_t gather(const py::dict& kwargs, std::map<std::string, Column>& columns) {
  std::size_t n = 1;
  for (const auto& [k, v] : kwargs) {
    if (v.is_none()) continue;
    Column c = Column::ensure(v);
    if (!c) throw py::value_error(fmt::format("{}: expected numbers", py::str(k).cast<std::string>()));
    if (c.ndim() > 1)
      throw py::value_error(fmt::format("{}: expected a number or a 1-D array", py::str(k).cast<std::string>()));
    const auto size = static_cast<std::size_t>(c.size());
    if (size != 1) {
      if (n != 1 && size != n)
        throw py::value_error(fmt::format("{}: {} values, other inputs have {}",
                                          py::str(k).cast<std::string>(), size, n));
      n = size;
    }
    columns.emplace(py::str(k), std::move(c));
  }
  return n;
}

std::span<const double> span_of(const Column& c) {
  return {c.data(), static_cast<std::size_t>(c.size())};
}

py::dict tangential(const std::string& model_name, const py::object& options, const py::kwargs& kw) {
  const fc::ModelOptions o = scenarios::with_environment_options(model_name, model_options(options));
  std::unique_ptr<fc::TangentialModel> model;
  fc::CoefficientSource source{};
  scenarios::EvalInput defaults;
  defaults.model = model_name;
  try {
    model = fc::make_tangential_model(model_name, o);
    source = fc::coefficient_source_from_name(fc::option_string(o, "coefficients", "kalker_table"));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  std::map<std::string, Column> columns;
  const std::size_t n = gather(kw, columns);
  std::map<std::string, std::span<const double>> inputs;
  for (const auto& [k, c] : columns) inputs[k] = span_of(c);
  const char* names[] = {"semi_axis_x", "semi_axis_y", "peak_pressure", "force_x", "force_y",
                         "moment_z", "adhesion_fraction", "c11", "c22", "c23", "c33"};
  std::vector<py::array_t<double>> arrays;
  for (std::size_t i = 0; i < std::size(names); ++i) arrays.emplace_back(static_cast<py::ssize_t>(n));
  const auto out_span = [&](std::size_t i) {
    return std::span<double>(arrays[i].mutable_data(), n);
  };
  const scenarios::EvalOutputColumns out{out_span(0), out_span(1), out_span(2), out_span(3),
                                         out_span(4), out_span(5), out_span(6), out_span(7),
                                         out_span(8), out_span(9), out_span(10)};
  {
    py::gil_scoped_release release;
    scenarios::evaluate_contact_columns(defaults, inputs, n, *model, source, out);
  }
  py::dict d;
  for (std::size_t i = 0; i < std::size(names); ++i) d[names[i]] = arrays[i];
  return d;
}

py::dict normal(const std::string& model_name, const py::object& options, const py::object& fn,
                const py::object& curvature_x, const py::object& curvature_y, double g1,
                double nu1, double g2, double nu2, const py::object& gap_y,
                const py::object& gap_z) {
  std::unique_ptr<fc::NormalContactModel> model;
  try {
    model = fc::make_normal_model(model_name, model_options(options));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  fc::NormalProblem base;
  base.body1 = fc::Material{g1, nu1};
  base.body2 = fc::Material{g2, nu2};
  if (!gap_y.is_none()) base.gap_y = gap_y.cast<std::vector<double>>();
  if (!gap_z.is_none()) base.gap_z = gap_z.cast<std::vector<double>>();
  py::dict in;
  in["fn"] = fn;
  in["curvature_x"] = curvature_x;
  in["curvature_y"] = curvature_y;
  std::map<std::string, Column> columns;
  const std::size_t n = gather(in, columns);
  const auto col = [&](const char* k) {
    const auto it = columns.find(k);
    return it == columns.end() ? std::span<const double>() : span_of(it->second);
  };
  scenarios::NormalCases r;
  {
    py::gil_scoped_release release;
    r = scenarios::solve_normal_cases(*model, base, n, col("fn"), col("curvature_x"),
                                      col("curvature_y"));
  }
  py::dict d;
  d["approach"] = to_numpy(std::move(r.approach));
  std::vector<double> index, y, a, b, f, p;
  for (std::size_t k = 0; k < r.patches.size(); ++k) {
    index.push_back(static_cast<double>(r.patch_case[k]));
    y.push_back(r.patches[k].y_center);
    a.push_back(r.patches[k].semi_axis_x);
    b.push_back(r.patches[k].semi_axis_y);
    f.push_back(r.patches[k].normal_force);
    p.push_back(r.patches[k].peak_pressure);
  }
  d["patch_case"] = py::array(py::cast(r.patch_case));
  d["y_center"] = to_numpy(std::move(y));
  d["semi_axis_x"] = to_numpy(std::move(a));
  d["semi_axis_y"] = to_numpy(std::move(b));
  d["normal_force"] = to_numpy(std::move(f));
  d["peak_pressure"] = to_numpy(std::move(p));
  return d;
}

py::dict profile_dict(const fc::Profile& p) {
  py::dict d;
  d["y"] = to_numpy(std::vector<double>(p.y));
  d["z"] = to_numpy(std::vector<double>(p.z));
  d["kind"] = p.kind == fc::ProfileKind::wheel ? "wheel" : "rail";
  d["source"] = p.source;
  return d;
}

// A wheel-rail pair built from profile files and the search options.
struct Pair {
  scenarios::SearchPairOptions options;
  std::shared_ptr<fc::WheelRailPair> pair;
};

py::dict search(const Pair& p, double y, double roll, double yaw, const py::object& height,
                const py::object& load) {
  scenarios::PoseInput in;
  in.y = y;
  in.roll = roll;
  in.yaw = yaw;
  if (!height.is_none()) in.height = height.cast<double>();
  if (!load.is_none()) in.load = load.cast<double>();
  if (!std::isnan(in.height) && !std::isnan(in.load))
    throw py::value_error("give height or load, not both");
  const double estar = scenarios::pose_search_modulus(p.options.shear_modulus, p.options.poisson);
  scenarios::PoseResult r;
  {
    py::gil_scoped_release release;
    r = scenarios::solve_pose(*p.pair, in, estar);
  }
  py::dict d;
  d["lateral"] = r.pose.lateral;
  d["vertical"] = r.pose.vertical;
  d["roll"] = r.pose.roll;
  d["yaw"] = r.pose.yaw;
  py::list side;
  std::vector<double> wy, ry, x, ty, tz, lead, angle, radius, ca, cb, pen, gap, force;
  std::vector<bool> flange;
  for (const auto& c : r.points) {
    side.append(c.side == fc::Side::left ? "left" : "right");
    wy.push_back(c.wheel_y);
    ry.push_back(c.rail_y);
    x.push_back(c.x);
    ty.push_back(c.y);
    tz.push_back(c.z);
    lead.push_back(scenarios::contact_lead(*p.pair, r.pose, c));
    angle.push_back(c.contact_angle);
    radius.push_back(c.rolling_radius);
    ca.push_back(c.curvature_a);
    cb.push_back(c.curvature_b);
    pen.push_back(c.penetration);
    gap.push_back(c.vertical_gap);
    force.push_back(c.normal_force);
    flange.push_back(c.on_flange());
  }
  d["side"] = side;
  d["wheel_y"] = to_numpy(std::move(wy));
  d["rail_y"] = to_numpy(std::move(ry));
  d["x"] = to_numpy(std::move(x));
  d["y"] = to_numpy(std::move(ty));
  d["z"] = to_numpy(std::move(tz));
  d["lead"] = to_numpy(std::move(lead));
  d["contact_angle"] = to_numpy(std::move(angle));
  d["rolling_radius"] = to_numpy(std::move(radius));
  d["curvature_a"] = to_numpy(std::move(ca));
  d["curvature_b"] = to_numpy(std::move(cb));
  d["penetration"] = to_numpy(std::move(pen));
  d["vertical_gap"] = to_numpy(std::move(gap));
  d["normal_force"] = to_numpy(std::move(force));
  d["flange"] = py::array(py::cast(flange));
  return d;
}

py::dict table(const Pair& p, double lateral_min, double lateral_max, double lateral_step,
               const std::vector<double>& yaw) {
  fc::ContactTableParams tp;
  tp.lateral_min = lateral_min;
  tp.lateral_max = lateral_max;
  tp.lateral_step = lateral_step;
  tp.yaw = yaw;
  std::optional<fc::ContactTable> t;
  try {
    py::gil_scoped_release release;
    t.emplace(fc::ContactTable::build(*p.pair, tp));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  py::dict d;
  d["lateral"] = to_numpy(std::vector<double>(t->lateral()));
  d["yaw"] = to_numpy(std::vector<double>(t->yaw()));
  const auto nl = t->lateral().size(), ny = t->yaw().size();
  for (int c = 0; c < fc::ContactTable::kColumns; ++c) {
    std::vector<double> v(ny * nl);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nl; ++i) v[j * nl + i] = t->value(c, j, i);
    d[fc::ContactTable::column_names()[static_cast<std::size_t>(c)]] =
        ny == 1 ? to_numpy(std::move(v)) : to_numpy(std::move(v), {static_cast<py::ssize_t>(ny),
                                                                   static_cast<py::ssize_t>(nl)});
  }
  return d;
}

}  // namespace

void bind_contact(py::module_& m) {
  m.def("tangential_models", &fc::tangential_model_names, "Names of the tangential models.");
  m.def("normal_models", &fc::normal_model_names, "Names of the normal models.");

  scenarios::EvalInput case_keys;
  static const std::string tdoc =
      "tangential(model, options=None, **case) -> dict\n\nEvaluates a tangential (creep-force) "
      "model on Hertzian cases, the loop in C++ (`ferrodyn contact eval`, case after case,\n"
      "the same numbers to the last bit). Each case value is a number or a 1-D array (one\n"
      "value per case); the patch comes from the semi-axes (a, b) or the curvatures\n"
      "(curvature_x, curvature_y) with the load. options: the model's options ({'mx': 20,\n"
      "'coefficients': 'voco_fit', ...}; mim_table without 'table' reads $FERRO_MIM_TABLE).\n"
      "Returns arrays, one value per case: semi_axis_x, semi_axis_y [m], peak_pressure [Pa],\n"
      "force_x, force_y [N], moment_z [N m] (on the wheel from the rail), adhesion_fraction [-]\n"
      "(NaN when the model has none), c11, c22, c23, c33 [-] (Kalker's coefficients used, K_ij\n"
      "applied). Case:\n" +
      parameter_doc(scenarios::select_parameters(
          scenarios::parameters(case_keys),
          {"a", "b", "curvature_x", "curvature_y", "fn", "g1", "nu1", "g2", "nu2", "mu", "xi_x",
           "xi_y", "spin", "k11", "k22", "k23", "k33"}));
  m.def("tangential", &tangential, py::arg("model"), py::arg("options") = py::none(),
        tdoc.c_str());

  m.def("normal", &normal, py::arg("model") = "hertz", py::arg("options") = py::none(),
        py::arg("fn") = py::none(), py::arg("curvature_x") = py::none(),
        py::arg("curvature_y") = py::none(), py::arg("g1") = 82e9, py::arg("nu1") = 0.28,
        py::arg("g2") = 82e9, py::arg("nu2") = 0.28, py::arg("gap_y") = py::none(),
        py::arg("gap_z") = py::none(),
        "normal(model='hertz', options=None, fn, curvature_x, curvature_y, g1=82e9, nu1=0.28, "
        "g2=82e9, nu2=0.28, gap_y=None, gap_z=None) -> dict\n\nSolves a normal-contact model on "
        "cases: load fn [N] and curvatures A, B [1/m] as numbers or 1-D arrays; wheel (g1 [Pa],\n"
        "nu1) and rail (g2, nu2) materials; semi_hertz also reads the lateral gap samples\n"
        "gap_y, gap_z [m]. Returns approach [m] per case, and per patch (several per case for a\n"
        "split semi-Hertz contact): patch_case, y_center, semi_axis_x, semi_axis_y [m],\n"
        "normal_force [N], peak_pressure [Pa].");

  m.def(
      "read_profile",
      [](const std::filesystem::path& path, const std::string& kind) {
        if (kind != "wheel" && kind != "rail")
          throw py::value_error("kind: 'wheel' or 'rail'");
        try {
          return profile_dict(fc::read_profile(
              path.string(), kind == "wheel" ? fc::ProfileKind::wheel : fc::ProfileKind::rail));
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("path"), py::arg("kind"),
      "A wheel or rail profile file (.prw/.prr or two columns in mm) as arrays y, z [m] (z "
      "positive downwards), with kind and source. `kind` applies to two-column files.");

  scenarios::SearchPairOptions pair_keys;
  static const std::string pdoc =
      "WheelRailPair(wheel, rail, **options)\n\nA wheel and a rail profile placed on the "
      "track (`ferrodyn geometry search`). Options:\n" +
      parameter_doc(scenarios::select_parameters(
          scenarios::parameters(pair_keys),
          {"gauge", "gauge_depth", "inclination", "flange_back", "flange_back_y", "radius",
           "section_step", "shear_modulus", "poisson"}));
  py::class_<Pair>(m, "WheelRailPair", pdoc.c_str())
      .def(py::init([](const std::filesystem::path& wheel, const std::filesystem::path& rail,
                       const py::kwargs& kw) {
             Pair p;
             set_parameters(scenarios::select_parameters(
                                scenarios::parameters(p.options),
                                {"gauge", "gauge_depth", "inclination", "flange_back",
                                 "flange_back_y", "radius", "section_step", "shear_modulus",
                                 "poisson"}),
                            kw);
             p.options.wheel = wheel.string();
             p.options.rail = rail.string();
             try {
               p.pair = std::make_shared<fc::WheelRailPair>(scenarios::make_search_pair(p.options));
             } catch (const std::invalid_argument& e) {
               throw py::value_error(e.what());
             }
             return p;
           }),
           py::arg("wheel"), py::arg("rail"))
      .def_static(
          "from_pair_file",
          [](const std::filesystem::path& file) {
            const std::string path = file.string();
            Pair p;
            try {
              const scenarios::PairFile f = scenarios::load_pair_file(path);
              p.options.wheel = f.wheel_profile;
              p.options.rail = f.rail_profile;
              p.pair = std::make_shared<fc::WheelRailPair>(scenarios::make_wheel_rail_pair(f));
            } catch (const scenarios::YamlInputError& e) {
              raise_scene_error(e, path);
            } catch (const std::invalid_argument& e) {
              throw py::value_error(e.what());
            }
            return p;
          },
          py::arg("path"),
          "The pair of a pair file (`ferrodyn geometry pair PAIR.yaml`; the Manchester "
          "benchmark's format, lengths in mm). Loads and loads search use steel (82 GPa, 0.28).")
      .def("search", &search, py::arg("y") = 0.0, py::arg("roll") = 0.0, py::arg("yaw") = 0.0,
           py::arg("height") = py::none(), py::arg("load") = py::none(),
           "Every contact point of one wheelset position: y [m] lateral shift (+ right), roll,\n"
           "yaw [rad]; height [m] axle drop (+ down) or load [N] total vertical load (Hertz);\n"
           "neither: rigid contact, just touching (roll solved when 0). Returns the pose\n"
           "(lateral, vertical [m], roll, yaw [rad]) and per point: side, wheel_y, rail_y,\n"
           "x, y, z, lead [m], contact_angle [rad], rolling_radius [m], curvature_a,\n"
           "curvature_b [1/m], penetration, vertical_gap [m], normal_force [N], flange.")
      .def("table", &table, py::arg("lateral_min") = -12e-3, py::arg("lateral_max") = 12e-3,
           py::arg("lateral_step") = 0.1e-3, py::arg("yaw") = std::vector<double>{0.0},
           "The contact table (as the vehicle model looks it up): per lateral shift [m] (and "
           "yaw [rad]) each column of ContactTable (delta_r [m], roll [rad], per wheel the "
           "contact angle, rolling radius, positions, curvatures ...).")
      .def_property_readonly("wheel_profile",
                             [](const Pair& p) { return profile_dict(p.pair->wheel_profile()); })
      .def_property_readonly("rail_profile",
                             [](const Pair& p) { return profile_dict(p.pair->rail_profile()); })
      .def_static(
          "equivalent_conicity",
          [](const std::vector<double>& lateral, const std::vector<double>& delta_r,
             double amplitude) { return fc::equivalent_conicity(lateral, delta_r, amplitude); },
          py::arg("lateral"), py::arg("delta_r"), py::arg("amplitude"),
          "Equivalent conicity [-] at a lateral amplitude [m] from delta_r(y) [m] (EN 15302).");
}

}  // namespace ferro::python
