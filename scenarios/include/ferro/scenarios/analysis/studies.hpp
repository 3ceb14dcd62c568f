#pragma once
// The critical-speed studies of a scene as the command line and the Python module ask for
// them: a decelerating ramp, the periodic branch followed down to its fold (bifurcation), and
// the fold against the Kalker reduction factors (K_ij study, over threads); and the options of
// the assessment of a run (EN 14363 / UIC 518 / EN 12299). Each request holds the user's numbers
// (SI unless the key names its unit) and checks them; errors name the value as a key or as an
// option (see Spelling). The sweep of independent points is in sweep.hpp.

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/analysis/output.hpp"
#include "ferro/scenarios/analysis/scene_analysis.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios::analysis {

/// Settling of constant-speed runs (bifurcation, K_ij study, sweep).
struct SettleRequest {
  double disturbance = 0.01;      ///< lateral offset added to the leading wheelset [m]
  double segment = 10.0;          ///< simulated time per convergence check [s]
  double t_max = 60.0;            ///< simulated time limit per speed [s]
  double output_interval = 2e-3;  ///< sampling of the lateral states [s]
  double zero_amplitude = 1e-5;   ///< below: oscillation decayed [m]
  double max_amplitude = 0.05;    ///< above: diverged [m]
  int periods = 5;                ///< periods the steady amplitude is measured over
  double rel_tol = 2e-3;          ///< relative amplitude change that counts as settled [-]
  double k11 = 1.0, k22 = 1.0;    ///< reduction factors on C11, C22 [-]
  /// The factors k11, k22 (K23 and K33 following K22).
  [[nodiscard]] contact::ReductionFactors reduction() const {
    return contact::ReductionFactors::following_k22(k11, k22);
  }
};
/// The settle options of `scene`'s solver; throws std::invalid_argument naming the bad value.
[[nodiscard]] SettleOptions settle_options(const Scene& scene, const SettleRequest& request,
                                           Spelling spelling = Spelling::key);

/// A decelerating run after a lateral disturbance.
struct RampRequest {
  double speed_initial = 110.0;   ///< [m/s]
  double deceleration = 1.0;      ///< [m/s^2]
  double speed_final = NAN;       ///< [m/s] (NaN: 0.1 x speed_initial)
  double hold = 0.1;              ///< constant-speed piece duration [s]
  double threshold = 1e-4;        ///< envelope below which the oscillation died [m]
  double max_amplitude = 0.05;    ///< stop as diverged above this [m]
  double envelope_window = 2.0;   ///< envelope trailing window [s]
  double output_interval = 2e-3;  ///< sampling [s]
  double disturbance = 0.01;      ///< initial lateral offset [m]
  double k11 = 1.0, k22 = 1.0;    ///< reduction factors [-]
};
struct RampStudy {
  Scene scene;  ///< with the reduction factors applied
  RampOptions options;
  RampResult result;
  /// Names of the observed states (each wheelset's lateral displacement), in the order of
  /// result.signals.
  std::vector<std::string> observed;
};
[[nodiscard]] RampStudy run_ramp(const Scene& scene, const RampRequest& request,
                                 Spelling spelling = Spelling::key);

/// The periodic branch followed down from speed_max to its fold.
struct BranchRequest {
  double speed_max = NAN;  ///< first (highest) speed [m/s]
  double speed_min = NAN;  ///< lowest speed followed [m/s]
  double step = 2.0;       ///< downward speed step [m/s]
  double bracket = 0.1;    ///< fold bracket width [m/s]
  SettleRequest settle;
  bool hopf = true;  ///< also the eigenvalue (Hopf) speed in [0.5 min, 1.5 max]
};
[[nodiscard]] BranchOptions branch_options(const Scene& scene, const BranchRequest& request,
                                           Spelling spelling = Spelling::key);
/// The branch of `base` with reduction factors `k`; `names` receives the wheelset lateral
/// states (the amplitude columns); `on_point` is called after each run.
[[nodiscard]] KijRow run_bifurcation(const Scene& base, const BranchRequest& request,
                                     const contact::ReductionFactors& k, std::vector<std::string>* names,
                                     const std::function<void(const BranchPoint&)>& on_point = {},
                                     Spelling spelling = Spelling::key);

/// Linear eigenvalues against speed with reduction factors (the Hopf speed of the linear
/// model): its own speed range, whatever the scene's analysis.eigen says.
struct EigenRequest {
  RunOverrides range = eigen_study_range();  ///< speed_min, speed_max, points
  double k11 = 1.0, k22 = 1.0;              ///< reduction factors on C11, C22 [-]
  /// 1 to 150 m/s, 150 speeds.
  [[nodiscard]] static RunOverrides eigen_study_range();
};
/// `scene` with the request's reduction factors (K23, K33 following K22) and speed range;
/// run_eigen() of it is the study. Throws std::invalid_argument naming the bad value.
[[nodiscard]] Scene eigen_study_scene(const Scene& scene, const EigenRequest& request,
                                      Spelling spelling = Spelling::key);
/// The heading (scene, factors) and eigen_modes_report() of the study's sweep, 16 rows.
[[nodiscard]] std::string eigen_study_report(const Scene& scene, const EigenRequest& request,
                                             const EigenReport& report);

/// The reduction factors of a study: one per value of `k`, set on both (K11 = K22 = K23 = K33),
/// on k11 only or on k22 only (K23 and K33 following K22) (`coefficient`), the other from `base`.
[[nodiscard]] std::vector<contact::ReductionFactors> study_reductions(
    const std::vector<double>& k, const std::string& coefficient,
    const contact::ReductionFactors& base, Spelling spelling = Spelling::key);

/// The fold against reduction factors, one branch per factor, over `jobs` threads.
struct KijStudyRequest {
  BranchRequest branch;
  std::vector<double> k = {1.0, 0.9, 0.8, 0.7, 0.6, 0.5};
  std::string coefficient = "both";  ///< both | k11 | k22
  int jobs = 1;                      ///< worker threads
};
struct KijStudy {
  std::vector<KijRow> rows;        ///< in the order of request.k
  std::vector<std::string> names;  ///< wheelset lateral states
  bool interrupted = false;        ///< should_stop fired: rows are incomplete
};
/// `on_row(row, done, total)` is called (serialised) as each branch finishes.
[[nodiscard]] KijStudy run_kij_study(
    const Scene& scene, const KijStudyRequest& request,
    const std::function<bool()>& should_stop = {},
    const std::function<void(const KijRow&, std::size_t, std::size_t)>& on_row = {},
    Spelling spelling = Spelling::key);

/// The assessment's options as a user gives them (unset: the run's or the standard's value).
struct AssessmentRequest {
  double mu = NAN;                 ///< friction coefficient in Nadal's limit [-], [0, 2); NaN: the run's
  double flange_angle_deg = NAN;  ///< [deg] in (0, 90); NaN: each wheel's largest contact angle
  double section_length = 0.0;     ///< > 0: statistics over windows of this length [m] instead
                                   ///< of the scene's sections
  double f0 = NAN;                 ///< instability frequency [Hz]; NaN: from the run's spectrum
  double floor_offset = 1.0;       ///< lateral offset of the vertical floor points [m], >= 0
  double y_over_q_limit = 0.8;     ///< (Y/Q) limit of the 2 m mean [-], > 0
  std::string category;            ///< coach | locomotive | power_car | wagon; "": the run's
  bool twist_test = false;         ///< assess the wheel unloading dQ/Q0 too
  bool no_twist_test = false;      ///< do not, even when the scene says it is the twist test
};
[[nodiscard]] AssessmentOptions assessment_options(const AssessmentRequest& request,
                                                   Spelling spelling = Spelling::key);

/// Each request's values as parameters (see parameters.hpp); a branch's include its settle
/// request's, a K_ij study's its branch's.
[[nodiscard]] Parameters parameters(SettleRequest& request);
[[nodiscard]] Parameters parameters(RampRequest& request);
[[nodiscard]] Parameters parameters(BranchRequest& request);
[[nodiscard]] Parameters parameters(KijStudyRequest& request);
[[nodiscard]] Parameters parameters(AssessmentRequest& request);
/// speed_min, speed_max, points, k11, k22.
[[nodiscard]] Parameters parameters(EigenRequest& request);

}  // namespace ferro::scenarios::analysis
