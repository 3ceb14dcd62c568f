// make_contact_source(): every kind, the table cache (reused while its inputs are unchanged,
// rebuilt otherwise), and the error naming the field and the allowed values.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ferro/contact/geometry/contact_source_factory.hpp"
#include "ferro/contact/geometry/multi_point_contact_table.hpp"
#include "ferro/io/hdf5.hpp"

namespace fc = ferro::contact;
namespace fio = ferro::io;

namespace {

const std::string kData = FERRO_DATA_DIR;

fc::ContactSourceSpec a22_spec(const std::string& kind) {
  fc::ContactSourceSpec s;
  s.kind = kind;
  s.wheel_profile = kData + "/profiles/MBench_S1002_v3.prw";
  s.rail_profile = kData + "/profiles/MBench_UIC60_v3.prr";
  s.pair.track_gauge = 1.435;
  s.pair.flange_back_distance = 1.360;
  s.pair.flange_back_y = -0.070;
  s.pair.nominal_radius = 0.460;
  s.table.lateral_min = -1e-3;
  s.table.lateral_max = 1e-3;
  s.table.roll_min = s.table.roll_max = 0.0;
  return s;
}

}  // namespace

TEST(make_contact_source, every_kind_and_the_table_cache) {
  EXPECT_EQ(fc::make_contact_source(a22_spec("search"))->name(), "search");
  fc::ContactSourceSpec imp;
  imp.kind = "imported";
  imp.imported_table = kData + "/cooperrider_wagon/contact_table_s1002_uic60_1in40.csv";
  EXPECT_EQ(fc::make_contact_source(imp)->name(), "imported");
  fc::ContactSourceSpec con;
  con.kind = "conical";
  con.conical = {0.05, 0.75, 0.46, 1.09, 3.3};
  EXPECT_EQ(fc::make_contact_source(con)->name(), "conical");

  fc::ContactSourceSpec tab = a22_spec("table");
  tab.table_file = std::string(FERRO_BINARY_DIR) + "/factory_table_test.h5";
  std::filesystem::remove(tab.table_file);
  const auto built = fc::make_contact_source(tab);
  ASSERT_TRUE(std::filesystem::exists(tab.table_file));
  const auto mtime = std::filesystem::last_write_time(tab.table_file);
  const auto cached = fc::make_contact_source(tab);  // read back, not rebuilt
  EXPECT_EQ(std::filesystem::last_write_time(tab.table_file), mtime);
  fc::WheelsetPose pose{0.37e-3, 0.0, 0.0, 0.0};
  pose = fc::touching_pose(fc::WheelRailPair(fc::read_profile(tab.wheel_profile, fc::ProfileKind::wheel),
                                             fc::read_profile(tab.rail_profile, fc::ProfileKind::rail),
                                             tab.pair),
                           pose);
  pose.vertical += 50e-6;
  std::vector<fc::WheelRailContact> a, b;
  built->contacts(pose, a);
  cached->contacts(pose, b);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].penetration, b[i].penetration);
  // Another grid: the cache no longer belongs to the inputs and is rebuilt.
  tab.table.lateral_step = 0.2e-3;
  const auto rebuilt = fc::make_contact_source(tab);
  const auto& t = dynamic_cast<const fc::MultiPointContactTable&>(*rebuilt);
  EXPECT_EQ(t.node_count(), 11u);
  EXPECT_EQ(fc::MultiPointContactTable::load_hdf5(tab.table_file).node_count(), 11u);
  // A yaw axis, then another one: each is another table, the cache is rebuilt each time; back
  // without it, rebuilt again.
  tab.table.yaw_min = -0.010;
  tab.table.yaw_max = 0.010;
  tab.table.yaw_step = 0.005;
  (void)fc::make_contact_source(tab);
  EXPECT_EQ(fc::MultiPointContactTable::load_hdf5(tab.table_file).node_count(), 55u);
  tab.table.yaw_step = 0.010;
  (void)fc::make_contact_source(tab);
  EXPECT_EQ(fc::MultiPointContactTable::load_hdf5(tab.table_file).node_count(), 33u);
  tab.table.yaw_min = tab.table.yaw_max = 0.0;
  (void)fc::make_contact_source(tab);
  EXPECT_EQ(fc::MultiPointContactTable::load_hdf5(tab.table_file).node_count(), 11u);
  // A cache in an older layout (format_version 1, 15 columns) is rebuilt, not an error; a file
  // that is not a table at all is still refused by name.
  {
    fio::H5File old = fio::H5File::create(tab.table_file);
    old.set_attribute("/", "format_version", 1.0);
    old.write_array("/node_offset", std::vector<double>{0.0}, {1});
    old.write_array("/candidates", std::vector<double>(15, 0.0), {1, 15});
  }
  EXPECT_TRUE(fc::MultiPointContactTable::is_table_of_another_version(tab.table_file));
  (void)fc::make_contact_source(tab);
  EXPECT_EQ(fc::MultiPointContactTable::load_hdf5(tab.table_file).node_count(), 11u);
  EXPECT_FALSE(fc::MultiPointContactTable::is_table_of_another_version(tab.table_file));
  std::filesystem::remove(tab.table_file);
  // The cache is written beside its path and renamed over it (so runs started together never
  // read a half-written file), into a directory created on demand; nothing else is left behind.
  const std::filesystem::path dir = std::string(FERRO_BINARY_DIR) + "/factory_table_cache_dir";
  std::filesystem::remove_all(dir);
  tab.table_file = (dir / "table.h5").string();
  (void)fc::make_contact_source(tab);
  ASSERT_TRUE(std::filesystem::exists(tab.table_file));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator{}),
            1);
  std::filesystem::remove_all(dir);
}

TEST(make_contact_source, unknown_kind_names_the_field_and_the_allowed_values) {
  fc::ContactSourceSpec s;
  s.kind = "tabel";
  try {
    (void)fc::make_contact_source(s);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "ContactSourceSpec.kind: 'tabel' is not one of table, search, imported, conical"),
              std::string::npos)
        << e.what();
  }
  s.kind = "imported";
  EXPECT_THROW((void)fc::make_contact_source(s), std::invalid_argument);
}
