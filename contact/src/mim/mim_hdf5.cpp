// HDF5 output of a MIM solution (through the io layer, ferro/io/hdf5.hpp).
//
// References: none (file format). Known deviations: none.

#include <fmt/format.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ferro/contact/mim/mim.hpp"
#include "ferro/io/hdf5.hpp"

namespace ferro::contact::mim {

void write_hdf5(const MimResult& r, const std::string& path) {
  const std::size_t n = r.grid.size();
  if (r.pressure.size() != n || r.traction_x.size() != n || r.traction_y.size() != n ||
      r.slip_x.size() != n || r.slip_y.size() != n || r.state.size() != n) {
    throw std::invalid_argument(fmt::format(
        "write_hdf5 {}: result fields do not match the {} x {} grid", path, r.grid.nx, r.grid.ny));
  }
  io::H5File file = io::H5File::create(path);
  const std::pair<const char*, double> attributes[] = {
      {"dx_m", r.grid.dx},
      {"dy_m", r.grid.dy},
      {"x0_m", r.grid.x0},
      {"y0_m", r.grid.y0},
      {"normal_force_N", r.normal_force},
      {"force_x_N", r.force_x},
      {"force_y_N", r.force_y},
      {"moment_z_Nm", r.moment_z},
      {"approach_m", r.approach},
      {"gap_residual", r.gap_residual},
      {"penetration_residual", r.penetration_residual},
      {"stick_residual", r.stick_residual},
      {"direction_residual", r.direction_residual},
      {"coulomb_residual", r.coulomb_residual},
      {"converged", r.converged ? 1.0 : 0.0},
      {"patch_truncated", r.patch_truncated ? 1.0 : 0.0}};
  for (const auto& [name, value] : attributes) file.set_attribute("/", name, value);
  const io::Dims dims = {static_cast<std::uint64_t>(r.grid.ny), static_cast<std::uint64_t>(r.grid.nx)};
  file.write_array("/pressure_Pa", r.pressure, dims);
  file.write_array("/traction_x_Pa", r.traction_x, dims);
  file.write_array("/traction_y_Pa", r.traction_y, dims);
  file.write_array("/slip_x", r.slip_x, dims);
  file.write_array("/slip_y", r.slip_y, dims);
  std::vector<std::uint8_t> state(n);
  for (std::size_t i = 0; i < n; ++i) state[i] = static_cast<std::uint8_t>(r.state[i]);
  file.write_array("/state", std::span<const std::uint8_t>(state), dims);
  file.close();
}

}  // namespace ferro::contact::mim
