// Reading any ferrodyn HDF5 file back (see the header).
#include "ferro/scenarios/h5_reader.hpp"

#include "ferro/io/hdf5.hpp"

namespace ferro::scenarios {
namespace {

std::string child(const std::string& group, const std::string& name) {
  return group == "/" ? "/" + name : group + "/" + name;
}

void read_attributes(const io::H5File& file, const std::string& object, H5Contents& out) {
  for (const std::string& name : file.attribute_names(object)) {
    H5Attribute a;
    a.object = object;
    a.name = name;
    try {
      a.text = file.string_attribute(object, name);
      a.is_text = true;
    } catch (const io::Hdf5Error&) {
      a.number = file.number_attribute(object, name);
    }
    out.attributes.push_back(std::move(a));
  }
}

void read_dataset(const io::H5File& file, const std::string& name, H5Contents& out) {
  H5Dataset d;
  d.name = name;
  try {
    d.text = file.read_text(name);
    d.is_text = true;
  } catch (const io::Hdf5Error&) {
    io::Dims dims;
    d.values = file.read_array(name, &dims);
    d.dims.assign(dims.begin(), dims.end());
  }
  out.datasets.push_back(std::move(d));
}

// A group and everything under it: the layer lists a group's links; an object that cannot be
// listed as a group is a dataset.
void read_group(const io::H5File& file, const std::string& group, H5Contents& out) {
  read_attributes(file, group, out);
  for (const std::string& name : file.members(group)) {
    const std::string path = child(group, name);
    std::vector<std::string> below;
    bool is_group = true;
    try {
      below = file.members(path);
    } catch (const io::Hdf5Error&) {
      is_group = false;
    }
    if (is_group) {
      read_group(file, path, out);
    } else {
      read_dataset(file, path, out);
      read_attributes(file, path, out);
    }
  }
}

}  // namespace

H5Contents read_h5_file(const std::string& path) {
  const io::H5File file = io::H5File::open_read(path);
  H5Contents out;
  read_group(file, "/", out);
  return out;
}

}  // namespace ferro::scenarios
