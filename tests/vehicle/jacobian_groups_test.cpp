// The column groups of a finite-difference Jacobian (jacobian_column_groups) on Manchester
// vehicle 1 on its discrete track: a partition of the states whose groups touch disjoint rows of
// the model's Jacobian pattern, as few as the structural bound allows.
//
// Oracle: no partition into groups of columns with disjoint rows has fewer groups than the
// largest number of non-zeros in one row (those columns must all be apart); the groups are
// checked against the pattern entry by entry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"
#include "ferro/vehicle/vehicle_model.hpp"
#include "manchester_config.hpp"
#include "model_helpers.hpp"

namespace ferro::vehicle {
namespace {

TEST(JacobianColumnGroups, manchester_vehicle_on_the_discrete_track_reaches_the_row_bound) {
  VehicleModelInputs in;
  in.track_structure.kind = track::TrackStructureSpec::Kind::discrete;
  in.config = testing::manchester_vehicle1(9.81);
  WheelRailSpec& wr = in.config.wheel_rail;
  testing::use_thesis_cone(wr);
  in.geometry = make_geometry_source(wr, FERRO_DATA_DIR);
  in.speed.initial = 30.0;
  const VehicleModel m(in);
  const std::vector<std::vector<int>> pattern = m.jacobian_pattern();
  const std::size_t n = m.size();
  ASSERT_EQ(pattern.size(), n);

  std::vector<int> row_count(n, 0);
  for (const auto& column : pattern) {
    for (const int i : column) ++row_count[static_cast<std::size_t>(i)];
  }
  const int bound = *std::max_element(row_count.begin(), row_count.end());

  const auto groups = jacobian_column_groups(pattern, n);
  std::vector<int> seen(n, 0);
  for (const auto& group : groups) {
    ASSERT_TRUE(std::is_sorted(group.begin(), group.end()));
    std::vector<int> owner(n, -1);
    for (const int j : group) {
      ++seen[static_cast<std::size_t>(j)];
      for (const int i : pattern[static_cast<std::size_t>(j)]) {
        EXPECT_EQ(owner[static_cast<std::size_t>(i)], -1)
            << "columns " << owner[static_cast<std::size_t>(i)] << " and " << j
            << " of one group both touch row " << i;
        owner[static_cast<std::size_t>(i)] = j;
      }
    }
  }
  for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(seen[j], 1) << "state " << j;
  EXPECT_EQ(static_cast<int>(groups.size()), bound);
  std::printf("%zu states, %zu groups, largest row %d non-zeros\n", n, groups.size(), bound);
}

}  // namespace
}  // namespace ferro::vehicle
