#pragma once
// What `ferrodyn contact eval | curve | patch` produce besides the pictures: the JSON of one
// evaluation, the creep-curve files and the patch-picture file of a contact case. Forces and
// moment are those of the rail on the wheel; SI units.

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/contact_eval.hpp"

namespace ferro::scenarios {

/// key=value items (the repeatable --option) as model options. Throws std::invalid_argument
/// ("--option '<item>': expected key=value") for an item without '=' or with an empty key.
[[nodiscard]] contact::ModelOptions parse_model_options(const std::vector<std::string>& items);

/// Gives `input` the K_ij table of the HDF5 file `path`, looked up at the axis=value items `at`
/// (--kij-at). Throws std::invalid_argument naming the axis whose value is not a number.
void use_kij_table(EvalInput& input, const std::string& path, const std::vector<std::string>& at);

/// One evaluation as indented JSON: model, patch (semi-axes, load, peak pressure), forces and
/// moment on the wheel, adhesion fraction, C_ij used, units and convention.
[[nodiscard]] std::string eval_json(const EvalInput& in, const EvalOutput& out);

/// `contact eval` as a user asks for it: a case, model options (key=value items), a K_ij table
/// file and its point (axis=value items; empty file: the case's k11..k33).
struct EvalRequest {
  EvalInput input;
  std::vector<std::string> options, kij_at;
  std::string kij_table;
};
/// Solves the request's case and writes its JSON (eval_json) and a newline to `out`; with
/// `batch`, reads cases as CSV from `in` (named `in_name` in messages) and writes one row per
/// case (evaluate_contact_batch). The C_ij come from the models' "coefficients" option
/// (default kalker_table); a mim_table model given no table takes the environment's
/// (with_environment_options).
void run_contact_eval(const EvalRequest& request, bool batch, std::istream& in,
                      const std::string& in_name, std::ostream& out);

/// The files of `contact curve`: <out_dir>/<case>_curves.{csv,h5} (written), the picture's path
/// <case>_curves.png (not drawn here) and its title (patch size, load, friction).
struct CurveFiles {
  std::string csv, h5, png, title;
};
/// Loads the case file, solves its normal problem and every requested creep curve, writes the
/// CSV and HDF5 into `out_dir` (made when missing). Throws std::invalid_argument naming the file
/// when the case asks for no curve.
[[nodiscard]] CurveFiles write_creep_curve_files(const std::string& case_path,
                                                 const std::string& out_dir);

/// The files of `contact patch`: <out_dir>/<case>_patch.csv (written), the picture's path
/// <case>_patch.png (not drawn here), its title, and the per-patch summary as indented JSON
/// (centre, semi-axes, load, peak pressure, forces, moment, adhesion fraction).
struct PatchFiles {
  std::string csv, png, title, summary_json;
};
/// Loads the case file, solves its normal problem and the patch picture, writes the CSV into
/// `out_dir` (made when missing).
[[nodiscard]] PatchFiles write_patch_files(const std::string& case_path,
                                           const std::string& out_dir);

}  // namespace ferro::scenarios
