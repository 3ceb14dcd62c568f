#pragma once
// Checked text output (CSV, reports): every write is checked, so a full disk or a file size
// limit raises an error naming the file and the cause ("No space left on device") instead of
// leaving a truncated file behind a success. RAII: the destructor closes without throwing; call
// close() to see whether the last buffered bytes reached the disk.

#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace ferro::io {

class TextWriter {
 public:
  /// Creates (truncating) `path`; throws std::runtime_error "cannot create '<path>': <cause>".
  /// With `reserve` > 0 the writer checks the room left (io::room_for) every 64 KiB and fails
  /// with the cause before it would leave less than `reserve` bytes on the file system, so
  /// other files written beside it (an HDF5 output) can still be closed.
  explicit TextWriter(const std::string& path, std::uint64_t reserve = 0);
  TextWriter(TextWriter&& other) noexcept;
  TextWriter& operator=(TextWriter&&) = delete;
  TextWriter(const TextWriter&) = delete;
  TextWriter& operator=(const TextWriter&) = delete;
  ~TextWriter();

  /// Throws std::runtime_error "cannot write '<path>': <cause>".
  void write(std::string_view text);
  template <class... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    write(fmt::format(format, std::forward<Args>(args)...));
  }
  /// Flushes to the operating system; throws on failure.
  void flush();
  /// Flushes and closes; throws on failure. Idempotent.
  void close();
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail(const char* what, int error);
  std::FILE* file_ = nullptr;
  std::string path_;
  std::uint64_t reserve_ = 0;
  std::uint64_t unchecked_ = 0;  // bytes written since the last room check
};

}  // namespace ferro::io
