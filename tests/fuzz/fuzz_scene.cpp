// Fuzz target: the scene loader (YAML reader, includes, every part's validation). Bad input
// must surface as std::invalid_argument (exit code 2 in the program); anything else escaping
// (another exception type, a crash, a sanitizer report) is a defect.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "ferro/scenarios/scene.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = ferro::fuzz::write_scratch("scene.yaml", data, size);
  try {
    (void)ferro::scenarios::load_scene(path);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
