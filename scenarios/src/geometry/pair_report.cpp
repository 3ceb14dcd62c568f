// The geometry report of a wheel-rail pair (see the header).
#include "ferro/scenarios/pair_report.hpp"

#include <filesystem>
#include <numbers>

#include "ferro/contact/geometry/contact_table.hpp"
#include "ferro/io/text_writer.hpp"

namespace ferro::scenarios {

namespace fc = ferro::contact;

std::vector<std::string> write_pair_report(const fc::WheelRailPair& pair,
                                           const std::string& folder) {
  std::filesystem::create_directories(folder);
  const std::filesystem::path dir(folder);

  fc::ContactTableParams tp;
  tp.lateral_min = -12e-3;
  tp.lateral_max = 12e-3;
  tp.lateral_step = 0.1e-3;
  const fc::ContactTable table = fc::ContactTable::build(pair, tp);
  table.save_hdf5((dir / "contact_table.h5").string());

  // Contact-point diagram and delta_r(y).
  io::TextWriter diag((dir / "contact_points.csv").string());
  diag.write(
      "y_mm,delta_r_mm,roll_rad,left_wheel_y_mm,left_rail_y_mm,left_angle_deg,"
      "right_wheel_y_mm,right_rail_y_mm,right_angle_deg,right_radius_mm,left_radius_mm\n");
  std::vector<double> ys, dr;
  for (std::size_t i = 0; i < table.lateral().size(); ++i) {
    const double y = table.lateral()[i];
    const fc::ContactTableEntry e = table.lookup(y);
    ys.push_back(y);
    dr.push_back(e.delta_r);
    diag.print("{:.4f},{:.6f},{:.9g},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}\n",
               y * 1e3, e.delta_r * 1e3, e.roll, e.wheel_y[0] * 1e3, e.rail_y[0] * 1e3,
               e.contact_angle[0] * 180.0 / std::numbers::pi, e.wheel_y[1] * 1e3, e.rail_y[1] * 1e3,
               e.contact_angle[1] * 180.0 / std::numbers::pi, e.rolling_radius[1] * 1e3,
               e.rolling_radius[0] * 1e3);
  }
  io::TextWriter con((dir / "conicity.csv").string());
  con.write("amplitude_mm,equivalent_conicity\n");
  for (int k = 1; k <= 20; ++k) {
    const double a = 0.5e-3 * k;
    con.print("{:.2f},{:.6f}\n", a * 1e3, fc::equivalent_conicity(ys, dr, a));
  }
  // Profiles in track coordinates for the diagram (right side).
  io::TextWriter prof((dir / "profiles.csv").string());
  prof.write("kind,y_mm,z_mm\n");
  for (std::size_t i = 0; i < pair.wheel_profile().size(); ++i) {
    prof.print("wheel,{:.5f},{:.5f}\n", pair.wheel_profile().y[i] * 1e3,
               pair.wheel_profile().z[i] * 1e3);
  }
  for (std::size_t i = 0; i < pair.rail_profile().size(); ++i) {
    prof.print("rail,{:.5f},{:.5f}\n", pair.rail_profile().y[i] * 1e3,
               (pair.rail_profile().z[i] - pair.rail_reference().top_z) * 1e3);
  }
  diag.close();
  con.close();
  prof.close();
  return {"contact_table.h5", "contact_points.csv", "conicity.csv", "profiles.csv"};
}

}  // namespace ferro::scenarios
