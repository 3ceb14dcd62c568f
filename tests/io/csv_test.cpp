// The one reader of delimited text tables: cells, comments, headers, numbers and located errors.
#include "ferro/io/csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ferro::io {
namespace {

using Cells = std::vector<std::string>;

// The message of the std::invalid_argument `f` throws ("" when it does not throw).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(csv, header_rows_comments_and_blank_lines) {
  std::istringstream in("# made by hand\n\nx, y ,z\r\n1,2,3\n  # another\n4, 5e-3 ,-6\n");
  CsvReader r(in, "table.csv");
  EXPECT_EQ(r.header(), (Cells{"x", "y", "z"}));
  EXPECT_TRUE(r.has_column("y"));
  EXPECT_FALSE(r.has_column("w"));
  Cells c;
  ASSERT_TRUE(r.next(c));
  EXPECT_EQ(c, (Cells{"1", "2", "3"}));
  EXPECT_EQ(r.line(), 4);
  ASSERT_TRUE(r.next(c));
  EXPECT_EQ(r.line(), 6);
  EXPECT_EQ(r.number(c, 1), 5e-3);
  EXPECT_EQ(r.number(c, 2), -6.0);
  EXPECT_FALSE(r.next(c));
  EXPECT_EQ(r.comments(), (Cells{"made by hand", "another"}));
}

TEST(csv, errors_name_source_line_and_column) {
  std::istringstream in("a,b\n1,2\n3\n");
  CsvReader r(in, "in.csv");
  Cells c;
  ASSERT_TRUE(r.next(c));
  EXPECT_EQ(error_of([&] {
              (void)r.number(Cells{"1", "2x"}, 1);
            }),
            "in.csv:2, column 'b': not a number: '2x'");
  EXPECT_EQ(error_of([&] {
              (void)r.number(Cells{"nan", "1"}, 0);
            }),
            "in.csv:2, column 'a': not a finite number: 'nan'");
  EXPECT_EQ(error_of([&] { r.next(c); }), "in.csv:3: 1 cells, the header has 2");
  EXPECT_EQ(error_of([&] { r.require_known_columns({"a"}); }),
            "in.csv:1: unknown CSV column 'b'; allowed: a");

  std::istringstream twice("a,a\n");
  EXPECT_EQ(error_of([&] { CsvReader t(twice, "t.csv"); }), "t.csv:1: column 'a' appears twice");
  std::istringstream empty("# nothing\n\n");
  EXPECT_NE(error_of([&] { CsvReader t(empty, "e.csv"); }).find("e.csv: empty input"),
            std::string::npos);
  EXPECT_EQ(error_of([] { (void)CsvReader::open("/no/such/file.csv", {}, "contact table"); }),
            "/no/such/file.csv: cannot open the contact table");
}

TEST(csv, blank_separated_tables_without_header) {
  CsvFormat f;
  f.separators = ",;\t";
  f.blank_separated = true;
  f.comment_marks = "#!%";
  f.header = false;
  EXPECT_EQ(split_cells("1.5  2.5", f), (Cells{"1.5", "2.5"}));
  EXPECT_EQ(split_cells("1.5 , 2.5;3", f), (Cells{"1.5", "2.5", "3"}));
  EXPECT_EQ(split_cells("\t1.5\t2.5 ", f), (Cells{"1.5", "2.5"}));
  std::istringstream in("% profile\n-10 0.5 1\n! note\n10,0.25\n");
  CsvReader r(in, "p.txt", f);
  Cells c;
  ASSERT_TRUE(r.next(c));
  EXPECT_EQ(c, (Cells{"-10", "0.5", "1"}));
  ASSERT_TRUE(r.next(c));
  EXPECT_EQ(r.number(c, 1), 0.25);
  EXPECT_EQ(error_of([&] {
              (void)r.number(Cells{"a", "b"}, 1);
            }),
            "p.txt:4, column 2: not a number: 'b'");
}

TEST(csv, trailing_comments_and_lines) {
  CsvFormat f = CsvFormat::blanks();
  f.comment_marks = "!";
  f.trailing_comments = true;
  std::istringstream in("key = 'value' ! why\n! only a comment\n  point.begin   \n");
  CsvReader r(in, "s.prw", f);
  std::string line;
  ASSERT_TRUE(r.next_line(line));
  EXPECT_EQ(line, "key = 'value'");
  ASSERT_TRUE(r.next_line(line));
  EXPECT_EQ(line, "point.begin");
  EXPECT_EQ(r.line(), 3);
  EXPECT_FALSE(r.next_line(line));
}

TEST(csv, numbers_are_read_whole_and_exactly) {
  EXPECT_EQ(parse_number("0.1"), 0.1);
  EXPECT_EQ(parse_number(" +2.5e-3 "), 2.5e-3);
  EXPECT_EQ(parse_number("-0.20000000000000001"), -0.2);
  EXPECT_TRUE(std::isnan(*parse_number("nan")));
  EXPECT_FALSE(parse_number("1.0x"));
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("1 2"));
  EXPECT_EQ(split_cells("a,,b,"), (Cells{"a", "", "b", ""}));
}

}  // namespace
}  // namespace ferro::io
