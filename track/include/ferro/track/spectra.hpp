#pragma once
// One-sided power spectral densities of track irregularities.
//
// Spatial angular frequency Omega [rad/m] (wavelength 2 pi / Omega); densities in
// m^2 / (rad/m), one-sided: the variance of the irregularity over a band is the integral of the
// density over that band of positive Omega.
//
// ERRI / ORE B176 (ORE B176 RP1, 1989; constants as reproduced in e.g. Claus & Schiehlen,
// Vehicle System Dynamics 29 (1998) and Zhai, "Vehicle-Track Coupled Dynamics" (2020) §3),
// Omega_c = 0.8246, Omega_r = 0.0206, Omega_s = 0.4380 rad/m, b = 0.75 m:
//   lateral   S = A_a Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2))
//   vertical  S = A_v Omega_c^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2))
//   cross-level angle  S = (A_v / b^2) Omega_c^2 Omega^2 /
//                          ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2)(Omega^2 + Omega_s^2))
//   gauge     S = A_g Omega_c^2 Omega^2 / ((Omega^2 + Omega_r^2)(Omega^2 + Omega_c^2)(Omega^2 +
//   Omega_s^2)) low level:  A_a = 2.119e-7, A_v = 4.032e-7, A_g = 5.32e-8  [m rad] high level: A_a
//   = 6.125e-7, A_v = 1.080e-6, A_g = 1.032e-7 [m rad] (cross-check: GENSYS' ORE B176 high-level
//   lateral table gives 6.1608e-6 m^2/(1/m) at 0.1 1/m, i.e. 2 pi * S_a(0.628 rad/m) with A_a
//   = 6.125e-7.)
// FRA classes 1-6 (Hamid, Rasmussen, Baluja & Yang, "Analytical Descriptions of Track Geometry
// Variations", US DOT / FRA final report, work 1976-1981; as tabulated by Garg &
// Dukkipati, "Dynamics of Railway Vehicle Systems" (1984) ch. 10 and Zhai (2020)), k = 0.25,
// Omega_c = 0.8245 rad/m, A in cm^2 rad/m:
//   vertical  S = k A_v Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2))     [cm^2/(rad/m)]
//   lateral   S = k A_a Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2))
//   cross-level and gauge  S = 4 k A_v Omega_c^2 / ((Omega^2 + Omega_c^2)(Omega^2 + Omega_s^2))
//   class:  1       2       3       4       5       6
//   A_v   1.2107  1.0181  0.6816  0.5376  0.2095  0.0339
//   A_a   3.3634  1.2107  0.4128  0.3027  0.0762  0.0339
//   Omega_s 0.6046 0.9308 0.8520  1.1312  0.8209  0.4380
//
// Known deviations: the ERRI cross-level spectrum is of the cross-level angle; it is returned
// here as the height difference over 2b = 1.5 m, i.e. multiplied by (2b)^2 (so 4 A_v ...).
// Whether ORE B176 densities are one- or two-sided is read differently in the literature; they
// are used here as one-sided (as GENSYS and most simulation papers do). The FRA gauge spectrum
// uses the cross-level form with A_v, as in the secondary sources above; it has not been checked
// against the FRA report. A_a and Omega_s of the FRA table were taken from the secondary
// sources and not re-derived.

#include <string>
#include <string_view>

#include "ferro/track/irregularity.hpp"

namespace ferro::track {

enum class TrackSpectrum {
  kErriLow,
  kErriHigh,
  kFraClass1,
  kFraClass2,
  kFraClass3,
  kFraClass4,
  kFraClass5,
  kFraClass6,
};

/// Parses "erri_low", "erri_high" (also "ore_b176_low/high"), "fra_1" ... "fra_6" (also
/// "fra_class_1" ...); throws std::invalid_argument naming `where` and the allowed values.
[[nodiscard]] TrackSpectrum track_spectrum_from_string(std::string_view name,
                                                       const std::string& where);
[[nodiscard]] std::string_view to_string(TrackSpectrum spectrum);

/// One-sided PSD of `channel` at `omega` [rad/m], in m^2/(rad/m). omega must be > 0.
[[nodiscard]] double one_sided_psd(TrackSpectrum spectrum, IrregularityChannel channel,
                                   double omega);

}  // namespace ferro::track
