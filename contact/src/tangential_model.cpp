// Tangential-model registry, problem validation and Kalker's linear theory with K_ij.
//
// References: Toumi (2016) eqs. (38)-(40), (156).
// Known deviations: none.
#include "ferro/contact/tangential_model.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "ferro/contact/fastsim.hpp"
#include "ferro/contact/mim_table.hpp"
#include "ferro/contact/mim_tangential_model.hpp"
#include "ferro/contact/polach.hpp"
#include "ferro/contact/saturation_laws.hpp"

namespace ferro::contact {

void TractionMap::clear() {
  x.clear();
  y.clear();
  dx.clear();
  dy.clear();
  pressure.clear();
  traction_x.clear();
  traction_y.clear();
  slip.clear();
}

void TangentialProblem::validate() const {
  if (patch == nullptr) throw std::invalid_argument("tangential problem.patch: must be set");
  patch->validate("tangential problem.patch");
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    throw std::invalid_argument(
        fmt::format("tangential problem.friction: must be finite and >= 0, got {}", friction));
  }
  if (!std::isfinite(creepage.longitudinal) || !std::isfinite(creepage.lateral) ||
      !std::isfinite(creepage.spin)) {
    throw std::invalid_argument(
        fmt::format("tangential problem.creepage: must be finite, got ({}, {}, {})",
                    creepage.longitudinal, creepage.lateral, creepage.spin));
  }
  // Material::validate builds a std::string: call it only when the quick check fails.
  const auto plausible = [](const Material& m) {
    return m.shear_modulus > 0.0 && std::isfinite(m.shear_modulus) && m.poisson >= 0.0 &&
           m.poisson < 0.5;
  };
  if (!plausible(body1)) body1.validate("tangential problem.body1");
  if (!plausible(body2)) body2.validate("tangential problem.body2");
  reduction.validate("tangential problem.reduction");
}

TangentialSolution LinearCreepStiffness::forces(const Creepage& cr) const {
  const double ab = a * b;
  const double gab = shear_modulus * ab;
  const double gab15 = gab * std::sqrt(ab);
  TangentialSolution s;
  s.force_x = -gab * c.c11 * cr.longitudinal;
  s.force_y = -gab * c.c22 * cr.lateral - gab15 * c.c23 * cr.spin;
  s.moment_z = gab15 * c.c23 * cr.lateral - gab * ab * c.c33 * cr.spin;
  return s;
}

LinearCreepStiffness linear_creep_stiffness(const TangentialProblem& problem,
                                            CoefficientSource source) {
  const CombinedMaterial m = combine(problem.body1, problem.body2);
  const ContactPatch& p = *problem.patch;
  LinearCreepStiffness k;
  k.shear_modulus = m.shear_modulus;
  k.poisson = m.poisson;
  k.a = p.semi_axis_x;
  k.b = p.semi_axis_y;
  const double ratio = p.curvature_x / p.curvature_y;
  if (source == CoefficientSource::kVocoFit && !(ratio > 0.0 && std::isfinite(ratio))) {
    throw std::invalid_argument(
        "coefficients=voco_fit needs the patch curvatures A and B (curvature_x, curvature_y)");
  }
  k.c = kalker_coefficients(source, k.a, k.b, std::min(m.poisson, 0.5), ratio);
  k.c.c11 *= problem.reduction.k11;
  k.c.c22 *= problem.reduction.k22;
  k.c.c23 *= problem.reduction.k23;
  k.c.c33 *= problem.reduction.k33;
  return k;
}

namespace {

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

std::vector<std::string> tangential_model_names() {
  return {
      "kalker_linear", "linear_saturated", "vermeulen_johnson", "shen_hedrick_elkins", "chopaya",
      "polach",        "fastsim",           "mim",
      "mim_table"};
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
      check_option_keys(name, options, {"coefficients"});
      return std::make_unique<SaturatedCreepModel>(law, source);
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
    check_option_keys(name, options, {"coefficients", "mx", "my", "flexibility"});
    FastsimOptions o;
    o.source = source;
    o.mx = option_int(options, "mx", o.mx);
    o.my = option_int(options, "my", o.my);
    const std::string flex = option_string(options, "flexibility", "three");
    if (flex == "three") {
      o.flexibility = Flexibility::kThree;
    } else if (flex == "weighted") {
      o.flexibility = Flexibility::kWeighted;
    } else {
      throw std::invalid_argument(fmt::format(
          "fastsim option 'flexibility': unknown value '{}'; allowed: three, weighted", flex));
    }
    return std::make_unique<FastsimModel>(o);
  }
  if (name == "mim") {
    check_option_keys(name, options, {"elements"});
    MimModelOptions o;
    o.elements = option_int(options, "elements", o.elements);
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
