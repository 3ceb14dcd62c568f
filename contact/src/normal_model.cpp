// Registry of normal-contact models and the option helpers shared with the tangential registry.
//
// References: Toumi (2016) section 1.1.
// Known deviations: none.
#include "ferro/contact/normal_model.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/hertz.hpp"
#include "ferro/contact/semi_hertz.hpp"

namespace ferro::contact {
namespace {

void validate_common(const NormalProblem& p) {
  if (!(p.normal_force >= 0.0) || !std::isfinite(p.normal_force)) {
    throw std::invalid_argument(fmt::format(
        "normal problem.normal_force: must be finite and >= 0 [N], got {}", p.normal_force));
  }
  p.body1.validate("normal problem.body1");
  p.body2.validate("normal problem.body2");
}

class HertzModel final : public NormalContactModel {
 public:
  std::string_view name() const override { return "hertz"; }
  NormalSolution solve(const NormalProblem& problem) const override {
    validate_common(problem);
    const CombinedMaterial m = combine(problem.body1, problem.body2);
    const HertzSolution h = hertz_solve(problem.curvature_x, problem.curvature_y,
                                        problem.normal_force, m.contact_modulus);
    const HertzCurvatures cv = hertz_curvatures(problem.curvature_x, problem.curvature_y);
    NormalSolution s;
    s.approach = h.approach;
    s.patches.push_back(hertz_patch(h, cv.x, cv.y));
    return s;
  }
};

class SemiHertzModel final : public NormalContactModel {
 public:
  explicit SemiHertzModel(SemiHertzOptions options) : options_(options) { options_.validate(); }
  std::string_view name() const override { return "semi_hertz"; }
  NormalSolution solve(const NormalProblem& problem) const override {
    validate_common(problem);
    return semi_hertz_solve(problem, options_);
  }

 private:
  SemiHertzOptions options_;
};

}  // namespace

std::vector<std::string> normal_model_names() {
  return {"hertz", "semi_hertz"};
}

std::unique_ptr<NormalContactModel> make_normal_model(std::string_view name,
                                                      const ModelOptions& options) {
  if (name == "hertz") {
    check_option_keys(name, options, {});
    return std::make_unique<HertzModel>();
  }
  if (name == "semi_hertz") {
    check_option_keys(name, options, {"strips", "curvature"});
    SemiHertzOptions o;
    o.strips = option_int(options, "strips", o.strips);
    const std::string curvature = option_string(options, "curvature", "fit");
    if (curvature == "fit") {
      o.curvature = SemiHertzOptions::Curvature::kFit;
    } else if (curvature == "three_point") {
      o.curvature = SemiHertzOptions::Curvature::kThreePoint;
    } else {
      throw std::invalid_argument(fmt::format(
          "semi_hertz option 'curvature': unknown value '{}'; allowed: fit, three_point",
          curvature));
    }
    return std::make_unique<SemiHertzModel>(o);
  }
  throw std::invalid_argument(fmt::format("unknown normal contact model '{}'; allowed: {}", name,
                                          fmt::join(normal_model_names(), ", ")));
}

double option_double(const ModelOptions& options, const std::string& key, double fallback) {
  const auto it = options.find(key);
  if (it == options.end()) return fallback;
  try {
    std::size_t used = 0;
    const double v = std::stod(it->second, &used);
    if (used != it->second.size()) throw std::invalid_argument("trailing characters");
    return v;
  } catch (const std::exception&) {
    throw std::invalid_argument(
        fmt::format("option '{}': expected a number, got '{}'", key, it->second));
  }
}

int option_int(const ModelOptions& options, const std::string& key, int fallback) {
  const auto it = options.find(key);
  if (it == options.end()) return fallback;
  try {
    std::size_t used = 0;
    const int v = std::stoi(it->second, &used);
    if (used != it->second.size()) throw std::invalid_argument("trailing characters");
    return v;
  } catch (const std::exception&) {
    throw std::invalid_argument(
        fmt::format("option '{}': expected an integer, got '{}'", key, it->second));
  }
}

std::string option_string(const ModelOptions& options, const std::string& key,
                          const std::string& fallback) {
  const auto it = options.find(key);
  return it == options.end() ? fallback : it->second;
}

void check_option_keys(std::string_view model, const ModelOptions& options,
                       const std::vector<std::string>& allowed) {
  for (const auto& [key, value] : options) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw std::invalid_argument(fmt::format(
          "model '{}': unknown option '{}'; allowed: {}", model, key,
          allowed.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(allowed, ", "))));
    }
  }
}

}  // namespace ferro::contact
