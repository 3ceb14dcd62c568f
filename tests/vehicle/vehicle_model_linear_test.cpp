// Linearisations of the multibody VehicleModel against independent linear models:
//  - single suspended wheelset (lateral + yaw, kinematic cone, linear creep): the eigenvalue
//    critical speed against the closed form of Toumi eq. (151);
//  - one two-axle bogie (lateral + yaw of frame and wheelsets, the car body at rest): the
//    eigenvalues against the textbook linear bogie equations (Wickens 2003 ch. 2) written out
//    here as a 12x12 state matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "conical_test_source.hpp"
#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/vehicle/stability.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle {
namespace {

using testing::ConicalTestParams;
using testing::ConicalTestSource;

constexpr double kG = 9.81;

/// Linear creep data shared by the model and the oracle: Hertz patch at the static wheel load,
/// Kalker's C11 and C22 brought to the smaller of the two by K11 = Cmin/C11 and K22 = Cmin/C22
/// (reduction factors stay in (0, 1]; f11 = f22 as eq. 150 assumes), K23 = K33 ~ 0 drops spin.
struct LinearCreep {
  double penetration = 0.0;  // Hertz approach at the wheel load [m]
  double f = 0.0;            // f11 = f22 = G a b min(C11, C22) [N]
  contact::ReductionFactors reduction;
};

LinearCreep linear_creep(double wheel_load, double A, double B) {
  const contact::Material steel = contact::Material::steel();
  const auto mat = contact::combine(steel, steel);
  const auto h = contact::hertz_solve(A, B, wheel_load, mat.contact_modulus);
  const auto c = contact::kalker_coefficients_table(h.semi_axis_x, h.semi_axis_y, mat.poisson);
  LinearCreep lc;
  lc.penetration = h.approach;
  const double c_min = std::min(c.c11, c.c22);
  lc.f = mat.shear_modulus * h.semi_axis_x * h.semi_axis_y * c_min;
  // The spin coefficients must be positive for the contact layer; 1e-9 removes spin's effect
  // far below the tolerances here.
  lc.reduction = {c_min / c.c11, c_min / c.c22, 1e-9, 1e-9};
  return lc;
}

RigidBodySpec wheelset_body(const std::string& name, double x, double m, double e, double r0) {
  RigidBodySpec w;
  w.name = name;
  w.kind = BodyKind::wheelset;
  w.mass = m;
  w.inertia = {m * e * e, 0.1 * m * r0 * r0, m * e * e};
  w.position = {x, 0.0, r0};
  w.nominal_rolling_radius = r0;
  return w;
}

SuspensionElementSpec spring(const std::string& name, int a, int b, Eigen::Vector3d pa,
                             Eigen::Vector3d pb, Eigen::Vector3d k) {
  SuspensionElementSpec s;
  s.name = name;
  s.type = ElementType::spring_damper;
  s.body_a = a;
  s.body_b = b;
  s.point_a = pa;
  s.point_b = pb;
  s.stiffness = k;
  return s;
}

// --- single wheelset -------------------------------------------------------------------------

struct WheelsetCase {
  double m, e, r0, gamma, kx, ky, A, B;
};

/// The same wheelset as the linear model of eq. (151) (I_zz = m e^2).
SuspendedWheelsetParams oracle_params(const WheelsetCase& c) {
  SuspendedWheelsetParams p;
  p.mass = c.m;
  p.yaw_inertia = c.m * c.e * c.e;
  p.half_gauge = c.e;
  p.rolling_radius = c.r0;
  p.conicity = c.gamma;
  p.primary_stiffness_x = c.kx;
  p.primary_stiffness_y = c.ky;
  return p;
}

VehicleModelInputs single_wheelset(const WheelsetCase& c, double speed, LinearCreep& lc) {
  lc = linear_creep(0.5 * c.m * kG, c.A, c.B);
  VehicleModelInputs in;
  RigidBodySpec w = wheelset_body("wheelset_1", 0.0, c.m, c.e, c.r0);
  w.active = {false, true, false, false, false, true};  // lateral + yaw
  in.config.bodies.push_back(w);
  for (double side : {1.0, -1.0}) {
    in.config.elements.push_back(spring("primary", -1, 0, {0.0, side * c.e, c.r0},
                                        {0.0, side * c.e, 0.0}, {c.kx, c.ky, 0.0}));
  }
  in.config.wheel_rail.tangential_model = "kalker_linear";
  in.config.wheel_rail.reduction = lc.reduction;
  in.config.gravity = kG;
  in.selection.scope = "wheelset";
  ConicalTestParams g;
  g.conicity = c.gamma;
  g.half_distance = c.e;
  g.nominal_radius = c.r0;
  g.curvature_a = c.A;
  g.curvature_b = c.B;
  g.rail_raise = lc.penetration;  // the frozen vertical position carries the wheel load
  in.geometry = std::make_shared<ConicalTestSource>(g);
  in.speed.initial = speed;
  return in;
}

TEST(VehicleModelLinear, single_wheelset_reproduces_critical_speed_of_eq_151) {
  // The model and eq. (151) describe the same linear system (kinematic cone, f11 = f22, no spin,
  // I_zz = m e^2, no damping); what separates them is the central-difference Jacobian of the
  // nonlinear rhs (relative steps 1e-7 around a creepage-free state) and the bisection width.
  // The issue asks for 1 %; we hold 1e-4.
  constexpr double kRelTol = 1e-4;
  const WheelsetCase cases[] = {{1813.0, 0.75, 0.46, 0.20, 0.8e6, 0.8e6, 1.087, 1.0},
                                {1500.0, 0.75, 0.50, 0.15, 1.5e6, 0.6e6, 1.0, 3.0}};
  for (const WheelsetCase& c : cases) {
    LinearCreep lc;
    (void)single_wheelset(c, 10.0, lc);
    const SuspendedWheelsetParams p = oracle_params(c);
    const double v_formula = analytic_critical_speed(p, CreepCoefficients{lc.f, lc.f});
    ASSERT_TRUE(std::isfinite(v_formula));
    const SystemAtSpeed factory = [&c](double v) {
      LinearCreep unused;
      return std::make_unique<VehicleModel>(single_wheelset(c, v, unused));
    };
    const std::vector<double> x0(4, 0.0);
    const auto vc = critical_speed(factory, 0.2 * v_formula, 3.0 * v_formula, x0, 64, 1e-9);
    ASSERT_TRUE(vc.has_value());
    EXPECT_NEAR(*vc / v_formula, 1.0, kRelTol) << "formula " << v_formula << " m/s";
    std::printf("single wheelset: eq. (151) %.6f m/s, eigenvalues %.6f m/s, rel. error %.2e\n",
                v_formula, *vc, *vc / v_formula - 1.0);
  }
}

TEST(VehicleModelLinear, kij_table_in_the_rhs_scales_the_critical_speed_as_eq_151) {
  // A K_ij table over the wheel load (taken from each contact patch) and a layer thickness
  // (fixed by the scene), separable K = K(F) g(h): at the cell centre multilinear interpolation
  // gives mean K x mean g = 0.7 x 0.75. Eq. (151) with f11 = f22 = 0.525 f is the oracle; same
  // tolerance as the constant-K case above.
  constexpr double kRelTol = 1e-4;
  constexpr double kExpectedK = 0.7 * 0.75;
  // Kx != Ky: with equal stiffnesses eq. (151) does not depend on f.
  const WheelsetCase c{1500.0, 0.75, 0.50, 0.15, 1.5e6, 0.6e6, 1.0, 3.0};
  LinearCreep lc;
  (void)single_wheelset(c, 10.0, lc);
  const double f0 = 0.5 * c.m * kG;  // static wheel load
  const std::vector<double> loads{0.5 * f0, 1.5 * f0}, layers{0.0, 1.0e-4};
  const double k_load[2] = {0.6, 0.8}, g_layer[2] = {1.0, 0.5};
  std::vector<double> k11, k22, k23, k33;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double k = k_load[i] * g_layer[j];
      k11.push_back(k * lc.reduction.k11);
      k22.push_back(k * lc.reduction.k22);
      k23.push_back(lc.reduction.k23);
      k33.push_back(lc.reduction.k33);
    }
  }
  const std::string path = ::testing::TempDir() + "vehicle_kij_table.h5";
  contact::KijTable({"normal_force", "layer_thickness"}, {loads, layers}, k11, k22, k23, k33)
      .write_hdf5(path);

  const SuspendedWheelsetParams p = oracle_params(c);
  const double f = kExpectedK * lc.f;
  const double v_formula = analytic_critical_speed(p, CreepCoefficients{f, f});
  ASSERT_TRUE(std::isfinite(v_formula));
  const SystemAtSpeed factory = [&](double v) {
    LinearCreep unused;
    VehicleModelInputs in = single_wheelset(c, v, unused);
    in.config.wheel_rail.reduction_table = path;
    in.config.wheel_rail.reduction_table_point = {{"layer_thickness", 0.5e-4}};
    return std::make_unique<VehicleModel>(std::move(in));
  };
  const std::vector<double> x0(4, 0.0);
  const auto vc = critical_speed(factory, 0.2 * v_formula, 3.0 * v_formula, x0, 64, 1e-9);
  ASSERT_TRUE(vc.has_value());
  EXPECT_NEAR(*vc / v_formula, 1.0, kRelTol) << "formula " << v_formula << " m/s";
  const double v_k1 = analytic_critical_speed(p, CreepCoefficients{lc.f, lc.f});
  std::printf("single wheelset, K_ij table: eq. (151) %.6f m/s (K = 1: %.6f), eigenvalues %.6f "
              "m/s\n",
              v_formula, v_k1, *vc);
  EXPECT_GT(std::abs(v_formula / v_k1 - 1.0), 0.1);  // the table matters here

  // The table's other axes must be given; unknown names are refused.
  LinearCreep unused;
  VehicleModelInputs missing = single_wheelset(c, 10.0, unused);
  missing.config.wheel_rail.reduction_table = path;
  EXPECT_THROW({ VehicleModel m(std::move(missing)); }, std::invalid_argument);
  VehicleModelInputs unknown = single_wheelset(c, 10.0, unused);
  unknown.config.wheel_rail.reduction_table = path;
  unknown.config.wheel_rail.reduction_table_point = {{"layer_thickness", 0.0}, {"tau", 1.0}};
  EXPECT_THROW({ VehicleModel m(std::move(unknown)); }, std::invalid_argument);
}

// --- one bogie -------------------------------------------------------------------------------

struct BogieData {
  double mw = 1813.0, iw = 1120.0, r0 = 0.46, e = 0.7465, gamma = 0.15;
  double mb = 2615.0, ib = 3067.0, a = 1.28;        // frame mass, yaw inertia, semi-wheelbase
  double kx = 31.391e6, ky = 3.884e6, d = 1.0;      // primary per axlebox, lateral semi-spacing
  double cx = 0.0, cy = 2.0e3;                      // primary damping per axlebox
  double ksy = 160.0e3, ds = 1.0, kpsi = 2 * 10.5e3;  // secondary lateral per side, yaw
  double csy = 32.0e3;                              // secondary lateral damping per side
  double A = 1.087, B = 1.0;
};

VehicleModelInputs bogie_inputs(const BogieData& b, double speed, LinearCreep& lc) {
  const double car_mass = 32000.0;
  lc = linear_creep(0.5 * kG * (b.mw + 0.5 * b.mb + 0.25 * car_mass), b.A, b.B);
  VehicleModelInputs in;
  RigidBodySpec car;
  car.name = "car_body";
  car.kind = BodyKind::car_body;
  car.mass = car_mass;
  car.inertia = {56800.0, 1.97e6, 1.97e6};
  car.position = {0.0, 0.0, 1.8};
  RigidBodySpec frame;
  frame.name = "bogie_1";
  frame.kind = BodyKind::bogie_frame;
  frame.mass = b.mb;
  frame.inertia = {1722.0, 1476.0, b.ib};
  frame.position = {9.5, 0.0, 0.6};
  frame.active = {false, true, false, false, false, true};
  in.config.bodies = {car, frame};
  for (int j = 0; j < 2; ++j) {
    RigidBodySpec w = wheelset_body(j == 0 ? "wheelset_1" : "wheelset_2",
                                    9.5 + (j == 0 ? b.a : -b.a), b.mw, b.e, b.r0);
    w.inertia.z() = b.iw;
    w.active = {false, true, false, false, false, true};
    in.config.bodies.push_back(w);
  }
  for (int j = 0; j < 2; ++j) {
    const double xj = j == 0 ? b.a : -b.a;
    for (double side : {1.0, -1.0}) {
      auto s = spring("primary", 1, 2 + j, {xj, side * b.d, b.r0 - 0.6}, {0.0, side * b.d, 0.0},
                      {b.kx, b.ky, 0.0});
      s.damping = {b.cx, b.cy, 0.0};
      in.config.elements.push_back(s);
    }
  }
  for (double side : {1.0, -1.0}) {
    auto s = spring("secondary", 0, 1, {9.5, side * b.ds, 0.8 - 1.8}, {0.0, side * b.ds, 0.2},
                    {0.0, b.ksy, 0.0});
    s.damping = {0.0, b.csy, 0.0};
    in.config.elements.push_back(s);
  }
  SuspensionElementSpec yaw;
  yaw.name = "bogie_yaw";
  yaw.type = ElementType::torsion;
  yaw.axis = Dof::yaw;
  yaw.body_a = 0;
  yaw.body_b = 1;
  yaw.k = b.kpsi;
  in.config.elements.push_back(yaw);
  in.config.wheel_rail.tangential_model = "kalker_linear";
  in.config.wheel_rail.reduction = lc.reduction;
  in.config.gravity = kG;
  in.selection.scope = "bogie";
  ConicalTestParams g;
  g.conicity = b.gamma;
  g.half_distance = b.e;
  g.nominal_radius = b.r0;
  g.curvature_a = b.A;
  g.curvature_b = b.B;
  g.rail_raise = lc.penetration;
  in.geometry = std::make_shared<ConicalTestSource>(g);
  in.speed.initial = speed;
  return in;
}

/// Textbook linear bogie, states [y1 psi1 y2 psi2 yb psib] and their rates (Wickens ch. 2):
///   m_w y_j'' = -2 f (y_j'/V - psi_j) - 2 k_y (y_j - y_b - x_j psi_b) - 2 c_y (rates)
///   I_w psi_j'' = -2 f e (e psi_j'/V + gamma y_j / r0) - 2 d^2 (k_x (psi_j - psi_b) + c_x rates)
///   m_b y_b'' = sum_j 2 k_y (y_j - y_b - x_j psi_b) + ... - 2 k_sy y_b - 2 c_sy y_b'
///   I_b psi_b'' = sum_j [2 x_j k_y (...) + 2 d^2 k_x (psi_j - psi_b)] - k_psi psi_b
Eigen::MatrixXd textbook_bogie(const BogieData& b, double f, double V) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6), C = Eigen::MatrixXd::Zero(6, 6);
  Eigen::VectorXd M(6);
  M << b.mw, b.iw, b.mw, b.iw, b.mb, b.ib;
  const double xs[2] = {b.a, -b.a};
  // Primary lateral between wheelset j and the frame point at x_j: deflection
  // q = y_j - y_b - x_j psi_b; generalised forces -2 k q on y_j, +2 k q on y_b, +2 k x_j q on
  // psi_b. Same for the damper with rates.
  for (int j = 0; j < 2; ++j) {
    const int y = 2 * j, p = 2 * j + 1;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(6);  // dq/dstates
    g[y] = 1.0;
    g[4] = -1.0;
    g[5] = -xs[j];
    K += 2.0 * b.ky * g * g.transpose();
    C += 2.0 * b.cy * g * g.transpose();
    Eigen::VectorXd h = Eigen::VectorXd::Zero(6);  // relative yaw psi_j - psi_b
    h[p] = 1.0;
    h[5] = -1.0;
    K += 2.0 * b.d * b.d * b.kx * h * h.transpose();
    C += 2.0 * b.d * b.d * b.cx * h * h.transpose();
    // Creep: lateral -2f (y'/V - psi), yaw -2 f e (e psi'/V + gamma y / r0).
    C(y, y) += 2.0 * f / V;
    K(y, p) += -2.0 * f;
    C(p, p) += 2.0 * f * b.e * b.e / V;
    K(p, y) += 2.0 * f * b.e * b.gamma / b.r0;
  }
  K(4, 4) += 2.0 * b.ksy;
  C(4, 4) += 2.0 * b.csy;
  K(5, 5) += b.kpsi;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(12, 12);
  A.topRightCorner(6, 6).setIdentity();
  A.bottomLeftCorner(6, 6) = -(M.cwiseInverse().asDiagonal() * K);
  A.bottomRightCorner(6, 6) = -(M.cwiseInverse().asDiagonal() * C);
  return A;
}

TEST(VehicleModelLinear, bogie_eigenvalues_match_the_textbook_linear_bogie) {
  // Same linear system written twice: the residual error is the central-difference Jacobian of
  // the multibody rhs (relative step 1e-7, creepage-free state) and second-order geometry
  // (exact attitude rotation). The issue asks for 1 %; we hold 1e-4 of |lambda|.
  constexpr double kRelTol = 1e-4;
  BogieData b;
  for (double V : {20.0, 55.0}) {
    LinearCreep lc;
    const VehicleModel model(bogie_inputs(b, V, lc));
    ASSERT_EQ(model.size(), 12u);
    const auto modes = linear_modes(model, 0.0, model.rest_state());
    Eigen::EigenSolver<Eigen::MatrixXd> es(textbook_bogie(b, lc.f, V), false);
    std::vector<std::complex<double>> ours, ref;
    for (const Mode& m : modes) ours.push_back(m.eigenvalue);
    for (Eigen::Index i = 0; i < 12; ++i) ref.push_back(es.eigenvalues()[i]);
    ASSERT_EQ(ours.size(), ref.size());
    // Match every reference eigenvalue to its nearest model eigenvalue.
    double worst = 0.0;
    for (const auto& r : ref) {
      double best = 1e300;
      for (const auto& o : ours) best = std::min(best, std::abs(o - r));
      EXPECT_LT(best / std::abs(r), kRelTol) << "V = " << V << " lambda_ref = " << r;
      worst = std::max(worst, best / std::abs(r));
    }
    std::printf("bogie at %.0f m/s: largest |lambda - lambda_ref| / |lambda_ref| = %.2e\n", V,
                worst);
  }
}

}  // namespace
}  // namespace ferro::vehicle
