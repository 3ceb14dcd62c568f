// One MIM solve as a user asks for it (see the header).
#include "ferro/scenarios/mim_solve.hpp"

#include "ferro/io/text_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ferro::scenarios {

Parameters parameters(MimRequest& r) {
  return {
      Parameter{"a", "m", "semi-axis along the rolling direction", &r.a, false}.formerly("a_mm",
                                                                                       1e-3),
      Parameter{"b", "m", "lateral semi-axis", &r.b, false}.formerly("b_mm", 1e-3),
      {"fn", "N", "normal force", &r.fn, false},
      {"xi_x", "-", "longitudinal creepage", &r.xi_x},
      {"xi_y", "-", "lateral creepage", &r.xi_y},
      {"spin", "1/m", "spin creepage", &r.spin},
      {"mu", "-", "friction coefficient", &r.mu},
      Parameter{"young", "Pa", "Young's modulus of both bodies", &r.young}.formerly("young_gpa",
                                                                                     1e9),
      {"poisson", "-", "Poisson's ratio of both bodies", &r.poisson},
      {"elements", "", "elements across the shorter axis", &r.elements},
  };
}

contact::mim::HertzRollingInput mim_input(const MimRequest& r, Spelling sp) {
  for (const auto& [value, key] : {std::pair{r.a, "a"}, {r.b, "b"}, {r.fn, "fn"}}) {
    if (std::isnan(value))
      throw std::invalid_argument(fmt::format("{} is required", spelled(key, sp)));
  }
  contact::mim::HertzRollingInput in;
  in.semi_axis_x = r.a;
  in.semi_axis_y = r.b;
  in.normal_force = r.fn;
  in.rolling = contact::mim::RollingInput{r.xi_x, r.xi_y, r.spin, r.mu};
  in.body1 = in.body2 = contact::Material::from_young(r.young, r.poisson);
  in.elements_minor = r.elements;
  // The solver's field names become the request's keys in its messages.
  try {
    in.validate("mim");
  } catch (const std::invalid_argument& e) {
    std::string msg = e.what();
    const std::pair<const char*, std::string> names[] = {
        {"mim.semi_axis_x/semi_axis_y", spelled("a", sp) + "/" + spelled("b", sp)},
        {"mim.normal_force", spelled("fn", sp)},
        {"mim.elements_minor", spelled("elements", sp)},
        {"mim.rolling.creepage_x", spelled("xi_x", sp)},
        {"mim.rolling.creepage_y", spelled("xi_y", sp)},
        {"mim.rolling.spin", spelled("spin", sp)},
        {"mim.rolling.friction", spelled("mu", sp)},
        {"mim.body1", spelled("young", sp) + "/" + spelled("poisson", sp)}};
    for (const auto& [field, key] : names) {
      if (msg.rfind(field, 0) == 0) {
        msg = key + msg.substr(std::string(field).size());
        break;
      }
    }
    throw std::invalid_argument(msg);
  }
  return in;
}

std::string mim_report(const MimRequest& request, const contact::mim::MimResult& r, double ms) {
  int stick = 0, slip = 0;
  for (auto s : r.state) {
    stick += s == contact::mim::ElementState::stick ? 1 : 0;
    slip += s == contact::mim::ElementState::slip ? 1 : 0;
  }
  std::string text = fmt::format("grid {} x {}, dx = {:.4f} mm; {} stick, {} slip elements\n",
                                 r.grid.nx, r.grid.ny, r.grid.dx * 1.0e3, stick, slip);
  text += fmt::format(
      "Fn = {:.6g} N, Fx = {:.6g} N, Fy = {:.6g} N, Mz = {:.6g} N m, approach = {:.6g} mm\n",
      r.normal_force, r.force_x, r.force_y, r.moment_z, r.approach * 1.0e3);
  const double mu = request.mu;
  text += fmt::format(
      "Fx/(mu Fn) = {:.5f}, Fy/(mu Fn) = {:.5f}; converged: {}; {:.1f} ms (incl. set-up)\n",
      mu > 0.0 ? r.force_x / (mu * r.normal_force) : 0.0,
      mu > 0.0 ? r.force_y / (mu * r.normal_force) : 0.0, r.converged ? "yes" : "NO", ms);
  if (r.patch_truncated)
    text += "warning: the pressure reaches the grid boundary (patch truncated)\n";
  return text;
}

Parameters parameters(contact::MimTableSpec& spec) {
  return {
      {"elements", "", "MIM elements across the shorter axis", &spec.elements},
      {"grid", "",
       "MIM grid of the nodes: minor (square elements, `elements` across the shorter axis), "
       "patch (elements x elements over the patch), patch_richardson (patch grid, forces "
       "extrapolated from `elements` and its half)",
       &spec.grid},
      {"threads", "", "build threads", &spec.threads},
      {"poisson", "-", "combined Poisson ratio of the table", &spec.poisson},
      {"density", "", "node density: split every creepage and spin interval into N parts (1-8)",
       &spec.density},
  };
}

void check_mim_table_spec(const contact::MimTableSpec& spec, Spelling sp) {
  try {
    spec.validate();
  } catch (const std::invalid_argument& e) {
    std::string msg = e.what();
    for (const char* key : {"elements", "threads", "grid", "poisson", "density"}) {
      const std::string field = std::string("mim table ") + key;
      if (msg.rfind(field, 0) == 0) msg = spelled(key, sp) + msg.substr(field.size());
    }
    throw std::invalid_argument(msg);
  }
}

std::string write_mim_table_error_map(const std::vector<contact::MimTableErrorPoint>& map,
                                      const std::string& path, const std::string& shown) {
  io::TextWriter csv(path);
  csv.write("ratio,xi_x,xi_y,phi,fx_table,fy_table,fx_mim,fy_mim,error_mu_fn\n");
  std::vector<double> err;
  for (const auto& e : map) {
    csv.print("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", e.ratio, e.xi_x,
              e.xi_y, e.spin, e.table.f_x, e.table.f_y, e.direct.f_x, e.direct.f_y, e.error);
    err.push_back(e.error);
  }
  csv.close();
  std::sort(err.begin(), err.end());
  double sum = 0.0;
  for (double v : err) sum += v;
  return fmt::format(
      "error map {} ({} points): table vs direct MIM mean {:.4f}, p95 {:.4f}, max {:.4f} mu Fn\n",
      shown.empty() ? path : shown, err.size(), sum / static_cast<double>(err.size()),
      err[static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(err.size()))) - 1],
      err.back());
}

}  // namespace ferro::scenarios
