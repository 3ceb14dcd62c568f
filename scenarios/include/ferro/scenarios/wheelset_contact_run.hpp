#pragma once
// `ferrodyn contact wheelset` without its picture: the chosen cases of a wheelset-contact study
// file solved (contact/geometry/wheelset_contact.hpp), the table printed as text and written as
// HDF5 and CSV.

#include <string>
#include <vector>

#include "ferro/scenarios/wheelset_contact_file.hpp"

namespace ferro::scenarios {

/// Keeps the cases whose ids are in `only`, in the order of `only` (empty: every case). Throws
/// std::invalid_argument ("--cases: case <id> is not in <source> (ids <first>..<last>)") for an
/// id the file does not have.
void select_wheelset_cases(WheelsetContactInput& in, const std::vector<int>& only,
                           const std::string& source);

/// What the study wrote: the HDF5 table, the CSV beside it (same stem), the table as text.
struct WheelsetContactFiles {
  std::string h5, csv, report;
};

/// Loads `study_path`, claims `h5_path` and its CSV (an existing file only with `overwrite`),
/// solves the cases `only` (select_wheelset_cases), writes both files.
[[nodiscard]] WheelsetContactFiles write_wheelset_contact_files(const std::string& study_path,
                                                                const std::string& h5_path,
                                                                const std::vector<int>& only,
                                                                bool overwrite);

}  // namespace ferro::scenarios
