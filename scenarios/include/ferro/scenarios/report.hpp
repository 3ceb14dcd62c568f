#pragma once
// Text reports of results: what `ferrodyn run`, `eig` and `contact wheelset` print, and what the
// Python module's results give as their summary. Plain text, two-space indented lines, units in
// the headings; every line ends in '\n'.

#include <string>

#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/contact/geometry/wheelset_contact.hpp"

namespace ferro::scenarios {

/// The run of `scene`: model, solver statistics, status and cause, then peak and final value of
/// each signal (for a vehicle: wheel forces, wheelset displacements and car-body accelerations;
/// the output file has every signal). A suspended_wheelset scene also names its least damped
/// linear mode at the scene's speed.
[[nodiscard]] std::string run_report(const Scene& scene, const RunSummary& summary);

/// What `ferrodyn validate` prints for a scene that passed check_scene(): its file, name,
/// schema, model, track, integrator, duration and speed, on one line.
[[nodiscard]] std::string valid_scene_line(const std::string& path, const Scene& scene);

/// The eigenvalue sweep per speed (at most `max_rows`, evenly strided): the least damped
/// hunting mode (damping ratio, frequency, shape) and the least damped mode of each other class
/// apart; the Hopf speed (a hunting mode crossing zero); the least damped modes at the scene's
/// own speed. Unclassified sweeps: the least damped mode per speed.
[[nodiscard]] std::string eigen_modes_report(const Scene& scene, const EigenReport& report,
                                             std::size_t max_rows);

/// The eigenvalue sweep (eigen_modes_report, 16 rows) with its heading and, when it applies,
/// the closed form of eq. (151).
[[nodiscard]] std::string eigen_sweep_report(const Scene& scene, const EigenReport& report);

/// One row per contact patch of every case: position, angle, load, creepages, forces, approach,
/// peak pressure (mm, deg, N, um, MPa as the Manchester benchmark tables give them).
[[nodiscard]] std::string wheelset_contact_report(const std::vector<contact::WheelsetContact>& results);

}  // namespace ferro::scenarios
