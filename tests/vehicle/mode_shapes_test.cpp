// Mode shapes and classes (stability.hpp) against closed forms.
//  - Two masses in series, a wheelset on the contact stiffness over a rail mass on its pad: the
//    undamped modes of M x'' + K x = 0 are known in closed form (generalised eigenproblem), and
//    each mode's kinetic-energy shares m_i phi_i^2 / sum m_j phi_j^2 must be what
//    linear_modes() reports; the mode the rail carries is a track mode, the other the
//    wheelset's contact mode.
//  - The grouping of state names and the fallback for states whose mass is unknown.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ferro/vehicle/stability.hpp"

namespace ferro::vehicle {
namespace {

// Wheelset (mass m_w) on a contact spring k_c over a rail (mass m_r) on a pad k_p to the ground,
// vertical only. States: wheelset_1.z, track.rail_1.z, their rates.
class WheelsetOnRail final : public OdeSystem {
 public:
  static constexpr double kMw = 1813.0;   // Manchester vehicle 1 wheelset [kg]
  static constexpr double kMr = 170.0;    // effective rail mass per wheel [kg]
  static constexpr double kKc = 1.4e9;    // linearised Hertz stiffness, two wheels [N/m]
  static constexpr double kKp = 2.0e8;    // pad [N/m]
  [[nodiscard]] std::size_t size() const override { return 4; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    const double f_contact = kKc * (x[1] - x[0]);
    xd[0] = x[2];
    xd[1] = x[3];
    xd[2] = f_contact / kMw;
    xd[3] = (-f_contact - kKp * x[1]) / kMr;
    return kRhsOk;
  }
  [[nodiscard]] std::vector<SignalInfo> state_info() const override {
    return {{"wheelset_1.z", "m", ""},
            {"track.rail_1.z", "m", ""},
            {"wheelset_1.z_dot", "m/s", ""},
            {"track.rail_1.z_dot", "m/s", ""}};
  }
};

TEST(ModeShapes, two_masses_in_series_have_the_closed_form_energy_shares) {
  const WheelsetOnRail sys;
  const auto shapes = mode_shape_input(sys.state_info(), [](const std::string& body,
                                                            const std::string& dof) {
    EXPECT_EQ(dof, "z");
    return body == "wheelset_1" ? WheelsetOnRail::kMw : WheelsetOnRail::kMr;
  });
  ASSERT_EQ(shapes.group[2], DofGroup::wheelset_vertical_roll);
  ASSERT_EQ(shapes.group[3], DofGroup::track);
  EXPECT_EQ(shapes.group[0], DofGroup::none);
  const std::vector<double> x0(4, 0.0);
  const auto modes = linear_modes(sys, 0.0, x0, shapes);
  ASSERT_EQ(modes.size(), 4u);  // two undamped pairs
  // Closed form: det(K - w^2 M) = 0 with K = [[kc, -kc], [-kc, kc + kp]], M = diag(mw, mr);
  // mode shape (1, r) with r = (kc - w^2 mw) / kc.
  const double a = WheelsetOnRail::kMw * WheelsetOnRail::kMr;
  const double b = -(WheelsetOnRail::kKc * WheelsetOnRail::kMr +
                     (WheelsetOnRail::kKc + WheelsetOnRail::kKp) * WheelsetOnRail::kMw);
  const double c = WheelsetOnRail::kKc * WheelsetOnRail::kKp;
  for (const double sign : {-1.0, 1.0}) {
    const double w2 = (-b + sign * std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    const double r = (WheelsetOnRail::kKc - w2 * WheelsetOnRail::kMw) / WheelsetOnRail::kKc;
    const double e_w = WheelsetOnRail::kMw, e_r = WheelsetOnRail::kMr * r * r;
    const double share_wheelset = e_w / (e_w + e_r);
    const double f = std::sqrt(w2) / (2.0 * std::numbers::pi);
    const Mode* found = nullptr;
    for (const Mode& m : modes)
      if (std::abs(m.frequency_hz - f) < 1e-4 * f && m.eigenvalue.imag() > 0.0) found = &m;
    ASSERT_NE(found, nullptr) << "no mode at " << f << " Hz";
    // The Jacobian is a central difference of an exactly linear right-hand side: round-off.
    constexpr double kShareTol = 1e-6;
    EXPECT_NEAR(found->participation[static_cast<std::size_t>(DofGroup::wheelset_vertical_roll)],
                share_wheelset, kShareTol)
        << f << " Hz";
    EXPECT_NEAR(found->participation[static_cast<std::size_t>(DofGroup::track)],
                1.0 - share_wheelset, kShareTol)
        << f << " Hz";
    // The low mode moves the wheelset with the rail on the pad (wheelset energy dominant), the
    // high one the rail against the wheelset (rail energy dominant).
    EXPECT_EQ(found->kind, share_wheelset >= 0.5 ? ModeClass::contact : ModeClass::track)
        << f << " Hz, wheelset share " << share_wheelset;
    std::printf("[ figures  ] %.2f Hz: wheelset share %.6f (closed form %.6f), %s\n", f,
                found->participation[1], share_wheelset, to_string(found->kind));
  }
}

TEST(ModeShapes, state_names_give_the_groups_and_unknown_masses_the_median) {
  const std::vector<SignalInfo> states = {
      {"wheelset_2.y", "m", ""},          {"wheelset_2.y_dot", "m/s", ""},
      {"wheelset_2.yaw_dot", "rad/s", ""}, {"wheelset_2.roll_dot", "rad/s", ""},
      {"wheelset_2.spin", "rad/s", ""},   {"wheelset_2.x_dot", "m/s", ""},
      {"bogie_1.yaw_dot", "rad/s", ""},   {"bogie_1.pitch_dot", "rad/s", ""},
      {"car_body.y_dot", "m/s", ""},      {"car_body.z_dot", "m/s", ""},
      {"track.sleeper_3.z_dot", "m/s", ""}, {"secondary.bogie_1.yaw_damper.damper_deflection", "m", ""}};
  const auto in = mode_shape_input(states, [](const std::string& body, const std::string& dof) -> double {
    if (body.rfind("track.", 0) == 0) return NAN;  // a structure without stated masses
    return dof == "y" ? 1.0 : dof == "yaw" ? 2.0 : dof == "roll" ? 3.0 : 4.0;
  });
  const std::vector<DofGroup> expected = {
      DofGroup::none,          DofGroup::wheelset_lateral_yaw,   DofGroup::wheelset_lateral_yaw,
      DofGroup::wheelset_vertical_roll, DofGroup::wheelset_longitudinal_spin,
      DofGroup::wheelset_longitudinal_spin, DofGroup::frame_lateral, DofGroup::frame_vertical,
      DofGroup::carbody_lateral, DofGroup::carbody_vertical, DofGroup::track, DofGroup::none};
  for (std::size_t i = 0; i < states.size(); ++i)
    EXPECT_EQ(in.group[i], expected[i]) << states[i].name;
  // Known weights 1, 2, 3, 4, 4, 2, 4, 1, 4: median 3.
  EXPECT_EQ(in.weight[10], 3.0);
  EXPECT_EQ(in.weight[0], 0.0);
  EXPECT_EQ(in.weight[11], 0.0);
}

TEST(ModeShapes, classes_from_participation) {
  const auto with = [](std::initializer_list<std::pair<DofGroup, double>> shares) {
    std::array<double, kDofGroups> p{};
    for (const auto& [g, s] : shares) p[static_cast<std::size_t>(g)] = s;
    return classify_mode(p);
  };
  // A bogie hunting mode (Cooperrider wagon at 110 m/s), a car-body sway mode (wheelsets 0.3 %),
  // a wheelset bouncing on the contact, a track mode, a bogie pitch mode.
  EXPECT_EQ(with({{DofGroup::wheelset_lateral_yaw, 0.12}, {DofGroup::frame_lateral, 0.88}}),
            ModeClass::hunting);
  EXPECT_EQ(with({{DofGroup::wheelset_lateral_yaw, 0.003}, {DofGroup::frame_lateral, 0.02},
                  {DofGroup::carbody_lateral, 0.977}}),
            ModeClass::body);
  EXPECT_EQ(with({{DofGroup::wheelset_vertical_roll, 0.95}, {DofGroup::wheelset_lateral_yaw, 0.05}}),
            ModeClass::contact);
  EXPECT_EQ(with({{DofGroup::track, 0.6}, {DofGroup::wheelset_vertical_roll, 0.4}}),
            ModeClass::track);
  EXPECT_EQ(with({{DofGroup::frame_vertical, 1.0}}), ModeClass::body);
  EXPECT_EQ(with({{DofGroup::wheelset_longitudinal_spin, 1.0}}), ModeClass::longitudinal);
  EXPECT_EQ(with({}), ModeClass::unclassified);
}

}  // namespace
}  // namespace ferro::vehicle
