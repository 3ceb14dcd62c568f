#include "ferro/contact/tangential/kalker_coefficients.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ferro::contact {
namespace {

// Annex A.2 (Kalker 1967). Rows 0-9: a/b = 0.1 ... 1.0; rows 10-18: b/a = 0.9 ... 0.1.
// Columns: nu = 0, 1/4, 1/2.
constexpr int kRows = 19;
using Column3 = std::array<double, 3>;
constexpr std::array<Column3, kRows> kC11 = {{{2.51, 3.31, 4.85},
                                              {2.59, 3.37, 4.81},
                                              {2.68, 3.44, 4.80},
                                              {2.78, 3.53, 4.82},
                                              {2.88, 3.62, 4.83},
                                              {2.98, 3.72, 4.91},
                                              {3.09, 3.81, 4.97},
                                              {3.19, 3.91, 5.05},
                                              {3.29, 4.01, 5.12},
                                              {3.40, 4.12, 5.20},
                                              {3.51, 4.22, 5.30},
                                              {3.65, 4.36, 5.42},
                                              {3.82, 4.54, 5.58},
                                              {4.06, 4.78, 5.80},
                                              {4.37, 5.10, 6.11},
                                              {4.84, 5.57, 6.57},
                                              {5.57, 6.34, 7.34},
                                              {6.96, 7.78, 8.82},
                                              {10.7, 11.7, 12.9}}};
constexpr std::array<Column3, kRows> kC22 = {{{2.51, 2.52, 2.53},
                                              {2.59, 2.63, 2.66},
                                              {2.68, 2.75, 2.81},
                                              {2.78, 2.88, 2.98},
                                              {2.88, 3.01, 3.14},
                                              {2.98, 3.14, 3.31},
                                              {3.09, 3.28, 3.48},
                                              {3.19, 3.41, 3.65},
                                              {3.29, 3.54, 3.82},
                                              {3.40, 3.67, 3.98},
                                              {3.51, 3.81, 4.16},
                                              {3.65, 3.99, 4.39},
                                              {3.82, 4.21, 4.67},
                                              {4.06, 4.50, 5.04},
                                              {4.37, 4.90, 5.56},
                                              {4.84, 5.48, 6.31},
                                              {5.57, 6.40, 7.51},
                                              {6.96, 8.14, 9.79},
                                              {10.7, 12.8, 16.0}}};
constexpr std::array<Column3, kRows> kC23 = {{{0.334, 0.473, 0.731},
                                              {0.483, 0.603, 0.809},
                                              {0.607, 0.715, 0.889},
                                              {0.720, 0.823, 0.977},
                                              {0.827, 0.929, 1.07},
                                              {0.930, 1.03, 1.18},
                                              {1.03, 1.14, 1.29},
                                              {1.13, 1.25, 1.40},
                                              {1.23, 1.36, 1.51},
                                              {1.33, 1.47, 1.63},
                                              {1.44, 1.59, 1.77},
                                              {1.58, 1.75, 1.94},
                                              {1.76, 1.95, 2.18},
                                              {2.01, 2.23, 2.50},
                                              {2.35, 2.62, 2.96},
                                              {2.88, 3.24, 3.70},
                                              {3.79, 4.32, 5.01},
                                              {5.72, 6.63, 7.89},
                                              {12.2, 14.6, 18.0}}};
constexpr std::array<Column3, kRows> kC33 = {{{6.42, 8.28, 11.7},
                                              {3.46, 4.27, 5.66},
                                              {2.49, 2.96, 3.72},
                                              {2.02, 2.32, 2.77},
                                              {1.74, 1.93, 2.22},
                                              {1.56, 1.68, 1.86},
                                              {1.43, 1.50, 1.60},
                                              {1.34, 1.37, 1.42},
                                              {1.27, 1.27, 1.27},
                                              {1.21, 1.19, 1.16},
                                              {1.16, 1.11, 1.06},
                                              {1.10, 1.04, 0.954},
                                              {1.05, 0.965, 0.852},
                                              {1.01, 0.892, 0.751},
                                              {0.958, 0.819, 0.650},
                                              {0.912, 0.747, 0.549},
                                              {0.868, 0.674, 0.446},
                                              {0.828, 0.601, 0.341},
                                              {0.795, 0.526, 0.228}}};

// Ellipse parameter of row i: a/b for rows 0-9, 2 - b/a for rows 10-18 (so it increases).
constexpr double row_parameter(int i) {
  return i <= 9 ? 0.1 * (i + 1) : 2.0 - 0.1 * (18 - i + 1);
}
constexpr std::array<double, kRows> kRowParameter = [] {
  std::array<double, kRows> r{};
  for (int i = 0; i < kRows; ++i) r[static_cast<std::size_t>(i)] = row_parameter(i);
  return r;
}();

// Quadratic Lagrange weights in nu through the nodes 0, 1/4, 1/2.
struct PoissonWeights {
  double l0 = 0.0, l1 = 0.0, l2 = 0.0;
};

PoissonWeights poisson_weights(double nu) {
  constexpr double n0 = 0.0, n1 = 0.25, n2 = 0.5;
  return {(nu - n1) * (nu - n2) / ((n0 - n1) * (n0 - n2)),
          (nu - n0) * (nu - n2) / ((n1 - n0) * (n1 - n2)),
          (nu - n0) * (nu - n1) / ((n2 - n0) * (n2 - n1))};
}

double in_poisson(const Column3& c, const PoissonWeights& l) {
  return l.l0 * c[0] + l.l1 * c[1] + l.l2 * c[2];
}

// Where the ellipse parameter t and nu fall in the table, found once for the four coefficients.
struct TablePoint {
  double t = 0.0, nu = 0.0;
  PoissonWeights poisson;
  bool below = false;    ///< t below the first row: the asymptotes
  bool between = false;  ///< t between rows `row` and `row + 1`, weight w on the latter
  int row = 0;           ///< otherwise the row t lies on (or is clamped to)
  double w = 0.0;
};

TablePoint table_point(double t, double nu) {
  TablePoint p;
  p.t = t;
  p.nu = nu;
  p.poisson = poisson_weights(nu);
  if (t < kRowParameter[0]) {
    p.below = true;
  } else if (t >= kRowParameter[kRows - 1]) {
    p.row = kRows - 1;
  } else if (t > kRowParameter[0]) {
    int i = 0;
    while (i < kRows - 2 && t > kRowParameter[static_cast<std::size_t>(i + 1)]) ++i;
    const double t0 = kRowParameter[static_cast<std::size_t>(i)];
    const double t1 = kRowParameter[static_cast<std::size_t>(i + 1)];
    p.between = true;
    p.row = i;
    p.w = (t - t0) / (t1 - t0);
  }
  return p;
}

// Below a/b = 0.1: Kalker's g -> 0 asymptotes (annex A.2 first row), see the header.
enum class Coef { k11, k22, k23, k33 };
double below_table(const std::array<Column3, kRows>& table, Coef which, double g, double nu,
                   const PoissonWeights& poisson) {
  constexpr double kPi2 = 9.869604401089358;  // pi^2
  constexpr double g1 = 0.1;
  const double node = in_poisson(table[0], poisson);
  switch (which) {
    case Coef::k11: {
      const double lim = kPi2 / (4.0 * (1.0 - nu));
      return lim + (node - lim) * g / g1;
    }
    case Coef::k22: {
      const double lim = kPi2 / 4.0;
      return lim + (node - lim) * g / g1;
    }
    case Coef::k23:
      return node * std::sqrt(g / g1);
    case Coef::k33: {
      const double lim = kPi2 / (16.0 * (1.0 - nu));
      return (lim + (g1 * node - lim) * g / g1) / g;
    }
  }
  return node;
}

double lookup(const std::array<Column3, kRows>& table, Coef which, const TablePoint& p) {
  if (p.below) return below_table(table, which, p.t, p.nu, p.poisson);
  const auto row = static_cast<std::size_t>(p.row);
  if (!p.between) return in_poisson(table[row], p.poisson);
  return (1.0 - p.w) * in_poisson(table[row], p.poisson) +
         p.w * in_poisson(table[row + 1], p.poisson);
}

}  // namespace

KalkerCoefficients kalker_coefficients_table(double a, double b, double poisson) {
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
    throw std::invalid_argument(
        fmt::format("kalker_coefficients_table: semi-axes must be positive, got a={}, b={}", a, b));
  }
  if (!(poisson >= 0.0 && poisson <= 0.5)) {
    throw std::invalid_argument(
        fmt::format("kalker_coefficients_table: poisson must lie in [0, 0.5], got {}", poisson));
  }
  const TablePoint p = table_point(a <= b ? a / b : 2.0 - b / a, poisson);
  return KalkerCoefficients{lookup(kC11, Coef::k11, p), lookup(kC22, Coef::k22, p),
                            lookup(kC23, Coef::k23, p), lookup(kC33, Coef::k33, p)};
}

KalkerCoefficients kalker_coefficients_voco_fit(double curvature_ratio) {
  const double x = curvature_ratio;
  if (!(x > 0.0) || !std::isfinite(x)) {
    throw std::invalid_argument(fmt::format(
        "kalker_coefficients_voco_fit: curvature ratio X = A/B must be finite and > 0, got {}", x));
  }
  KalkerCoefficients c;
  c.c11 = 3.3 + 0.89 / (0.085 + x);
  c.c22 = 2.46 + 1.34 / (0.109 + x);
  c.c23 = 0.18 + 1.29 / std::pow(0.002 + x, 0.63);
  c.c33 = std::numeric_limits<double>::quiet_NaN();
  return c;
}

CoefficientSource coefficient_source_from_name(const std::string& name) {
  if (name == "kalker_table") return CoefficientSource::kKalkerTable;
  if (name == "voco_fit") return CoefficientSource::kVocoFit;
  throw std::invalid_argument(
      fmt::format("coefficients: unknown source '{}'; allowed: kalker_table, voco_fit", name));
}

const char* coefficient_source_name(CoefficientSource source) {
  return source == CoefficientSource::kVocoFit ? "voco_fit" : "kalker_table";
}

KalkerCoefficients kalker_coefficients(CoefficientSource source, double a, double b, double poisson,
                                       double curvature_ratio) {
  KalkerCoefficients c = kalker_coefficients_table(a, b, poisson);
  if (source == CoefficientSource::kVocoFit) {
    const KalkerCoefficients fit = kalker_coefficients_voco_fit(curvature_ratio);
    c.c11 = fit.c11;
    c.c22 = fit.c22;
    c.c23 = fit.c23;
  }
  return c;
}

}  // namespace ferro::contact
