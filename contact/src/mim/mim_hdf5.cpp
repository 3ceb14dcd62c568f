// HDF5 output of a MIM solution (HDF5 C API).
//
// References: none (file format). Known deviations: none.

#include <fmt/format.h>
#include <hdf5.h>

#include <stdexcept>
#include <vector>

#include "ferro/contact/mim/mim.hpp"
#include "../quiet_hdf5.hpp"

namespace ferro::contact::mim {
namespace {

struct H5Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  H5Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
  ~H5Handle() {
    if (id >= 0) close(id);
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
};

using detail::QuietHdf5;

void check(bool ok, const std::string& path, const std::string& what) {
  if (!ok) throw std::runtime_error(fmt::format("write_hdf5 {}: cannot write {}", path, what));
}

void attribute(hid_t file, const std::string& path, const char* name, double value) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle attr(H5Acreate2(file, name, H5T_NATIVE_DOUBLE, space.id, H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  check(attr.id >= 0 && H5Awrite(attr.id, H5T_NATIVE_DOUBLE, &value) >= 0, path, name);
}

template <class T>
void dataset(hid_t file, const std::string& path, const char* name, const Grid& g, const T* data,
             hid_t type) {
  const hsize_t dims[2] = {static_cast<hsize_t>(g.ny), static_cast<hsize_t>(g.nx)};
  H5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  H5Handle set(H5Dcreate2(file, name, type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
  check(set.id >= 0 && H5Dwrite(set.id, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0, path,
        name);
}

}  // namespace

void write_hdf5(const MimResult& r, const std::string& path) {
  const std::size_t n = r.grid.size();
  if (r.pressure.size() != n || r.traction_x.size() != n || r.traction_y.size() != n ||
      r.slip_x.size() != n || r.slip_y.size() != n || r.state.size() != n) {
    throw std::invalid_argument(fmt::format(
        "write_hdf5 {}: result fields do not match the {} x {} grid", path, r.grid.nx, r.grid.ny));
  }
  const QuietHdf5 quiet;
  H5Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  check(file.id >= 0, path, "file");
  attribute(file.id, path, "dx_m", r.grid.dx);
  attribute(file.id, path, "dy_m", r.grid.dy);
  attribute(file.id, path, "x0_m", r.grid.x0);
  attribute(file.id, path, "y0_m", r.grid.y0);
  attribute(file.id, path, "normal_force_N", r.normal_force);
  attribute(file.id, path, "force_x_N", r.force_x);
  attribute(file.id, path, "force_y_N", r.force_y);
  attribute(file.id, path, "moment_z_Nm", r.moment_z);
  attribute(file.id, path, "approach_m", r.approach);
  attribute(file.id, path, "gap_residual", r.gap_residual);
  attribute(file.id, path, "penetration_residual", r.penetration_residual);
  attribute(file.id, path, "stick_residual", r.stick_residual);
  attribute(file.id, path, "direction_residual", r.direction_residual);
  attribute(file.id, path, "coulomb_residual", r.coulomb_residual);
  attribute(file.id, path, "converged", r.converged ? 1.0 : 0.0);
  attribute(file.id, path, "patch_truncated", r.patch_truncated ? 1.0 : 0.0);
  dataset(file.id, path, "pressure_Pa", r.grid, r.pressure.data(), H5T_NATIVE_DOUBLE);
  dataset(file.id, path, "traction_x_Pa", r.grid, r.traction_x.data(), H5T_NATIVE_DOUBLE);
  dataset(file.id, path, "traction_y_Pa", r.grid, r.traction_y.data(), H5T_NATIVE_DOUBLE);
  dataset(file.id, path, "slip_x", r.grid, r.slip_x.data(), H5T_NATIVE_DOUBLE);
  dataset(file.id, path, "slip_y", r.grid, r.slip_y.data(), H5T_NATIVE_DOUBLE);
  std::vector<unsigned char> state(n);
  for (std::size_t i = 0; i < n; ++i) state[i] = static_cast<unsigned char>(r.state[i]);
  dataset(file.id, path, "state", r.grid, state.data(), H5T_NATIVE_UCHAR);
}

}  // namespace ferro::contact::mim
