#pragma once
// HDF5 output (C API, serial HDF5 1.10). Layout: docs/OUTPUT.md.
//  - H5File: RAII file handle with attribute, vector and text helpers.
//  - TimeSeriesWriter: chunked, extendible 1-D datasets /time and /signals/<name>, written in
//    blocks and flushed to disk as the run goes, so a run stopped at any moment leaves every
//    sample up to its last flush (and, on a clean stop, up to the stop) in a valid file.

#include <hdf5.h>

#include <chrono>
#include <span>
#include <string>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::scenarios {

class H5File {
 public:
  /// Creates (truncating) `path`, making parent folders. Throws std::runtime_error naming it.
  static H5File create(const std::string& path);
  /// Opens an existing file read-only.
  static H5File open_read(const std::string& path);

  H5File(H5File&& other) noexcept;
  H5File& operator=(H5File&& other) noexcept;
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;
  ~H5File();

  [[nodiscard]] hid_t id() const { return id_; }
  [[nodiscard]] const std::string& path() const { return path_; }

  /// Creates the group (and parents) when missing.
  void ensure_group(const std::string& group);
  /// Attributes on an object (group or dataset) at `object` ("/" for the root); replaces any
  /// attribute of the same name.
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, long value);
  [[nodiscard]] std::string string_attribute(const std::string& object,
                                             const std::string& name) const;
  [[nodiscard]] double number_attribute(const std::string& object, const std::string& name) const;

  /// Fixed-size 1-D dataset of doubles with `unit` and `description` attributes.
  void write_vector(const std::string& dataset, std::span<const double> values,
                    const std::string& unit, const std::string& description = "");
  /// 2-D row-major dataset of doubles (rows x cols).
  void write_matrix(const std::string& dataset, std::span<const double> values, std::size_t rows,
                    std::size_t cols, const std::string& unit, const std::string& description = "");
  /// A scalar string dataset (e.g. the scene text).
  void write_text(const std::string& dataset, const std::string& text);
  [[nodiscard]] std::vector<double> read_vector(const std::string& dataset) const;
  [[nodiscard]] bool exists(const std::string& object) const;

  void flush();

 private:
  H5File(hid_t id, std::string path) : id_(id), path_(std::move(path)) {}
  hid_t id_ = H5I_INVALID_HID;
  std::string path_;
};

class TimeSeriesWriter {
 public:
  /// Creates /time and /signals/<name> for each channel under `file`.
  TimeSeriesWriter(H5File& file, const std::vector<vehicle::SignalInfo>& channels,
                   double flush_seconds, std::size_t chunk_rows = 1024);
  /// Buffers one sample; writes and flushes when the buffer is full or `flush_seconds` of wall
  /// time have passed since the last flush.
  void append(double t, std::span<const double> values);
  /// Writes buffered samples and flushes the file.
  void flush();
  [[nodiscard]] long samples() const { return written_ + static_cast<long>(buffer_t_.size()); }

 private:
  H5File& file_;
  std::vector<hid_t> datasets_;  // [0] = time, then one per channel
  std::size_t chunk_rows_;
  double flush_seconds_;
  std::chrono::steady_clock::time_point last_flush_;
  std::vector<double> buffer_t_;
  std::vector<std::vector<double>> buffer_;  // per channel
  long written_ = 0;

 public:
  ~TimeSeriesWriter();
  TimeSeriesWriter(const TimeSeriesWriter&) = delete;
  TimeSeriesWriter& operator=(const TimeSeriesWriter&) = delete;
};

}  // namespace ferro::scenarios
