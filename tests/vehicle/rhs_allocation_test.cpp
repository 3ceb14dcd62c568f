// The right-hand side of a vehicle allocates nothing once its workspace has grown: it runs
// 10^5 times per simulated second, and a heap allocation per call costs as much as the contact
// geometry itself. Manchester vehicle 1 on S1002 / UIC60 through the multi-point contact table,
// on the discrete track (one geometry query per rail), at its static equilibrium and with the
// leading wheelset against the flange (two contact points on a wheel).
//
// Oracle: the count of global operator new calls (every std::vector, std::string and
// std::function allocation goes through it) around the calls is zero. Eigen's dynamic matrices
// allocate with malloc and are not counted here.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "ferro/vehicle/vehicle_model.hpp"
#include "manchester_config.hpp"
#include "model_helpers.hpp"

namespace {
std::atomic<long> g_news{0};
}  // namespace

// Replacements of the global allocation functions for this test program (every form that is not
// over-aligned, so that whatever one form allocates another may free): counted, then malloc.
namespace {
void* counted_malloc(std::size_t n) noexcept {
  g_news.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n == 0 ? 1 : n);
}
}  // namespace
// GCC takes free() in a replacement delete for a mismatch with the new it inlines beside it
// (-Wmismatched-new-delete); these replacements pair malloc with free by construction.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  if (void* p = counted_malloc(n)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted_malloc(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted_malloc(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace ferro::vehicle {
namespace {

using testing::signal;

constexpr double kG = 9.81;

TEST(VehicleRhsAllocation, table_geometry_on_the_discrete_track_allocates_nothing) {
  VehicleModelInputs in;
  in.track_structure.kind = track::TrackStructureSpec::Kind::discrete;
  in.config = testing::manchester_vehicle1(kG);
  WheelRailSpec& wr = in.config.wheel_rail;
  wr.geometry = "table";
  wr.wheel_profile = "profiles/MBench_S1002_v3.prw";
  wr.rail_profile = "profiles/MBench_UIC60_v3.prr";
  wr.track_gauge = 1.435;
  wr.flange_back_distance = 1.360;
  wr.flange_back_y = -0.070;
  wr.nominal_radius = 0.46;
  in.geometry = make_geometry_source(wr, FERRO_DATA_DIR);
  in.speed.initial = 30.0;
  const VehicleModel m(in);
  const std::vector<double> rest = static_equilibrium(m, 0.0);
  // The leading wheelset moved to the left until its left wheel touches on two points (tread
  // and flange root: S1002 / UIC60 1:40 changes over near 6.2 mm).
  std::vector<double> flange = rest;
  const int iy = m.state_index("wheelset_1", Dof::y);
  ASSERT_GE(iy, 0);
  std::vector<double> s(m.signal_info().size());
  double points = 0.0, shift = 0.0;
  for (int k = 0; k <= 60 && points < 2.0; ++k) {
    shift = 5.0e-3 + 0.05e-3 * k;
    flange[static_cast<std::size_t>(iy)] = rest[static_cast<std::size_t>(iy)] + shift;
    m.signals(0.0, flange, s);
    points = signal(m, s, "wheelset_1.left.points");
  }
  ASSERT_GE(points, 2.0) << "no two-point contact of the left wheel for shifts of 5-8 mm";

  std::vector<double> xdot(m.size());
  ASSERT_EQ(m.rhs(0.0, rest, xdot), 0);    // the workspace grows here
  ASSERT_EQ(m.rhs(0.0, flange, xdot), 0);
  const long before = g_news.load();
  for (int k = 0; k < 100; ++k) {
    ASSERT_EQ(m.rhs(1e-3 * k, k % 2 == 0 ? rest : flange, xdot), 0);
  }
  const long news = g_news.load() - before;
  EXPECT_EQ(news, 0) << "allocations in 100 right-hand sides";
  std::printf("operator new calls in 100 right-hand sides: %ld (left wheel on %.0f points at a "
              "shift of %.2f mm)\n",
              news, points, shift * 1e3);
}

}  // namespace
}  // namespace ferro::vehicle
