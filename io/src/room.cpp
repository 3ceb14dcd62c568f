// Room left for an output file (see the header).
//
// References: POSIX statvfs(3), getrlimit(2). Known deviations: none.
#include "ferro/io/room.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>

#include <filesystem>
#include <limits>

namespace ferro::io {

Room room_for(const std::string& path) {
  Room room{std::numeric_limits<std::uint64_t>::max(), "no limit"};
  struct stat st {};
  const bool present = stat(path.c_str(), &st) == 0;
  if (present && !S_ISREG(st.st_mode)) return room;  // a device: no file grows
  std::filesystem::path p(path);
  std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  struct statvfs fs {};
  if (statvfs(dir.c_str(), &fs) == 0) {
    room = {static_cast<std::uint64_t>(fs.f_bavail) * static_cast<std::uint64_t>(fs.f_frsize),
            "no space left on device"};
  }
  struct rlimit limit {};
  if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t current = present ? static_cast<std::uint64_t>(st.st_size) : 0;
    const std::uint64_t cap = static_cast<std::uint64_t>(limit.rlim_cur);
    const std::uint64_t left = cap > current ? cap - current : 0;
    if (left < room.bytes) room = {left, "file size limit (RLIMIT_FSIZE) reached"};
  }
  return room;
}

}  // namespace ferro::io
