// The co-running discrete track's vertical receptance at the rail head against two references:
//   - a continuous rail on the same pad, sleeper and ballast smeared along the track (per metre:
//     pad k_p / a, c_p / a; half a sleeper m_s / (2 a); ballast k_b / a, c_b / a), as an Euler
//     and as a Timoshenko beam, in closed form in the frequency domain. It has the lumped
//     model's parameters, so the difference between the two is the lumping (the co-running
//     Ritz reduction on the static deflection shape), not the parameters;
//   - the same rail on the same seats discretely supported every sleeper spacing (finite
//     elements, Euler beam, 60 m of track), which separates the continuous smearing from the
//     lumping: loaded over a sleeper and mid-span;
//   - the ranges measured on ballasted tracks, for the parameters.
// Loads: equal vertical forces on both rail heads (a wheelset), receptance per wheel.
//
// References: Hetenyi, "Beams on Elastic Foundation" (1946) (static point receptance
// 1 / (8 E I beta^3)); Knothe & Grassie, Veh. Syst. Dyn. 22 (1993) 209-262 (continuously
// supported rail on a pad-sleeper-ballast foundation); de Man, "A Survey of Dynamic Railway Track
// Properties and their Quality", PhD thesis, TU Delft (2002) (measured ranges on ballasted
// tracks: full-track resonance 40-140 Hz, rail resonance on the pads 250-1500 Hz, pinned-pinned
// resonance 500-1200 Hz; quoted from a secondary summary of the survey, not read in the thesis).
// Known deviations: the references are Euler beams where the shear of the rail matters (the
// discretely supported Euler rail's pinned-pinned resonance lies at 1420 Hz, above the measured
// 500-1200 Hz); measured receptances are taken with one rail struck, which lets the sleeper roll
// (the figures here load both rails alike; one rail alone moves the lumped model's full-track
// resonance by 0.2 Hz).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <complex>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "ferro/track/track_structure.hpp"

namespace ferro::track {
namespace {

using cd = std::complex<double>;
constexpr int kN = kTrackPositions;
constexpr double kPi = std::numbers::pi;
constexpr double kSteelDensity = 7850.0;  // [kg/m^3]
const cd kI(0.0, 1.0);

/// Vertical receptance per wheel of the implemented equations (both rail heads loaded alike),
/// from their linearisation at rest (they are linear: the differences are exact to round-off).
class LumpedTrack {
 public:
  explicit LumpedTrack(const CoRunningTrackParams& p) {
    const double zero[kN] = {};
    const RailLoad none[2] = {};
    for (int j = 0; j < kN; ++j) {
      double e[kN] = {};
      e[j] = 1.0;
      co_running_track_accelerations(p, e, zero, none, minus_mik_.col(j).data());
      co_running_track_accelerations(p, zero, e, none, minus_mic_.col(j).data());
    }
    RailLoad both[2] = {};
    both[0].force_z = both[1].force_z = 1.0;
    co_running_track_accelerations(p, zero, zero, both, mib_.data());
  }
  /// Left rail's vertical displacement per unit vertical force on each head, at complex
  /// angular frequency w (e^{i w t}).
  [[nodiscard]] cd receptance(cd w) const {
    const Eigen::Matrix<cd, kN, kN> d = -w * w * Eigen::Matrix<cd, kN, kN>::Identity() -
                                        minus_mik_.cast<cd>() - kI * w * minus_mic_.cast<cd>();
    const Eigen::Matrix<cd, kN, 1> q = d.partialPivLu().solve(mib_.cast<cd>());
    return q(1);
  }

 private:
  Eigen::Matrix<double, kN, kN> minus_mik_, minus_mic_;
  Eigen::Matrix<double, kN, 1> mib_;
};

/// One rail continuously supported by the track's pads, sleepers and ballast smeared per metre.
struct ContinuousTrack {
  const BallastedTrackSpec s;
  double shear_coefficient = 0.0;  ///< Timoshenko's kappa; 0: Euler-Bernoulli beam
  bool rotary_inertia = true;      ///< Timoshenko only

  /// Dynamic stiffness of the foundation per metre: pad in series with the sleeper mass on the
  /// ballast.
  [[nodiscard]] cd foundation(cd w) const {
    const double a = s.sleeper_spacing;
    const cd pad = (s.pad_stiffness_vertical + kI * w * s.pad_damping_vertical) / a;
    const cd ballast = (s.ballast_stiffness_vertical + kI * w * s.ballast_damping_vertical) / a;
    const cd sleeper = ballast - w * w * (0.5 * s.sleeper_mass / a);
    return pad * sleeper / (pad + sleeper);
  }

  /// Point receptance at the load. Euler: EI w'''' - m w^2 w + s w = F delta gives
  /// F / (8 EI lambda^3), lambda^4 = (s - m w^2) / (4 EI), the principal root (the damping keeps
  /// s - m w^2 off the negative real axis). Timoshenko: the transform of the deflection is
  /// (EI k^2 + C) / (a k^4 + b k^2 + c) with a = kGA EI, b = D EI - kGA rho I w^2, c = D C,
  /// D = s - m w^2, C = kGA - rho I w^2; partial fractions in k^2 and
  /// int dk / (k^2 - r) = i pi / sqrt(r) (Im sqrt(r) > 0) give the integral over k.
  [[nodiscard]] cd receptance(cd w) const {
    const double ei = s.rail_young_modulus * s.rail_inertia_vertical;
    const double m = s.rail_mass_per_length;
    const cd d = foundation(w) - m * w * w;
    if (shear_coefficient == 0.0) {
      const cd lambda = std::pow(d / (4.0 * ei), 0.25);
      return 1.0 / (8.0 * ei * lambda * lambda * lambda);
    }
    const double kga = shear_coefficient * s.rail_shear_modulus * m / kSteelDensity;
    const double rho_i = rotary_inertia ? kSteelDensity * s.rail_inertia_vertical : 0.0;
    const cd c0 = kga - rho_i * w * w;
    const cd qa = kga * ei, qb = d * ei - kga * rho_i * w * w, qc = d * c0;
    const cd disc = std::sqrt(qb * qb - 4.0 * qa * qc);
    const cd r1 = (-qb + disc) / (2.0 * qa), r2 = (-qb - disc) / (2.0 * qa);
    const auto upper_root = [](cd r) {
      const cd q = std::sqrt(r);
      return q.imag() < 0.0 ? -q : q;
    };
    const cd a1 = (ei * r1 + c0) / (qa * (r1 - r2)), a2 = (ei * r2 + c0) / (qa * (r2 - r1));
    return 0.5 * kI * (a1 / upper_root(r1) + a2 / upper_root(r2));
  }
};

/// A resonance: frequency [Hz] and |receptance| there [m/N].
struct Peak {
  double frequency, magnitude;
};

/// The rail discretely supported: Euler beam finite elements (cubic Hermite, consistent mass),
/// `bays` sleeper bays of `elements` elements each, free ends, a seat at every sleeper (pad in
/// series with half the sleeper's mass on its ballast), or the seats smeared along the rail
/// (`smeared`: the continuous foundation, to check the elements against the closed form).
struct DiscreteTrack {
  const BallastedTrackSpec s;
  bool smeared = false;
  int bays = 100, elements = 6;

  [[nodiscard]] cd seat(double w) const {
    const cd pad = s.pad_stiffness_vertical + kI * w * s.pad_damping_vertical;
    const cd sleeper = s.ballast_stiffness_vertical + kI * w * s.ballast_damping_vertical -
                       w * w * (0.5 * s.sleeper_mass);
    return pad * sleeper / (pad + sleeper);
  }

  /// Point receptance at the middle sleeper, or mid-span next to it.
  [[nodiscard]] cd receptance(double w, bool mid_span) const {
    const int n_el = bays * elements, n = 2 * (n_el + 1);
    const double l = s.sleeper_spacing / elements;
    const double ei = s.rail_young_modulus * s.rail_inertia_vertical;
    const double k[4][4] = {{12.0, 6.0 * l, -12.0, 6.0 * l},
                            {6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l},
                            {-12.0, -6.0 * l, 12.0, -6.0 * l},
                            {6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l}};
    const double m[4][4] = {{156.0, 22.0 * l, 54.0, -13.0 * l},
                            {22.0 * l, 4.0 * l * l, 13.0 * l, -3.0 * l * l},
                            {54.0, 13.0 * l, 156.0, -22.0 * l},
                            {-13.0 * l, -3.0 * l * l, -22.0 * l, 4.0 * l * l}};
    const cd foundation = smeared ? seat(w) / s.sleeper_spacing : cd(0.0);
    const cd mass_like = (foundation - w * w * s.rail_mass_per_length) * (l / 420.0);
    std::vector<Eigen::Triplet<cd>> entries;
    for (int e = 0; e < n_el; ++e) {
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
          entries.emplace_back(2 * e + i, 2 * e + j,
                               ei / (l * l * l) * k[i][j] + mass_like * m[i][j]);
        }
      }
    }
    if (!smeared) {
      for (int b = 0; b <= bays; ++b)
        entries.emplace_back(2 * b * elements, 2 * b * elements, seat(w));
    }
    Eigen::SparseMatrix<cd> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<cd>> lu(a);
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(n);
    const int node = (bays / 2) * elements + (mid_span ? elements / 2 : 0);
    f(2 * node) = 1.0;
    return lu.solve(f)(2 * node);
  }
};

/// The largest |h| on a grid from f0 to f1 [Hz] in steps of df.
Peak grid_peak(const std::function<double(double)>& magnitude, double f0, double f1, double df) {
  Peak best{f0, 0.0};
  for (double f = f0; f <= f1 + 1e-9; f += df) {
    const double v = magnitude(f);
    if (v > best.magnitude) best = {f, v};
  }
  return best;
}

/// The first two local maxima of |receptance| between 20 and 2000 Hz (0.05 Hz grid): the
/// full-track resonance and the rail-on-pad resonance.
struct Resonances {
  Peak track, pad;
};
Resonances resonances(const std::function<cd(cd)>& h) {
  std::vector<Peak> maxima;
  const auto at = [&](double f) { return std::abs(h(cd(2.0 * kPi * f, 0.0))); };
  double prev = at(20.0), cur = at(20.05);
  for (double f = 20.05; f < 2000.0 && maxima.size() < 2; f += 0.05) {
    const double next = at(f + 0.05);
    if (cur > prev && cur >= next) maxima.push_back({f, cur});
    prev = cur;
    cur = next;
  }
  if (maxima.size() < 2) {
    ADD_FAILURE() << "fewer than two resonances between 20 and 2000 Hz";
    maxima.resize(2, Peak{0.0, 0.0});
  }
  return {maxima[0], maxima[1]};
}

/// Complex angular frequency of a wheel (unsprung mass m per wheel on the linearised Hertz
/// spring k_h) on a track of receptance h: 1 = m w^2 (1 / k_h + h(w)), by Newton's method
/// from w0. Natural frequency |w| / 2 pi, damping ratio Im w / |w|.
cd wheel_on_track_mode(const std::function<cd(cd)>& h, double m, double k_h, cd w) {
  const auto residual = [&](cd x) { return 1.0 - m * x * x * (1.0 / k_h + h(x)); };
  for (int it = 0; it < 50; ++it) {
    const cd step = cd(1e-3 * std::abs(w), 0.0);
    const cd slope = (residual(w + step) - residual(w - step)) / (2.0 * step);
    const cd dw = residual(w) / slope;
    w -= dw;
    if (std::abs(dw) < 1e-12 * std::abs(w)) return w;
  }
  ADD_FAILURE() << "wheel-on-track mode: Newton did not converge";
  return w;
}

std::function<cd(cd)> of(const LumpedTrack& t) {
  return [&t](cd w) { return t.receptance(w); };
}
std::function<cd(cd)> of(const ContinuousTrack& t) {
  return [&t](cd w) { return t.receptance(w); };
}

TEST(TrackReceptance, continuous_reference_is_the_static_beam_and_its_euler_limit) {
  // The reference checked on its own: at 0 Hz the Euler beam is Hetenyi's 1 / (8 EI beta^3)
  // with beta^4 = k_seat / (4 EI a); the Timoshenko form without rotary inertia and with a
  // shear stiffness 1e4 times the rail's is the Euler beam to within EI k^2 / (kappa G A), below
  // 1e-4 up to 2000 Hz: within 1e-3.
  const BallastedTrackSpec s;
  const ContinuousTrack euler{s, 0.0};
  const ContinuousTrack stiff_shear{s, 1.0e4, false};
  const double ei = s.rail_young_modulus * s.rail_inertia_vertical;
  const double k_seat = 1.0 / (1.0 / s.pad_stiffness_vertical + 1.0 / s.ballast_stiffness_vertical);
  const double beta = std::pow(k_seat / (s.sleeper_spacing * 4.0 * ei), 0.25);
  EXPECT_NEAR(std::abs(euler.receptance(cd(1e-6, 0.0))) * 8.0 * ei * beta * beta * beta, 1.0, 1e-9);
  for (double f = 1.0; f <= 2000.0; f *= 1.1) {
    const cd w(2.0 * kPi * f, 0.0);
    EXPECT_LT(std::abs(stiff_shear.receptance(w) / euler.receptance(w) - 1.0), 1e-3)
        << "f = " << f << " Hz";
  }
}

TEST(TrackReceptance, lumped_track_against_the_continuous_beam_with_the_same_parameters) {
  // Lumping error of the co-running model (track_structure.hpp) against the same track as a
  // continuous Euler beam:
  //   - below 20 Hz the two agree within 0.5 % (the lumping keeps the static deflection exactly;
  //     1.6 % inertia at 20 Hz in both);
  //   - the full-track resonance (rail and sleepers on the ballast) and the rail-on-pad
  //     resonance: the lumped model puts them 17 % higher (129.9 / 110.6 Hz, 477 / 408 Hz) and
  //     its full-track peak 35 % higher (its dampers and masses weigh with the static shape;
  //     at resonance the continuous rail's deflection basin is shorter and it radiates energy
  //     along the rail). Bounds: frequencies 10-25 % above, peak 20-50 % above, so that the
  //     documented error is pinned both ways;
  //   - Timoshenko against Euler (shear coefficient 0.4, a value used for rail sections in
  //     vertical bending): 8 % more static deflection (shear), resonances within 2 %.
  const BallastedTrackSpec s;
  const LumpedTrack lumped(co_running_equivalent(s, 1.5));
  const ContinuousTrack euler{s, 0.0};
  const ContinuousTrack timoshenko{s, 0.4};
  for (const double f : {1.0, 5.0, 10.0, 20.0}) {
    const cd w(2.0 * kPi * f, 0.0);
    EXPECT_LT(std::abs(std::abs(lumped.receptance(w)) / std::abs(euler.receptance(w)) - 1.0), 5e-3)
        << "f = " << f << " Hz";
  }
  const auto [lumped_track, lumped_pad] = resonances(of(lumped));
  const auto [euler_track, euler_pad] = resonances(of(euler));
  const auto [timo_track, timo_pad] = resonances(of(timoshenko));
  RecordProperty("lumped_full_track_hz", std::to_string(lumped_track.frequency));
  RecordProperty("continuous_full_track_hz", std::to_string(euler_track.frequency));
  const double track_ratio = lumped_track.frequency / euler_track.frequency;
  const double pad_ratio = lumped_pad.frequency / euler_pad.frequency;
  const double peak_ratio = lumped_track.magnitude / euler_track.magnitude;
  EXPECT_GT(track_ratio, 1.10) << lumped_track.frequency << " / " << euler_track.frequency;
  EXPECT_LT(track_ratio, 1.25) << lumped_track.frequency << " / " << euler_track.frequency;
  EXPECT_GT(pad_ratio, 1.10) << lumped_pad.frequency << " / " << euler_pad.frequency;
  EXPECT_LT(pad_ratio, 1.25) << lumped_pad.frequency << " / " << euler_pad.frequency;
  EXPECT_GT(peak_ratio, 1.20) << lumped_track.magnitude << " / " << euler_track.magnitude;
  EXPECT_LT(peak_ratio, 1.50) << lumped_track.magnitude << " / " << euler_track.magnitude;
  const double static_shear =
      std::abs(timoshenko.receptance(cd(1e-6, 0.0)) / euler.receptance(cd(1e-6, 0.0)));
  EXPECT_GT(static_shear, 1.05);
  EXPECT_LT(static_shear, 1.10);
  EXPECT_NEAR(timo_track.frequency / euler_track.frequency, 1.0, 0.02);
  EXPECT_NEAR(timo_pad.frequency / euler_pad.frequency, 1.0, 0.02);
}

TEST(TrackReceptance, discrete_support_against_the_continuous_beam) {
  // The elements checked first: with the seats smeared they give the closed form within 1e-3
  // up to 1000 Hz (six elements per sleeper bay, five or more per bending wavelength). Then the
  // seats every 0.6 m: the full-track and rail-on-pad resonances and the receptance below
  // 50 Hz move by less than 2 % from the continuous beam's, over a sleeper and mid-span
  // (measured: 111 / 110 against 110.6 Hz, 408 / 407 against 408.3 Hz, -0.5 / +1.0 % at
  // 1 Hz), so the continuous beam stands for the track below the pinned-pinned resonance; that
  // resonance (the rail bending between sleepers, nodes at the seats) shows mid-span at the
  // closed form of a pinned-pinned Euler span, pi / (2 a^2) sqrt(EI / m') = 1420 Hz, within 1 %
  // (the lumped model has no such mode).
  const BallastedTrackSpec s;
  const ContinuousTrack euler{s, 0.0};
  const DiscreteTrack smeared{s, true};
  const DiscreteTrack discrete{s, false};
  for (const double f : {1.0, 50.0, 110.0, 200.0, 408.0, 600.0, 1000.0}) {
    const double w = 2.0 * kPi * f;
    EXPECT_LT(std::abs(smeared.receptance(w, false) / euler.receptance(cd(w, 0.0)) - 1.0), 1e-3)
        << "f = " << f << " Hz";
  }
  const auto [track, pad] = resonances(of(euler));
  for (const bool mid_span : {false, true}) {
    const auto magnitude = [&](double f) {
      return std::abs(discrete.receptance(2.0 * kPi * f, mid_span));
    };
    const Peak d_track = grid_peak(magnitude, 95.0, 125.0, 0.5);
    const Peak d_pad = grid_peak(magnitude, 390.0, 425.0, 0.5);
    EXPECT_NEAR(d_track.frequency / track.frequency, 1.0, 0.02) << "mid-span " << mid_span;
    EXPECT_NEAR(d_pad.frequency / pad.frequency, 1.0, 0.02) << "mid-span " << mid_span;
    EXPECT_NEAR(magnitude(1.0) / std::abs(euler.receptance(cd(2.0 * kPi, 0.0))), 1.0, 0.02);
  }
  const double ei = s.rail_young_modulus * s.rail_inertia_vertical;
  const double pinned_pinned =
      kPi / (2.0 * s.sleeper_spacing * s.sleeper_spacing) * std::sqrt(ei / s.rail_mass_per_length);
  const Peak mid =
      grid_peak([&](double f) { return std::abs(discrete.receptance(2.0 * kPi * f, true)); },
                0.9 * pinned_pinned, 1.1 * pinned_pinned, 2.0);
  EXPECT_NEAR(mid.frequency / pinned_pinned, 1.0, 0.01) << mid.frequency << " Hz";
}

TEST(TrackReceptance, wheel_on_track_p2_mode_is_not_changed_by_the_lumping) {
  // The P2 mode: an unsprung mass per wheel (half of a 1813 kg wheelset) on the linearised
  // Hertz spring (1.56e9 N/m) on the track. Lumped: 58.12 Hz, zeta 0.063; continuous Euler
  // beam with the same parameters: 58.08 Hz, zeta 0.067. The mode lies far below the track's
  // resonances, where the track is nearly its static stiffness, which the lumping keeps
  // exactly: frequency within 1 %; the damping within 10 % (the lumped dampers weigh with the
  // static shape; 7 % here).
  const BallastedTrackSpec s;
  const LumpedTrack lumped(co_running_equivalent(s, 1.5));
  const ContinuousTrack euler{s, 0.0};
  const double unsprung = 0.5 * 1813.0, hertz = 1.56e9;
  const cd start(2.0 * kPi * 58.0, 20.0);
  const cd w_lumped = wheel_on_track_mode(of(lumped), unsprung, hertz, start);
  const cd w_euler = wheel_on_track_mode(of(euler), unsprung, hertz, start);
  const double f_lumped = std::abs(w_lumped) / (2.0 * kPi);
  const double f_euler = std::abs(w_euler) / (2.0 * kPi);
  const double zeta_lumped = w_lumped.imag() / std::abs(w_lumped);
  const double zeta_euler = w_euler.imag() / std::abs(w_euler);
  EXPECT_NEAR(f_lumped, 58.1, 0.05);  // the figure VALIDATION.md names
  EXPECT_NEAR(zeta_lumped, 0.063, 0.0005);
  EXPECT_NEAR(f_lumped / f_euler, 1.0, 0.01) << f_lumped << " / " << f_euler << " Hz";
  EXPECT_NEAR(zeta_lumped / zeta_euler, 1.0, 0.10) << zeta_lumped << " / " << zeta_euler;
}

TEST(TrackReceptance, default_track_within_the_measured_ranges_of_ballasted_track) {
  // de Man (2002), ballasted tracks: full-track resonance 40-140 Hz, rail resonance on the
  // pads 250-1500 Hz. Both the lumped model and the continuous beam with the default
  // parameters must fall inside (lumped 129.9 and 477 Hz; continuous 110.6 and 408 Hz). The
  // ranges are the measurement scatter over many tracks, not a tolerance on one: they test
  // the parameters (a ballast stiff enough to move the full-track resonance above 140 Hz
  // fails), not the model.
  const BallastedTrackSpec s;
  const LumpedTrack lumped(co_running_equivalent(s, 1.5));
  const ContinuousTrack euler{s, 0.0};
  for (const auto& [name, h] :
       {std::pair{"lumped", of(lumped)}, std::pair{"continuous", of(euler)}}) {
    const auto [track, pad] = resonances(h);
    EXPECT_GE(track.frequency, 40.0) << name;
    EXPECT_LE(track.frequency, 140.0) << name;
    EXPECT_GE(pad.frequency, 250.0) << name;
    EXPECT_LE(pad.frequency, 1500.0) << name;
  }
  // The test can fail: a ballast twice as stiff (200 MN/m per seat) moves the lumped full-track
  // resonance out of the range.
  BallastedTrackSpec stiff = s;
  stiff.ballast_stiffness_vertical = 200.0e6;
  const LumpedTrack lumped_stiff(co_running_equivalent(stiff, 1.5));
  EXPECT_GT(resonances(of(lumped_stiff)).track.frequency, 140.0);
}

}  // namespace
}  // namespace ferro::track
