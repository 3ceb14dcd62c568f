// Checked text output (see the header).
//
// References: none (file output). Known deviations: none.
#include "ferro/io/text_writer.hpp"

#include <cerrno>
#include <cstring>

#include "ferro/io/room.hpp"

namespace ferro::io {

TextWriter::TextWriter(const std::string& path, std::uint64_t reserve)
    : path_(path), reserve_(reserve) {
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) fail("create", errno);
}

TextWriter::TextWriter(TextWriter&& other) noexcept
    : file_(std::exchange(other.file_, nullptr)),
      path_(std::move(other.path_)),
      reserve_(other.reserve_),
      unchecked_(other.unchecked_) {}

TextWriter::~TextWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void TextWriter::fail(const char* what, int error) {
  throw std::runtime_error(fmt::format("cannot {} '{}': {}", what, path_,
                                       error != 0 ? std::strerror(error) : "I/O error"));
}

void TextWriter::write(std::string_view text) {
  if (file_ == nullptr) fail("write (closed)", 0);
  constexpr std::uint64_t kCheckEvery = 64 * 1024;
  unchecked_ += text.size();
  if (reserve_ > 0 && unchecked_ >= kCheckEvery) {
    const Room room = room_for(path_);
    if (room.bytes < unchecked_ + reserve_) {
      throw std::runtime_error(
          fmt::format("cannot write '{}': {} ({} bytes left)", path_, room.limit, room.bytes));
    }
    unchecked_ = 0;
  }
  errno = 0;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) fail("write", errno);
}

void TextWriter::flush() {
  if (file_ == nullptr) return;
  errno = 0;
  if (std::fflush(file_) != 0) fail("write", errno);
}

void TextWriter::close() {
  if (file_ == nullptr) return;
  errno = 0;
  const bool flushed = std::fflush(file_) == 0;
  const int flush_error = errno;
  const bool closed = std::fclose(file_) == 0;
  const int close_error = errno;
  file_ = nullptr;
  if (!flushed) fail("write", flush_error);
  if (!closed) fail("close", close_error);
}

}  // namespace ferro::io
