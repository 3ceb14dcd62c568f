#pragma once
// Room left for an output file, so writers can stop cleanly before a disk or a file size limit
// is reached (and keep a reserve to close their files) instead of failing half-way through a
// write.

#include <cstdint>
#include <string>

namespace ferro::io {

/// Room left for the file `path` (existing or not).
struct Room {
  std::uint64_t bytes = 0;  ///< bytes that can still be written
  std::string limit;        ///< what limits them, as a cause for messages
};

/// The smaller of the free space of the file's file system (for an unprivileged writer) and what
/// RLIMIT_FSIZE still allows beyond the file's current size. A huge number when neither limits
/// (and for a device such as /dev/null).
[[nodiscard]] Room room_for(const std::string& path);

}  // namespace ferro::io
