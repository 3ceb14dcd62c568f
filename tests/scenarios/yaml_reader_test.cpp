// The strict YAML reader's structure check against alias expansion: the node count of an
// expanded document has a closed form, and the check must reach it without expanding.
#include <gtest/gtest.h>

#include <ctime>
#include <string>

#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios {
namespace {

// Levels a0 .. a_top: a0 a list of 10 scalars, a_k a list of 10 aliases of a_{k-1}. Expanded,
// a_k holds (10^(k+2) - 1) / 9 nodes (list node included) and the whole document that plus one
// per level and the root.
std::string alias_levels(int top) {
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int k = 1; k <= top; ++k) {
    text += "a" + std::to_string(k) + ": &a" + std::to_string(k) + " [";
    for (int i = 0; i < 10; ++i) text += (i ? ", *a" : "*a") + std::to_string(k - 1);
    text += "]\n";
  }
  return text;
}

TEST(yaml_reader, alias_expansion_counted_to_the_node) {
  // Closed form: 1 + sum_{k=0..4} (10^(k+2) - 1) / 9 = 123,456 nodes <= 10^6: accepted.
  EXPECT_NO_THROW((void)parse_yaml_text(alias_levels(4), "four.yaml"));
  // One level more: a5 alone expands to 1,111,111 > 10^6 nodes.
  try {
    (void)parse_yaml_text(alias_levels(5), "five.yaml");
    ADD_FAILURE() << "a 1.2e6-node expansion was accepted";
  } catch (const YamlInputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 1000000 nodes"), std::string::npos)
        << e.what();
  }
}

TEST(yaml_reader, billion_laughs_rejected_without_expanding) {
  // 10^12 nodes expanded: a walk of the expansion would take hours, the check is linear in
  // the text. Bound: one CPU second (the text holds 11 lines).
  constexpr double kMaxCpuSeconds = 1.0;
  const std::clock_t start = std::clock();
  EXPECT_THROW((void)parse_yaml_text(alias_levels(10), "laughs.yaml"), YamlInputError);
  EXPECT_LT(static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC, kMaxCpuSeconds);
}

TEST(yaml_reader, nesting_through_an_alias_is_bounded) {
  // A 40-level list anchored once and used inside itself 40 levels deeper: 80 levels expanded.
  std::string deep = "a: &d ";
  for (int i = 0; i < 40; ++i) deep += "[";
  deep += "x";
  for (int i = 0; i < 40; ++i) deep += "]";
  deep += "\nb: ";
  for (int i = 0; i < 40; ++i) deep += "[";
  deep += "*d";
  for (int i = 0; i < 40; ++i) deep += "]";
  deep += "\n";
  try {
    (void)parse_yaml_text(deep, "deep.yaml");
    ADD_FAILURE() << "80 levels accepted";
  } catch (const YamlInputError& e) {
    EXPECT_NE(std::string(e.what()).find("nested deeper than 64 levels"), std::string::npos)
        << e.what();
  }
}

TEST(yaml_reader, comma_line_in_a_root_list_is_refused_not_looped_on) {
  // yaml-cpp 0.7 loops without end, allocating, on a root block list followed by a line that
  // starts with ','. A ferrodyn file's root is a mapping: refused at the list's first line.
  for (const char* text : {"- a\n, c\n", "- a: b\n# note\n- c\n,\n", "- {a: 1}\n, c\n"}) {
    try {
      (void)parse_yaml_text(text, "list.yaml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const YamlInputError& e) {
      EXPECT_EQ(e.line(), 1) << e.what();
      EXPECT_NE(std::string(e.what()).find("got a list"), std::string::npos) << e.what();
    }
  }
}

TEST(yaml_reader, comma_line_left_of_an_indented_root_is_refused_not_looped_on) {
  // Same loop on a root mapping indented by one or more columns and a later ',' line left of
  // it: refused at that line.
  for (const char* text : {" a: 1\n, c\n", "  a: 1\n b: 2\n , c\n", " a:\n  - x\n, c\n"}) {
    try {
      (void)parse_yaml_text(text, "indented.yaml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const YamlInputError& e) {
      EXPECT_GE(e.line(), 2) << e.what();
      EXPECT_NE(std::string(e.what()).find("cannot start with ','"), std::string::npos)
          << e.what();
    }
  }
  // A multi-line flow list with leading commas under a root at column 0 stays valid.
  EXPECT_NO_THROW((void)parse_yaml_text("a: [1\n, 2]\nb: 3\n", "flow.yaml"));
}

TEST(yaml_reader, comma_after_a_tag_or_anchor_at_document_start_is_refused_not_looped_on) {
  // Same loop when the document's first token after its properties is ','.
  for (const char* text : {"!x,\n", " !xx*kk,kk]\n", "&a\n,\n", "--- !x &a ,\n", "! ,\n"}) {
    try {
      (void)parse_yaml_text(text, "tag.yaml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const YamlInputError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot start with ','"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace ferro::scenarios
