// The assessment of a run against closed forms: the limits (Nadal, Prud'homme with the
// category's alpha, Q_max, bogie frame), static axle loads by the lever rule, the track-shift
// force of a single axle against -Y_L + Y_R (its sign), Y/Q, the twist test's dQ/Q0, the floor
// acceleration of a yawing car body, and the command line.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <functional>
#include <map>

#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/h5_output.hpp"
#include "ferro/scenarios/vehicle_file.hpp"
#include "process.hpp"

namespace ferro::scenarios::analysis {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kRoundoff = 1e-12;
constexpr double kThesisRounding = 5e-3;  // the thesis rounds Nadal's limit to two digits

TEST(Nadal, ThesisValue70DegMu036) {
  EXPECT_NEAR(nadal_limit(70.0 * kDeg, 0.36), 1.2, kThesisRounding);
}

TEST(Nadal, ClosedFormMu05) {
  // tan 70 = 2.7474774194546; (2.7474774 - 0.5) / (1 + 0.5 * 2.7474774) = 0.9468091
  EXPECT_NEAR(nadal_limit(70.0 * kDeg, 0.5), 0.946809103396597, kRoundoff);
  EXPECT_NEAR(nadal_limit(60.0 * kDeg, 0.0), std::sqrt(3.0), kRoundoff);
  EXPECT_THROW((void)nadal_limit(95.0 * kDeg, 0.3), std::invalid_argument);
  EXPECT_THROW((void)nadal_limit(60.0 * kDeg, -0.1), std::invalid_argument);
}

TEST(Limits, PrudhommeQmaxBogie) {
  // P0 = 120 kN: alpha (10 + 40) kN: 50 kN for a coach, 42.5 kN for a wagon.
  EXPECT_NEAR(prudhomme_limit(120.0e3, track_shift_alpha("coach")), 50.0e3, kRoundoff * 5e4);
  EXPECT_NEAR(prudhomme_limit(120.0e3, track_shift_alpha("locomotive")), 50.0e3, 1e-7);
  EXPECT_NEAR(prudhomme_limit(120.0e3, track_shift_alpha("wagon")), 42.5e3, 1e-7);
  // Q_lim = min(90 kN + Q0, cap(V)): Q0 = 60 kN gives 150 kN below every cap; Q0 = 112.5 kN
  // gives the caps 200 / 190 / 180 / 170 / 160 kN.
  EXPECT_NEAR(q_max_limit(50.0, 60.0e3), 150.0e3, 1e-7);
  EXPECT_NEAR(q_max_limit(160.0 / 3.6, 112.5e3), 200.0e3, 1e-7);
  EXPECT_NEAR(q_max_limit(200.0 / 3.6, 112.5e3), 190.0e3, 1e-7);
  EXPECT_NEAR(q_max_limit(250.0 / 3.6, 112.5e3), 180.0e3, 1e-7);
  EXPECT_NEAR(q_max_limit(300.0 / 3.6, 112.5e3), 170.0e3, 1e-7);
  EXPECT_NEAR(q_max_limit(320.0 / 3.6, 112.5e3), 160.0e3, 1e-7);
  // Bogie of 5 t: (12 - 1)/2 = 5.5 m/s^2.
  EXPECT_NEAR(bogie_acceleration_limit(5000.0), 5.5, kRoundoff);
}

TEST(StaticAxleLoads, LeverRuleOnTheManchesterVehicle) {
  std::string category;
  const auto v = load_vehicle_file(FERRO_SOURCE_DIR "/scenarios/vehicles/manchester_vehicle1.yaml",
                                   &category);
  EXPECT_EQ(category, "coach");
  const auto loads = static_axle_loads(v);
  // Symmetric vehicle: every axle carries a quarter of the total weight.
  double total = 0.0;
  for (const auto& b : v.bodies) total += b.mass;
  int wheelsets = 0;
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    if (v.bodies[i].kind != vehicle::BodyKind::wheelset) {
      EXPECT_EQ(loads[i], 0.0);
      continue;
    }
    ++wheelsets;
    EXPECT_NEAR(loads[i], total * v.gravity / 4.0, 1e-9 * total) << v.bodies[i].name;
  }
  EXPECT_EQ(wheelsets, 4);
  // (32000 + 2 x 2615 + 4 x 1813) kg x 9.81 / 4 = 109.09 kN.
  EXPECT_NEAR(total * v.gravity / 4.0, 109092.1, 0.1);
}

// A synthetic run file: the vehicle context, and signals given as functions of time.
struct SyntheticRun {
  RunContext context;
  double dt = 1e-3, t_end = 20.0, speed = 10.0;
  std::map<std::string, std::function<double(double t)>> signals;
  std::string status = "completed";

  std::string write(const std::string& name) const {
    const auto path = (std::filesystem::temp_directory_path() / name).string();
    H5File f = H5File::create(path);
    f.set_attribute("/", "kind", std::string("time_simulation"));
    write_run_context(f, context);
    std::vector<vehicle::SignalInfo> ch = {{"position", "m", ""}, {"speed", "m/s", ""}};
    for (const auto& [n, fn] : signals) ch.push_back({n, "SI", ""});
    {
      TimeSeriesWriter w(f, ch, 10.0);
      std::vector<double> row(ch.size());
      const auto n = static_cast<long>(std::lround(t_end / dt));
      for (long i = 0; i <= n; ++i) {
        const double t = dt * static_cast<double>(i);
        row[0] = speed * t;
        row[1] = speed;
        std::size_t k = 2;
        for (const auto& [nm, fn] : signals) row[k++] = fn(t);
        w.append(t, row);
      }
      w.flush();
    }
    f.set_attribute("/", "status", status);
    return path;
  }
};

RunContext single_axle(const std::string& category, double axle_load) {
  RunContext c;
  c.vehicle = "one_axle";
  c.category = category;
  c.friction = 0.5;
  c.bodies.push_back({"wheelset_1", "wheelset", 1800.0, 5.0, 0.0, 0.46, axle_load});
  return c;
}

const AssessmentRow* find_row(const Assessment& a, const std::string& quantity,
                              const std::string& item) {
  for (const auto& r : a.rows)
    if (r.quantity == quantity && r.item == item) return &r;
  return nullptr;
}

const AssessedSignal* find_signal(const Assessment& a, const std::string& quantity,
                                  const std::string& item) {
  for (const auto& s : a.signals)
    if (s.quantity == quantity && s.item == item) return &s;
  return nullptr;
}

TEST(Assessment, TrackShiftForceOfOneAxleIsMinusLeftPlusRight) {
  // Each wheel's Y is + towards the track centre. Left wheel Y_L = -(3 + sin(k s)) kN pushes the
  // wheelset to +y (left) by 3 + sin; right wheel Y_R = 5 kN pushes it +y too. The track-shift
  // force is -Y_L + Y_R = 8 + sin(k s) kN; the wrong sum Y_L + Y_R would give 2 - sin.
  const double k = 2.0 * M_PI / 20.0;  // 20 m wavelength: 0.5 Hz at 10 m/s
  SyntheticRun run;
  run.context = single_axle("coach", 100.0e3);
  const double x0 = 5.0;  // the wheelset's rest x: positions are the wheelset's
  run.signals["wheelset_1.left.Y"] = [&](double t) { return -(3.0e3 + 1.0e3 * std::sin(k * (10.0 * t + x0))); };
  run.signals["wheelset_1.right.Y"] = [](double) { return 5.0e3; };
  run.signals["wheelset_1.left.Q"] = [](double) { return 50.0e3; };
  run.signals["wheelset_1.right.Q"] = [](double) { return 50.0e3; };
  run.signals["wheelset_1.left.contact_angle"] = [](double) { return 0.05; };
  run.signals["wheelset_1.right.contact_angle"] = [](double) { return 0.05; };
  const auto path = run.write("ferro_assess_one_axle.h5");
  const auto a = assess_run(path, {});
  const auto* s = find_signal(a, "sum Y 2 m", "wheelset_1");
  ASSERT_NE(s, nullptr);
  // 2 m mean of sin: sin(k c) sin(k) / k (window half-length 1 m); the zero-phase 20 Hz low-pass
  // passes 0.5 Hz with gain 1 - 1e-12.
  const double sinc = std::sin(k * 1.0) / (k * 1.0);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < s->position.size(); ++i) {
    const double c = s->position[i];
    if (c < 20.0 || c > 180.0) continue;  // away from the filter's edges
    EXPECT_NEAR(s->value[i], 8.0e3 + 1.0e3 * std::sin(k * c) * sinc, 1e-3) << c;
    ++checked;
  }
  EXPECT_GT(checked, 300u);
  // Limit 1.0 x (10 + 100/3) kN, position at the wheelset (rest x 5 m ahead of the reference).
  const auto* r = find_row(a, "sum Y 2 m", "wheelset_1");
  ASSERT_NE(r, nullptr);
  EXPECT_NEAR(r->limit, 10.0e3 + 100.0e3 / 3.0, 1e-6);
  EXPECT_EQ(r->verdict, Verdict::pass);
  EXPECT_NEAR(r->max_abs, 8.0e3 + 1.0e3 * sinc, 1.0);
  // Y/Q of the right wheel: 5 / 50 = 0.1 everywhere.
  const auto* yq = find_row(a, "Y/Q 2 m", "wheelset_1.right");
  ASSERT_NE(yq, nullptr);
  EXPECT_NEAR(yq->value, 0.1, 1e-9);
  EXPECT_NEAR(yq->limit, 0.8, kRoundoff);
  EXPECT_EQ(find_row(a, "dQ/Q0", "wheelset_1.left"), nullptr);  // no twist test
  std::filesystem::remove(path);
}

TEST(Assessment, CategoryTwistTestAndLimits) {
  SyntheticRun run;
  run.context = single_axle("wagon", 120.0e3);
  run.context.twist_test = true;
  run.t_end = 12.0;
  // The left wheel unloads to 40 % of Q0 = 60 kN over a 10 m stretch (a cos^2 bump at 60 m).
  const auto bump = [](double t) {
    const double s = 10.0 * t + 5.0;
    return std::abs(s - 60.0) < 5.0 ? std::pow(std::cos(M_PI * (s - 60.0) / 10.0), 2) : 0.0;
  };
  run.signals["wheelset_1.left.Y"] = [&](double t) { return 45.0e3 * bump(t); };
  run.signals["wheelset_1.right.Y"] = [](double) { return 0.0; };
  run.signals["wheelset_1.left.Q"] = [&](double t) { return 60.0e3 * (1.0 - 0.6 * bump(t)); };
  run.signals["wheelset_1.right.Q"] = [&](double t) { return 60.0e3 * (1.0 + 0.6 * bump(t)); };
  run.signals["wheelset_1.left.contact_angle"] = [&](double t) { return (3.0 + 67.0 * bump(t)) * kDeg; };
  run.signals["wheelset_1.right.contact_angle"] = [](double) { return 3.0 * kDeg; };
  const auto path = run.write("ferro_assess_twist.h5");
  const auto a = assess_run(path, {});
  EXPECT_EQ(a.category, "wagon");
  EXPECT_NEAR(a.alpha, 0.85, kRoundoff);
  EXPECT_NEAR(a.mu, 0.5, kRoundoff);  // the run's friction
  const auto* sum = find_row(a, "sum Y 2 m", "wheelset_1");
  ASSERT_NE(sum, nullptr);
  EXPECT_NEAR(sum->limit, 0.85 * (10.0e3 + 40.0e3), 1e-6);
  // Left wheel's Y pushes the wheelset +y: -Y_L = -45 kN at the peak: the 2 m mean of cos^2
  // over |u| < 1 m is 1/2 + sin(pi/5)/(2 pi/5); |sum Y| = 45 kN times it > 42.5 kN: FAIL.
  const double mean_cos2 = 0.5 + std::sin(M_PI / 5.0) / (2.0 * M_PI / 5.0);
  EXPECT_NEAR(sum->max_abs, 45.0e3 * mean_cos2, 0.01 * 45.0e3);
  EXPECT_NEAR(sum->position, 60.0, 0.5);  // at the wheelset
  EXPECT_EQ(sum->verdict, Verdict::fail);
  EXPECT_FALSE(a.pass);
  // dQ/Q0 = 0.6 at the peak (20 Hz filtered): the 99.85 % percentile is at most that.
  const auto* dq = find_row(a, "dQ/Q0", "wheelset_1.left");
  ASSERT_NE(dq, nullptr);
  EXPECT_NEAR(dq->max_abs, 0.6, 2e-3);
  EXPECT_NEAR(dq->limit, 0.6, kRoundoff);
  // Nadal for the left wheel at 70 deg, mu 0.5, information only.
  bool nadal_seen = false;
  for (const auto& r : a.rows) {
    if (r.item != "wheelset_1.left" || r.quantity != "Y/Q 2 m against Nadal") continue;
    nadal_seen = true;
    EXPECT_NEAR(r.limit, nadal_limit(70.0 * kDeg, 0.5), 1e-9);
    EXPECT_EQ(r.verdict, Verdict::info);
  }
  EXPECT_TRUE(nadal_seen);
  // The category of the options replaces the run's; without one at all the run is refused.
  AssessmentOptions coach;
  coach.category = "coach";
  EXPECT_NEAR(assess_run(path, coach).alpha, 1.0, kRoundoff);
  std::filesystem::remove(path);
  SyntheticRun none = run;
  none.context.category = "";
  const auto p2 = none.write("ferro_assess_no_category.h5");
  try {
    (void)assess_run(p2, {});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("category"), std::string::npos) << e.what();
  }
  std::filesystem::remove(p2);
}

TEST(Assessment, FloorAccelerationOfAYawingCarBody) {
  // Car body yawing at 2 Hz, yaw rate amplitude 0.01 rad/s, no lateral acceleration at its
  // centre: above the bogie 9.5 m ahead the floor's lateral acceleration is 9.5 x yaw
  // acceleration = 9.5 x 0.01 x 2 pi 2 cos(2 pi 2 t) (band 0.4-10 Hz passes 2 Hz with gain
  // 1 - 1e-6; central differences at 1 ms: relative error (w dt)^2 / 6 = 2.6e-5).
  SyntheticRun run;
  run.context = single_axle("coach", 100.0e3);
  run.context.bodies.push_back({"car_body", "car_body", 30000.0, 0.0, 0.0, 1.8, 0.0});
  run.context.bodies.push_back({"bogie_1", "bogie_frame", 2600.0, 9.5, 0.0, 0.6, 0.0});
  for (const char* side : {"left", "right"}) {
    run.signals[fmt::format("wheelset_1.{}.Y", side)] = [](double) { return 0.0; };
    run.signals[fmt::format("wheelset_1.{}.Q", side)] = [](double) { return 50.0e3; };
    run.signals[fmt::format("wheelset_1.{}.contact_angle", side)] = [](double) { return 0.05; };
  }
  const double w = 2.0 * M_PI * 2.0;
  run.signals["car_body.ay"] = [](double) { return 0.0; };
  run.signals["car_body.yaw_dot"] = [&](double t) { return 0.01 * std::sin(w * t); };
  const auto path = run.write("ferro_assess_floor.h5");
  const auto a = assess_run(path, {});
  const auto* s = find_signal(a, "car body lateral acc.", "floor_front");
  ASSERT_NE(s, nullptr);
  // Least-squares fit of a cos(w t) + b sin(w t) over 4-16 s (away from the filter's edges).
  double cc = 0, cs = 0, ss = 0, yc = 0, ys = 0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < s->position.size(); ++i) {
    const double t = (s->position[i] - 9.5) / 10.0;
    if (t < 4.0 || t > 16.0) continue;
    const double c = std::cos(w * t), sn = std::sin(w * t);
    cc += c * c, cs += c * sn, ss += sn * sn, yc += s->value[i] * c, ys += s->value[i] * sn;
    ++used;
  }
  ASSERT_GT(used, 10000u);
  // Pointwise between 9 and 11 s: the band's 0.4 Hz high-pass rings from the record's ends
  // (the odd reflection of a cosine at its crest has another mean) and decays at 0.86 /s.
  double worst = 0.0;
  for (std::size_t i = 0; i < s->position.size(); ++i) {
    const double t = (s->position[i] - 9.5) / 10.0;
    if (t < 9.0 || t > 11.0) continue;
    worst = std::max(worst, std::abs(s->value[i] - 9.5 * 0.01 * w * std::cos(w * t)));
  }
  EXPECT_LT(worst, 5e-4 * 9.5 * 0.01 * w);
  const double det = cc * ss - cs * cs;
  const double a_cos = (yc * ss - ys * cs) / det, b_sin = (ys * cc - yc * cs) / det;
  const double amplitude = 9.5 * 0.01 * w;
  std::printf("floor lateral acc.: cos %.9f sin %.9f (expected %.9f, 0)\n", a_cos, b_sin, amplitude);
  EXPECT_NEAR(a_cos, amplitude, 1e-4 * amplitude);
  EXPECT_NEAR(b_sin, 0.0, 1e-4 * amplitude);
  // Comfort rows exist for the point (their values: ride_comfort_test).
  bool nmv = false;
  for (const auto& r : a.rows)
    nmv = nmv || (r.item == "floor_front" && r.quantity.rfind("N_MV", 0) == 0);
  EXPECT_TRUE(nmv);
  std::filesystem::remove(path);
}

TEST(AssessCli, TablePlotsOffAndBadInput) {
  SyntheticRun run;
  run.context = single_axle("coach", 100.0e3);
  for (const char* side : {"left", "right"}) {
    run.signals[fmt::format("wheelset_1.{}.Y", side)] = [](double) { return 2.0e3; };
    run.signals[fmt::format("wheelset_1.{}.Q", side)] = [](double) { return 50.0e3; };
    run.signals[fmt::format("wheelset_1.{}.contact_angle", side)] = [](double) { return 0.05; };
  }
  const auto path = run.write("ferro_assess_cli.h5");
  const auto out = (std::filesystem::temp_directory_path() / "ferro_assess_cli_out.h5").string();
  const auto r = test::run_capture({FERRODYN_EXE, "assess", path, "-o", out, "--no-plots"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("sum Y 2 m"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("verdict   pass"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
  {
    const auto f = H5File::open_read(out);
    EXPECT_EQ(f.string_attribute("/", "kind"), "assessment");
    EXPECT_NE(f.read_text("/assessment/table").find("wheelset_1.left"), std::string::npos);
  }
  const auto bad = test::run_capture({FERRODYN_EXE, "assess", "/nonexistent/run.h5"});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  const auto cat = test::run_capture({FERRODYN_EXE, "assess", path, "--category", "tram"});
  EXPECT_NE(cat.exit_code, 0) << cat.output;
  std::filesystem::remove(path);
  std::filesystem::remove(out);
}

TEST(AssessCost, TenSecondsAtTwoTenthsOfAMillisecondUnderOneSecond) {
  // A whole-vehicle run's worth of signals: 10 s at 0.2 ms (50 001 samples), four wheelsets,
  // two bogie frames and the car body. CPU time of the assessment and its file.
  SyntheticRun run;
  run.dt = 2e-4;
  run.t_end = 10.0;
  run.speed = 55.0;
  run.context.vehicle = "manchester_like";
  run.context.category = "coach";
  run.context.friction = 0.32;
  run.context.bodies = {{"car_body", "car_body", 32000, 0, 0, 1.8, 0},
                        {"bogie_1", "bogie_frame", 2615, 9.5, 0, 0.6, 0},
                        {"bogie_2", "bogie_frame", 2615, -9.5, 0, 0.6, 0}};
  const double xs[4] = {10.78, 8.22, -8.22, -10.78};
  for (int i = 0; i < 4; ++i) {
    const std::string ws = fmt::format("wheelset_{}", i + 1);
    run.context.bodies.push_back({ws, "wheelset", 1813, xs[i], 0, 0.46, 109.1e3});
    for (const char* side : {"left", "right"}) {
      const double ph = i + (side[0] == 'l' ? 0.0 : 1.0);
      run.signals[ws + "." + side + ".Y"] = [ph](double t) { return 3e3 * std::sin(30 * t + ph); };
      run.signals[ws + "." + side + ".Q"] = [ph](double t) { return 54e3 + 5e3 * std::sin(200 * t + ph); };
      run.signals[ws + "." + side + ".contact_angle"] = [](double) { return 0.05; };
    }
  }
  for (const char* s : {"car_body.ay", "car_body.z_dot", "car_body.x_dot", "car_body.roll_dot",
                        "car_body.pitch_dot", "car_body.yaw_dot", "bogie_1.y_dot",
                        "bogie_1.yaw_dot", "bogie_2.y_dot", "bogie_2.yaw_dot"})
    run.signals[s] = [](double t) { return 0.01 * std::sin(7 * t); };
  const auto path = run.write("ferro_assess_cost.h5");
  const auto out = (std::filesystem::temp_directory_path() / "ferro_assess_cost_out.h5").string();
  const std::clock_t c0 = std::clock();
  const auto a = assess_run(path, {});
  write_assessment(a, path, out);
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  std::printf("assess of 10 s at 0.2 ms output: %.3f CPU-s, %zu rows\n", cpu, a.rows.size());
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
  // The bound is the optimised build's; an instrumented or unoptimised build only runs the work.
  EXPECT_GT(a.rows.size(), 0u);
#else
  EXPECT_LT(cpu, 1.0);
#endif
  std::filesystem::remove(path);
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace ferro::scenarios::analysis
