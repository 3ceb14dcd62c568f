// Multi-point contact table: every candidate point per wheel over lateral shift, roll and yaw;
// penetration online from the vertical position; per-branch interpolation; HDF5 I/O.
//
// References: see wheel_rail_geometry.hpp (search), multi_point_contact_table.hpp (branches).
// Known deviations: see MultiPointContactTable in multi_point_contact_table.hpp.

#include "ferro/contact/geometry/multi_point_contact_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "ferro/io/hdf5.hpp"

namespace ferro::contact {
namespace {

// Barrier stored for a wheel's first candidate (no previous one): never submerged [m].
constexpr double kNoBarrier = 1.0;
constexpr int kFields = 18;  // columns of /candidates
using Candidate = MultiPointContactTable::Candidate;
// The numeric Candidate fields in the column order of /candidates (after the side column).
constexpr std::array<double Candidate::*, kFields - 1> kColumns = {
    &Candidate::gap,           &Candidate::barrier,        &Candidate::x,
    &Candidate::y,             &Candidate::z,              &Candidate::wheel_y,
    &Candidate::rail_y,        &Candidate::contact_angle,  &Candidate::rolling_radius,
    &Candidate::curvature_a,   &Candidate::curvature_b,    &Candidate::dgap_dlateral,
    &Candidate::dgap_droll,    &Candidate::dgap_dyaw,      &Candidate::dbarrier_dlateral,
    &Candidate::dbarrier_droll, &Candidate::dbarrier_dyaw};
// Columns interpolated with the corner weights alone: x to curvature_b (gap and barrier carry a
// Taylor shift; the gradients serve that shift at the nodes and are not interpolated).
constexpr std::size_t kFirstWeighted = 2;
constexpr std::size_t kEndWeighted = 11;
static_assert(kColumns[kEndWeighted - 1] == &Candidate::curvature_b &&
              kColumns[kEndWeighted] == &Candidate::dgap_dlateral);
// 3: no candidate where a wheel section meets no rail surface (older caches may hold such
// candidates, A = inf, and are rebuilt).
constexpr double kFormatVersion = 3.0;

// Load share of a branch whose present corners carry the interpolation weight w in (0, 1]:
// C1 smoothstep over w in [kFadeStart, 1 - kFadeStart], exactly 1 for a branch present at every
// corner. share(w) + share(1 - w) = 1, so a branch dying across the corners where another is
// born hands its load over to it with shares that sum to one. The middle half of the weight:
// a wider band (down to w = 0) spreads more poses over two points (measured on S1002 / UIC60:
// 20 or more instead of 11 of 400 wheels off the search's points, and three sharp-curve
// equilibria of docs/VALIDATION.md failing that converge with this band); a narrower one
// steepens the hand-over (slope up to 1.5 / (1 - 2 kFadeStart) of the two branches' force
// difference per cell).
constexpr double kFadeStart = 0.25;  // [-]
double load_share(double w) {
  if (w > 1.0 - 1e-12) return 1.0;
  const double t = std::clamp((w - kFadeStart) / (1.0 - 2.0 * kFadeStart), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

int axis_count(double min, double max, double step, const char* name) {
  if (!std::isfinite(min) || !std::isfinite(max) || max < min) {
    throw std::invalid_argument(fmt::format(
        "MultiPointTableParams.{0}_min/{0}_max: need finite min <= max, got {1}, {2}", name, min,
        max));
  }
  if (max == min) return 1;
  if (!(step > 0.0)) {
    throw std::invalid_argument(
        fmt::format("MultiPointTableParams.{}_step: must be > 0, got {}", name, step));
  }
  const double u = (max - min) / step;
  const double n = std::round(u);
  if (std::abs(u - n) > 1e-6 * std::max(1.0, n) || n > 100000) {
    throw std::invalid_argument(fmt::format(
        "MultiPointTableParams.{0}_step: ({0}_max - {0}_min) / {0}_step = {1} must be a whole "
        "number of steps (at most 100000)",
        name, u));
  }
  return static_cast<int>(n) + 1;
}

}  // namespace

void MultiPointTableParams::validate() const {
  (void)axis_count(lateral_min, lateral_max, lateral_step, "lateral");
  (void)axis_count(roll_min, roll_max, roll_step, "roll");
  (void)axis_count(yaw_min, yaw_max, yaw_step, "yaw");
  if (max_points_per_wheel < 1 ||
      max_points_per_wheel > MultiPointContactTable::kMaxPointsPerWheel) {
    throw std::invalid_argument(
        fmt::format("MultiPointTableParams.max_points_per_wheel: must be in [1, {}], got {}",
                    MultiPointContactTable::kMaxPointsPerWheel, max_points_per_wheel));
  }
  if (!(capture_depth > 0.0 && capture_depth < 0.05)) {
    throw std::invalid_argument(fmt::format(
        "MultiPointTableParams.capture_depth: must be in (0, 0.05) m, got {}", capture_depth));
  }
}

std::uint64_t MultiPointContactTable::fingerprint(const WheelRailPair& pair,
                                                  const MultiPointTableParams& params) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&](double v) {
    unsigned char b[sizeof(double)];
    std::memcpy(b, &v, sizeof(double));
    for (unsigned char c : b) {
      h ^= c;
      h *= 1099511628211ULL;
    }
  };
  for (const Profile* p : {&pair.wheel_profile(), &pair.rail_profile()}) {
    for (double v : p->y) mix(v);
    for (double v : p->z) mix(v);
  }
  const WheelRailPairParams& q = pair.params();
  for (double v : {q.track_gauge, q.gauge_depth, q.flange_back_distance, q.flange_back_y,
                   q.nominal_radius, q.rail_inclination, q.grid_step, q.section_step}) {
    mix(v);
  }
  for (double v : {params.lateral_min, params.lateral_max, params.lateral_step, params.roll_min,
                   params.roll_max, params.roll_step, params.yaw_min, params.yaw_max,
                   params.yaw_step, static_cast<double>(params.max_points_per_wheel),
                   params.capture_depth}) {
    mix(v);
  }
  return h;
}

std::size_t MultiPointContactTable::node_index(int i, int j, int k) const {
  return (static_cast<std::size_t>(k) * static_cast<std::size_t>(axes_[1].n) +
          static_cast<std::size_t>(j)) *
             static_cast<std::size_t>(axes_[0].n) +
         static_cast<std::size_t>(i);
}

std::pair<const MultiPointContactTable::Candidate*, const MultiPointContactTable::Candidate*>
MultiPointContactTable::node(int i, int j, int k) const {
  const std::size_t n = node_index(i, j, k);
  return {nodes_.data() + node_offset_[n], nodes_.data() + node_offset_[n + 1]};
}

MultiPointContactTable MultiPointContactTable::build(const WheelRailPair& pair,
                                                     const MultiPointTableParams& params) {
  params.validate();
  MultiPointContactTable t;
  t.params_ = params;
  t.fingerprint_ = fingerprint(pair, params);
  t.axes_[0] = {params.lateral_min, params.lateral_step,
                axis_count(params.lateral_min, params.lateral_max, params.lateral_step, "lateral")};
  t.axes_[1] = {params.roll_min, params.roll_step,
                axis_count(params.roll_min, params.roll_max, params.roll_step, "roll")};
  t.axes_[2] = {params.yaw_min, params.yaw_step,
                axis_count(params.yaw_min, params.yaw_max, params.yaw_step, "yaw")};
  const std::size_t n_nodes = static_cast<std::size_t>(t.axes_[0].n) *
                              static_cast<std::size_t>(t.axes_[1].n) *
                              static_cast<std::size_t>(t.axes_[2].n);
  t.node_offset_.assign(n_nodes + 1, 0);
  std::vector<std::size_t> keep;
  for (int k = 0; k < t.axes_[2].n; ++k) {
    for (int j = 0; j < t.axes_[1].n; ++j) {
      for (int i = 0; i < t.axes_[0].n; ++i) {
        WheelsetPose pose;
        pose.lateral = t.axes_[0].min + i * t.axes_[0].step;
        pose.roll = t.axes_[1].min + j * t.axes_[1].step;
        pose.yaw = t.axes_[2].min + k * t.axes_[2].step;
        for (const Side side : {Side::left, Side::right}) {
          const std::vector<ContactPoint> c = candidate_points(pair, pose, side);
          if (c.empty()) continue;
          // Keep the deepest max_points_per_wheel within capture_depth of the deepest.
          const double deepest = deepest_candidate(c).vertical_gap;
          keep.resize(c.size());
          std::iota(keep.begin(), keep.end(), std::size_t{0});
          std::stable_sort(keep.begin(), keep.end(), [&](std::size_t a, std::size_t b) {
            return c[a].vertical_gap < c[b].vertical_gap;
          });
          std::vector<bool> kept(c.size(), false);
          for (std::size_t r = 0; r < keep.size(); ++r) {
            kept[keep[r]] = static_cast<int>(r) < params.max_points_per_wheel &&
                            c[keep[r]].vertical_gap <= deepest + params.capture_depth;
          }
          // Gap gradient over the grid axes at a point of the wheel/rail surfaces (envelope
          // theorem: the derivative of the minimum is the partial derivative at the fixed
          // minimising wheel point P): with the rail slope dz/dy = -s tan(gamma) at the point
          // and d = P - C (C the axle centre), d(gap) = slope dP_y - dP_z, dP = omega x d for a
          // rotation omega (roll: about the yawed axle direction (cos yaw, sin yaw, 0); yaw:
          // about z). A barrier is a maximum over sections of these minima: same formula at
          // its own section.
          const double sgn = side_sign(side);
          const WheelsetFrame frame(pose, pair.params().nominal_radius);
          const double cy = frame.cos_yaw, sy = frame.sin_yaw;
          auto gradient = [&](double x, double y, double z_rail, double gap, double angle) {
            const double slope = -sgn * std::tan(angle);
            const double dx = x, dy = y - frame.centre_y;
            const double dz = (z_rail - gap) - frame.centre_z;
            return std::array<double, 3>{slope, slope * (-cy * dz) - (cy * dy - sy * dx),
                                         slope * dx};
          };
          // In wheel_y order; a dropped candidate's barrier and gap fold into the next one's.
          double pending = -kNoBarrier;
          std::array<double, 3> pending_grad{};
          for (std::size_t q = 0; q < c.size(); ++q) {
            const bool has_barrier = std::isfinite(c[q].barrier);
            const double barrier = has_barrier ? c[q].barrier : kNoBarrier;
            const std::array<double, 3> gap_grad = gradient(
                c[q].x, c[q].y, c[q].z, c[q].vertical_gap, c[q].contact_angle);
            const std::array<double, 3> barrier_grad =
                has_barrier ? gradient(c[q].barrier_x, c[q].barrier_y, c[q].barrier_z,
                                       c[q].barrier, c[q].barrier_angle)
                            : std::array<double, 3>{};
            if (!kept[q]) {
              if (has_barrier && barrier > pending) {
                pending = barrier;
                pending_grad = barrier_grad;
              }
              if (c[q].vertical_gap > pending) {
                pending = c[q].vertical_gap;
                pending_grad = gap_grad;
              }
              continue;
            }
            Candidate s;
            s.side = side;
            s.gap = c[q].vertical_gap;
            const bool folded = pending > barrier;
            s.barrier = std::min(kNoBarrier, folded ? pending : barrier);
            const std::array<double, 3>& bg = folded ? pending_grad : barrier_grad;
            s.dbarrier_dlateral = bg[0];
            s.dbarrier_droll = bg[1];
            s.dbarrier_dyaw = bg[2];
            s.x = c[q].x;
            s.y = c[q].y;
            s.z = c[q].z;
            s.wheel_y = c[q].wheel_y;
            s.rail_y = c[q].rail_y;
            s.contact_angle = c[q].contact_angle;
            s.rolling_radius = c[q].rolling_radius;
            s.curvature_a = c[q].curvature_a;
            s.curvature_b = c[q].curvature_b;
            s.dgap_dlateral = gap_grad[0];
            s.dgap_droll = gap_grad[1];
            s.dgap_dyaw = gap_grad[2];
            t.nodes_.push_back(s);
            pending = -kNoBarrier;
          }
        }
        t.node_offset_[t.node_index(i, j, k) + 1] = t.nodes_.size();
      }
    }
  }
  t.finish();
  return t;
}

void MultiPointContactTable::finish() {
  // Active axes (more than one node) and cells.
  std::array<int, 3> cells{};
  for (int a = 0; a < 3; ++a) cells[a] = std::max(axes_[a].n - 1, 1);
  std::array<int, 3> active{};
  int d = 0;
  for (int a = 0; a < 3; ++a) {
    if (axes_[a].n > 1) active[d++] = a;
  }
  const int n_corners = 1 << d;
  cell_offset_.assign(static_cast<std::size_t>(cells[0]) * cells[1] * cells[2] + 1, 0);
  groups_.clear();
  std::vector<int> parent;
  std::vector<int> corner_of;
  struct Link {
    double cost;  // distance in wheel_y [m]
    int a, b;     // flattened candidate indices
  };
  std::vector<Link> links;
  std::vector<unsigned> corner_mask;
  std::vector<int> global;
  for (int ck = 0; ck < cells[2]; ++ck) {
    for (int cj = 0; cj < cells[1]; ++cj) {
      for (int ci = 0; ci < cells[0]; ++ci) {
        // Candidates of the cell's corners, flattened.
        std::array<std::size_t, 9> first{};
        parent.clear();
        corner_of.clear();
        global.clear();
        for (int c = 0; c < n_corners; ++c) {
          std::array<int, 3> idx{ci, cj, ck};
          for (int b = 0; b < d; ++b) {
            if (c & (1 << b)) idx[active[b]] += 1;
          }
          if (d < 3) {
            for (int a = 0; a < 3; ++a) {
              if (axes_[a].n == 1) idx[a] = 0;
            }
          }
          const std::size_t n = node_index(idx[0], idx[1], idx[2]);
          first[c] = global.size();
          for (std::size_t q = node_offset_[n]; q < node_offset_[n + 1]; ++q) {
            parent.push_back(static_cast<int>(parent.size()));
            corner_of.push_back(c);
            global.push_back(static_cast<int>(q));
          }
        }
        first[n_corners] = global.size();
        auto find = [&](int x) {
          while (parent[x] != x) x = parent[x] = parent[parent[x]];
          return x;
        };
        // Order-preserving alignment of the candidates of one wheel at corners c1 and c2
        // (each list increasing in wheel_y): minimum total cost, a match costing the distance in
        // wheel_y, leaving a candidate unmatched costing kBranchMatch.
        auto align = [&](int c1, int c2, Side side) {
          std::array<int, kMaxPointsPerWheel> u{}, v{};
          int nu = 0, nv = 0;
          for (std::size_t q = first[c1]; q < first[c1 + 1]; ++q) {
            if (nodes_[global[q]].side == side && nu < kMaxPointsPerWheel) u[nu++] = static_cast<int>(q);
          }
          for (std::size_t q = first[c2]; q < first[c2 + 1]; ++q) {
            if (nodes_[global[q]].side == side && nv < kMaxPointsPerWheel) v[nv++] = static_cast<int>(q);
          }
          constexpr int kN = kMaxPointsPerWheel + 1;
          double cost[kN][kN];
          for (int i = 0; i <= nu; ++i) {
            for (int j = 0; j <= nv; ++j) {
              if (i == 0 || j == 0) {
                cost[i][j] = kBranchMatch * (i + j);
                continue;
              }
              const double m = std::abs(nodes_[global[u[i - 1]]].wheel_y -
                                        nodes_[global[v[j - 1]]].wheel_y);
              cost[i][j] = std::min({cost[i - 1][j - 1] + m, cost[i - 1][j] + kBranchMatch,
                                     cost[i][j - 1] + kBranchMatch});
            }
          }
          for (int i = nu, j = nv; i > 0 && j > 0;) {
            const double m = std::abs(nodes_[global[u[i - 1]]].wheel_y -
                                      nodes_[global[v[j - 1]]].wheel_y);
            if (cost[i][j] == cost[i - 1][j - 1] + m) {
              links.push_back({m, u[i - 1], v[j - 1]});
              --i;
              --j;
            } else if (cost[i][j] == cost[i - 1][j] + kBranchMatch) {
              --i;
            } else {
              --j;
            }
          }
        };
        links.clear();
        for (int c1 = 0; c1 < n_corners; ++c1) {
          for (int b = 0; b < d; ++b) {
            if (c1 & (1 << b)) continue;
            align(c1, c1 | (1 << b), Side::left);
            align(c1, c1 | (1 << b), Side::right);
          }
        }
        // The links close into branches, the closest first; a link that would give a branch two
        // candidates at one corner is left out (the edges of a cell may disagree, more so with
        // a third axis), so every branch keeps the links it agrees with.
        std::stable_sort(links.begin(), links.end(),
                         [](const Link& x, const Link& y) { return x.cost < y.cost; });
        corner_mask.resize(parent.size());
        for (std::size_t p = 0; p < parent.size(); ++p) corner_mask[p] = 1u << corner_of[p];
        for (const Link& l : links) {
          const int ra = find(l.a), rb = find(l.b);
          if (ra == rb || (corner_mask[ra] & corner_mask[rb]) != 0u) continue;
          parent[ra] = rb;
          corner_mask[rb] |= corner_mask[ra];
        }
        // One group per root (at most one candidate per corner, by construction).
        std::vector<int> root_group(parent.size(), -1);
        for (std::size_t p = 0; p < parent.size(); ++p) {
          const int r = find(static_cast<int>(p));
          if (root_group[r] < 0) {
            root_group[r] = static_cast<int>(groups_.size());
            Group g;
            g.side = nodes_[global[p]].side;
            groups_.push_back(g);
          }
          groups_[static_cast<std::size_t>(root_group[r])].corner[corner_of[p]] = global[p];
        }
        const std::size_t cell =
            (static_cast<std::size_t>(ck) * cells[1] + cj) * cells[0] + ci;
        cell_offset_[cell + 1] = groups_.size();
      }
    }
  }
}

bool MultiPointContactTable::in_range(const WheelsetPose& pose) const {
  const std::array<double, 3> v{pose.lateral, pose.roll, pose.yaw};
  for (int a = 0; a < 3; ++a) {
    if (axes_[a].n == 1) continue;
    const double u = (v[a] - axes_[a].min) / axes_[a].step;
    if (!(u >= -1e-9 && u <= axes_[a].n - 1 + 1e-9)) return false;
  }
  return true;
}

template <class Emit>
void MultiPointContactTable::interpolate(const WheelsetPose& pose, Emit&& emit) const {
  static constexpr const char* kAxisName[3] = {"lateral shift", "roll", "yaw"};
  static constexpr const char* kAxisUnit[3] = {"m", "rad", "rad"};
  const std::array<double, 3> v{pose.lateral, pose.roll, pose.yaw};
  std::array<int, 3> cell{0, 0, 0};
  std::array<double, 3> frac{0.0, 0.0, 0.0};
  std::array<int, 3> cells{};
  int d = 0;
  std::array<int, 3> active{};
  for (int a = 0; a < 3; ++a) {
    cells[a] = std::max(axes_[a].n - 1, 1);
    if (axes_[a].n == 1) continue;  // absent axis: not looked at
    active[d++] = a;
    const double u = (v[a] - axes_[a].min) / axes_[a].step;
    if (!(u >= -1e-9 && u <= axes_[a].n - 1 + 1e-9)) {
      throw std::out_of_range(fmt::format(
          "multi-point contact table: {} {} {} outside the table's [{}, {}]", kAxisName[a], v[a],
          kAxisUnit[a], axes_[a].min, axes_[a].min + (axes_[a].n - 1) * axes_[a].step));
    }
    cell[a] = std::clamp(static_cast<int>(std::floor(u)), 0, axes_[a].n - 2);
    frac[a] = std::clamp(u - cell[a], 0.0, 1.0);
  }
  std::array<double, 8> w{};
  std::array<std::array<double, 3>, 8> offset{};  // pose - corner along each axis [m, rad, rad]
  for (int c = 0; c < (1 << d); ++c) {
    double wc = 1.0;
    for (int b = 0; b < d; ++b) {
      const int a = active[b];
      const bool upper = (c & (1 << b)) != 0;
      wc *= upper ? frac[a] : 1.0 - frac[a];
      offset[c][a] = v[a] - (axes_[a].min + (cell[a] + (upper ? 1 : 0)) * axes_[a].step);
    }
    w[c] = wc;
  }
  const std::size_t ci =
      (static_cast<std::size_t>(cell[2]) * cells[1] + cell[1]) * cells[0] + cell[0];
  for (std::size_t gi = cell_offset_[ci]; gi < cell_offset_[ci + 1]; ++gi) {
    const Group& g = groups_[gi];
    double wsum = 0.0;
    for (int c = 0; c < (1 << d); ++c) {
      if (g.corner[c] >= 0) wsum += w[c];
    }
    const double share = load_share(wsum);
    if (!(share > 0.0)) continue;  // no present corner carries weight
    // Full branch: weights w_c on g_c + (1/2) grad g_c . (q - q_c), exact for quadratics (the
    // half-gradient terms cancel for linear and bilinear parts). Partial branch: full Taylor
    // from the present corners, exact for linear functions.
    const double taylor = wsum > 1.0 - 1e-12 ? 0.5 : 1.0;
    Candidate s;  // every field 0 (the gradients stay so)
    s.side = g.side;
    double wbarrier = 0.0, barrier_shift = 0.0;
    for (int c = 0; c < (1 << d); ++c) {
      if (g.corner[c] < 0 || w[c] == 0.0) continue;
      const Candidate& q = nodes_[static_cast<std::size_t>(g.corner[c])];
      const double wc = w[c] / wsum;
      const double shift = taylor * (q.dgap_dlateral * offset[c][0] +
                                     q.dgap_droll * offset[c][1] + q.dgap_dyaw * offset[c][2]);
      s.gap += wc * (q.gap + shift);
      // A corner where the branch is its wheel's first candidate has no barrier (kNoBarrier):
      // the barrier comes from the corners that have one, with its own gradient.
      if (q.barrier < kNoBarrier) {
        const double bshift = q.dbarrier_dlateral * offset[c][0] +
                              q.dbarrier_droll * offset[c][1] + q.dbarrier_dyaw * offset[c][2];
        s.barrier += w[c] * q.barrier;
        barrier_shift += w[c] * bshift;
        wbarrier += w[c];
      }
      for (std::size_t k = kFirstWeighted; k < kEndWeighted; ++k)
        s.*kColumns[k] += wc * q.*kColumns[k];
    }
    // Half the gradient term where every corner has the barrier (exact for quadratics, as the
    // gap), the full first-order Taylor value otherwise.
    const double barrier_taylor = wbarrier > 1.0 - 1e-12 ? 0.5 : 1.0;
    s.barrier = wbarrier > 0.0 ? (s.barrier + barrier_taylor * barrier_shift) / wbarrier
                               : kNoBarrier;
    emit(s, share);
  }
}

namespace {

// Penetration of a point of vertical gap `gap` (< 0: penetrating) and load share `share`: the
// Hertz approach at which it carries share times the force of its full approach (F ~ approach^1.5
// at fixed curvatures, so approach * share^(2/3)).
double shared_penetration(double gap, double contact_angle, double share) {
  const double full = std::max(0.0, -gap * std::cos(contact_angle));
  return share < 1.0 ? full * std::cbrt(share * share) : full;
}

WheelRailContact to_contact(const MultiPointContactTable::Candidate& s, double drop,
                            double share) {
  WheelRailContact c = WheelRailContact::geometry_of(s);
  c.vertical_gap = s.gap - drop;
  c.penetration = shared_penetration(c.vertical_gap, s.contact_angle, share);
  return c;
}

}  // namespace

void MultiPointContactTable::candidates(const WheelsetPose& pose,
                                        std::vector<WheelRailContact>& out) const {
  out.clear();
  interpolate(pose, [&](const Candidate& s, double share) {
    out.push_back(to_contact(s, pose.vertical, share));
  });
  std::stable_sort(out.begin(), out.end(), [](const WheelRailContact& a, const WheelRailContact& b) {
    if (a.side != b.side) return a.side == Side::left;
    return a.wheel_y < b.wheel_y;
  });
}

void MultiPointContactTable::contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                                      ContactScratch& scratch) const {
  out.clear();
  // Interpolated candidates of the cell (at most kMaxPointsPerWheel per wheel and corner), in
  // the caller's scratch: its buffers grow once to this size and are reused from call to call.
  constexpr std::size_t kBuf = 2 * kMaxPointsPerWheel * 8;
  std::vector<WheelRailContact>& candidates = scratch.candidates;
  std::vector<RunMember>& members = scratch.members;
  if (candidates.capacity() < kBuf) {
    candidates.reserve(kBuf);
    members.reserve(kBuf);
    scratch.gaps.reserve(kBuf);
  }
  candidates.clear();
  members.clear();
  interpolate(pose, [&](const Candidate& s, double load_share) {
    if (candidates.size() < kBuf) {
      candidates.push_back(WheelRailContact::geometry_of(s));
      members.push_back({s.side, s.gap, s.barrier, load_share});
    }
  });
  // Left first, each wheel in increasing wheel_y (insertion sort: a handful of entries).
  const int n = static_cast<int>(candidates.size());
  for (int i = 1; i < n; ++i) {
    const WheelRailContact key = candidates[static_cast<std::size_t>(i)];
    const RunMember key_member = members[static_cast<std::size_t>(i)];
    int j = i - 1;
    auto before = [](const WheelRailContact& a, const WheelRailContact& b) {
      if (a.side != b.side) return a.side == Side::left;
      return a.wheel_y < b.wheel_y;
    };
    while (j >= 0 && before(key, candidates[static_cast<std::size_t>(j)])) {
      candidates[static_cast<std::size_t>(j + 1)] = candidates[static_cast<std::size_t>(j)];
      members[static_cast<std::size_t>(j + 1)] = members[static_cast<std::size_t>(j)];
      --j;
    }
    candidates[static_cast<std::size_t>(j + 1)] = key;
    members[static_cast<std::size_t>(j + 1)] = key_member;
  }
  // Penetrating candidates, joined runs sharing their depth as contacts_from_candidates().
  std::vector<double>& gaps = scratch.gaps;
  gaps.resize(candidates.size());
  share_joined_runs(members.data(), n, pose.vertical, gaps.data());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const double g = gaps[i];
    if (!(g < 0.0)) continue;
    out.push_back(candidates[i]);
    out.back().vertical_gap = g;
    out.back().penetration = shared_penetration(g, candidates[i].contact_angle, members[i].share);
  }
}

void MultiPointContactTable::save_hdf5(const std::string& path) const {
  io::H5File file = io::H5File::create(path);
  const std::array<std::pair<const char*, double>, 14> attrs{{
      {"format_version", kFormatVersion},
      {"lateral_min", axes_[0].min},
      {"lateral_step", axes_[0].step},
      {"lateral_count", static_cast<double>(axes_[0].n)},
      {"roll_min", axes_[1].min},
      {"roll_step", axes_[1].step},
      {"roll_count", static_cast<double>(axes_[1].n)},
      {"yaw_min", axes_[2].min},
      {"yaw_step", axes_[2].step},
      {"yaw_count", static_cast<double>(axes_[2].n)},
      {"max_points_per_wheel", static_cast<double>(params_.max_points_per_wheel)},
      {"capture_depth", params_.capture_depth},
      {"fingerprint_high", static_cast<double>(fingerprint_ >> 32)},
      {"fingerprint_low", static_cast<double>(fingerprint_ & 0xffffffffULL)},
  }};
  for (const auto& [name, value] : attrs) file.set_attribute("/", name, value);
  std::vector<double> offsets(node_offset_.begin(), node_offset_.end());
  file.write_array("/node_offset", offsets, {offsets.size()});
  std::vector<double> c;
  c.reserve(nodes_.size() * kFields);
  for (const Candidate& s : nodes_) {
    c.push_back(s.side == Side::right ? 1.0 : 0.0);
    for (double Candidate::*field : kColumns) c.push_back(s.*field);
  }
  file.write_array("/candidates", c, {nodes_.size(), static_cast<std::uint64_t>(kFields)});
  file.close();
}

bool MultiPointContactTable::is_table_of_another_version(const std::string& path) {
  try {
    const io::H5File file = io::H5File::open_read(path);
    return file.has_attribute("/", "format_version") && file.exists("/node_offset") &&
           file.exists("/candidates") &&
           file.number_attribute("/", "format_version") != kFormatVersion;
  } catch (const io::Hdf5Error&) {
    return false;
  }
}

MultiPointContactTable MultiPointContactTable::load_hdf5(const std::string& path) {
  const io::H5File file = io::H5File::open_input(path, "multi-point contact table");
  const auto read_attribute = [&](const std::string& name) {
    if (!file.has_attribute("/", name)) {
      throw std::invalid_argument(fmt::format("{}: missing attribute '{}'", path, name));
    }
    return file.number_attribute("/", name);
  };
  io::Dims dims;
  const auto read_dataset = [&](const std::string& name) {
    if (!file.exists(name)) {
      throw std::invalid_argument(fmt::format("{}: missing dataset '{}'", path, name));
    }
    return file.read_array(name, &dims);
  };
  if (read_attribute("format_version") != kFormatVersion) {
    throw std::invalid_argument(
        fmt::format("{}: multi-point contact table format_version must be {}", path,
                    kFormatVersion));
  }
  MultiPointContactTable t;
  const char* names[3] = {"lateral", "roll", "yaw"};
  for (int a = 0; a < 3; ++a) {
    const std::string n = names[a];
    t.axes_[a].min = read_attribute(n + "_min");
    t.axes_[a].step = read_attribute(n + "_step");
    const double count = read_attribute(n + "_count");
    if (!(count >= 1.0 && count <= 100001.0) || count != std::round(count) ||
        !(t.axes_[a].step > 0.0)) {
      throw std::invalid_argument(
          fmt::format("{}: attributes {}_count = {} / {}_step = {} invalid", path, n, count, n,
                      t.axes_[a].step));
    }
    t.axes_[a].n = static_cast<int>(count);
  }
  t.params_.lateral_min = t.axes_[0].min;
  t.params_.lateral_step = t.axes_[0].step;
  t.params_.lateral_max = t.axes_[0].min + (t.axes_[0].n - 1) * t.axes_[0].step;
  t.params_.roll_min = t.axes_[1].min;
  t.params_.roll_step = t.axes_[1].step;
  t.params_.roll_max = t.axes_[1].min + (t.axes_[1].n - 1) * t.axes_[1].step;
  t.params_.yaw_min = t.axes_[2].min;
  t.params_.yaw_step = t.axes_[2].step;
  t.params_.yaw_max = t.axes_[2].min + (t.axes_[2].n - 1) * t.axes_[2].step;
  t.params_.max_points_per_wheel =
      static_cast<int>(read_attribute("max_points_per_wheel"));
  t.params_.capture_depth = read_attribute("capture_depth");
  t.fingerprint_ = (static_cast<std::uint64_t>(read_attribute("fingerprint_high")) << 32) |
                   static_cast<std::uint64_t>(read_attribute("fingerprint_low"));
  const std::size_t n_nodes = static_cast<std::size_t>(t.axes_[0].n) * t.axes_[1].n * t.axes_[2].n;
  const std::vector<double> offsets = read_dataset("node_offset");
  if (offsets.size() != n_nodes + 1) {
    throw std::invalid_argument(fmt::format("{}: dataset 'node_offset' has {} values, expected {}",
                                            path, offsets.size(), n_nodes + 1));
  }
  if (!file.exists("candidates")) {
    throw std::invalid_argument(fmt::format("{}: missing dataset 'candidates'", path));
  }
  dims = file.dimensions("candidates");
  if (dims.size() != 2 || dims[1] != static_cast<std::uint64_t>(kFields)) {
    throw std::invalid_argument(
        fmt::format("{}: dataset 'candidates' must be [n x {}]", path, kFields));
  }
  t.node_offset_.resize(n_nodes + 1);
  for (std::size_t i = 0; i <= n_nodes; ++i) {
    const double o = offsets[i];
    if (!(o >= 0.0 && o <= static_cast<double>(dims[0])) || (i > 0 && o < offsets[i - 1]) ||
        (i == n_nodes && o != static_cast<double>(dims[0])) ||
        (i + 1 < offsets.size() &&
         offsets[i + 1] - o > 2.0 * kMaxPointsPerWheel)) {
      throw std::invalid_argument(
          fmt::format("{}: dataset 'node_offset' is not a valid offset list at {}", path, i));
    }
    t.node_offset_[i] = static_cast<std::size_t>(o);
  }
  // By blocks of rows: the file's rows are not held beside the candidates made of them.
  t.nodes_.resize(dims[0]);
  constexpr std::size_t kBlockRows = 8192;
  std::vector<double> block;
  for (std::size_t first = 0; first < dims[0]; first += kBlockRows) {
    const std::size_t rows = std::min<std::size_t>(kBlockRows, dims[0] - first);
    block.resize(rows * kFields);
    file.read_rows("candidates", first, rows, block);
    for (std::size_t i = first; i < first + rows; ++i) {
      const double* r = block.data() + (i - first) * kFields;
      for (int f = 0; f < kFields; ++f) {
        if (!std::isfinite(r[f])) {
          throw std::invalid_argument(fmt::format(
              "{}: dataset 'candidates' row {} column {} is not finite", path, i, f));
        }
      }
      Candidate& s = t.nodes_[i];
      s.side = r[0] == 1.0 ? Side::right : Side::left;
      for (std::size_t k = 0; k < kColumns.size(); ++k) s.*kColumns[k] = r[k + 1];
    }
  }
  t.finish();
  return t;
}

}  // namespace ferro::contact
