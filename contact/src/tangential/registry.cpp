// The tangential (creep-force) model registry: every model a scene, a case file or the command
// line can name, as {name, factory}; each factory parses its model's own options.
//
// References: each model's own file.
// Known deviations: none.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <stdexcept>

#include "ferro/contact/tangential/fastrip.hpp"
#include "ferro/contact/tangential/fastsim.hpp"
#include "ferro/contact/tangential/mim_model.hpp"
#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/contact/tangential/polach.hpp"
#include "ferro/contact/tangential/saturation_laws.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {
namespace {

template <SaturationLaw kLaw>
std::unique_ptr<TangentialModel> make_saturated(const ModelOptions& options) {
  return SaturatedCreepModel::from_options(kLaw, options);
}

constexpr std::array<TangentialModelEntry, 10> kTangentialModels{{
    {"kalker_linear", &KalkerLinearModel::from_options},
    {"linear_saturated", &make_saturated<SaturationLaw::kLinear>},
    {"vermeulen_johnson", &make_saturated<SaturationLaw::kVermeulenJohnson>},
    {"shen_hedrick_elkins", &make_saturated<SaturationLaw::kShenHedrickElkins>},
    {"chopaya", &make_saturated<SaturationLaw::kChopaya>},
    {"polach", &PolachModel::from_options},
    {"fastsim", &FastsimModel::from_options},
    {"fastrip", &FastripModel::from_options},
    {"mim", &MimTangentialModel::from_options},
    {"mim_table", &MimTableModel::from_options},
}};

}  // namespace

std::span<const TangentialModelEntry> tangential_models() {
  return kTangentialModels;
}

std::vector<std::string> tangential_model_names() {
  return registry_names(tangential_models());
}

std::unique_ptr<TangentialModel> make_tangential_model(std::string_view name,
                                                       const ModelOptions& options) {
  return registry_entry(tangential_models(), name, "tangential").make(options);
}

}  // namespace ferro::contact
