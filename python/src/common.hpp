#pragma once
// Shared pieces of the Python bindings: keyword arguments onto the library's parameter tables,
// vectors handed to NumPy without a copy, and Ctrl-C while the GIL is released.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/scene.hpp"

namespace ferro::python {

namespace py = pybind11;

/// Sets each keyword argument on the parameter of the same key (numbers, strings, booleans,
/// sequences); None leaves the value. Raises TypeError for a key not in `params` (naming the
/// allowed ones) and ValueError for a value of the wrong type.
void set_parameters(const scenarios::Parameters& params, const py::dict& kwargs);

/// Docstring lines of parameters: "key [unit]: help (default: value)".
[[nodiscard]] std::string parameter_doc(const scenarios::Parameters& params);

/// The vector as a NumPy array of `shape` (default: 1-D), owning the memory (no copy).
[[nodiscard]] py::array_t<double> to_numpy(std::vector<double>&& values,
                                           std::vector<py::ssize_t> shape = {});

/// A scene and where it came from: a file or YAML text, and the values given by key.
struct SceneSource {
  std::string path;   ///< the file, or the name given to the text
  std::string text;   ///< YAML text ("" for a file)
  bool from_text = false;
  std::vector<scenarios::KeyOverride> overrides;
  scenarios::Scene scene;  ///< as loaded and validated
  void load();             ///< (re)loads `scene`
};

/// Converts a YAML node (as the scene files hold it) to Python: mappings to dict, sequences to
/// list, scalars to bool, int, float or str.
[[nodiscard]] py::object yaml_to_python(const YAML::Node& node);

/// Ctrl-C while the GIL is released: stop() is polled by the work (any thread, no GIL); on the
/// thread that created the watch it checks the interpreter's signals at most every 20 ms of wall
/// time, taking the GIL for that moment. When Ctrl-C came, raise_if_stopped() (GIL held) raises
/// the KeyboardInterrupt with `partial` set as its attribute `result`.
class SignalWatch {
 public:
  SignalWatch() : owner_(std::this_thread::get_id()) {}
  bool stop();
  [[nodiscard]] bool stopped() const { return stopped_; }
  void raise_if_stopped(const py::object& partial);

 private:
  std::thread::id owner_;
  std::atomic<bool> stopped_{false};
  std::chrono::steady_clock::time_point last_check_{};
  std::optional<py::error_already_set> error_;
};

// Registration of each group of the API (one file each).
void bind_scene(py::module_& m);
void bind_run(py::module_& m);
void bind_analysis(py::module_& m);
void bind_contact(py::module_& m);
void bind_output(py::module_& m);

/// The SceneError type (registered by bind_scene).
[[nodiscard]] py::object scene_error_type();
/// Raises SceneError for a library error about a scene's input: a located YamlInputError, or a
/// std::invalid_argument whose message starts with the key ("speed: must be > 0").
[[noreturn]] void raise_scene_error(const std::exception& e, const std::string& file);

}  // namespace ferro::python
