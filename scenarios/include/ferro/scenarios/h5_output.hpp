#pragma once
// Run output over the HDF5 layer (ferro/io/hdf5.hpp). Layout: docs/OUTPUT.md.
//  - H5File: the io layer's RAII file handle.
//  - TimeSeriesWriter: chunked, extendible 1-D datasets /time and /signals/<name>, written in
//    blocks and flushed to disk as the run goes, so a run stopped at any moment leaves every
//    sample up to its last flush (and, on a clean stop, up to the stop) in a valid file. Before
//    each block it checks the room left for the file (file system and RLIMIT_FSIZE): when the
//    block does not fit it writes the samples that do, keeps a reserve for closing the file, and
//    throws OutputFull naming the cause.

#include <chrono>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ferro/io/hdf5.hpp"
#include "ferro/vehicle/ode_system.hpp"

namespace ferro::scenarios {

using io::H5File;

/// The output file has no room left for the next samples (disk full or file size limit).
class OutputFull : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TimeSeriesWriter {
 public:
  /// Bytes kept free for closing the file (status attributes, final metadata) [B].
  static constexpr std::uint64_t kCloseReserve = 64 * 1024;

  /// Creates /time and /signals/<name> for each channel under `file`.
  TimeSeriesWriter(H5File& file, const std::vector<vehicle::SignalInfo>& channels,
                   double flush_seconds, std::size_t chunk_rows = 1024);
  /// Buffers one sample; writes and flushes when the buffer is full or `flush_seconds` of wall
  /// time have passed since the last flush.
  void append(double t, std::span<const double> values);
  /// Writes buffered samples and flushes the file. Throws OutputFull or io::Hdf5Error.
  void flush();
  /// Samples written to the file so far.
  [[nodiscard]] long written() const { return written_; }
  /// Samples written or buffered.
  [[nodiscard]] long samples() const { return written_ + static_cast<long>(buffer_t_.size()); }

 private:
  // Bytes the file may grow by when `rows` more rows are written.
  [[nodiscard]] std::uint64_t growth(std::size_t rows) const;
  void write_rows(std::size_t rows);

  H5File& file_;
  std::vector<io::ExtendibleSeries> series_;  // [0] = time, then one per channel
  std::size_t chunk_rows_;
  double flush_seconds_;
  std::chrono::steady_clock::time_point last_flush_;
  std::vector<double> buffer_t_;
  std::vector<std::vector<double>> buffer_;  // per channel
  long written_ = 0;
  double last_written_t_ = 0.0;  // time of the last sample in the file [s]
};

}  // namespace ferro::scenarios
