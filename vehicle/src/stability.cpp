#include "ferro/vehicle/stability.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <stdexcept>

namespace ferro::vehicle {

const char* to_string(DofGroup g) {
  switch (g) {
    case DofGroup::wheelset_lateral_yaw: return "wheelset lateral/yaw";
    case DofGroup::wheelset_vertical_roll: return "wheelset vertical/roll";
    case DofGroup::wheelset_longitudinal_spin: return "wheelset longitudinal/spin";
    case DofGroup::frame_lateral: return "frame lateral";
    case DofGroup::frame_vertical: return "frame vertical";
    case DofGroup::carbody_lateral: return "car body lateral";
    case DofGroup::carbody_vertical: return "car body vertical";
    case DofGroup::track: return "track";
    case DofGroup::none: return "none";
  }
  return "?";
}

const char* to_string(ModeClass c) {
  switch (c) {
    case ModeClass::unclassified: return "unclassified";
    case ModeClass::hunting: return "hunting";
    case ModeClass::contact: return "contact";
    case ModeClass::longitudinal: return "longitudinal";
    case ModeClass::body: return "body";
    case ModeClass::track: return "track";
  }
  return "?";
}

ModeShapeInput mode_shape_input(
    const std::vector<SignalInfo>& states,
    const std::function<double(const std::string& body, const std::string& dof)>& mass) {
  ModeShapeInput in;
  in.group.assign(states.size(), DofGroup::none);
  in.weight.assign(states.size(), 0.0);
  const auto ends_with = [](const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
  };
  std::vector<double> known;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const std::string& name = states[i].name;
    const bool track = name.rfind("track.", 0) == 0;
    const bool spin = !track && ends_with(name, ".spin");
    if (!ends_with(name, "_dot") && !spin) continue;
    const std::string stem = spin ? name : name.substr(0, name.size() - 4);
    const auto dot = stem.rfind('.');
    if (dot == std::string::npos) continue;
    const std::string body = stem.substr(0, dot), dof = stem.substr(dot + 1);
    DofGroup g = DofGroup::none;
    if (track) {
      g = DofGroup::track;
    } else if (body.rfind("wheelset", 0) == 0) {
      if (dof == "y" || dof == "yaw") g = DofGroup::wheelset_lateral_yaw;
      if (dof == "z" || dof == "roll") g = DofGroup::wheelset_vertical_roll;
      if (dof == "x" || dof == "spin") g = DofGroup::wheelset_longitudinal_spin;
    } else if (body.rfind("bogie", 0) == 0) {
      if (dof == "y" || dof == "roll" || dof == "yaw") g = DofGroup::frame_lateral;
      if (dof == "x" || dof == "z" || dof == "pitch") g = DofGroup::frame_vertical;
    } else if (body.rfind("car_body", 0) == 0) {
      if (dof == "y" || dof == "roll" || dof == "yaw") g = DofGroup::carbody_lateral;
      if (dof == "x" || dof == "z" || dof == "pitch") g = DofGroup::carbody_vertical;
    }
    if (g == DofGroup::none) continue;
    in.group[i] = g;
    in.weight[i] = mass ? mass(body, dof) : NAN;
    if (std::isfinite(in.weight[i]) && in.weight[i] > 0.0) known.push_back(in.weight[i]);
  }
  // Unknown masses: the median of the known ones.
  double fallback = 1.0;
  if (!known.empty()) {
    std::nth_element(known.begin(), known.begin() + static_cast<long>(known.size() / 2),
                     known.end());
    fallback = known[known.size() / 2];
  }
  for (std::size_t i = 0; i < states.size(); ++i)
    if (in.group[i] != DofGroup::none && !(std::isfinite(in.weight[i]) && in.weight[i] > 0.0))
      in.weight[i] = fallback;
  return in;
}

ModeClass classify_mode(const std::array<double, kDofGroups>& p) {
  const auto share = [&p](DofGroup g) { return p[static_cast<std::size_t>(g)]; };
  if (share(DofGroup::track) >= kDominantShare) return ModeClass::track;
  const double wheelset_lateral = share(DofGroup::wheelset_lateral_yaw);
  const double lateral = wheelset_lateral + share(DofGroup::frame_lateral) +
                         share(DofGroup::carbody_lateral);
  const double contact = share(DofGroup::wheelset_vertical_roll);
  const double longitudinal = share(DofGroup::wheelset_longitudinal_spin);
  const double vertical = share(DofGroup::frame_vertical) + share(DofGroup::carbody_vertical);
  const double largest = std::max({lateral, contact, longitudinal, vertical});
  if (!(largest > 0.0)) return ModeClass::unclassified;
  if (lateral == largest)
    return wheelset_lateral >= kHuntingWheelsetShare * lateral ? ModeClass::hunting
                                                               : ModeClass::body;
  if (contact == largest) return ModeClass::contact;
  if (longitudinal == largest) return ModeClass::longitudinal;
  return ModeClass::body;
}

std::string Mode::shape() const {
  std::array<int, kDofGroups> order{};
  for (int g = 0; g < kDofGroups; ++g) order[static_cast<std::size_t>(g)] = g;
  std::sort(order.begin(), order.end(), [this](int a, int b) {
    return participation[static_cast<std::size_t>(a)] > participation[static_cast<std::size_t>(b)];
  });
  std::string s;
  double covered = 0.0;
  for (int g : order) {
    const double share = participation[static_cast<std::size_t>(g)];
    if (!(share >= 0.05) || covered >= 0.9) break;
    s += fmt::format("{}{} {:.2f}", s.empty() ? "" : ", ", to_string(static_cast<DofGroup>(g)),
                     share);
    covered += share;
  }
  return s;
}

double shape_correlation(const Mode& a, const Mode& b) {
  if (a.energy_vector.size() != b.energy_vector.size() || a.energy_vector.empty()) return 0.0;
  std::complex<double> dot = 0.0;
  for (std::size_t k = 0; k < a.energy_vector.size(); ++k)
    dot += std::conj(a.energy_vector[k]) * b.energy_vector[k];
  return std::norm(dot);
}

std::vector<Mode> linear_modes(const OdeSystem& system, double t, std::span<const double> x_eq,
                               const ModeShapeInput& shapes) {
  const auto n = static_cast<Eigen::Index>(system.size());
  const bool shaped = !shapes.empty();
  if (shaped && (shapes.group.size() != system.size() || shapes.weight.size() != system.size()))
    throw std::invalid_argument(fmt::format(
        "linear_modes: shape input for {} states, the system has {}", shapes.group.size(),
        system.size()));
  const auto rows = numerical_jacobian(system, t, x_eq);
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
      rows.data(), n, n);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(J, /*computeEigenvectors=*/shaped);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("linear_modes: eigenvalue computation did not converge");
  }
  // eigenvectors() assembles the complex matrix from the real Schur form at every call: once.
  const Eigen::MatrixXcd vectors = shaped ? solver.eigenvectors() : Eigen::MatrixXcd();
  std::vector<Mode> modes;
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::complex<double> lambda = solver.eigenvalues()[i];
    const double mag = std::abs(lambda);
    if (mag < 1e-9) continue;
    Mode m;
    m.eigenvalue = lambda;
    m.damping_ratio = -lambda.real() / mag;
    m.frequency_hz = std::abs(lambda.imag()) / (2.0 * std::numbers::pi);
    if (shaped) {
      double total = 0.0;
      for (Eigen::Index k = 0; k < n; ++k) {
        const auto g = shapes.group[static_cast<std::size_t>(k)];
        if (g == DofGroup::none) continue;
        const std::complex<double> component =
            std::sqrt(shapes.weight[static_cast<std::size_t>(k)]) * vectors(k, i);
        m.energy_vector.push_back(component);
        const double e = std::norm(component);
        m.participation[static_cast<std::size_t>(g)] += e;
        total += e;
      }
      if (total > 0.0) {
        for (double& s : m.participation) s /= total;
        for (auto& c : m.energy_vector) c /= std::sqrt(total);
      }
      m.kind = classify_mode(m.participation);
    }
    modes.push_back(m);
  }
  std::sort(modes.begin(), modes.end(),
            [](const Mode& a, const Mode& b) { return a.damping_ratio < b.damping_ratio; });
  return modes;
}

namespace {
/// Every mode at `speed` (classified when the family gives shape input).
std::vector<Mode> all_modes_at(const LinearisationAtSpeed& family, double speed) {
  const Linearisation lin = family(speed);
  auto modes = linear_modes(*lin.system, 0.0, lin.x_eq, lin.shapes);
  if (modes.empty())
    throw std::runtime_error(fmt::format("no non-neutral mode at V = {} m/s", speed));
  return modes;
}

/// The modes the Hopf search looks at: the hunting modes when they are classified, else all.
std::vector<Mode> modes_at(const LinearisationAtSpeed& family, double speed) {
  auto modes = all_modes_at(family, speed);
  const bool classified = modes.front().kind != ModeClass::unclassified;
  if (classified) std::erase_if(modes, [](const Mode& m) { return m.kind != ModeClass::hunting; });
  return modes;
}

/// The least damped mode of `modes` (sorted by damping ratio) that is not neutral; the first
/// one when every mode is neutral; a mode with NaN damping when there is none.
Mode least_damped_of(const std::vector<Mode>& modes) {
  for (const Mode& m : modes) {
    if (std::abs(m.damping_ratio) >= kNeutralDamping) return m;
  }
  if (!modes.empty()) return modes.front();  // every mode neutral
  Mode none;
  none.damping_ratio = none.frequency_hz = NAN;
  none.eigenvalue = {NAN, NAN};
  return none;
}

Mode least_damped_at(const LinearisationAtSpeed& family, double speed) {
  return least_damped_of(modes_at(family, speed));
}

std::complex<double> upper(std::complex<double> l) {
  return {l.real(), std::abs(l.imag())};
}

/// Eigenvalues (upper half plane) of the modes that are neutral at every speed: within
/// kNeutralDamping of zero damping at `speed` and at `v_ref`, with the same eigenvalue (within
/// kNeutralDamping |lambda|) at both. A structural mode without damping stays put; a hunting
/// mode passing zero damping moves with the speed.
std::vector<std::complex<double>> neutral_modes(const LinearisationAtSpeed& family, double speed,
                                                double v_ref) {
  const auto at = modes_at(family, speed), ref = modes_at(family, v_ref);
  std::vector<std::complex<double>> out;
  for (const Mode& m : at) {
    if (std::abs(m.damping_ratio) >= kNeutralDamping) continue;
    const double tol = kNeutralDamping * std::abs(m.eigenvalue);
    for (const Mode& r : ref) {
      if (std::abs(upper(r.eigenvalue) - upper(m.eigenvalue)) < tol) {
        out.push_back(upper(m.eigenvalue));
        break;
      }
    }
  }
  return out;
}

/// The largest real part among the modes that are not in `neutral` [1/s]: continuous in the
/// speed (no mode has to be followed, which fails when two hunting modes, e.g. the two
/// bogies', lie close together), it changes sign where the first mode crosses.
double largest_real_part(const LinearisationAtSpeed& family, double speed,
                         const std::vector<std::complex<double>>& neutral) {
  double largest = -INFINITY;
  for (const Mode& m : modes_at(family, speed)) {
    bool is_neutral = false;
    for (const auto& n : neutral)
      is_neutral |= std::abs(upper(m.eigenvalue) - n) < kNeutralDamping * std::abs(n);
    if (!is_neutral) largest = std::max(largest, m.eigenvalue.real());
  }
  return largest;
}

LinearisationAtSpeed about(const SystemAtSpeed& factory, std::span<const double> x_eq) {
  return [&factory, x = std::vector<double>(x_eq.begin(), x_eq.end())](double v) {
    return Linearisation{factory(v), x, {}};
  };
}
}  // namespace

std::vector<SweepPoint> damping_sweep(const LinearisationAtSpeed& family,
                                      const std::vector<double>& speeds) {
  std::vector<SweepPoint> out;
  std::vector<std::vector<Mode>> hunting_modes;  // per speed: the hunting class, Im >= 0
  out.reserve(speeds.size());
  for (double v : speeds) {
    const auto modes = all_modes_at(family, v);
    SweepPoint p;
    p.speed = v;
    p.least_damped = least_damped_of(modes);
    for (std::size_t c = 0; c < p.least_damped_of.size(); ++c) {
      std::vector<Mode> of_class;
      for (const Mode& m : modes)
        if (static_cast<std::size_t>(m.kind) == c) of_class.push_back(m);
      p.least_damped_of[c] = least_damped_of(of_class);
    }
    std::vector<Mode> hunting;
    for (const Mode& m : modes)
      if (m.kind == ModeClass::hunting && m.eigenvalue.imag() >= 0.0) hunting.push_back(m);
    hunting_modes.push_back(std::move(hunting));
    out.push_back(std::move(p));
  }
  // The hunting mode: from the highest speed down, by shape correlation.
  std::vector<std::size_t> order(speeds.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&speeds](std::size_t a, std::size_t b) { return speeds[a] > speeds[b]; });
  const Mode* above = nullptr;
  for (const std::size_t i : order) {
    const auto& candidates = hunting_modes[i];
    if (candidates.empty()) {
      above = nullptr;
      continue;
    }
    const Mode* best = nullptr;
    double best_correlation = 0.0;
    if (above != nullptr) {
      for (const Mode& m : candidates) {
        const double c = shape_correlation(*above, m);
        if (c > best_correlation) {
          best_correlation = c;
          best = &m;
        }
      }
    }
    if (best == nullptr || best_correlation < kShapeTracked) {
      best = &candidates.front();  // sorted by damping: the least damped
      for (const Mode& m : candidates)
        if (std::abs(m.damping_ratio) >= kNeutralDamping) {
          best = &m;
          break;
        }
      best_correlation = above == nullptr ? 1.0 : best_correlation;
    }
    out[i].hunting = *best;
    out[i].hunting_correlation = best_correlation;
    above = best;
  }
  return out;
}

std::vector<SweepPoint> damping_sweep(const SystemAtSpeed& factory,
                                      const std::vector<double>& speeds,
                                      std::span<const double> x_eq) {
  return damping_sweep(about(factory, x_eq), speeds);
}

std::optional<double> critical_speed(const SystemAtSpeed& factory, double v_min, double v_max,
                                     std::span<const double> x_eq, int scan_points,
                                     double rel_tol) {
  return critical_speed(about(factory, x_eq), v_min, v_max, scan_points, rel_tol);
}

std::optional<double> critical_speed(const LinearisationAtSpeed& family, double v_min, double v_max,
                                     int scan_points, double rel_tol) {
  if (!(v_min > 0.0) || !(v_max > v_min) || scan_points < 2) {
    throw std::invalid_argument(
        fmt::format("critical_speed: need 0 < v_min < v_max and scan_points >= 2, got {}, {}, {}",
                    v_min, v_max, scan_points));
  }
  if (least_damped_at(family, v_min).damping_ratio < 0.0) return v_min;
  double v_prev = v_min;
  for (int i = 1; i < scan_points; ++i) {
    const double v = v_min + (v_max - v_min) * i / (scan_points - 1);
    const Mode m = least_damped_at(family, v);
    if (m.damping_ratio < 0.0) {
      // Bisection on the largest real part among the modes that are not neutral at every
      // speed. The mode the scan saw may have crossed before it passed -kNeutralDamping: step
      // back to a speed where every such mode is damped.
      const double dv = (v_max - v_min) / (scan_points - 1);
      double lo = v_prev, hi = v;
      const auto neutral = neutral_modes(family, v, v_min);
      while (largest_real_part(family, lo, neutral) >= 0.0) {
        hi = lo;
        if (lo <= v_min) return v_min;
        lo = std::max(v_min, lo - dv);
      }
      while (hi - lo > rel_tol * hi) {
        const double mid = 0.5 * (lo + hi);
        (largest_real_part(family, mid, neutral) < 0.0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    v_prev = v;
  }
  return std::nullopt;
}

}  // namespace ferro::vehicle
