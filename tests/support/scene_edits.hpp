#pragma once
// Edited copies of the shipped scene files for tests: a scratch copy of the repository's scene
// tree made of links (scenarios/{scenes,vehicles,parts}, data/, out/, fe_contact/examples/), so
// that an edited file written beside its original's link finds every file it names relative to
// itself.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ferro::test {

inline std::string text_of(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The linked copy of the scene tree (made once per process).
inline std::filesystem::path scene_mirror() {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("ferro_scene_mirror_" + std::to_string(getpid()));
  if (fs::exists(root / "data")) return root;
  for (const char* part : {"scenarios/scenes", "scenarios/vehicles", "scenarios/parts",
                           "fe_contact/examples"}) {
    fs::create_directories(root / part);
    for (const auto& e : fs::directory_iterator(part))
      fs::create_symlink(fs::absolute(e.path()), root / part / e.path().filename());
  }
  fs::create_directories("out");
  fs::create_directory_symlink(fs::absolute("data"), root / "data");
  fs::create_directory_symlink(fs::absolute("out"), root / "out");
  fs::copy_file("README.md", root / "README.md", fs::copy_options::overwrite_existing);
  return root;
}

/// The repository file `source` with its first `from` replaced by `to`, written as `name` beside
/// the mirror's link to `source`; returns its path. Throws when `from` is not in the file.
inline std::string edited_copy(const std::string& source, const std::string& from,
                               const std::string& to, const std::string& name) {
  std::string text = text_of(source);
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("'" + from + "' not in " + source);
  text.replace(at, from.size(), to);
  const auto out = (scene_mirror() / source).parent_path() / name;
  std::ofstream(out) << text;
  return out.string();
}

}  // namespace ferro::test
