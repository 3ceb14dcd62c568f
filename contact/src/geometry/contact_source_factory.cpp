// make_contact_source(): the one place that turns a ContactSourceSpec into a geometry source.
//
// References: none (construction only).
// Known deviations: none.

#include "ferro/contact/geometry/contact_source_factory.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "ferro/contact/geometry/conical_source.hpp"
#include "ferro/contact/geometry/imported_contact_table.hpp"
#include "ferro/contact/geometry/multi_point_contact_table.hpp"
#include "ferro/contact/geometry/search_source.hpp"

namespace ferro::contact {
namespace {

std::shared_ptr<const WheelRailPair> make_pair(const ContactSourceSpec& spec) {
  if (spec.wheel_profile.empty() || spec.rail_profile.empty()) {
    throw std::invalid_argument(fmt::format(
        "ContactSourceSpec.wheel_profile/rail_profile: geometry '{}' needs both profile files",
        spec.kind));
  }
  Profile wheel = read_profile(spec.wheel_profile, ProfileKind::wheel);
  if (std::isfinite(spec.wheel_tread_conicity)) {
    if (!std::isfinite(spec.wheel_tread_join_y)) {
      throw std::invalid_argument(
          "ContactSourceSpec.wheel_tread_join_y: required with wheel_tread_conicity [m]");
    }
    wheel = splice_conical_tread(wheel, spec.wheel_tread_conicity, spec.wheel_tread_join_y);
  }
  return std::make_shared<const WheelRailPair>(
      wheel, read_profile(spec.rail_profile, ProfileKind::rail), spec.pair);
}

}  // namespace

std::shared_ptr<const ContactGeometrySource> make_contact_source(const ContactSourceSpec& spec) {
  if (spec.kind == "search") return std::make_shared<const SearchContactSource>(make_pair(spec));
  if (spec.kind == "conical") return std::make_shared<const ConicalContactSource>(spec.conical);
  if (spec.kind == "imported") {
    if (spec.imported_table.empty()) {
      throw std::invalid_argument(
          "ContactSourceSpec.imported_table: geometry 'imported' needs the CSV table file");
    }
    return std::make_shared<const ImportedContactTable>(spec.imported_table);
  }
  if (spec.kind == "table") {
    const auto pair = make_pair(spec);
    const std::uint64_t fp = MultiPointContactTable::fingerprint(*pair, spec.table);
    // A cache written by another format version of the table is rebuilt and overwritten.
    if (!spec.table_file.empty() && std::filesystem::exists(spec.table_file) &&
        !MultiPointContactTable::is_table_of_another_version(spec.table_file)) {
      auto t = std::make_shared<MultiPointContactTable>(
          MultiPointContactTable::load_hdf5(spec.table_file));
      if (t->fingerprint() == fp) {
        t->attach_pair(pair);
        return t;
      }
    }
    auto t = std::make_shared<MultiPointContactTable>(
        MultiPointContactTable::build(*pair, spec.table));
    if (!spec.table_file.empty()) {
      // Written beside the cache and renamed over it: runs started together never read a
      // half-written table.
      const std::filesystem::path target(spec.table_file);
      if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
      const std::string partial =
          fmt::format("{}.partial.{}", spec.table_file, static_cast<long>(::getpid()));
      t->save_hdf5(partial);
      std::filesystem::rename(partial, target);
    }
    t->attach_pair(pair);
    return t;
  }
  throw std::invalid_argument(fmt::format("ContactSourceSpec.kind: '{}' is not one of {}",
                                          spec.kind, fmt::join(kContactSourceKinds, ", ")));
}

}  // namespace ferro::contact
