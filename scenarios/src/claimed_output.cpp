#include "ferro/scenarios/claimed_output.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace ferro::scenarios {

std::string sibling(const std::string& file, const std::string& suffix) {
  const std::filesystem::path p(file);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

void check_plot_folder(const std::string& dir, const std::string& what) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(dir);
  // Folders missing on the way are made for the probe and removed again.
  std::vector<fs::path> missing;
  std::error_code ec;
  fs::path existing = folder;
  while (!fs::exists(existing, ec) && existing != existing.parent_path()) {
    missing.push_back(existing);
    existing = existing.parent_path();
  }
  const auto fail = [&](const std::string& why) {
    for (const auto& m : missing) rmdir(m.c_str());
    throw std::invalid_argument(fmt::format("{}: cannot write the plots in '{}': {}", what, dir, why));
  };
  if (!fs::is_directory(existing, ec)) fail(fmt::format("'{}' is not a folder", existing.string()));
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (mkdir(it->c_str(), 0777) != 0) fail(std::strerror(errno));
  }
  std::string probe = (folder / ".ferrodyn-probe-XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) fail(std::strerror(errno));
  close(fd);
  unlink(probe.c_str());
  for (const auto& m : missing) rmdir(m.c_str());
}

ClaimedOutput::ClaimedOutput(const std::string& path, const char* option, bool overwrite,
                             std::vector<std::string> inputs, bool no_plots)
    : set({overwrite, std::move(inputs)}) {
  file = &set.claim(path, option);
  if (!no_plots) check_plot_folder(sibling(file->path(), "_plots"), "plots");
}

ClaimedOutput ClaimedOutput::given_or(const std::string& given, const std::string& fallback,
                                      bool overwrite, std::vector<std::string> inputs,
                                      bool no_plots) {
  return {given.empty() ? fallback : given, given.empty() ? "output" : "-o", overwrite,
          std::move(inputs), no_plots};
}

const std::string& ClaimedOutput::commit() {
  file->commit();
  return file->path();
}

}  // namespace ferro::scenarios
