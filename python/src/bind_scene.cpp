// Scenes from Python: a file or YAML text, values changed by key, SceneError with the location.
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "common.hpp"
#include "ferro/scenarios/model_factory.hpp"

namespace ferro::python {
namespace {

PyObject* g_scene_error = nullptr;

void set_scene_error(const std::exception& e, const std::string& file) {
  py::gil_scoped_acquire gil;
  py::object type = py::reinterpret_borrow<py::object>(g_scene_error);
  py::object exc = type(e.what());
  if (const auto* y = dynamic_cast<const scenarios::YamlInputError*>(&e)) {
    exc.attr("file") = y->file();
    exc.attr("line") = y->line() > 0 ? py::object(py::int_(y->line())) : py::none();
    exc.attr("column") = y->line() > 0 ? py::object(py::int_(y->column())) : py::none();
    exc.attr("key") = y->key();
    exc.attr("message") = y->message();
  } else {
    // "<key>: <message>" from the run-time checks (apply_overrides and the like).
    const std::string what = e.what();
    const auto colon = what.find(": ");
    const bool keyed = colon != std::string::npos && what.find(' ') > colon;
    exc.attr("file") = file.empty() ? py::object(py::none()) : py::object(py::str(file));
    exc.attr("line") = py::none();
    exc.attr("column") = py::none();
    exc.attr("key") = keyed ? py::object(py::str(what.substr(0, colon))) : py::object(py::none());
    exc.attr("message") = keyed ? what.substr(colon + 2) : what;
  }
  PyErr_SetObject(g_scene_error, exc.ptr());
}

// Python value -> YAML text of the same value (JSON is YAML); NumPy scalars and arrays as their
// Python equivalents.
std::string yaml_text(py::object value) {
  if (py::hasattr(value, "tolist")) value = value.attr("tolist")();
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

scenarios::YamlFile source_file(const SceneSource& s) {
  return s.from_text ? scenarios::parse_yaml_text(s.text, s.path) : scenarios::load_yaml_file(s.path);
}

// Loads with the overrides; on failure restores the previous ones and raises SceneError.
void reload(SceneSource& s, std::vector<scenarios::KeyOverride> previous) {
  try {
    s.load();
  } catch (const std::invalid_argument& e) {
    s.overrides = std::move(previous);
    raise_scene_error(e, s.path);
  }
}

void set_values(SceneSource& s, const py::dict& values) {
  auto previous = s.overrides;
  for (const auto& [k, v] : values) {
    const std::string key = py::str(k);
    const std::string text = yaml_text(py::reinterpret_borrow<py::object>(v));
    bool replaced = false;
    for (auto& o : s.overrides) {
      if (o.key == key) {
        o.value = text;
        replaced = true;
      }
    }
    if (!replaced) s.overrides.push_back({key, text});
  }
  reload(s, std::move(previous));
}

std::shared_ptr<SceneSource> make_source(const std::string& path, const std::string* text,
                                         const py::object& overrides) {
  auto s = std::make_shared<SceneSource>();
  s->path = path;
  if (text != nullptr) {
    s->text = *text;
    s->from_text = true;
  }
  if (!overrides.is_none()) {
    for (const auto& [k, v] : overrides.cast<py::dict>())
      s->overrides.push_back({py::str(k), yaml_text(py::reinterpret_borrow<py::object>(v))});
  }
  try {
    s->load();
  } catch (const std::invalid_argument& e) {
    raise_scene_error(e, path);
  }
  return s;
}

}  // namespace

py::object scene_error_type() { return py::reinterpret_borrow<py::object>(g_scene_error); }

void raise_scene_error(const std::exception& e, const std::string& file) {
  set_scene_error(e, file);
  throw py::error_already_set();
}

void bind_scene(py::module_& m) {
  g_scene_error = PyErr_NewExceptionWithDoc(
      "ferrodyn.SceneError",
      "Bad input in a scene: a ValueError with the location of the offending value.\n\n"
      "Attributes: file (the file, or the scene's name for YAML text), line and column (1-based;\n"
      "None for a value given by key or as a run argument), key (dotted key path, e.g.\n"
      "'simulation.speed'), message (without the location).",
      PyExc_ValueError, nullptr);
  m.attr("SceneError") = py::reinterpret_borrow<py::object>(g_scene_error);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const scenarios::YamlInputError& e) {
      set_scene_error(e, e.file());
    }
  });

  py::class_<SceneSource, std::shared_ptr<SceneSource>>(m, "Scene", R"doc(
A scene: the YAML file of a run (model, track, contact, solver, output; docs/SCENES.md),
loaded and validated as `ferrodyn run` does. Raises SceneError (file, line, key) for bad input.

Any value can be changed by its dotted key path from the scene's root, also inside parts and
vehicle files the scene names by file, e.g. scene["simulation.speed"] = 40.0,
scene["solver.integrator"] = "cvode_bdf", scene["contact.tangential"] = "fastsim",
scene["model.vehicle.wheel_rail.friction"] = 0.3. Each change reloads and validates the scene;
a rejected value raises SceneError and leaves the scene as it was.
)doc")
      .def(py::init([](const std::filesystem::path& path, const py::object& overrides) {
             return make_source(path.string(), nullptr, overrides);
           }),
           py::arg("path"), py::arg("overrides") = py::none(),
           "Loads the scene file at `path`, with `overrides` ({key: value}) applied.")
      .def_static(
          "from_yaml",
          [](const std::string& text, const std::filesystem::path& path,
             const py::object& overrides) { return make_source(path.string(), &text, overrides); },
          py::arg("text"), py::arg("path") = "scene.yaml", py::arg("overrides") = py::none(),
          "A scene given as YAML text; `path` names it in messages, and files it names are "
          "looked for in the folder of `path`.")
      .def("__getitem__",
           [](const SceneSource& s, const std::string& key) {
             for (const auto& o : s.overrides) {
               if (o.key == key) return yaml_to_python(YAML::Load(o.value));
             }
             return yaml_to_python(scenarios::scene_value(source_file(s), key));
           },
           "The value at a dotted key path (as given by key, else as written in the files); "
           "None when absent.")
      .def("__setitem__",
           [](SceneSource& s, const std::string& key, const py::object& value) {
             py::dict d;
             d[py::str(key)] = value;
             set_values(s, d);
           })
      .def("__delitem__",
           [](SceneSource& s, const std::string& key) {
             auto previous = s.overrides;
             std::erase_if(s.overrides, [&](const auto& o) { return o.key == key; });
             if (s.overrides.size() == previous.size()) throw py::key_error(key);
             reload(s, std::move(previous));
           },
           "Drops the value given for `key` (back to the file's).")
      .def("update", &set_values, py::arg("values"),
           "Sets several values at once ({key: value}), validated together.")
      .def_property_readonly("overrides",
                             [](const SceneSource& s) {
                               py::dict d;
                               for (const auto& o : s.overrides)
                                 d[py::str(o.key)] = yaml_to_python(YAML::Load(o.value));
                               return d;
                             },
                             "The values given by key, {key: value}.")
      .def("validate",
           [](const SceneSource& s) {
             try {
               py::gil_scoped_release release;
               const auto system = scenarios::build_system(s.scene, s.scene.simulation.speed);
               (void)scenarios::initial_state(s.scene, *system);
             } catch (const scenarios::YamlInputError& e) {
               raise_scene_error(scenarios::at_override(e, s.path, s.overrides), s.path);
             } catch (const std::invalid_argument& e) {
               raise_scene_error(e, s.path);
             }
           },
           "Builds the model and its initial state as a run does before its first step; raises "
           "SceneError for what loading alone cannot see (e.g. an unknown state name in "
           "simulation.initial).")
      .def_property_readonly("path", [](const SceneSource& s) { return s.scene.path; })
      .def_property_readonly("name", [](const SceneSource& s) { return s.scene.name; })
      .def_property_readonly("description",
                             [](const SceneSource& s) { return s.scene.description; })
      .def_property_readonly("text", [](const SceneSource& s) { return s.scene.text; },
                             "The scene's text followed by each included file's.")
      .def_property_readonly("model_type", [](const SceneSource& s) { return s.scene.model.type; })
      .def_property_readonly("speed", [](const SceneSource& s) { return s.scene.simulation.speed; },
                             "Forward speed at t = 0 [m/s].")
      .def_property_readonly("t_end", [](const SceneSource& s) { return s.scene.simulation.t_end; },
                             "End time [s].")
      .def_property_readonly("integrator",
                             [](const SceneSource& s) { return s.scene.solver.method; })
      .def_property_readonly("output_file",
                             [](const SceneSource& s) { return s.scene.output.file; })
      .def_property_readonly("output_interval",
                             [](const SceneSource& s) { return s.scene.output.interval; },
                             "Sampling interval of the outputs [s].")
      .def("__repr__", [](const SceneSource& s) {
        return "<ferrodyn.Scene '" + s.scene.name + "' (" + s.scene.path + ")>";
      });
}

}  // namespace ferro::python
