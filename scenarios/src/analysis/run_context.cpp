// The run context the assessment reads (see the header).
#include "ferro/scenarios/analysis/run_context.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "ferro/scenarios/scene.hpp"

namespace ferro::scenarios::analysis {

namespace {

const char* kind_name(vehicle::BodyKind k) {
  switch (k) {
    case vehicle::BodyKind::car_body:
      return "car_body";
    case vehicle::BodyKind::bogie_frame:
      return "bogie_frame";
    case vehicle::BodyKind::wheelset:
      return "wheelset";
  }
  return "car_body";
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

const RunBody* RunContext::body(const std::string& name) const {
  for (const auto& b : bodies)
    if (b.name == name) return &b;
  return nullptr;
}

std::vector<double> static_axle_loads(const vehicle::VehicleConfig& config) {
  const std::size_t n = config.bodies.size();
  std::vector<std::set<int>> below(n), above(n);
  for (const auto& e : config.elements) {
    if (e.body_a < 0 || e.body_b < 0 || e.body_a == e.body_b) continue;
    below[static_cast<std::size_t>(e.body_a)].insert(e.body_b);
    above[static_cast<std::size_t>(e.body_b)].insert(e.body_a);
  }
  std::vector<double> load(n, 0.0), axle(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) load[i] = config.bodies[i].mass * config.gravity;
  std::vector<bool> done(n, false);
  // Pass loads down, a body once every body above it has passed its load on.
  for (std::size_t pass = 0; pass < n; ++pass) {
    for (std::size_t i = 0; i < n; ++i) {
      if (done[i]) continue;
      if (!std::all_of(above[i].begin(), above[i].end(),
                       [&](int a) { return done[static_cast<std::size_t>(a)]; }))
        continue;
      done[i] = true;
      const auto& sup = below[i];
      if (sup.empty()) {
        axle[i] = config.bodies[i].kind == vehicle::BodyKind::wheelset ? load[i] : 0.0;
        continue;
      }
      const double xc = config.bodies[i].position.x();
      if (sup.size() == 2) {
        const int a = *sup.begin(), b = *std::next(sup.begin());
        const double xa = config.bodies[static_cast<std::size_t>(a)].position.x();
        const double xb = config.bodies[static_cast<std::size_t>(b)].position.x();
        if (std::abs(xa - xb) > 1e-9) {
          load[static_cast<std::size_t>(a)] += load[i] * (xb - xc) / (xb - xa);
          load[static_cast<std::size_t>(b)] += load[i] * (xc - xa) / (xb - xa);
          continue;
        }
      }
      for (int s : sup) load[static_cast<std::size_t>(s)] += load[i] / static_cast<double>(sup.size());
    }
  }
  return axle;
}

RunContext run_context(const Scene& scene) {
  RunContext c;
  const auto& v = scene.model.vehicle;
  c.vehicle = v.name;
  c.category = scene.model.category;
  c.gravity = v.gravity;
  c.friction = v.wheel_rail.friction;
  const auto loads = static_axle_loads(v);
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const auto& b = v.bodies[i];
    c.bodies.push_back({b.name, kind_name(b.kind), b.mass, b.position.x(), b.position.y(),
                        b.position.z(), loads[i]});
  }
  if (scene.track.type == "design") {
    c.rail_spacing = scene.track.design.rail_spacing;
    double s = scene.track.design.start_s;
    int k = 0;
    for (const auto& sec : scene.track.design.sections) {
      TrackSection t;
      t.kind = std::string(track::to_string(sec.kind));
      t.start = s;
      t.end = s + sec.length;
      t.radius = sec.kind == track::SectionKind::kCurve ? sec.radius : 0.0;
      t.cant = sec.kind == track::SectionKind::kCurve ? sec.cant : 0.0;
      t.name = sec.kind == track::SectionKind::kCurve
                   ? fmt::format("{} curve R {:g}", ++k, std::abs(sec.radius))
                   : fmt::format("{} {}", ++k, t.kind);
      c.sections.push_back(t);
      s = t.end;
    }
  }
  c.twist_test = scene.assessment.twist_test;
  c.anti_alias_frequency = scene.output.anti_alias_frequency;
  c.anti_alias_order = c.anti_alias_frequency > 0.0 ? scene.output.anti_alias_order : 0;
  return c;
}

void write_run_context(io::H5File& file, const RunContext& c) {
  file.ensure_group("/vehicle");
  file.set_attribute("/vehicle", "name", c.vehicle);
  file.set_attribute("/vehicle", "category", c.category);
  file.set_attribute("/vehicle", "gravity", c.gravity);
  file.set_attribute("/vehicle", "friction", c.friction);
  std::vector<std::string> names, kinds;
  std::vector<double> mass, x, y, z, load;
  for (const auto& b : c.bodies) {
    names.push_back(b.name);
    kinds.push_back(b.kind);
    mass.push_back(b.mass);
    x.push_back(b.rest_x);
    y.push_back(b.rest_y);
    z.push_back(b.rest_z);
    load.push_back(b.static_load);
  }
  file.set_attribute("/vehicle", "body_names", fmt::format("{}", fmt::join(names, ",")));
  file.set_attribute("/vehicle", "body_kinds", fmt::format("{}", fmt::join(kinds, ",")));
  file.write_vector("/vehicle/body_mass", mass, "kg", "mass of each body (body_names order)");
  file.write_vector("/vehicle/body_rest_x", x, "m",
                    "rest x of each body's centre of mass from the vehicle reference point");
  file.write_vector("/vehicle/body_rest_y", y, "m", "rest y (+ left)");
  file.write_vector("/vehicle/body_rest_z", z, "m", "rest height above top of rail");
  file.write_vector("/vehicle/static_axle_load", load, "N",
                    "static axle load P0 of each wheelset (0 for other bodies): weights passed "
                    "down the suspension by the lever rule");
  file.ensure_group("/track");
  file.set_attribute("/track", "rail_spacing", c.rail_spacing);
  if (!c.sections.empty()) {
    std::vector<std::string> kinds_s, names_s;
    std::vector<double> start, end, radius, cant;
    for (const auto& s : c.sections) {
      kinds_s.push_back(s.kind);
      names_s.push_back(s.name);
      start.push_back(s.start);
      end.push_back(s.end);
      radius.push_back(s.radius);
      cant.push_back(s.cant);
    }
    file.set_attribute("/track", "section_kinds", fmt::format("{}", fmt::join(kinds_s, ",")));
    file.set_attribute("/track", "section_names", fmt::format("{}", fmt::join(names_s, ",")));
    file.write_vector("/track/section_start", start, "m", "arc length where each section starts");
    file.write_vector("/track/section_end", end, "m", "arc length where each section ends");
    file.write_vector("/track/section_radius", radius, "m",
                      "signed radius of each curve (+ left), 0 for other sections");
    file.write_vector("/track/section_cant", cant, "m", "cant of each curve, 0 for others");
  }
  file.ensure_group("/assessment");
  file.set_attribute("/assessment", "twist_test", c.twist_test ? 1 : 0);
  file.set_attribute("/assessment", "anti_alias_frequency", c.anti_alias_frequency);
  file.set_attribute("/assessment", "anti_alias_order", c.anti_alias_order);
}

RunContext read_run_context(const io::H5File& file) {
  RunContext c;
  if (!file.exists("/vehicle")) return c;
  c.vehicle = file.string_attribute("/vehicle", "name");
  c.category = file.string_attribute("/vehicle", "category");
  c.gravity = file.number_attribute("/vehicle", "gravity");
  c.friction = file.number_attribute("/vehicle", "friction");
  const auto names = split(file.string_attribute("/vehicle", "body_names"));
  const auto kinds = split(file.string_attribute("/vehicle", "body_kinds"));
  const auto mass = file.read_vector("/vehicle/body_mass");
  const auto x = file.read_vector("/vehicle/body_rest_x");
  const auto y = file.read_vector("/vehicle/body_rest_y");
  const auto z = file.read_vector("/vehicle/body_rest_z");
  const auto load = file.read_vector("/vehicle/static_axle_load");
  if (names.size() != mass.size() || kinds.size() != mass.size() || x.size() != mass.size() ||
      load.size() != mass.size())
    throw std::invalid_argument(fmt::format("{}: /vehicle: {} body names for {} masses",
                                            file.path(), names.size(), mass.size()));
  for (std::size_t i = 0; i < names.size(); ++i)
    c.bodies.push_back({names[i], kinds[i], mass[i], x[i], y[i], z[i], load[i]});
  if (file.has_attribute("/track", "rail_spacing"))
    c.rail_spacing = file.number_attribute("/track", "rail_spacing");
  if (file.has_attribute("/track", "section_kinds")) {
    const auto kinds_s = split(file.string_attribute("/track", "section_kinds"));
    const auto names_s = split(file.string_attribute("/track", "section_names"));
    const auto start = file.read_vector("/track/section_start");
    const auto end = file.read_vector("/track/section_end");
    const auto radius = file.read_vector("/track/section_radius");
    const auto cant = file.read_vector("/track/section_cant");
    for (std::size_t i = 0; i < start.size() && i < kinds_s.size() && i < names_s.size(); ++i)
      c.sections.push_back({names_s[i], kinds_s[i], start[i], end[i], radius[i], cant[i]});
  }
  if (file.has_attribute("/assessment", "twist_test"))
    c.twist_test = file.integer_attribute("/assessment", "twist_test") != 0;
  if (file.has_attribute("/assessment", "anti_alias_frequency")) {
    c.anti_alias_frequency = file.number_attribute("/assessment", "anti_alias_frequency");
    c.anti_alias_order =
        static_cast<int>(file.integer_attribute("/assessment", "anti_alias_order"));
  }
  return c;
}

double RunContext::anti_alias_delay() const {
  if (!(anti_alias_frequency > 0.0) || anti_alias_order < 2) return 0.0;
  double sum = 0.0;
  for (int k = 1; k <= anti_alias_order / 2; ++k)
    sum += 2.0 * std::sin((2.0 * k - 1.0) * M_PI / (2.0 * anti_alias_order));
  return sum / (2.0 * M_PI * anti_alias_frequency);
}

double track_shift_alpha(const std::string& category) { return category == "wagon" ? 0.85 : 1.0; }

}  // namespace ferro::scenarios::analysis
