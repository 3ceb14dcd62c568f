#include "ferro/scenarios/track_config.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "ferro/track/alignment.hpp"
#include "ferro/track/measured_irregularity.hpp"
#include "ferro/track/spectra.hpp"
#include "located.hpp"
#include "yaml_values.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kSectionKinds = {"straight", "transition", "clothoid", "curve",
                                                "circular"};
const std::vector<std::string> kSpectra = {"erri_low", "erri_high", "fra_1", "fra_2", "fra_3",
                                           "fra_4",    "fra_5",     "fra_6"};
const std::vector<std::string> kChannels = {"lateral", "vertical", "cross_level", "gauge"};

track::SectionSpec read_section(MapReader& s) {
  track::SectionSpec out;
  out.kind = track::section_kind_from_string(s.string("kind", kSectionKinds), s.key_path("kind"));
  out.length = s.number("length");
  if (out.kind == track::SectionKind::kCurve) {
    out.radius = s.number("radius");
    out.cant = s.number_or("cant", out.cant);
    if (s.has("cant_mm")) {
      if (s.has("cant")) s.fail("cant_mm", "give either cant [m] or cant_mm, not both");
      out.cant = s.number("cant_mm") * 1e-3;
    }
    s.allow("cant_mm");
    out.gauge_widening = s.number_or("gauge_widening", out.gauge_widening);
  }
  s.finish();
  return out;
}

IrregularityConfig read_irregularity(MapReader& r, const track::TrackDesign& design,
                                     bool bounded) {
  IrregularityConfig out;
  out.type = r.string("type", {"stochastic", "measured", "defect"});
  if (out.type == "stochastic") {
    auto& st = out.stochastic;
    st.spectrum = track::track_spectrum_from_string(r.string("spectrum", kSpectra),
                                                    r.key_path("spectrum"));
    const auto channels = r.string_list_or("channels", kChannels);
    st.channels.clear();
    for (const auto& c : channels) {
      if (std::find(kChannels.begin(), kChannels.end(), c) == kChannels.end()) {
        r.fail("channels",
               fmt::format("unknown channel '{}'; allowed: lateral, vertical, cross_level, gauge", c));
      }
      st.channels.push_back(track::irregularity_channel_from_string(c, r.key_path("channels")));
    }
    st.wavelength_min = r.number_or("wavelength_min", st.wavelength_min);
    st.wavelength_max = r.number_or("wavelength_max", st.wavelength_max);
    st.start_s = r.number_or("start_s", design.start_s);
    const double to_end = design.start_s + design.total_length() - st.start_s;
    if (!r.has("length") && !bounded) {
      r.fail("length", "required on a track without sections (the realisation's extent [m])");
    }
    st.length = r.number_or("length", to_end);
    const long seed = r.integer_or("seed", static_cast<long>(st.seed));
    if (seed < 0) r.fail("seed", fmt::format("must be >= 0, got {}", seed));
    st.seed = static_cast<std::uint64_t>(seed);
    st.grid_spacing = r.number_or("grid_spacing", st.grid_spacing);
    st.amplitude_scale = r.number_or("amplitude_scale", st.amplitude_scale);
    st.fade_in_length = r.number_or("fade_in_length", st.fade_in_length);
    r.finish();
    detail::located(r, [&] { st.validate(""); });
  } else if (out.type == "measured") {
    const std::string file = r.string("file");
    const fs::path base = fs::path(r.file()).parent_path();
    out.measured_file = (base / file).lexically_normal().string();
    if (!fs::exists(out.measured_file)) {
      r.fail("file", fmt::format("measured irregularity file '{}' does not exist (looked for {})",
                                 file, out.measured_file));
    }
    r.finish();
  } else {
    auto& d = out.defect;
    d.channel = track::irregularity_channel_from_string(r.string("channel", kChannels),
                                                        r.key_path("channel"));
    d.shape = track::defect_shape_from_string(
        r.string_or("shape", "one_minus_cosine", {"one_minus_cosine", "sine", "dipped_joint"}), r.key_path("shape"));
    d.amplitude = r.number("amplitude");
    d.wavelength = r.number("wavelength");
    d.start_s = r.number("start_s");
    d.periods = static_cast<int>(r.integer_or("periods", d.periods));
    r.finish();
    detail::located(r, [&] { d.validate(""); });
  }
  return out;
}

}  // namespace

/// `track.structure`: `rigid`, `discrete` (the default ballasted track), or a mapping with
/// `model` and the components' keys (docs/SCENES.md, "Track structure").
track::TrackStructureSpec read_structure(MapReader& r) {
  track::TrackStructureSpec out{track::TrackStructureSpec::Kind::discrete, {}};
  if (!r.has("structure")) {
    r.allow("structure");
    return out;
  }
  const std::vector<std::string> models = {"rigid", "discrete"};
  if (r.yaml()["structure"].IsScalar()) {
    const std::string kind = r.string("structure", models);
    if (kind == "rigid") out.kind = track::TrackStructureSpec::Kind::rigid;
    return out;
  }
  MapReader s = r.map("structure");
  if (s.string_or("model", "discrete", models) == "rigid") {
    out.kind = track::TrackStructureSpec::Kind::rigid;
    s.finish();
    return out;
  }
  track::BallastedTrackSpec& b = out.ballasted;
  {
    MapReader m = s.map_or_empty("rail");
    b.rail_mass_per_length = m.number_or("mass_per_length", b.rail_mass_per_length);
    b.rail_young_modulus = m.number_or("young_modulus", b.rail_young_modulus);
    b.rail_shear_modulus = m.number_or("shear_modulus", b.rail_shear_modulus);
    b.rail_inertia_vertical = m.number_or("inertia_vertical", b.rail_inertia_vertical);
    b.rail_inertia_lateral = m.number_or("inertia_lateral", b.rail_inertia_lateral);
    b.rail_torsion_constant = m.number_or("torsion_constant", b.rail_torsion_constant);
    b.rail_height = m.number_or("height", b.rail_height);
    b.rail_centroid_height = m.number_or("centroid_height", b.rail_centroid_height);
    b.rail_foot_width = m.number_or("foot_width", b.rail_foot_width);
    m.finish();
  }
  {
    MapReader m = s.map_or_empty("pad");
    b.pad_stiffness_vertical = m.number_or("stiffness_vertical", b.pad_stiffness_vertical);
    b.pad_damping_vertical = m.number_or("damping_vertical", b.pad_damping_vertical);
    b.pad_stiffness_lateral = m.number_or("stiffness_lateral", b.pad_stiffness_lateral);
    b.pad_damping_lateral = m.number_or("damping_lateral", b.pad_damping_lateral);
    b.pad_stiffness_roll = m.number_or("stiffness_roll", b.pad_stiffness_roll);
    b.pad_damping_roll = m.number_or("damping_roll", b.pad_damping_roll);
    m.finish();
  }
  {
    MapReader m = s.map_or_empty("sleeper");
    b.sleeper_mass = m.number_or("mass", b.sleeper_mass);
    b.sleeper_length = m.number_or("length", b.sleeper_length);
    b.sleeper_spacing = m.number_or("spacing", b.sleeper_spacing);
    m.finish();
  }
  {
    MapReader m = s.map_or_empty("ballast");
    b.ballast_stiffness_vertical = m.number_or("stiffness_vertical", b.ballast_stiffness_vertical);
    b.ballast_damping_vertical = m.number_or("damping_vertical", b.ballast_damping_vertical);
    b.ballast_stiffness_lateral = m.number_or("stiffness_lateral", b.ballast_stiffness_lateral);
    b.ballast_damping_lateral = m.number_or("damping_lateral", b.ballast_damping_lateral);
    b.ballast_mass = m.number_or("mass", b.ballast_mass);
    m.finish();
  }
  s.finish();
  detail::located(s, [&] { b.validate("track.structure"); }, "track.structure");
  return out;
}

TrackConfig read_track(MapReader& r) {
  TrackConfig out;
  const bool has_sections = r.has("sections");
  out.type = r.string_or("type", has_sections ? "design" : "straight", {"straight", "design"});
  auto& d = out.design;
  if (out.type == "straight" && has_sections) {
    r.fail("sections", "a 'straight' track has no sections; use type: design (or leave type out)");
  }
  if (out.type == "straight" && r.has("length")) {
    // A bounded straight: one straight section, so that irregularities have an extent.
    out.type = "design";
    d.sections.push_back({track::SectionKind::kStraight, r.number("length")});
  } else {
    r.allow("length");
  }
  if (out.type == "design" && !has_sections && d.sections.empty()) {
    r.fail("sections", "required for type design: a list of {kind, length, ...} sections");
  }
  out.gauge = r.number_or("gauge", out.gauge);
  if (!std::isnan(out.gauge)) d.gauge = out.gauge;
  d.rail_spacing = r.number_or("rail_spacing", d.rail_spacing);
  out.rail_inclination = r.number_or("rail_inclination", out.rail_inclination);
  if (!std::isnan(out.rail_inclination) && !(std::abs(out.rail_inclination) < 0.2)) {
    r.fail("rail_inclination",
           fmt::format("must be an angle in radians below 0.2 in magnitude (1:40 = 0.025), got {}",
                       out.rail_inclination));
  }
  {
    MapReader start = r.map_or_empty("start");
    d.start_s = start.number_or("s", d.start_s);
    d.start_x = start.number_or("x", d.start_x);
    d.start_y = start.number_or("y", d.start_y);
    d.start_heading = start.number_or("heading", d.start_heading);
    start.finish();
  }
  for (auto& s : detail::map_list(r, "sections", "a section {kind, length, ...}")) {
    d.sections.push_back(read_section(s));
  }
  if (out.type == "design") {
    detail::located(r, [&] { d.validate(""); });
  }
  for (auto& item : detail::map_list(r, "irregularities", "an irregularity {type, ...}")) {
    out.irregularities.push_back(read_irregularity(item, d, out.type == "design"));
  }
  out.structure = read_structure(r);
  if (out.type == "straight" && !out.irregularities.empty()) {
    r.fail("irregularities",
           "need a bounded track: give 'length' (straight) or 'sections' (design)");
  }
  r.finish();
  return out;
}

std::shared_ptr<const track::Track> build_track(const TrackConfig& config) {
  if (config.type == "straight") return nullptr;
  std::shared_ptr<const track::Irregularity> irregularity;
  if (!config.irregularities.empty()) {
    auto sum = std::make_shared<track::IrregularitySum>();
    for (const auto& item : config.irregularities) {
      if (item.type == "stochastic") {
        sum->add(std::make_shared<track::StochasticIrregularity>(item.stochastic));
      } else if (item.type == "measured") {
        sum->add(std::make_shared<track::MeasuredIrregularity>(item.measured_file));
      } else {
        sum->add(std::make_shared<track::IsolatedDefect>(item.defect));
      }
    }
    irregularity = std::move(sum);
  }
  return std::make_shared<track::Track>(track::Alignment(config.design), irregularity);
}

}  // namespace ferro::scenarios
