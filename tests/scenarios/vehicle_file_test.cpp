// Vehicle files -> vehicle::VehicleConfig. Oracles: the data files themselves, read here
// independently with yaml-cpp (data/manchester_vehicle1.yaml, data/cooperrider_wagon/wagon.yaml
// with its element lists and derived linear equivalents), and statics (the preloads of the
// vertical springs carry exactly the weight above them).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "ferro/scenarios/vehicle_file.hpp"

namespace ferro::scenarios {
namespace {

using vehicle::Dof;
using vehicle::ElementType;
using vehicle::SuspensionElementSpec;
using vehicle::VehicleConfig;

// Values are copied, not computed: equal to the last bit except sums (relative 1e-12).
constexpr double kSumTolerance = 1e-12;
// The data file's preloads are printed to 0.01 N.
constexpr double kPreloadRounding = 0.01;

const std::string kSrc = FERRO_SOURCE_DIR;
const std::string kManchester = kSrc + "/scenarios/vehicles/manchester_vehicle1.yaml";
const std::string kWagon = kSrc + "/scenarios/vehicles/cooperrider_wagon.yaml";

const vehicle::RigidBodySpec& body(const VehicleConfig& v, const std::string& name) {
  const int i = body_index(v, name);
  EXPECT_GE(i, 0) << name;
  return v.bodies.at(static_cast<std::size_t>(i));
}

std::vector<const SuspensionElementSpec*> elements_with(const VehicleConfig& v,
                                                        const std::string& fragment) {
  std::vector<const SuspensionElementSpec*> out;
  for (const auto& e : v.elements)
    if (e.name.find(fragment) != std::string::npos) out.push_back(&e);
  return out;
}

// Every scalar of `data` appears with the same text in `copy` (extra keys allowed), except
// the listed paths.
void expect_contained(const YAML::Node& data, const YAML::Node& copy, const std::string& path,
                      const std::set<std::string>& except) {
  if (except.count(path)) return;
  ASSERT_TRUE(copy.IsDefined()) << path << " missing in the copy";
  if (data.IsScalar()) {
    EXPECT_EQ(data.Scalar(), copy.Scalar()) << path;
  } else if (data.IsSequence()) {
    ASSERT_EQ(data.size(), copy.size()) << path;
    for (std::size_t i = 0; i < data.size(); ++i)
      expect_contained(data[i], copy[i], path + "[" + std::to_string(i) + "]", except);
  } else if (data.IsMap()) {
    for (const auto& kv : data) {
      const std::string k = kv.first.as<std::string>();
      expect_contained(kv.second, copy[k], path + "." + k, except);
    }
  }
}

TEST(VehicleFile, manchester_copy_is_faithful_to_the_data_file) {
  const YAML::Node data = YAML::LoadFile(std::string(FERRO_DATA_DIR) + "/manchester_vehicle1.yaml");
  const YAML::Node copy = YAML::LoadFile(kManchester);
  expect_contained(data, copy, "", {".wheel_rail.wheel_profile", ".wheel_rail.rail_profile"});
  EXPECT_EQ(copy["wheel_rail"]["wheel_profile"].Scalar(),
            "../../data/" + data["wheel_rail"]["wheel_profile"].Scalar());
  EXPECT_EQ(copy["schema_version"].as<int>(), 1);
}

TEST(VehicleFile, manchester_expands_to_bodies_and_elements_of_the_data_file) {
  const YAML::Node d = YAML::LoadFile(std::string(FERRO_DATA_DIR) + "/manchester_vehicle1.yaml");
  const VehicleConfig v = load_vehicle_file(kManchester);
  ASSERT_EQ(v.bodies.size(), 7u);
  const double semi_spacing = d["geometry"]["bogie_centre_spacing"].as<double>() / 2;
  const double semi_base = d["geometry"]["wheelbase"].as<double>() / 2;
  EXPECT_EQ(body(v, "car_body").mass, d["car_body"]["mass"].as<double>());
  EXPECT_EQ(body(v, "car_body").inertia.x(), d["car_body"]["inertia"]["roll"].as<double>());
  EXPECT_EQ(body(v, "car_body").position.z(), d["car_body"]["cg_height"].as<double>());
  EXPECT_EQ(body(v, "bogie_2").position.x(), -semi_spacing);
  EXPECT_EQ(body(v, "bogie_1").inertia.z(), d["bogie_frame"]["inertia"]["yaw"].as<double>());
  const double ws_x[4] = {semi_spacing + semi_base, semi_spacing - semi_base,
                          -semi_spacing + semi_base, -semi_spacing - semi_base};
  for (int i = 0; i < 4; ++i) {
    const auto& w = body(v, "wheelset_" + std::to_string(i + 1));
    EXPECT_EQ(w.kind, vehicle::BodyKind::wheelset);
    EXPECT_EQ(w.position.x(), ws_x[i]);
    EXPECT_EQ(w.position.z(), d["wheelset"]["nominal_rolling_radius"].as<double>());
    EXPECT_EQ(w.nominal_rolling_radius, 0.46);
    EXPECT_EQ(w.inertia.y(), d["wheelset"]["inertia"]["pitch"].as<double>());
  }
  // 2 axleboxes x 4 wheelsets; per bogie: 2 sides, bump stop, anti-roll bar, yaw stiffness.
  EXPECT_EQ(v.elements.size(), 8u + 2u * 5u);
  const auto primary = elements_with(v, "primary.");
  ASSERT_EQ(primary.size(), 8u);
  for (const auto* e : primary) {
    EXPECT_EQ(e->type, ElementType::spring_damper);
    EXPECT_EQ(e->stiffness.x(), d["primary_suspension"]["stiffness"]["x"].as<double>());
    EXPECT_EQ(e->stiffness.y(), d["primary_suspension"]["stiffness"]["y"].as<double>());
    EXPECT_EQ(e->stiffness.z(), d["primary_suspension"]["stiffness"]["z"].as<double>());
    EXPECT_EQ(e->damping.z(), d["primary_suspension"]["damping"]["z"].as<double>());
    EXPECT_EQ(e->damping.x(), 0.0);
    EXPECT_EQ(std::abs(e->point_b.y()), d["geometry"]["primary_lateral_semi_spacing"].as<double>());
    // The bogie end of the spring sits over the axle: same absolute x as the wheelset.
    const auto& up = v.bodies[static_cast<std::size_t>(e->body_a)];
    const auto& lo = v.bodies[static_cast<std::size_t>(e->body_b)];
    EXPECT_EQ(up.kind, vehicle::BodyKind::bogie_frame);
    EXPECT_NEAR(up.position.x() + e->point_a.x(), lo.position.x() + e->point_b.x(), 1e-12);
  }
  const auto sides = elements_with(v, ".left");
  const auto right = elements_with(v, ".right");
  EXPECT_EQ(sides.size() + right.size(), 12u);
  const auto secondary = elements_with(v, "secondary.bogie_1.left");
  ASSERT_EQ(secondary.size(), 1u);
  const auto* s = secondary[0];
  EXPECT_EQ(s->stiffness.z(), d["secondary_suspension"]["stiffness"]["z"].as<double>());
  EXPECT_EQ(s->damping.y(), d["secondary_suspension"]["damping"]["y"].as<double>());
  EXPECT_NEAR(body(v, "car_body").position.z() + s->point_a.z(),
              d["geometry"]["secondary_height"].as<double>(), 1e-12);
  const auto bump = elements_with(v, "lateral_bump_stop");
  ASSERT_EQ(bump.size(), 2u);
  const auto table = d["secondary_suspension"]["lateral_bump_stop"];
  EXPECT_EQ(bump[0]->type, ElementType::bump_stop);
  EXPECT_EQ(bump[0]->axis, Dof::y);
  EXPECT_EQ(bump[0]->clearance, table["clearance"].as<double>());
  EXPECT_EQ(bump[0]->table_force, table["force"].as<std::vector<double>>());
  EXPECT_EQ(bump[0]->table_displacement, table["displacement"].as<std::vector<double>>());
  const auto arb = elements_with(v, "anti_roll_bar");
  ASSERT_EQ(arb.size(), 2u);
  EXPECT_EQ(arb[0]->axis, Dof::roll);
  EXPECT_EQ(arb[0]->k, d["secondary_suspension"]["anti_roll_bar"].as<double>());
  const auto yaw = elements_with(v, "yaw_stiffness");
  ASSERT_EQ(yaw.size(), 2u);
  EXPECT_EQ(yaw[0]->axis, Dof::yaw);
  EXPECT_EQ(yaw[0]->k, 2.0 * d["secondary_suspension"]["bogie_yaw_stiffness"].as<double>());
  // Wheel-rail block.
  EXPECT_EQ(v.wheel_rail.geometry, "table");
  EXPECT_EQ(v.wheel_rail.friction, d["wheel_rail"]["friction"].as<double>());
  EXPECT_EQ(v.wheel_rail.track_gauge, d["geometry"]["track_gauge"].as<double>());
  EXPECT_EQ(v.wheel_rail.flange_back_distance, d["wheelset"]["flange_back_distance"].as<double>());
  EXPECT_TRUE(std::filesystem::exists(v.wheel_rail.wheel_profile)) << v.wheel_rail.wheel_profile;
  EXPECT_TRUE(std::filesystem::exists(v.wheel_rail.rail_profile));
}

TEST(VehicleFile, manchester_static_preloads_carry_the_weight_above) {
  const VehicleConfig v = load_vehicle_file(kManchester);
  double secondary = 0.0, primary = 0.0;
  for (const auto& e : v.elements) {
    if (e.name.rfind("secondary.", 0) == 0) secondary += e.preload.z();
    if (e.name.rfind("primary.", 0) == 0) primary += e.preload.z();
  }
  const double car = body(v, "car_body").mass, bogie = body(v, "bogie_1").mass;
  // Preloads act on the lower body, pushing it down.
  EXPECT_NEAR(secondary, -car * v.gravity, kSumTolerance * car * v.gravity);
  EXPECT_NEAR(primary, -(car + 2 * bogie) * v.gravity, kSumTolerance * car * v.gravity);
}

struct WagonPair {
  const char* group;  // path in wagon.yaml suspension
  const char* list;
  const char* upper_key;
  const char* lower_key;
  const char* upper_body;
  const char* lower_body;
};

TEST(VehicleFile, cooperrider_wagon_reproduces_every_element_of_the_data_file) {
  const YAML::Node d = YAML::LoadFile(std::string(FERRO_DATA_DIR) + "/cooperrider_wagon/wagon.yaml");
  const VehicleConfig v = load_vehicle_file(kWagon);
  ASSERT_EQ(v.bodies.size(), 7u);
  // Bodies: masses and centres as the data file lists them.
  const auto& b = d["bodies"];
  EXPECT_EQ(body(v, "car_body").mass, b["car_body"]["mass"].as<double>());
  EXPECT_NEAR(body(v, "car_body").position.z(), b["car_body"]["centre"][2].as<double>(), 1e-12);
  const char* ws_keys[4] = {"leading_bogie_leading", "leading_bogie_trailing",
                            "trailing_bogie_leading", "trailing_bogie_trailing"};
  double total = body(v, "car_body").mass;
  for (int i = 0; i < 4; ++i) {
    const auto& w = body(v, "wheelset_" + std::to_string(i + 1));
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(w.position[k], b["wheelsets"][ws_keys[i]]["centre"][k].as<double>(), 1e-12)
          << ws_keys[i];
    EXPECT_FALSE(w.active[static_cast<int>(Dof::x)]);
    EXPECT_FALSE(w.active[static_cast<int>(Dof::pitch)]);
    EXPECT_TRUE(w.spin_dof);
    EXPECT_EQ(w.inertia.y(), b["wheelsets"]["inertia"]["spin"].as<double>());
    total += w.mass;
  }
  for (const char* name : {"bogie_1", "bogie_2"}) total += body(v, name).mass;
  EXPECT_NEAR(total, b["total_mass"].as<double>(), kSumTolerance * total);
  EXPECT_NEAR(body(v, "bogie_1").position.x(), b["bogie_frames"]["leading"]["centre"][0].as<double>(),
              1e-12);

  const WagonPair pairs[] = {
      {"secondary", "leading_bogie", "upper_carbody", "lower_bogie", "car_body", "bogie_1"},
      {"secondary", "trailing_bogie", "upper_carbody", "lower_bogie", "car_body", "bogie_2"},
      {"primary", "leading_wheelset_of_bogie", "upper_bogie", "lower_wheelset", "bogie_1",
       "wheelset_1"},
      {"primary", "trailing_wheelset_of_bogie", "upper_bogie", "lower_wheelset", "bogie_1",
       "wheelset_2"},
      {"primary", "leading_wheelset_of_bogie", "upper_bogie", "lower_wheelset", "bogie_2",
       "wheelset_3"},
      {"primary", "trailing_wheelset_of_bogie", "upper_bogie", "lower_wheelset", "bogie_2",
       "wheelset_4"},
  };
  std::size_t checked = 0;
  for (const auto& p : pairs) {
    const auto list = d["suspension"][p.group][p.list];
    ASSERT_TRUE(list.IsSequence()) << p.list;
    const std::string prefix = std::string(p.group) + "." + p.lower_body + ".";
    for (const auto& item : list) {
      const std::string name = prefix + item["name"].as<std::string>();
      const auto found = elements_with(v, name);
      ASSERT_EQ(found.size(), 1u) << name;
      const auto& e = *found[0];
      EXPECT_EQ(v.bodies[static_cast<std::size_t>(e.body_a)].name, p.upper_body) << name;
      EXPECT_EQ(v.bodies[static_cast<std::size_t>(e.body_b)].name, p.lower_body) << name;
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(e.point_a[k], item[p.upper_key][k].as<double>()) << name << " upper " << k;
        EXPECT_EQ(e.point_b[k], item[p.lower_key][k].as<double>()) << name << " lower " << k;
      }
      const std::string type = item["type"].as<std::string>();
      int axis = 0;
      if (item["axis"]) axis = static_cast<int>(std::string("xyz").find(item["axis"].as<std::string>()));
      EXPECT_EQ(e.type, ElementType::spring_damper) << name;
      if (type == "axis_spring") {
        EXPECT_EQ(e.stiffness[axis], item["k"].as<double>()) << name;
        EXPECT_EQ(e.stiffness.sum(), item["k"].as<double>()) << name;
        EXPECT_EQ(e.damping.norm(), 0.0) << name;
        const double preload = item["preload"] ? item["preload"].as<double>() : 0.0;
        EXPECT_EQ(-e.preload.z(), preload) << name;
      } else {
        EXPECT_EQ(e.damping.sum(), item["c"].as<double>()) << name;
        EXPECT_EQ(e.stiffness.norm(), 0.0) << name;
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, v.elements.size());
  EXPECT_EQ(v.elements.size(), 72u);

  // Linear equivalents the data file derives from its layout.
  const auto eq = d["suspension"]["derived_equivalents"];
  double lat_k = 0, lat_c = 0, vert_k = 0, yaw_k = 0, roll_k = 0;
  for (const auto* e : elements_with(v, "secondary.bogie_1.")) {
    lat_k += e->stiffness.y();
    lat_c += e->damping.y();
    vert_k += e->stiffness.z();
    yaw_k += e->stiffness.x() * e->point_b.y() * e->point_b.y();
    roll_k += e->stiffness.z() * e->point_b.y() * e->point_b.y();
  }
  const auto sec = eq["secondary_per_bogie"];
  EXPECT_NEAR(lat_k, sec["lateral_stiffness"].as<double>(), kSumTolerance * lat_k);
  EXPECT_NEAR(lat_c, sec["lateral_damping"].as<double>(), kSumTolerance * lat_c);
  EXPECT_NEAR(vert_k, sec["vertical_stiffness"].as<double>(), kSumTolerance * vert_k);
  EXPECT_NEAR(yaw_k, sec["yaw_stiffness"].as<double>(), kSumTolerance * yaw_k);
  EXPECT_NEAR(roll_k, sec["roll_stiffness_from_vertical"].as<double>(), 1e-6 * roll_k);
  double p_yaw = 0, p_preload = 0, s_preload = 0;
  for (const auto* e : elements_with(v, "primary.wheelset_1.")) {
    p_yaw += e->stiffness.x() * e->point_b.y() * e->point_b.y();
    p_preload += -e->preload.z();
  }
  for (const auto* e : elements_with(v, "secondary.")) s_preload += -e->preload.z();
  EXPECT_NEAR(p_yaw, eq["primary_per_wheelset"]["yaw_stiffness"].as<double>(), 1e-6 * p_yaw);
  // Statics: the secondary springs carry the car body, the primary ones body and bogies.
  const double g = 9.81;
  EXPECT_NEAR(s_preload, b["car_body"]["mass"].as<double>() * g, 4 * kPreloadRounding);
  EXPECT_NEAR(4 * p_preload,
              (b["car_body"]["mass"].as<double>() + 2 * b["bogie_frames"]["mass"].as<double>()) * g,
              16 * kPreloadRounding);

  // Contact as the data file states it.
  const auto wr = d["wheel_rail_contact"];
  EXPECT_EQ(v.wheel_rail.geometry, "imported");
  EXPECT_EQ(v.wheel_rail.friction, wr["creep_force"]["mu"].as<double>());
  EXPECT_EQ(v.wheel_rail.shear_modulus, wr["creep_force"]["shear_modulus_G"].as<double>());
  EXPECT_EQ(v.wheel_rail.poisson, wr["creep_force"]["poisson_nu"].as<double>());
  EXPECT_EQ(v.wheel_rail.tangential_model, "shen_hedrick_elkins");
  EXPECT_TRUE(std::filesystem::exists(v.wheel_rail.imported_table));
  EXPECT_EQ(std::filesystem::path(v.wheel_rail.imported_table).filename().string(),
            wr["table"]["file"].as<std::string>());
}

// ----- located errors -----

std::string vehicle_error(const std::string& patch_from, const std::string& patch_to) {
  std::ifstream in(kManchester);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const auto at = text.find(patch_from);
  EXPECT_NE(at, std::string::npos) << patch_from;
  text.replace(at, patch_from.size(), patch_to);
  // Same directory, so that the relative profile paths still resolve.
  const std::string path = kSrc + "/scenarios/vehicles/bad_vehicle.yaml";
  try {
    const YamlFile f = parse_yaml_text(text, path);
    MapReader r(f.root, path, "");
    (void)read_vehicle(r);
  } catch (const YamlInputError& e) {
    return e.what();
  }
  return "(no error)";
}

int line_of(const std::string& text_fragment) {
  std::ifstream in(kManchester);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.find(text_fragment) != std::string::npos) return n;
  }
  return -1;
}

TEST(VehicleFile, located_errors_name_line_key_and_allowed_values) {
  struct Case {
    const char* from;
    const char* to;
    const char* key;
    const char* hint;
  };
  const Case cases[] = {
      {"  stiffness: {x: 31.391e6", "  stifness: {x: 31.391e6", "primary_suspension.stifness",
       "did you mean 'stiffness'?"},
      {"  mass: 32000", "  mass: -32000", "car_body.mass", "must be > 0 kg"},
      {"  anti_roll_bar: 940e3", "  anti_roll_bar: stiff", "secondary_suspension.anti_roll_bar",
       "expected a number"},
      {"    force:        [0,     600,", "    force:        [600,",
       "secondary_suspension.lateral_bump_stop.force", "same length"},
      {"  friction: 0.32", "  friction: 0", "wheel_rail.friction", "must lie in (0, 2]"},
      {"  friction: 0.32", "  hunt_crossley_alpha: -3\n  friction: 0.32",
       "wheel_rail.hunt_crossley_alpha", "must be finite and >= 0 s/m"},
      {"  friction: 0.32", "  hunt_crossley_alph: 3\n  friction: 0.32",
       "wheel_rail.hunt_crossley_alph", "did you mean 'hunt_crossley_alpha'?"},
      {"  tangential: chopaya", "  tangential: chopya", "wheel_rail.tangential",
       "did you mean 'chopaya'?"},
      {"  wheel_profile: ../../data/profiles/MBench_S1002_v3.prw",
       "  wheel_profile: ../../data/profiles/none.prw", "wheel_rail.wheel_profile",
       "does not exist"},
      {"  geometry: table ", "  geometry: conical ", "wheel_rail.conicity",
       "required for geometry 'conical'"},
      {"  rail_inclination: 0.0 ", "  wheel_conical_tread: {conicity: 1.5, join_y: -0.015}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.wheel_conical_tread.conicity", "must lie in (0, 1)"},
      {"  rail_inclination: 0.0 ", "  wheel_conical_tread: {conicity: 0.1, join_y: -15}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.wheel_conical_tread.join_y",
       "must lie in (-0.1, 0.1) m"},
      {"  rail_inclination: 0.0 ", "  wheel_conical_tread: {conicity: 0.1}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.wheel_conical_tread.join_y",
       "missing required key 'join_y'"},
      {"  rail_inclination: 0.0 ", "  table_yaw: {max: 0.025, step: 0.004}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.table_yaw.step", "must be a whole number"},
      {"  rail_inclination: 0.0 ", "  table_yaw: {max: 0.5, step: 0.005}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.table_yaw.max", "must lie in (0, 0.1] rad"},
      {"  rail_inclination: 0.0 ", "  table_yaw: {max: 0.025}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.table_yaw", "missing required key 'step'"},
      {"  rail_inclination: 0.0 ", "  table_yaw: {max: 0.025, step: -0.005}\n"
       "  rail_inclination: 0.0 ", "wheel_rail.table_yaw.step", "must lie in (0, max = 0.025] rad"},
      {"  nominal_rolling_radius: 0.46", "  nominal_rolling_radius: 0.46\n  dofs: [y, yaw, spn]",
       "wheelset.dofs", "did you mean 'spin'?"},
  };
  for (const auto& c : cases) {
    const std::string msg = vehicle_error(c.from, c.to);
    const int line = line_of(std::string(c.from).substr(0, std::string(c.from).find('\n')));
    EXPECT_NE(msg.find("bad_vehicle.yaml:"), std::string::npos) << msg;
    EXPECT_NE(msg.find(c.key), std::string::npos) << c.to << " -> " << msg;
    EXPECT_NE(msg.find(c.hint), std::string::npos) << c.to << " -> " << msg;
    if (std::string(c.key) != "wheel_rail.conicity" && std::string(c.key) != "wheelset.dofs") {
      EXPECT_NE(msg.find(":" + std::to_string(line) + ":"), std::string::npos)
          << c.to << " -> " << msg;
    }
  }
}

TEST(VehicleFile, misaligned_vector_damper_is_refused) {
  const std::string text = R"(
car_body: {mass: 1, inertia: {roll: 1, pitch: 1, yaw: 1}, cg_height: 2}
bogie_frame: {mass: 1, inertia: {roll: 1, pitch: 1, yaw: 1}, cg_height: 0.5}
wheelset: {mass: 1, inertia: {roll: 1, spin: 1, yaw: 1}, nominal_rolling_radius: 0.4}
geometry: {bogie_centre_spacing: 10, wheelbase: 2}
secondary_suspension:
  elements:
    - {name: d, type: vector_damper, c: 1, upper: [5, 1, -1], lower: [0, 0.5, 0]}
primary_suspension:
  elements:
    - {name: s, type: axis_spring, axis: z, k: 1, upper: [1, 0, 0.2], lower: [0, 0, 0]}
wheel_rail: {geometry: conical, conicity: 0.2, contact_half_distance: 0.75}
)";
  const YamlFile f = parse_yaml_text(text, "v.yaml");
  MapReader r(f.root, "v.yaml", "");
  try {
    (void)read_vehicle(r);
    FAIL() << "accepted a misaligned vector damper";
  } catch (const YamlInputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("v.yaml:8:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("secondary_suspension.elements[0].upper"), std::string::npos) << msg;
    EXPECT_NE(msg.find("along x, y or z"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace ferro::scenarios
