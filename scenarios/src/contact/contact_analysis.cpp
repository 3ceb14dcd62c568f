// Creep curves and patch pictures for `ferrodyn contact curve|patch`.
#include "ferro/scenarios/contact_analysis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "ferro/io/hdf5.hpp"
#include "ferro/io/text_writer.hpp"

namespace ferro::scenarios {
namespace {

contact::TangentialSolution solve_all_patches(const contact::TangentialModel& model,
                                              const ContactCase& c,
                                              const contact::NormalSolution& normal,
                                              const contact::Creepage& cr) {
  contact::TangentialSolution sum;
  for (const contact::ContactPatch& patch : normal.patches) {
    contact::TangentialProblem p;
    p.patch = &patch;
    p.creepage = cr;
    p.friction = c.friction;
    p.body1 = c.normal.body1;
    p.body2 = c.normal.body2;
    p.reduction = c.reduction;
    p.gap = &c.normal;
    const contact::TangentialSolution s = model.solve(p);
    require_finite_forces(s, fmt::format("model '{}' of case '{}'", model.name(), c.name));
    sum.force_x += s.force_x;
    sum.force_y += s.force_y;
    sum.moment_z += s.moment_z;
  }
  return sum;
}

}  // namespace

void require_finite_forces(const contact::TangentialSolution& s, const std::string& what) {
  if (std::isfinite(s.force_x) && std::isfinite(s.force_y) && std::isfinite(s.moment_z)) return;
  std::string which;
  for (const auto& [name, v] : {std::pair<const char*, double>{"F_x", s.force_x},
                                {"F_y", s.force_y},
                                {"M_z", s.moment_z}}) {
    if (!std::isfinite(v)) which += which.empty() ? name : std::string(", ") + name;
  }
  throw std::invalid_argument(fmt::format(
      "{}: the result overflowed ({} not finite): the input lies outside the physical range "
      "the model's arithmetic holds (check semi-axes, load, moduli and K_ij)",
      what, which));
}

std::vector<CurvePoint> compute_creep_curves(const ContactCase& c,
                                             const contact::NormalSolution& normal) {
  std::vector<CurvePoint> out;
  struct Sweep {
    const char* name;
    const CurveRequest* req;
  };
  const Sweep sweeps[] = {{"longitudinal", &c.longitudinal},
                          {"lateral", &c.lateral},
                          {"spin", &c.spin},
                          {"combined", &c.combined}};
  for (const NamedModel& m : c.models) {
    const auto model = contact::make_tangential_model(m.name, m.options);
    for (const Sweep& sw : sweeps) {
      if (!sw.req->enabled) continue;
      const int n = sw.req->points;
      const bool combined = std::string(sw.name) == "combined";
      for (int i = 0; i < n; ++i) {
        const double s =
            combined ? sw.req->max * i / (n - 1) : -sw.req->max + 2.0 * sw.req->max * i / (n - 1);
        contact::Creepage cr;
        if (std::string(sw.name) == "longitudinal") cr.longitudinal = s;
        if (std::string(sw.name) == "lateral") cr.lateral = s;
        if (std::string(sw.name) == "spin") cr.spin = s;
        if (combined) {
          const double ang = sw.req->angle_deg * std::numbers::pi / 180.0;
          cr.longitudinal = s * std::cos(ang);
          cr.lateral = s * std::sin(ang);
        }
        const contact::TangentialSolution f = solve_all_patches(*model, c, normal, cr);
        out.push_back({sw.name, m.label(), s, f.force_x, f.force_y, f.moment_z});
      }
    }
  }
  return out;
}

void write_curves_csv(const std::string& path, const std::vector<CurvePoint>& points) {
  io::TextWriter f(path);
  f.print("curve,model,creepage,force_x,force_y,moment_z,force_t\n");
  for (const CurvePoint& p : points) {
    f.print("{},\"{}\",{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", p.curve, p.model, p.creepage,
            p.force_x, p.force_y, p.moment_z, std::hypot(p.force_x, p.force_y));
  }
  f.close();
}

void write_curves_hdf5(const std::string& path, const std::vector<CurvePoint>& points) {
  io::H5File file = io::H5File::create(path);
  file.set_attribute("/", "schema_version", 1);
  file.set_attribute("/", "units",
                     "SI: creepage [-] or [1/m] (spin), force [N], moment [N m]; "
                     "forces on the wheel from the rail");
  // Group the points by curve then model, keeping order.
  std::map<std::string, std::map<std::string, std::vector<const CurvePoint*>>> groups;
  for (const CurvePoint& p : points) groups[p.curve][p.model].push_back(&p);
  for (const auto& [curve, models] : groups) {
    file.ensure_group("/" + curve);
    for (const auto& model_points : models) {
      // Not a structured binding: clang 14 (the fuzz build) cannot capture those in a lambda.
      const std::vector<const CurvePoint*>& pts = model_points.second;
      std::string name = model_points.first;
      for (char& ch : name)
        if (ch == '/') ch = '_';
      const std::string group = "/" + curve + "/" + name;
      file.ensure_group(group);
      auto write = [&](const char* ds, auto get) {
        std::vector<double> v;
        v.reserve(pts.size());
        for (const CurvePoint* p : pts) v.push_back(get(*p));
        file.write_array(group + "/" + ds, v, {v.size()});
      };
      write("creepage", [](const CurvePoint& p) { return p.creepage; });
      write("force_x", [](const CurvePoint& p) { return p.force_x; });
      write("force_y", [](const CurvePoint& p) { return p.force_y; });
      write("moment_z", [](const CurvePoint& p) { return p.moment_z; });
    }
  }
  file.close();
}

PatchPicture compute_patch_picture(const ContactCase& c, const contact::NormalSolution& normal) {
  PatchPicture pic;
  const auto model = contact::make_tangential_model(c.patch_model.name, c.patch_model.options);
  for (std::size_t k = 0; k < normal.patches.size(); ++k) {
    const contact::ContactPatch& patch = normal.patches[k];
    contact::TractionMap map;
    contact::TangentialProblem p;
    p.patch = &patch;
    p.creepage = c.patch_creepage;
    p.friction = c.friction;
    p.body1 = c.normal.body1;
    p.body2 = c.normal.body2;
    p.reduction = c.reduction;
    p.gap = &c.normal;
    p.map = &map;
    pic.forces.push_back(model->solve(p));
    require_finite_forces(pic.forces.back(), fmt::format("patch.model '{}'", c.patch_model.name));
    if (map.x.empty()) {
      throw std::invalid_argument(
          fmt::format("patch.model '{}' gives no traction map; use fastsim", c.patch_model.name));
    }
    std::size_t strip = 0;
    for (std::size_t i = 0; i < map.x.size(); ++i) {
      PatchCell cell;
      cell.patch = static_cast<int>(k);
      cell.x = map.x[i];
      cell.y = map.y[i] + patch.y_center;
      cell.dx = map.dx[i];
      cell.dy = map.dy[i];
      cell.traction_x = map.traction_x[i];
      cell.traction_y = map.traction_y[i];
      cell.slip = map.slip[i];
      // Pressure of the normal model (semi-ellipse), not FASTSIM's parabola.
      if (patch.elliptic()) {
        const double u = 1.0 - std::pow(map.x[i] / patch.semi_axis_x, 2) -
                         std::pow(map.y[i] / patch.semi_axis_y, 2);
        cell.pressure = u > 0.0 ? patch.peak_pressure * std::sqrt(u) : 0.0;
      } else {
        while (strip + 1 < patch.strips.size() && patch.strips[strip].y < map.y[i] - 1e-15) ++strip;
        const contact::PatchStrip& s = patch.strips[strip];
        const double u = 1.0 - std::pow((map.x[i] - s.x_center) / s.half_length, 2);
        cell.pressure = u > 0.0 ? s.peak_pressure * std::sqrt(u) : 0.0;
      }
      pic.cells.push_back(cell);
    }
  }
  return pic;
}

void write_patch_csv(const std::string& path, const PatchPicture& picture) {
  io::TextWriter f(path);
  f.print("patch,x,y,dx,dy,pressure,traction_x,traction_y,slip\n");
  for (const PatchCell& c : picture.cells) {
    f.print("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", c.patch, c.x, c.y, c.dx,
            c.dy, c.pressure, c.traction_x, c.traction_y, c.slip);
  }
  f.close();
}

}  // namespace ferro::scenarios
