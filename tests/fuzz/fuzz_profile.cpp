// Fuzz target: the wheel/rail profile readers (SIMPACK .prr and two-column mm files, then the
// profile checks). The first input byte picks the format. Bad input must surface as
// std::invalid_argument; anything else escaping is a defect.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "ferro/contact/geometry/profile.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool simpack = (data[0] & 1U) != 0;
  const std::string path =
      ferro::fuzz::write_scratch(simpack ? "profile.prr" : "profile.txt", data + 1, size - 1);
  try {
    (void)ferro::contact::read_profile(path, ferro::contact::ProfileKind::rail);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
