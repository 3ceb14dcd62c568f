#pragma once
// The one HDF5 layer of ferrodyn (serial HDF5 1.10, C API underneath). Every HDF5 file the
// program reads or writes goes through it: run outputs, analyses, contact tables, K_ij tables,
// MIM tables and MIM solutions. It lives in the bottom room io/, which every other folder may
// use; it depends on nothing else in the project.
//
//  - H5File: RAII file handle. Every HDF5 call is checked; a failure throws io::Hdf5Error naming
//    the operation, the object, the file and the cause reported by the system (e.g. "No space
//    left on device", "File too large"). HDF5's own error printing is off.
//  - ExtendibleSeries: a chunked, unlimited 1-D dataset of doubles appended to in blocks.
//
// This header does not include <hdf5.h>: handles are plain 64-bit identifiers (hid_t).

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace ferro::io {

/// A failed HDF5 operation: "HDF5: <operation> failed in '<file>': <cause>".
class Hdf5Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Dataset dimensions, slowest first (row-major).
using Dims = std::vector<std::uint64_t>;

class ExtendibleSeries;

class H5File {
 public:
  /// Creates (truncating) `path`, making parent folders. Throws Hdf5Error naming it.
  static H5File create(const std::string& path);
  /// Opens an existing file read-only. Throws Hdf5Error naming it.
  static H5File open_read(const std::string& path);
  /// Opens an input the user named (a table, a cache) read-only: a file that cannot be opened is
  /// bad input, std::invalid_argument "<path>: cannot open the <what> as an HDF5 file (<cause>)".
  static H5File open_input(const std::string& path, const std::string& what);

  H5File(H5File&& other) noexcept;
  H5File& operator=(H5File&& other) noexcept;
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;
  /// Closes the file if still open; never throws (call close() to see a failure).
  ~H5File();

  /// Flushes and closes; throws Hdf5Error with the cause. The handle is closed afterwards
  /// whether or not it succeeded.
  void close();
  [[nodiscard]] bool is_open() const { return id_ >= 0; }
  [[nodiscard]] std::int64_t id() const { return id_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  /// Bytes the file takes (HDF5's end of allocated space).
  [[nodiscard]] std::uint64_t size_bytes() const;

  /// True when every component of the absolute path `object` exists ("/" always does).
  [[nodiscard]] bool exists(const std::string& object) const;
  /// Creates the group (and parents) when missing.
  void ensure_group(const std::string& group);
  /// Names of the links in `group`, in name order.
  [[nodiscard]] std::vector<std::string> members(const std::string& group) const;
  /// Names of the attributes of `object`, in name order.
  [[nodiscard]] std::vector<std::string> attribute_names(const std::string& object) const;

  /// Scalar attributes on an object (group or dataset; "/" for the root), replacing any of the
  /// same name. File types: UTF-8 string, float64, int64, int32.
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object, const std::string& name, const char* value);
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, long value);
  void set_attribute(const std::string& object, const std::string& name, int value);
  [[nodiscard]] bool has_attribute(const std::string& object, const std::string& name) const;
  [[nodiscard]] std::string string_attribute(const std::string& object,
                                             const std::string& name) const;
  /// Any numeric attribute, converted to double.
  [[nodiscard]] double number_attribute(const std::string& object, const std::string& name) const;
  /// Any integer attribute (an error for a float or string attribute).
  [[nodiscard]] long integer_attribute(const std::string& object, const std::string& name) const;

  /// N-D float64 dataset (parents created). values.size() must equal the product of dims.
  void write_array(const std::string& dataset, std::span<const double> values, const Dims& dims);
  /// N-D uint8 dataset.
  void write_array(const std::string& dataset, std::span<const std::uint8_t> values,
                   const Dims& dims);
  /// 1-D float64 dataset with `unit` and (when given) `description` attributes.
  void write_vector(const std::string& dataset, std::span<const double> values,
                    const std::string& unit, const std::string& description = "");
  /// 2-D row-major float64 dataset (rows x cols) with `unit` and `description` attributes.
  void write_matrix(const std::string& dataset, std::span<const double> values, std::size_t rows,
                    std::size_t cols, const std::string& unit, const std::string& description = "");
  /// A scalar string dataset (e.g. the scene text).
  void write_text(const std::string& dataset, const std::string& text);

  /// Reads a numeric dataset as float64 (any rank); `dims` receives its dimensions.
  [[nodiscard]] std::vector<double> read_array(const std::string& dataset,
                                               Dims* dims = nullptr) const;
  [[nodiscard]] std::vector<double> read_vector(const std::string& dataset) const {
    return read_array(dataset);
  }
  /// The dimensions of a dataset.
  [[nodiscard]] Dims dimensions(const std::string& dataset) const;
  /// Rows [first, first + rows) of a 2-D numeric dataset as float64 into `out` (rows x the
  /// dataset's columns, row-major), so that a large table is read by blocks.
  void read_rows(const std::string& dataset, std::uint64_t first, std::uint64_t rows,
                 std::span<double> out) const;
  [[nodiscard]] std::string read_text(const std::string& dataset) const;

  /// Chunked, unlimited 1-D float64 dataset (empty), with `unit` and `description` attributes.
  [[nodiscard]] ExtendibleSeries create_series(const std::string& dataset, const std::string& unit,
                                               const std::string& description,
                                               std::size_t chunk_rows);

  /// Writes every buffered change to disk. Throws Hdf5Error with the cause.
  void flush();

 private:
  H5File(std::int64_t id, std::string path) : id_(id), path_(std::move(path)) {}
  std::int64_t id_ = -1;
  std::string path_;
};

/// An unlimited 1-D float64 dataset opened for appending. RAII: closes its dataset handle.
class ExtendibleSeries {
 public:
  ExtendibleSeries(ExtendibleSeries&& other) noexcept;
  ExtendibleSeries& operator=(ExtendibleSeries&& other) noexcept;
  ExtendibleSeries(const ExtendibleSeries&) = delete;
  ExtendibleSeries& operator=(const ExtendibleSeries&) = delete;
  ~ExtendibleSeries();

  /// Appends `values` at the end. On failure (Hdf5Error) the dataset keeps its previous extent.
  void append(std::span<const double> values);
  [[nodiscard]] std::uint64_t size() const { return size_; }
  [[nodiscard]] const std::string& name() const { return name_; }

 private:
  friend class H5File;
  ExtendibleSeries(std::int64_t id, std::string name, std::string file)
      : id_(id), name_(std::move(name)), file_(std::move(file)) {}
  std::int64_t id_ = -1;
  std::string name_, file_;
  std::uint64_t size_ = 0;
};

}  // namespace ferro::io
