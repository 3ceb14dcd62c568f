#include "ferro/scenarios/h5_output.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

namespace ferro::scenarios {
namespace {

// HDF5 prints its own error stack by default; the library reports through exceptions instead.
void silence_hdf5() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

void check(herr_t rc, const std::string& what, const std::string& file) {
  if (rc < 0) throw std::runtime_error(fmt::format("HDF5: {} failed in '{}'", what, file));
}
hid_t check_id(hid_t id, const std::string& what, const std::string& file) {
  if (id < 0) throw std::runtime_error(fmt::format("HDF5: {} failed in '{}'", what, file));
  return id;
}

hid_t string_type(std::size_t size) {
  const hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, std::max<std::size_t>(size, 1));
  H5Tset_strpad(t, H5T_STR_NULLTERM);
  H5Tset_cset(t, H5T_CSET_UTF8);
  return t;
}

template <class Write>
void put_attribute(hid_t file, const std::string& path, const std::string& object,
                   const std::string& name, hid_t type, Write write) {
  const hid_t obj = check_id(H5Oopen(file, object.c_str(), H5P_DEFAULT), "open " + object, path);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t rc = attr < 0 ? -1 : write(attr);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Oclose(obj);
  check(rc, "write attribute " + object + "@" + name, path);
}

}  // namespace

H5File H5File::create(const std::string& path) {
  silence_hdf5();
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw std::runtime_error(fmt::format("cannot create HDF5 file '{}'", path));
  return H5File(id, path);
}

H5File H5File::open_read(const std::string& path) {
  silence_hdf5();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) throw std::runtime_error(fmt::format("cannot open HDF5 file '{}'", path));
  return H5File(id, path);
}

H5File::H5File(H5File&& o) noexcept : id_(o.id_), path_(std::move(o.path_)) {
  o.id_ = H5I_INVALID_HID;
}
H5File& H5File::operator=(H5File&& o) noexcept {
  if (this != &o) {
    if (id_ >= 0) H5Fclose(id_);
    id_ = o.id_;
    path_ = std::move(o.path_);
    o.id_ = H5I_INVALID_HID;
  }
  return *this;
}
H5File::~H5File() {
  if (id_ >= 0) H5Fclose(id_);
}

bool H5File::exists(const std::string& object) const {
  if (object == "/") return true;
  // Check each path component, as H5Lexists requires.
  std::size_t pos = 1;
  while (true) {
    const auto next = object.find('/', pos);
    const std::string prefix = object.substr(0, next);
    if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (next == std::string::npos) return true;
    pos = next + 1;
  }
}

void H5File::ensure_group(const std::string& group) {
  if (exists(group)) return;
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t g = H5Gcreate2(id_, group.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  check_id(g, "create group " + group, path_);
  H5Gclose(g);
}

void H5File::set_attribute(const std::string& object, const std::string& name,
                           const std::string& value) {
  const hid_t t = string_type(value.size() + 1);
  put_attribute(id_, path_, object, name, t,
                [&](hid_t a) { return H5Awrite(a, t, value.c_str()); });
  H5Tclose(t);
}
void H5File::set_attribute(const std::string& object, const std::string& name, double value) {
  put_attribute(id_, path_, object, name, H5T_IEEE_F64LE,
                [&](hid_t a) { return H5Awrite(a, H5T_NATIVE_DOUBLE, &value); });
}
void H5File::set_attribute(const std::string& object, const std::string& name, long value) {
  put_attribute(id_, path_, object, name, H5T_STD_I64LE,
                [&](hid_t a) { return H5Awrite(a, H5T_NATIVE_LONG, &value); });
}

std::string H5File::string_attribute(const std::string& object, const std::string& name) const {
  const hid_t a =
      check_id(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
               "open attribute " + object + "@" + name, path_);
  const hid_t ftype = H5Aget_type(a);
  const std::size_t size = H5Tget_size(ftype);
  std::string out(size, '\0');
  const hid_t mtype = string_type(size);
  const herr_t rc = H5Aread(a, mtype, out.data());
  H5Tclose(mtype);
  H5Tclose(ftype);
  H5Aclose(a);
  check(rc, "read attribute " + name, path_);
  out.resize(out.find('\0') == std::string::npos ? out.size() : out.find('\0'));
  return out;
}

double H5File::number_attribute(const std::string& object, const std::string& name) const {
  const hid_t a =
      check_id(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
               "open attribute " + object + "@" + name, path_);
  double v = 0.0;
  const herr_t rc = H5Aread(a, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(a);
  check(rc, "read attribute " + name, path_);
  return v;
}

void H5File::write_matrix(const std::string& dataset, std::span<const double> values,
                          std::size_t rows, std::size_t cols, const std::string& unit,
                          const std::string& description) {
  const auto slash = dataset.rfind('/');
  if (slash != std::string::npos && slash > 0) ensure_group(dataset.substr(0, slash));
  const hsize_t dims2[2] = {rows, cols};
  const hsize_t dims1[1] = {rows};
  const hid_t space =
      cols == 0 ? H5Screate_simple(1, dims1, nullptr) : H5Screate_simple(2, dims2, nullptr);
  const hid_t d = check_id(H5Dcreate2(id_, dataset.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                      H5P_DEFAULT, H5P_DEFAULT),
                           "create dataset " + dataset, path_);
  const herr_t rc =
      values.empty() ? 0
                     : H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(d);
  H5Sclose(space);
  check(rc, "write dataset " + dataset, path_);
  set_attribute(dataset, "unit", unit);
  if (!description.empty()) set_attribute(dataset, "description", description);
}

void H5File::write_vector(const std::string& dataset, std::span<const double> values,
                          const std::string& unit, const std::string& description) {
  write_matrix(dataset, values, values.size(), 0, unit, description);
}

void H5File::write_text(const std::string& dataset, const std::string& text) {
  const auto slash = dataset.rfind('/');
  if (slash != std::string::npos && slash > 0) ensure_group(dataset.substr(0, slash));
  const hid_t t = string_type(text.size() + 1);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t d =
      check_id(H5Dcreate2(id_, dataset.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               "create dataset " + dataset, path_);
  const herr_t rc = H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.c_str());
  H5Dclose(d);
  H5Sclose(space);
  H5Tclose(t);
  check(rc, "write text " + dataset, path_);
}

std::vector<double> H5File::read_vector(const std::string& dataset) const {
  const hid_t d =
      check_id(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), "open dataset " + dataset, path_);
  const hid_t space = H5Dget_space(d);
  const auto n = H5Sget_simple_extent_npoints(space);
  std::vector<double> out(static_cast<std::size_t>(std::max<hssize_t>(n, 0)));
  const herr_t rc =
      out.empty() ? 0 : H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(d);
  check(rc, "read dataset " + dataset, path_);
  return out;
}

void H5File::flush() {
  check(H5Fflush(id_, H5F_SCOPE_GLOBAL), "flush", path_);
}

TimeSeriesWriter::TimeSeriesWriter(H5File& file, const std::vector<vehicle::SignalInfo>& channels,
                                   double flush_seconds, std::size_t chunk_rows)
    : file_(file),
      chunk_rows_(chunk_rows),
      flush_seconds_(flush_seconds),
      last_flush_(std::chrono::steady_clock::now()),
      buffer_(channels.size()) {
  file_.ensure_group("/signals");
  const hsize_t zero[1] = {0}, unlimited[1] = {H5S_UNLIMITED}, chunk[1] = {chunk_rows_};
  auto make = [&](const std::string& name, const std::string& unit,
                  const std::string& description) {
    const hid_t space = H5Screate_simple(1, zero, unlimited);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(dcpl, 1, chunk);
    const hid_t d = check_id(
        H5Dcreate2(file_.id(), name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
        "create dataset " + name, file_.path());
    H5Pclose(dcpl);
    H5Sclose(space);
    datasets_.push_back(d);
    file_.set_attribute(name, "unit", unit);
    if (!description.empty()) file_.set_attribute(name, "description", description);
  };
  make("/time", "s", "simulation time");
  for (const auto& c : channels) make("/signals/" + c.name, c.unit, c.description);
  file_.flush();
}

TimeSeriesWriter::~TimeSeriesWriter() {
  try {
    flush();
  } catch (...) {
    // Destructors must not throw; an explicit flush() reports failures.
  }
  for (hid_t d : datasets_) H5Dclose(d);
}

void TimeSeriesWriter::append(double t, std::span<const double> values) {
  if (values.size() != buffer_.size()) {
    throw std::invalid_argument(fmt::format("TimeSeriesWriter::append: {} values for {} channels",
                                            values.size(), buffer_.size()));
  }
  buffer_t_.push_back(t);
  for (std::size_t i = 0; i < values.size(); ++i) buffer_[i].push_back(values[i]);
  const auto now = std::chrono::steady_clock::now();
  if (buffer_t_.size() >= chunk_rows_ ||
      std::chrono::duration<double>(now - last_flush_).count() >= flush_seconds_) {
    flush();
  }
}

void TimeSeriesWriter::flush() {
  last_flush_ = std::chrono::steady_clock::now();
  if (buffer_t_.empty()) return;
  const hsize_t n = buffer_t_.size();
  const hsize_t new_size[1] = {static_cast<hsize_t>(written_) + n};
  const hsize_t start[1] = {static_cast<hsize_t>(written_)}, count[1] = {n};
  for (std::size_t k = 0; k < datasets_.size(); ++k) {
    const double* data = k == 0 ? buffer_t_.data() : buffer_[k - 1].data();
    check(H5Dset_extent(datasets_[k], new_size), "extend dataset", file_.path());
    const hid_t fspace = H5Dget_space(datasets_[k]);
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hid_t mspace = H5Screate_simple(1, count, nullptr);
    const herr_t rc = H5Dwrite(datasets_[k], H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, data);
    H5Sclose(mspace);
    H5Sclose(fspace);
    check(rc, "write samples", file_.path());
  }
  written_ += static_cast<long>(n);
  buffer_t_.clear();
  for (auto& b : buffer_) b.clear();
  file_.set_attribute("/", "samples", written_);
  file_.flush();
}

}  // namespace ferro::scenarios
