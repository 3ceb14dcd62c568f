// Reading any ferrodyn HDF5 file into NumPy arrays (the Python layer adds pandas frames).
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "common.hpp"
#include "ferro/io/hdf5.hpp"
#include "ferro/scenarios/h5_reader.hpp"

namespace ferro::python {

void bind_output(py::module_& m) {
  m.def(
      "_read_h5",
      [](const std::filesystem::path& path) {
        scenarios::H5Contents c;
        try {
          py::gil_scoped_release release;
          c = scenarios::read_h5_file(path.string());
        } catch (const io::Hdf5Error& e) {
          throw py::value_error(e.what());
        }
        py::dict datasets, attributes;
        for (auto& d : c.datasets) {
          if (d.is_text) {
            datasets[py::str(d.name)] = d.text;
          } else {
            std::vector<py::ssize_t> shape(d.dims.begin(), d.dims.end());
            if (shape.empty()) shape = {static_cast<py::ssize_t>(d.values.size())};
            py::array_t<double> a = to_numpy(std::move(d.values), shape);
            datasets[py::str(d.name)] = d.dims.empty() && a.size() == 1 ? py::object(a[py::int_(0)])
                                                                        : py::object(a);
          }
        }
        for (const auto& a : c.attributes) {
          py::str object(a.object);
          if (!attributes.contains(object)) attributes[object] = py::dict();
          attributes[object][py::str(a.name)] =
              a.is_text ? py::object(py::str(a.text)) : py::object(py::float_(a.number));
        }
        return py::make_tuple(datasets, attributes);
      },
      py::arg("path"),
      "(datasets, attributes) of an HDF5 file: {path: array or text}, {object: {name: value}}.");
}

}  // namespace ferro::python
