// The one HDF5 layer (see the header). Every HDF5 call is checked; on failure the cause is taken
// from HDF5's error stack (the system's message when the file driver saw one).
//
// References: HDF5 1.10 C reference manual (H5F, H5D, H5A, H5E). Known deviations: none.
#include "ferro/io/hdf5.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <type_traits>

namespace ferro::io {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "the io layer stores hid_t as int64_t");
static_assert(std::is_same_v<hsize_t, std::uint64_t> || sizeof(hsize_t) == 8,
              "Dims holds hsize_t values");

// HDF5 prints its own error stack by default; this layer reports through exceptions instead.
// Every file is closed by its RAII handle; HDF5's own clean-up at exit would try again to close
// a file whose close failed (a full disk) and crash, so it is turned off before the library
// starts.
void silence_hdf5() {
  static const bool done = [] {
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

// The most specific cause on the current HDF5 error stack: the system's message when the file
// driver recorded one ("... errno = 28, error message = 'No space left on device'"), otherwise
// the innermost description.
std::string hdf5_cause() {
  struct Walk {
    std::string system, innermost;
  } walk;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
        auto& w = *static_cast<Walk*>(data);
        const std::string desc = e->desc ? e->desc : "";
        if (w.innermost.empty()) w.innermost = desc;
        const auto pos = desc.find("error message = '");
        if (w.system.empty() && pos != std::string::npos) {
          const auto start = pos + std::strlen("error message = '");
          const auto end = desc.find('\'', start);
          w.system = desc.substr(start, end == std::string::npos ? end : end - start);
        }
        return 0;
      },
      &walk);
  H5Eclear2(H5E_DEFAULT);
  if (!walk.system.empty()) return walk.system;
  return walk.innermost.empty() ? "unknown HDF5 error" : walk.innermost;
}

[[noreturn]] void fail(const std::string& what, const std::string& file) {
  throw Hdf5Error(fmt::format("HDF5: {} failed in '{}': {}", what, file, hdf5_cause()));
}
void check(herr_t rc, const std::string& what, const std::string& file) {
  if (rc < 0) fail(what, file);
}
hid_t check_id(hid_t id, const std::string& what, const std::string& file) {
  if (id < 0) fail(what, file);
  return id;
}

// The dimensions of a dataspace.
std::vector<hsize_t> extent_of(hid_t space, const std::string& what, const std::string& file) {
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail(what, file);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0) check(H5Sget_simple_extent_dims(space, dims.data(), nullptr), what, file);
  return dims;
}

// RAII owner of one HDF5 identifier.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(Id&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  Id& operator=(Id&&) = delete;
  [[nodiscard]] hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

Id string_type(std::size_t size, const std::string& file) {
  Id t(check_id(H5Tcopy(H5T_C_S1), "string type", file), H5Tclose);
  check(H5Tset_size(t.get(), std::max<std::size_t>(size, 1)), "string type", file);
  check(H5Tset_strpad(t.get(), H5T_STR_NULLTERM), "string type", file);
  check(H5Tset_cset(t.get(), H5T_CSET_UTF8), "string type", file);
  return t;
}

std::string parent_of(const std::string& dataset) {
  const auto slash = dataset.rfind('/');
  return slash == std::string::npos || slash == 0 ? std::string() : dataset.substr(0, slash);
}

}  // namespace

H5File H5File::create(const std::string& path) {
  silence_hdf5();
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec) {
      throw Hdf5Error(fmt::format("HDF5: cannot create folder '{}' for '{}': {}", parent.string(),
                                  path, ec.message()));
    }
  }
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) fail("create file", path);
  return H5File(id, path);
}

H5File H5File::open_read(const std::string& path) {
  silence_hdf5();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) fail("open file", path);
  return H5File(id, path);
}

H5File H5File::open_input(const std::string& path, const std::string& what) {
  try {
    return open_read(path);
  } catch (const Hdf5Error& e) {
    throw std::invalid_argument(
        fmt::format("{}: cannot open the {} as an HDF5 file ({})", path, what, e.what()));
  }
}

H5File::H5File(H5File&& o) noexcept : id_(o.id_), path_(std::move(o.path_)) {
  o.id_ = -1;
}

H5File& H5File::operator=(H5File&& o) noexcept {
  if (this != &o) {
    if (id_ >= 0) H5Fclose(id_);
    id_ = o.id_;
    path_ = std::move(o.path_);
    o.id_ = -1;
  }
  return *this;
}

H5File::~H5File() {
  if (id_ >= 0) {
    H5Fclose(id_);
    H5Eclear2(H5E_DEFAULT);
  }
}

void H5File::close() {
  if (id_ < 0) return;
  const hid_t id = id_;
  id_ = -1;
  check(H5Fclose(id), "close", path_);
}

std::uint64_t H5File::size_bytes() const {
  hsize_t size = 0;
  check(H5Fget_filesize(id_, &size), "file size", path_);
  return size;
}

bool H5File::exists(const std::string& object) const {
  if (object == "/" || object.empty()) return true;
  // Check each path component, as H5Lexists requires.
  std::size_t pos = object.front() == '/' ? 1 : 0;
  while (true) {
    const auto next = object.find('/', pos);
    const std::string prefix = object.substr(0, next);
    const htri_t rc = H5Lexists(id_, prefix.c_str(), H5P_DEFAULT);
    if (rc < 0) fail("look up " + prefix, path_);
    if (rc == 0) return false;
    if (next == std::string::npos) return true;
    pos = next + 1;
  }
}

void H5File::ensure_group(const std::string& group) {
  if (group.empty() || exists(group)) return;
  Id lcpl(check_id(H5Pcreate(H5P_LINK_CREATE), "create group " + group, path_), H5Pclose);
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "create group " + group, path_);
  Id g(check_id(H5Gcreate2(id_, group.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
                "create group " + group, path_),
       H5Gclose);
}

std::vector<std::string> H5File::members(const std::string& group) const {
  const std::string what = "list group " + group;
  Id g(check_id(H5Gopen2(id_, group.c_str(), H5P_DEFAULT), what, path_), H5Gclose);
  H5G_info_t info;
  check(H5Gget_info(g.get(), &info), what, path_);
  std::vector<std::string> out;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len =
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) fail(what, path_);
    std::string name(static_cast<std::size_t>(len), '\0');
    if (H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(),
                           static_cast<std::size_t>(len) + 1, H5P_DEFAULT) < 0) {
      fail(what, path_);
    }
    out.push_back(std::move(name));
  }
  return out;
}

std::vector<std::string> H5File::attribute_names(const std::string& object) const {
  const std::string what = "list attributes of " + object;
  Id obj(check_id(H5Oopen(id_, object.c_str(), H5P_DEFAULT), what, path_), H5Oclose);
  std::vector<std::string> out;
  const auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  hsize_t index = 0;
  check(H5Aiterate2(obj.get(), H5_INDEX_NAME, H5_ITER_INC, &index, collect, &out), what, path_);
  return out;
}

namespace {

void put_attribute(hid_t file, const std::string& path, const std::string& object,
                   const std::string& name, hid_t file_type, hid_t mem_type, const void* value) {
  const std::string what = "write attribute " + object + "@" + name;
  Id obj(check_id(H5Oopen(file, object.c_str(), H5P_DEFAULT), what, path), H5Oclose);
  const htri_t present = H5Aexists(obj.get(), name.c_str());
  if (present < 0) fail(what, path);
  if (present > 0) check(H5Adelete(obj.get(), name.c_str()), what, path);
  Id space(check_id(H5Screate(H5S_SCALAR), what, path), H5Sclose);
  Id attr(check_id(
              H5Acreate2(obj.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
              what, path),
          H5Aclose);
  check(H5Awrite(attr.get(), mem_type, value), what, path);
}

}  // namespace

void H5File::set_attribute(const std::string& object, const std::string& name,
                           const std::string& value) {
  const Id t = string_type(value.size() + 1, path_);
  put_attribute(id_, path_, object, name, t.get(), t.get(), value.c_str());
}
void H5File::set_attribute(const std::string& object, const std::string& name, const char* value) {
  set_attribute(object, name, std::string(value));
}
void H5File::set_attribute(const std::string& object, const std::string& name, double value) {
  put_attribute(id_, path_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}
void H5File::set_attribute(const std::string& object, const std::string& name, long value) {
  put_attribute(id_, path_, object, name, H5T_STD_I64LE, H5T_NATIVE_LONG, &value);
}
void H5File::set_attribute(const std::string& object, const std::string& name, int value) {
  put_attribute(id_, path_, object, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value);
}

bool H5File::has_attribute(const std::string& object, const std::string& name) const {
  if (!exists(object)) return false;
  const htri_t rc = H5Aexists_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT);
  if (rc < 0) fail("look up attribute " + object + "@" + name, path_);
  return rc > 0;
}

std::string H5File::string_attribute(const std::string& object, const std::string& name) const {
  const std::string what = "read attribute " + object + "@" + name;
  Id a(check_id(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), what,
                path_),
       H5Aclose);
  Id ftype(check_id(H5Aget_type(a.get()), what, path_), H5Tclose);
  if (H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) > 0) {
    throw Hdf5Error(fmt::format("HDF5: {} in '{}': not a fixed-length string", what, path_));
  }
  const std::size_t size = H5Tget_size(ftype.get());
  std::string out(size, '\0');
  const Id mtype = string_type(size, path_);
  check(H5Aread(a.get(), mtype.get(), out.data()), what, path_);
  out.resize(std::min(out.size(), out.find('\0')));
  return out;
}

double H5File::number_attribute(const std::string& object, const std::string& name) const {
  const std::string what = "read attribute " + object + "@" + name;
  Id a(check_id(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), what,
                path_),
       H5Aclose);
  double v = 0.0;
  check(H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v), what, path_);
  return v;
}

long H5File::integer_attribute(const std::string& object, const std::string& name) const {
  const std::string what = "read attribute " + object + "@" + name;
  Id a(check_id(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), what,
                path_),
       H5Aclose);
  Id ftype(check_id(H5Aget_type(a.get()), what, path_), H5Tclose);
  if (H5Tget_class(ftype.get()) != H5T_INTEGER) {
    throw Hdf5Error(fmt::format("HDF5: {} in '{}': not an integer", what, path_));
  }
  long v = 0;
  check(H5Aread(a.get(), H5T_NATIVE_LONG, &v), what, path_);
  return v;
}

namespace {

void write_dataset(hid_t file, const std::string& path, const std::string& dataset,
                   const void* values, std::size_t count, const Dims& dims, hid_t file_type,
                   hid_t mem_type) {
  const std::string what = "write dataset " + dataset;
  std::size_t product = 1;
  for (auto d : dims) product *= static_cast<std::size_t>(d);
  if (product != count) {
    throw std::invalid_argument(fmt::format("HDF5: {} in '{}': {} values for dimensions of {}",
                                            what, path, count, product));
  }
  const std::vector<hsize_t> hdims(dims.begin(), dims.end());
  Id space(check_id(hdims.empty()
                        ? H5Screate(H5S_SCALAR)
                        : H5Screate_simple(static_cast<int>(hdims.size()), hdims.data(), nullptr),
                    what, path),
           H5Sclose);
  Id d(check_id(H5Dcreate2(file, dataset.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                           H5P_DEFAULT),
                what, path),
       H5Dclose);
  if (count > 0)
    check(H5Dwrite(d.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), what, path);
}

}  // namespace

void H5File::write_array(const std::string& dataset, std::span<const double> values,
                         const Dims& dims) {
  ensure_group(parent_of(dataset));
  write_dataset(id_, path_, dataset, values.data(), values.size(), dims, H5T_IEEE_F64LE,
                H5T_NATIVE_DOUBLE);
}

void H5File::write_array(const std::string& dataset, std::span<const std::uint8_t> values,
                         const Dims& dims) {
  ensure_group(parent_of(dataset));
  write_dataset(id_, path_, dataset, values.data(), values.size(), dims, H5T_STD_U8LE,
                H5T_NATIVE_UINT8);
}

void H5File::write_matrix(const std::string& dataset, std::span<const double> values,
                          std::size_t rows, std::size_t cols, const std::string& unit,
                          const std::string& description) {
  write_array(dataset, values, cols == 0 ? Dims{rows} : Dims{rows, cols});
  set_attribute(dataset, "unit", unit);
  if (!description.empty()) set_attribute(dataset, "description", description);
}

void H5File::write_vector(const std::string& dataset, std::span<const double> values,
                          const std::string& unit, const std::string& description) {
  write_matrix(dataset, values, values.size(), 0, unit, description);
}

void H5File::write_text(const std::string& dataset, const std::string& text) {
  ensure_group(parent_of(dataset));
  const Id t = string_type(text.size() + 1, path_);
  write_dataset(id_, path_, dataset, text.c_str(), 1, {}, t.get(), t.get());
}

std::vector<double> H5File::read_array(const std::string& dataset, Dims* dims_out) const {
  const std::string what = "read dataset " + dataset;
  Id d(check_id(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), what, path_), H5Dclose);
  Id space(check_id(H5Dget_space(d.get()), what, path_), H5Sclose);
  const std::vector<hsize_t> dims = extent_of(space.get(), what, path_);
  std::size_t count = 1;
  for (hsize_t n : dims) count *= static_cast<std::size_t>(n);
  std::vector<double> out(count);
  if (count > 0) {
    check(H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), what,
          path_);
  }
  if (dims_out) dims_out->assign(dims.begin(), dims.end());
  return out;
}

Dims H5File::dimensions(const std::string& dataset) const {
  const std::string what = "read dimensions of " + dataset;
  Id d(check_id(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), what, path_), H5Dclose);
  Id space(check_id(H5Dget_space(d.get()), what, path_), H5Sclose);
  const std::vector<hsize_t> dims = extent_of(space.get(), what, path_);
  return Dims(dims.begin(), dims.end());
}

void H5File::read_rows(const std::string& dataset, std::uint64_t first, std::uint64_t rows,
                       std::span<double> out) const {
  const std::string what = fmt::format("read rows {}-{} of {}", first, first + rows, dataset);
  Id d(check_id(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), what, path_), H5Dclose);
  Id space(check_id(H5Dget_space(d.get()), what, path_), H5Sclose);
  const std::vector<hsize_t> dims = extent_of(space.get(), what, path_);
  if (dims.size() != 2 || first + rows > dims[0] || out.size() != rows * dims[1]) {
    throw Hdf5Error(fmt::format("HDF5: {} in '{}': not a 2-D dataset holding those rows, or the "
                                "buffer is not rows x columns",
                                what, path_));
  }
  if (rows == 0) return;
  const hsize_t start[2] = {first, 0}, count[2] = {rows, dims[1]};
  check(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr), what,
        path_);
  Id memory(check_id(H5Screate_simple(2, count, nullptr), what, path_), H5Sclose);
  check(H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, out.data()),
        what, path_);
}

std::string H5File::read_text(const std::string& dataset) const {
  const std::string what = "read text " + dataset;
  Id d(check_id(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), what, path_), H5Dclose);
  Id ftype(check_id(H5Dget_type(d.get()), what, path_), H5Tclose);
  if (H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) > 0) {
    throw Hdf5Error(fmt::format("HDF5: {} in '{}': not a fixed-length string", what, path_));
  }
  const std::size_t size = H5Tget_size(ftype.get());
  std::string out(size, '\0');
  const Id mtype = string_type(size, path_);
  check(H5Dread(d.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), what, path_);
  out.resize(std::min(out.size(), out.find('\0')));
  return out;
}

ExtendibleSeries H5File::create_series(const std::string& dataset, const std::string& unit,
                                       const std::string& description, std::size_t chunk_rows) {
  ensure_group(parent_of(dataset));
  const std::string what = "create dataset " + dataset;
  const hsize_t zero[1] = {0}, unlimited[1] = {H5S_UNLIMITED};
  const hsize_t chunk[1] = {std::max<hsize_t>(chunk_rows, 1)};
  Id space(check_id(H5Screate_simple(1, zero, unlimited), what, path_), H5Sclose);
  Id dcpl(check_id(H5Pcreate(H5P_DATASET_CREATE), what, path_), H5Pclose);
  check(H5Pset_chunk(dcpl.get(), 1, chunk), what, path_);
  const hid_t d = check_id(H5Dcreate2(id_, dataset.c_str(), H5T_IEEE_F64LE, space.get(),
                                      H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                           what, path_);
  ExtendibleSeries series(d, dataset, path_);
  set_attribute(dataset, "unit", unit);
  if (!description.empty()) set_attribute(dataset, "description", description);
  return series;
}

void H5File::flush() {
  check(H5Fflush(id_, H5F_SCOPE_GLOBAL), "flush", path_);
}

ExtendibleSeries::ExtendibleSeries(ExtendibleSeries&& o) noexcept
    : id_(o.id_), name_(std::move(o.name_)), file_(std::move(o.file_)), size_(o.size_) {
  o.id_ = -1;
}

ExtendibleSeries& ExtendibleSeries::operator=(ExtendibleSeries&& o) noexcept {
  if (this != &o) {
    if (id_ >= 0) H5Dclose(id_);
    id_ = o.id_;
    name_ = std::move(o.name_);
    file_ = std::move(o.file_);
    size_ = o.size_;
    o.id_ = -1;
  }
  return *this;
}

ExtendibleSeries::~ExtendibleSeries() {
  if (id_ >= 0) H5Dclose(id_);
}

void ExtendibleSeries::append(std::span<const double> values) {
  if (values.empty()) return;
  const std::string what = "append to dataset " + name_;
  const hsize_t n = values.size();
  const hsize_t new_size[1] = {size_ + n};
  const hsize_t start[1] = {size_}, count[1] = {n};
  check(H5Dset_extent(id_, new_size), what, file_);
  const auto write = [&] {
    Id fspace(check_id(H5Dget_space(id_), what, file_), H5Sclose);
    check(H5Sselect_hyperslab(fspace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr), what,
          file_);
    Id mspace(check_id(H5Screate_simple(1, count, nullptr), what, file_), H5Sclose);
    check(H5Dwrite(id_, H5T_NATIVE_DOUBLE, mspace.get(), fspace.get(), H5P_DEFAULT, values.data()),
          what, file_);
  };
  try {
    write();
  } catch (const Hdf5Error&) {
    const hsize_t old_size[1] = {size_};
    H5Dset_extent(id_, old_size);
    H5Eclear2(H5E_DEFAULT);
    throw;
  }
  size_ += n;
}

}  // namespace ferro::io
