// Fuzz target: the CSV batch of `ferrodyn contact eval --batch` (header, rows, numbers, model
// names), through the library's batch function with the command line's defaults (FASTSIM on a
// 6 x 4 mm patch, 10 kN, mu 0.3, 8 x 8 strips). Bad input must surface as
// std::invalid_argument (exit code 2 in the program); anything else escaping (another
// exception type, a crash, a sanitizer report) is a defect.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "ferro/scenarios/contact_eval.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ferro::scenarios::EvalInput defaults = [] {
    ferro::scenarios::EvalInput in;
    in.model = "fastsim";
    in.a = 6e-3;
    in.b = 4e-3;
    in.fn = 1e4;
    in.mu = 0.3;
    return in;
  }();
  static const ferro::contact::ModelOptions options = {{"mx", "8"}, {"my", "8"}};
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::ostringstream out;
  try {
    ferro::scenarios::evaluate_contact_batch(in, "batch.csv", defaults, options,
                                             ferro::contact::CoefficientSource::kKalkerTable, out);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
