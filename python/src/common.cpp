#include "common.hpp"

#include <fmt/format.h>

#include <type_traits>
#include <variant>

namespace ferro::python {

void set_parameters(const scenarios::Parameters& params, const py::dict& kwargs) {
  for (const auto& [key_handle, value] : kwargs) {
    const auto key = key_handle.cast<std::string>();
    const scenarios::Parameter* p = nullptr;
    for (const auto& q : params) {
      if (q.key == key) p = &q;
    }
    if (p == nullptr) {
      std::string allowed;
      for (const auto& q : params) allowed += (allowed.empty() ? "" : ", ") + q.key;
      throw py::type_error(fmt::format("unknown keyword '{}'; allowed: {}", key, allowed));
    }
    if (value.is_none()) continue;
    try {
      std::visit(
          [&](auto* target) {
            using T = std::remove_pointer_t<decltype(target)>;
            if constexpr (std::is_same_v<T, bool>) {
              if (!py::isinstance<py::bool_>(value)) throw py::cast_error("expected True or False");
            } else if constexpr (std::is_arithmetic_v<T>) {
              if (py::isinstance<py::bool_>(value)) throw py::cast_error("expected a number");
            }
            *target = value.cast<T>();
          },
          p->target);
    } catch (const py::cast_error& e) {
      throw py::value_error(fmt::format("{}: {} (got {})", key, e.what(),
                                        py::repr(value).cast<std::string>()));
    }
  }
}

std::string parameter_doc(const scenarios::Parameters& params) {
  std::string doc;
  for (const auto& p : params) {
    std::string value;
    if (p.has_default) {
      value = std::visit(
          [](auto* target) -> std::string {
            using T = std::remove_pointer_t<decltype(target)>;
            if constexpr (std::is_same_v<T, bool>) {
              return *target ? "True" : "False";
            } else if constexpr (std::is_arithmetic_v<T>) {
              return fmt::format("{}", *target);
            } else if constexpr (std::is_same_v<T, std::string>) {
              return "'" + *target + "'";
            } else {
              std::string list;
              for (const auto& v : *target) list += (list.empty() ? "" : ", ") + fmt::format("{}", v);
              return "[" + list + "]";
            }
          },
          p.target);
    }
    doc += fmt::format("    {}{}: {}{}\n", p.key, p.unit.empty() ? "" : " [" + p.unit + "]", p.help,
                       value.empty() ? "" : " (default " + value + ")");
  }
  return doc;
}

py::array_t<double> to_numpy(std::vector<double>&& values, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<double>(std::move(values));
  py::capsule free(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  if (shape.empty()) shape = {static_cast<py::ssize_t>(owner->size())};
  return py::array_t<double>(shape, owner->data(), free);
}

void SceneSource::load() {
  scene = from_text ? scenarios::load_scene_text(text, path, overrides)
                    : scenarios::load_scene(path, overrides);
}

py::object yaml_to_python(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return py::none();
  if (node.IsMap()) {
    py::dict d;
    for (const auto& kv : node) d[py::str(kv.first.Scalar())] = yaml_to_python(kv.second);
    return d;
  }
  if (node.IsSequence()) {
    py::list l;
    for (const auto& item : node) l.append(yaml_to_python(item));
    return l;
  }
  bool b = false;
  long i = 0;
  double x = 0.0;
  if (YAML::convert<bool>::decode(node, b)) return py::bool_(b);
  if (YAML::convert<long>::decode(node, i)) return py::int_(i);
  if (YAML::convert<double>::decode(node, x)) return py::float_(x);
  return py::str(node.Scalar());
}

bool SignalWatch::stop() {
  if (stopped_) return true;
  if (std::this_thread::get_id() != owner_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_check_ < std::chrono::milliseconds(20)) return false;
  last_check_ = now;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) {
    error_.emplace();  // takes the pending exception (KeyboardInterrupt)
    stopped_ = true;
  }
  return stopped_;
}

void SignalWatch::raise_if_stopped(const py::object& partial) {
  if (!error_) return;
  py::error_already_set e = *error_;
  error_.reset();
  if (!partial.is_none()) e.value().attr("result") = partial;
  throw e;
}

}  // namespace ferro::python
