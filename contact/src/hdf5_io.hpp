#pragma once
// Private to the contact library: a small RAII, error-checked layer over the HDF5 C API for
// flat files of double datasets and scalar double attributes. Errors throw with the file path and
// the dataset/attribute name. Callers silence HDF5's own error printing with a QuietHdf5 scope
// that outlives the file.
#include <fmt/format.h>
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "quiet_hdf5.hpp"

namespace ferro::contact::detail {

class Hdf5File {
 public:
  static Hdf5File create(const std::string& path) {
    Hdf5File f(path);
    f.id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (f.id_ < 0) throw std::runtime_error(fmt::format("{}: cannot create HDF5 file", path));
    return f;
  }
  static Hdf5File open(const std::string& path) {
    Hdf5File f(path);
    f.id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f.id_ < 0) {
      throw std::invalid_argument(fmt::format("{}: cannot open as an HDF5 file", path));
    }
    return f;
  }
  Hdf5File(Hdf5File&& o) noexcept : path_(std::move(o.path_)), id_(o.id_) { o.id_ = -1; }
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;
  Hdf5File& operator=(Hdf5File&&) = delete;
  ~Hdf5File() {
    if (id_ >= 0) H5Fclose(id_);
  }

  void write_dataset(const char* name, const std::vector<double>& v,
                     const std::vector<std::size_t>& dims) {
    std::vector<hsize_t> d(dims.begin(), dims.end());
    const Handle space(H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr), H5Sclose);
    const Handle set(H5Dcreate2(id_, name, H5T_IEEE_F64LE, space.id, H5P_DEFAULT, H5P_DEFAULT,
                                H5P_DEFAULT),
                     H5Dclose);
    if (space.id < 0 || set.id < 0 ||
        H5Dwrite(set.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
      throw std::runtime_error(fmt::format("{}: cannot write dataset '{}'", path_, name));
    }
  }
  [[nodiscard]] std::vector<double> read_dataset(const char* name,
                                                 std::vector<std::size_t>* dims_out) const {
    if (H5Lexists(id_, name, H5P_DEFAULT) <= 0) {
      throw std::invalid_argument(fmt::format("{}: missing dataset '{}'", path_, name));
    }
    const Handle set(H5Dopen2(id_, name, H5P_DEFAULT), H5Dclose);
    const Handle space(set.id < 0 ? -1 : H5Dget_space(set.id), H5Sclose);
    const int rank = space.id < 0 ? -1 : H5Sget_simple_extent_ndims(space.id);
    if (rank < 1 || rank > 4) {
      throw std::invalid_argument(fmt::format("{}: dataset '{}' unreadable", path_, name));
    }
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
    std::size_t n = 1;
    for (hsize_t d : dims) n *= static_cast<std::size_t>(d);
    std::vector<double> v(n);
    if (n > 0 && H5Dread(set.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
      throw std::invalid_argument(fmt::format("{}: cannot read dataset '{}'", path_, name));
    }
    if (dims_out) dims_out->assign(dims.begin(), dims.end());
    return v;
  }
  void write_attribute(const char* name, double value) {
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    const Handle attr(H5Acreate2(id_, name, H5T_IEEE_F64LE, space.id, H5P_DEFAULT, H5P_DEFAULT),
                      H5Aclose);
    if (attr.id < 0 || H5Awrite(attr.id, H5T_NATIVE_DOUBLE, &value) < 0) {
      throw std::runtime_error(fmt::format("{}: cannot write attribute '{}'", path_, name));
    }
  }
  [[nodiscard]] double read_attribute(const char* name) const {
    if (H5Aexists(id_, name) <= 0) {
      throw std::invalid_argument(fmt::format("{}: missing attribute '{}'", path_, name));
    }
    const Handle attr(H5Aopen(id_, name, H5P_DEFAULT), H5Aclose);
    double v = 0.0;
    if (attr.id < 0 || H5Aread(attr.id, H5T_NATIVE_DOUBLE, &v) < 0) {
      throw std::invalid_argument(fmt::format("{}: cannot read attribute '{}'", path_, name));
    }
    return v;
  }

 private:
  struct Handle {
    hid_t id;
    herr_t (*close)(hid_t);
    Handle(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) {}
    ~Handle() {
      if (id >= 0) close(id);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
  };
  explicit Hdf5File(std::string path) : path_(std::move(path)) {}
  std::string path_;
  hid_t id_ = -1;
};

}  // namespace ferro::contact::detail
