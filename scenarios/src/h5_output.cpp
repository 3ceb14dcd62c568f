#include "ferro/scenarios/h5_output.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "ferro/io/room.hpp"

namespace ferro::scenarios {

TimeSeriesWriter::TimeSeriesWriter(H5File& file, const std::vector<vehicle::SignalInfo>& channels,
                                   double flush_seconds, std::size_t chunk_rows)
    : file_(file),
      chunk_rows_(std::max<std::size_t>(chunk_rows, 1)),
      flush_seconds_(flush_seconds),
      last_flush_(std::chrono::steady_clock::now()),
      buffer_(channels.size()) {
  file_.ensure_group("/signals");
  series_.push_back(file_.create_series("/time", "s", "simulation time", chunk_rows_));
  for (const auto& c : channels)
    series_.push_back(file_.create_series("/signals/" + c.name, c.unit, c.description, chunk_rows_));
  file_.flush();
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

std::uint64_t TimeSeriesWriter::growth(std::size_t rows) const {
  // New chunks (allocated whole), plus one chunk-index node per dataset for each new chunk.
  constexpr std::uint64_t kIndexBytes = 2048;
  const auto chunks = [&](std::uint64_t n) { return (n + chunk_rows_ - 1) / chunk_rows_; };
  const std::uint64_t before = static_cast<std::uint64_t>(written_);
  const std::uint64_t new_chunks = chunks(before + rows) - chunks(before);
  return series_.size() * new_chunks * (chunk_rows_ * sizeof(double) + kIndexBytes);
}

void TimeSeriesWriter::write_rows(std::size_t rows) {
  if (rows == 0) return;
  for (std::size_t k = 0; k < series_.size(); ++k) {
    const double* data = k == 0 ? buffer_t_.data() : buffer_[k - 1].data();
    series_[k].append(std::span<const double>(data, rows));
  }
  written_ += static_cast<long>(rows);
  last_written_t_ = buffer_t_[rows - 1];
  buffer_t_.erase(buffer_t_.begin(), buffer_t_.begin() + static_cast<long>(rows));
  for (auto& b : buffer_) b.erase(b.begin(), b.begin() + static_cast<long>(rows));
  file_.set_attribute("/", "samples", written_);
  file_.flush();
}

void TimeSeriesWriter::flush() {
  last_flush_ = std::chrono::steady_clock::now();
  if (buffer_t_.empty()) return;
  const io::Room room = io::room_for(file_.path());
  const std::uint64_t usable = room.bytes > kCloseReserve ? room.bytes - kCloseReserve : 0;
  std::size_t rows = buffer_t_.size();
  if (growth(rows) > usable) {
    // Write the rows that fit (those filling already allocated chunks need no new space).
    std::size_t lo = 0, hi = rows;
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (growth(mid) <= usable) {
        lo = mid;
      } else {
        hi = mid - 1;
      }
    }
    write_rows(lo);
    throw OutputFull(fmt::format(
        "{} for '{}' ({} bytes left, more needed for the next samples); the file holds {} "
        "samples up to t = {:.9g} s",
        room.limit, file_.path(), room.bytes, written_, last_written_t_));
  }
  write_rows(rows);
}

}  // namespace ferro::scenarios
