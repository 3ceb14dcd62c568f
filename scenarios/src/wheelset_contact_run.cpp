#include "ferro/scenarios/wheelset_contact_run.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <set>
#include <stdexcept>

#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/report.hpp"

namespace ferro::scenarios {

namespace fc = ferro::contact;

void select_wheelset_cases(WheelsetContactInput& in, const std::vector<int>& only,
                           const std::string& source) {
  if (only.empty()) return;
  std::set<int> known;
  for (const auto& c : in.cases) known.insert(c.id);
  std::vector<fc::WheelsetCase> kept;
  for (int id : only) {
    if (!known.count(id)) {
      throw std::invalid_argument(fmt::format("--cases: case {} is not in {} (ids {}..{})", id,
                                              source, *known.begin(), *known.rbegin()));
    }
    for (const auto& c : in.cases) {
      if (c.id == id) kept.push_back(c);
    }
  }
  in.cases = kept;
}

WheelsetContactFiles write_wheelset_contact_files(const std::string& study_path,
                                                  const std::string& h5_path,
                                                  const std::vector<int>& only, bool overwrite) {
  WheelsetContactInput in = load_wheelset_contact_file(study_path);
  std::filesystem::path csv(h5_path);
  csv.replace_extension(".csv");
  WheelsetContactFiles files{std::filesystem::path(h5_path).string(), csv.string(), {}};
  OutputSet outputs({overwrite, {study_path}});
  OutputFile& h5_file = outputs.claim(files.h5, "-o");
  OutputFile& csv_file = outputs.claim(files.csv, "-o (its CSV)");
  select_wheelset_cases(in, only, study_path);
  const fc::WheelRailPair pair = make_wheel_rail_pair(in.pair);
  const auto results = fc::solve_wheelset_contacts(pair, in.spec, in.cases);
  files.report = wheelset_contact_report(results);
  fc::write_wheelset_contacts(results, in.spec, in.pair.path, h5_file.write_path(),
                              csv_file.write_path());
  outputs.commit_all();
  return files;
}

}  // namespace ferro::scenarios
