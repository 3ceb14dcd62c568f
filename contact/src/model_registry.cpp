// The contact-model registries: normal models and tangential (creep-force) models by name, with
// the option helpers they share. Every model a scene, a case file or the command line can
// name is created here.
//
// References: Toumi (2016) section 1.1 (normal models), eqs. (38)-(40), (156) (Kalker's linear
// theory with K_ij); each model's own file gives its references.
// Known deviations: none.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "ferro/contact/fastrip.hpp"
#include "ferro/contact/fastsim.hpp"
#include "ferro/contact/hertz.hpp"
#include "ferro/contact/mim_table.hpp"
#include "ferro/contact/mim_tangential_model.hpp"
#include "ferro/contact/normal_model.hpp"
#include "ferro/contact/polach.hpp"
#include "ferro/contact/saturation_laws.hpp"
#include "ferro/contact/semi_hertz.hpp"
#include "ferro/contact/tangential_model.hpp"

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
    NormalSolution s;
    s.approach = h.approach;
    const HertzCurvatures cv = hertz_curvatures(problem.curvature_x, problem.curvature_y);
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

class KalkerLinearModel final : public TangentialModel {
 public:
  explicit KalkerLinearModel(CoefficientSource source) : source_(source) {}
  std::string_view name() const override { return "kalker_linear"; }
  TangentialSolution solve(const TangentialProblem& problem) const override {
    problem.validate();
    return linear_creep_stiffness(problem, source_).forces(problem.creepage);
  }

 private:
  CoefficientSource source_;
};

}  // namespace

// ---- Option helpers ---------------------------------------------------------------------------

double option_double(const ModelOptions& options, const std::string& key, double fallback) {
  const auto it = options.find(key);
  if (it == options.end()) return fallback;
  try {
    std::size_t used = 0;
    const double v = std::stod(it->second, &used);
    if (used != it->second.size() || !std::isfinite(v)) {
      throw std::invalid_argument("trailing characters or not finite");
    }
    return v;
  } catch (const std::exception&) {
    throw std::invalid_argument(
        fmt::format("option '{}': expected a finite number, got '{}'", key, it->second));
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

// ---- Normal models ----------------------------------------------------------------------------

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

// ---- Tangential models ------------------------------------------------------------------------

std::vector<std::string> tangential_model_names() {
  return {"kalker_linear", "linear_saturated", "vermeulen_johnson", "shen_hedrick_elkins",
          "chopaya",       "polach",           "fastsim",           "fastrip",
          "mim",           "mim_table"};
}

std::unique_ptr<TangentialModel> make_tangential_model(std::string_view name,
                                                       const ModelOptions& options) {
  const CoefficientSource source =
      coefficient_source_from_name(option_string(options, "coefficients", "kalker_table"));
  if (name == "kalker_linear") {
    check_option_keys(name, options, {"coefficients"});
    return std::make_unique<KalkerLinearModel>(source);
  }
  const std::pair<const char*, SaturationLaw> laws[] = {
      {"linear_saturated", SaturationLaw::kLinear},
      {"vermeulen_johnson", SaturationLaw::kVermeulenJohnson},
      {"shen_hedrick_elkins", SaturationLaw::kShenHedrickElkins},
      {"chopaya", SaturationLaw::kChopaya}};
  for (const auto& [law_name, law] : laws) {
    if (name == law_name) {
      check_option_keys(name, options, {"coefficients", "spin_moment"});
      const std::string spin = option_string(options, "spin_moment", "true");
      if (spin != "true" && spin != "false") {
        throw std::invalid_argument(fmt::format(
            "{} option 'spin_moment': unknown value '{}'; allowed: true, false", name, spin));
      }
      return std::make_unique<SaturatedCreepModel>(law, source, spin == "true");
    }
  }
  if (name == "polach") {
    check_option_keys(name, options,
                      {"coefficients", "k_a", "k_s", "friction_ratio", "friction_decay"});
    PolachOptions o;
    o.source = source;
    o.k_a = option_double(options, "k_a", o.k_a);
    o.k_s = option_double(options, "k_s", o.k_s);
    o.friction_ratio = option_double(options, "friction_ratio", o.friction_ratio);
    o.friction_decay = option_double(options, "friction_decay", o.friction_decay);
    return std::make_unique<PolachModel>(o);
  }
  if (name == "fastsim") {
    check_option_keys(name, options,
                      {"coefficients", "mx", "my", "flexibility", "bound", "stiffening"});
    FastsimOptions o;
    o.source = source;
    o.mx = option_int(options, "mx", o.mx);
    o.my = option_int(options, "my", o.my);
    const std::string flex = option_string(options, "flexibility", "three");
    if (flex == "three") {
      o.flexibility = Flexibility::kThree;
    } else if (flex == "weighted") {
      o.flexibility = Flexibility::kWeighted;
    } else if (flex == "adaptive") {
      o.flexibility = Flexibility::kAdaptive;
    } else {
      throw std::invalid_argument(fmt::format(
          "fastsim option 'flexibility': unknown value '{}'; allowed: three, weighted, adaptive",
          flex));
    }
    o.stiffening = option_double(options, "stiffening", o.stiffening);
    if (!(o.stiffening >= 0.0 && o.stiffening <= 1.0)) {
      throw std::invalid_argument(
          fmt::format("fastsim option 'stiffening': must lie in [0, 1], got {}", o.stiffening));
    }
    const std::string bound = option_string(options, "bound", "parabolic");
    if (bound == "parabolic") {
      o.bound = TractionBound::kParabolic;
    } else if (bound == "elliptic") {
      o.bound = TractionBound::kElliptic;
    } else {
      throw std::invalid_argument(fmt::format(
          "fastsim option 'bound': unknown value '{}'; allowed: parabolic, elliptic", bound));
    }
    return std::make_unique<FastsimModel>(o);
  }
  if (name == "fastrip") {
    check_option_keys(name, options, {"coefficients", "mx", "my", "slip_flexibility"});
    FastripOptions o;
    o.source = source;
    o.mx = option_int(options, "mx", o.mx);
    o.my = option_int(options, "my", o.my);
    const std::string slip = option_string(options, "slip_flexibility", "longitudinal");
    if (slip == "longitudinal") {
      o.slip_flexibility = SlipFlexibility::kLongitudinal;
    } else if (slip == "weighted") {
      o.slip_flexibility = SlipFlexibility::kWeighted;
    } else if (slip == "three") {
      o.slip_flexibility = SlipFlexibility::kThree;
    } else {
      throw std::invalid_argument(fmt::format(
          "fastrip option 'slip_flexibility': unknown value '{}'; allowed: longitudinal, "
          "weighted, three",
          slip));
    }
    return std::make_unique<FastripModel>(o);
  }
  if (name == "mim") {
    check_option_keys(name, options, {"elements", "grid"});
    MimModelOptions o;
    o.elements = option_int(options, "elements", o.elements);
    const std::string grid = option_string(options, "grid", "minor");
    if (grid == "minor") {
      o.grid_over_patch = false;
    } else if (grid == "patch") {
      o.grid_over_patch = true;
    } else if (grid == "patch_richardson") {
      o.grid_over_patch = true;
      o.extrapolate = true;
    } else {
      throw std::invalid_argument(fmt::format(
          "mim option 'grid': unknown value '{}'; allowed: minor, patch, patch_richardson", grid));
    }
    return std::make_unique<MimTangentialModel>(o);
  }
  if (name == "mim_table") {
    check_option_keys(name, options, {"table"});
    const char* env = std::getenv("FERRO_MIM_TABLE");
    const std::string path = option_string(options, "table", env != nullptr ? env : "");
    if (path.empty()) {
      throw std::invalid_argument(
          "mim_table option 'table': give the HDF5 table path (table=PATH or $FERRO_MIM_TABLE; "
          "build one with `ferrodyn contact mim-table -o PATH`)");
    }
    return std::make_unique<MimTableModel>(MimTable::read_hdf5(path));
  }
  throw std::invalid_argument(fmt::format("unknown tangential contact model '{}'; allowed: {}",
                                          name, fmt::join(tangential_model_names(), ", ")));
}

}  // namespace ferro::contact
