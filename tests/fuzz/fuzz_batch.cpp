// Fuzz target: the CSV batch of `ferrodyn contact eval --batch` (header, rows, numbers, model
// names), run through the program's own entry point with the input on stdin. Exit codes 0 (all
// rows evaluated) and 2 (bad input, located) are answers; 1 (an unexpected failure) or a crash
// is a defect.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "cli.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = ferro::fuzz::write_scratch("batch.csv", data, size);
  if (std::freopen(path.c_str(), "r", stdin) == nullptr) std::abort();
  std::cin.clear();
  std::vector<std::string> args = {"ferrodyn", "contact", "eval",  "--batch", "--model",
                                   "fastsim",  "--a",     "6e-3",  "--b",     "4e-3",
                                   "--fn",     "1e4",     "--mu",  "0.3",     "--option",
                                   "mx=8",     "--option", "my=8"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  const int code = ferro::cli::run_main(static_cast<int>(argv.size()), argv.data());
  std::clearerr(stdin);
  if (code != ferro::cli::kExitOk && code != ferro::cli::kExitBadInput) std::abort();
  return 0;
}
