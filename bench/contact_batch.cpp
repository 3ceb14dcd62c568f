// Contact cases in a batch: 10^5 Hertzian cases (spread over micro-slip to full slip, with spin)
// through the library's case loop (scenarios::evaluate_contact_columns, the loop the Python
// module's ferrodyn.contact.tangential runs) with FaStrip, the figure the module's overhead is
// measured against (docs/PERFORMANCE.md). The CPU column is the CPU time of one batch.
#include <benchmark/benchmark.h>

#include <map>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/contact_eval.hpp"

namespace {

constexpr std::size_t kCases = 100000;

// Case i of an input: lo + (hi - lo) frac(i g) for an irrational g per input (a low-discrepancy
// sequence over the range), the same doubles as bench/python_contact_batch.py makes with NumPy.
std::vector<double> spread(double lo, double hi, double g) {
  std::vector<double> v(kCases);
  for (std::size_t i = 0; i < kCases; ++i)
    v[i] = lo + (hi - lo) * std::fmod(static_cast<double>(i) * g, 1.0);
  return v;
}

std::map<std::string, std::vector<double>> cases() {
  return {{"a", spread(4e-3, 8e-3, 0.41421356237309503)},
          {"b", spread(3e-3, 7e-3, 0.7320508075688772)},
          {"fn", spread(4e4, 1e5, 0.2360679774997898)},
          {"mu", std::vector<double>(kCases, 0.3)},
          {"xi_x", spread(-3e-3, 3e-3, 0.6457513110645907)},
          {"xi_y", spread(-3e-3, 3e-3, 0.3166247903554)},
          {"spin", spread(-0.5, 0.5, 0.6055512754639891)}};
}

void BM_contact_batch(benchmark::State& state, const std::string& model_name) {
  const auto columns = cases();
  std::map<std::string, std::span<const double>> inputs;
  for (const auto& [k, v] : columns) inputs[k] = v;
  const auto model = ferro::contact::make_tangential_model(model_name);
  ferro::scenarios::EvalInput defaults;
  defaults.model = model_name;
  std::vector<std::vector<double>> out(11, std::vector<double>(kCases));
  const ferro::scenarios::EvalOutputColumns o{out[0], out[1], out[2], out[3], out[4], out[5],
                                              out[6], out[7], out[8], out[9], out[10]};
  for (auto _ : state) {
    ferro::scenarios::evaluate_contact_columns(defaults, inputs, kCases, *model,
                                               ferro::contact::CoefficientSource::kKalkerTable, o);
    benchmark::DoNotOptimize(out[3].data());
  }
  state.counters["cases"] = static_cast<double>(kCases);
}

BENCHMARK_CAPTURE(BM_contact_batch, fastrip, std::string("fastrip"))
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
