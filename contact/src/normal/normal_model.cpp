// The normal-contact models behind their interface and their {name, factory} registry: Hertz and
// semi-Hertz, each parsing its own options.
//
// References: Toumi (2016) section 1.1 (Hertz eqs. 5-13, semi-Hertz eqs. 17-23).
// Known deviations: see hertz.hpp and semi_hertz.hpp.
#include "ferro/contact/normal/normal_model.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/normal/hertz.hpp"
#include "ferro/contact/normal/semi_hertz.hpp"

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
  static std::unique_ptr<NormalContactModel> from_options(const ModelOptions& options) {
    check_option_keys("hertz", options, {});
    return std::make_unique<HertzModel>();
  }
  std::string_view name() const override { return "hertz"; }
  NormalSolution solve(const NormalProblem& problem) const override {
    validate_common(problem);
    const CombinedMaterial m = combine(problem.body1, problem.body2);
    const HertzSolution h = hertz_solve(problem.curvature_x, problem.curvature_y,
                                        problem.normal_force, m.contact_modulus);
    NormalSolution s;
    s.approach = h.approach;
    const HertzCurvatures cv = hertz_curvatures(problem.curvature_x, problem.curvature_y);
    s.patches.push_back(hertz_patch(h, cv.x, cv.y));
    return s;
  }
};

class SemiHertzModel final : public NormalContactModel {
 public:
  /// Options: "strips" (default 200), "curvature" = fit (default) | three_point.
  static std::unique_ptr<NormalContactModel> from_options(const ModelOptions& options) {
    check_option_keys("semi_hertz", options, {"strips", "curvature"});
    SemiHertzOptions o;
    o.strips = option_int(options, "strips", o.strips);
    o.curvature = option_choice<SemiHertzOptions::Curvature>(
        "semi_hertz", options, "curvature",
        {{"fit", SemiHertzOptions::Curvature::kFit},
         {"three_point", SemiHertzOptions::Curvature::kThreePoint}},
        "fit");
    return std::make_unique<SemiHertzModel>(o);
  }
  explicit SemiHertzModel(SemiHertzOptions options) : options_(options) { options_.validate(); }
  std::string_view name() const override { return "semi_hertz"; }
  NormalSolution solve(const NormalProblem& problem) const override {
    validate_common(problem);
    return semi_hertz_solve(problem, options_);
  }

 private:
  SemiHertzOptions options_;
};

constexpr std::array<NormalModelEntry, 2> kNormalModels{{
    {"hertz", &HertzModel::from_options},
    {"semi_hertz", &SemiHertzModel::from_options},
}};

}  // namespace

std::span<const NormalModelEntry> normal_models() {
  return kNormalModels;
}

std::vector<std::string> normal_model_names() { return registry_names(normal_models()); }

std::unique_ptr<NormalContactModel> make_normal_model(std::string_view name,
                                                      const ModelOptions& options) {
  return registry_entry(normal_models(), name, "normal").make(options);
}

}  // namespace ferro::contact
