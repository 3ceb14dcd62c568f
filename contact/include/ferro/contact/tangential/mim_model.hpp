#pragma once
// The MIM boundary-element solver (contact/mim/) behind the tangential-model interface:
// registered as "mim" in make_tangential_model (option "elements", default 30: elements across
// the shorter extent of the patch; option "grid" = minor (square elements, `elements` across the
// shorter axis), patch (`elements` x `elements` over the patch) or patch_richardson (patch grid,
// forces extrapolated from `elements` and ceil(elements / 2))).
//
// Elliptic patch without lateral gap samples: the Hertzian gap A x^2 + B y^2 that reproduces the
// patch's a, b under its F_n (mim::HertzMimSolver, cached unit-grid operators). Non-elliptic
// patch (semi-Hertz strips) with TangentialProblem::gap holding lateral samples gap_y/gap_z: the
// full gap z(x, y) = A x^2 + z(y) over the patch's lateral extent, solved with the patch's F_n.
//
// References: Toumi (2016) chapter 2, eqs. (74)-(123) (see contact/include/ferro/contact/mim/);
// eqs. (38)-(40) for the sign convention shared with the other tangential models.
// Known deviations: quasi-identical bodies (K = 0); a non-elliptic patch is solved alone over
// [y_min, y_max] of its strips (plus a margin), with its own share of the load; K_ij reduction
// factors are not applied (MIM is the full theory; a non-unit K_ij throws).

#include <memory>
#include <mutex>
#include <string_view>

#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {

namespace mim {
class HertzMimSolver;
struct MimResult;
}  // namespace mim

struct MimModelOptions {
  int elements = 30;  ///< elements across the shorter extent of the patch [-] (>= 6)
  /// Elliptic patches: false = `elements` square elements across the shorter axis (the grid
  /// grows to elements x 5 elements at a/b = 5); true = `elements` x `elements` rectangular
  /// elements over the patch (dx/dy = a/b), the same cost at every a/b.
  bool grid_over_patch = false;
  /// With grid_over_patch: forces Richardson-extrapolated from `elements` and ceil(elements / 2)
  /// (mim::HertzRollingInput::extrapolate; option grid = patch_richardson). Non-elliptic
  /// patches are solved on their own grid without extrapolation.
  bool extrapolate = false;
  void validate() const;
};

/// The model "mim" (options in the file comment).
class MimTangentialModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(const ModelOptions& options);
  explicit MimTangentialModel(MimModelOptions options = {});
  ~MimTangentialModel() override;
  [[nodiscard]] std::string_view name() const override { return "mim"; }
  /// Thread-safe (one solve at a time; the operator cache is shared).
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;
  /// The full MIM result (fields on its grid, forces on the wheel), for pictures and tests.
  [[nodiscard]] mim::MimResult solve_full(const TangentialProblem& problem) const;

 private:
  MimModelOptions options_;
  mutable std::mutex mutex_;
  std::unique_ptr<mim::HertzMimSolver> solver_;
};

}  // namespace ferro::contact
