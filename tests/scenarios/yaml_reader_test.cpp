// The strict YAML reader's structure check against alias expansion: the node count of an
// expanded document has a closed form, and the check must reach it without expanding.
#include <gtest/gtest.h>

#include <fmt/format.h>

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

// Inputs holding a ',' outside every flow collection, on which yaml-cpp 0.7 loops without end
// (each verified to loop): refused at the ',' with its line and column.
struct StrayComma {
  const char* text;
  int line;
  int column;
};

TEST(yaml_reader, comma_outside_flow_collections_is_refused_not_looped_on) {
  const StrayComma cases[] = {
      {" a: 1\n, c\n", 2, 1},              // left of an indented root mapping
      {"  a: 1\n b: 2\n , c\n", 3, 2},     //
      {" a:\n  - x\n, c\n", 3, 1},         //
      {"!x,\n", 1, 3},                     // right after a tag or an anchor
      {" !xx*kk,kk]\n", 1, 8},             //
      {"&a\n,\n", 2, 1},                   //
      {"--- !x &a ,\n", 1, 11},            //
      {"! ,\n", 1, 3},                     //
      {"!&x\"\"\"# t\n\"\n, y\n", 3, 1},     //   a tag ends where its characters end
      {"&a foo\n, bar\n", 2, 1},           // after an anchored or tagged root scalar
      {"&a foo\n\n# note\n, bar\n", 4, 1}, //
      {"!t foo\n, bar\n", 2, 1},           //
      {"\"foo\"\n, bar\n", 2, 1},          // after a quoted root scalar, on its line or the next
      {"'x', y\n", 1, 4},                  //
      {"&a 'x' , y\n", 1, 8},              //
      {"\"a\"\"W\nWx\n\"\n, \n", 4, 1},    // after a second quoted scalar that spans lines
      {"[a], b\n", 1, 4},                  // after a root flow collection
      {"&a [1]\n, bar\n", 2, 1},           //
      {"[a:\"b]\n, c\n", 2, 1},            //   whose plain scalar holds ':' and a quote
      {"[a:'b]\n, c\n", 2, 1},              //
      {"[a]#\"\n, b\n", 2, 1},              //   with a comment right after it
      {"{a: \"b\"}\n, c\n", 2, 1},          //
      {"{a: 1}\n, b\n", 2, 1},             //
      {" a: foo\n  \"b\n, x\n", 3, 1},       // after a plain scalar's next line (text, not a
      {" a: foo\n  [b\n, x\n", 3, 1},        //   quote or a bracket)
      {" a:\n   foo\n   \"b\n, x\n", 4, 1},  //
      {"|\n, foo\n", 2, 1},                // left of a root block scalar's content
      {"a: 1\n---\n, x\n", 3, 1},          // at the start of a second document
      {"\xef\xbb\xbf, x\n", 1, 1},            // after a byte order mark
  };
  for (const StrayComma& c : cases) {
    try {
      (void)parse_yaml_text(c.text, "comma.yaml");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const YamlInputError& e) {
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_NE(std::string(e.what()).find(fmt::format(":{}:{}: ", c.line, c.column)),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("',' outside [ ] or { }"), std::string::npos)
          << e.what();
    }
  }
}

TEST(yaml_reader, explicit_keys_are_refused_where_they_stand) {
  // yaml-cpp 0.7 loops without end on a '?' key line after a root scalar with a tag or anchor
  // (each verified to loop; found by fuzzing). Keys are plain words: every explicit key is
  // refused at its place.
  const StrayComma cases[] = {{"!t x\n? a\n", 2, 1},
                              {" !t x\n ? a\n", 2, 2},
                              {"&a x\n?\n", 2, 1},
                              {"!&7m0.as: mqual\n? [a, b]t\n", 2, 1},
                              {"a: 1\n? [a, b]\n: 1\n", 2, 1}};
  for (const StrayComma& c : cases) {
    try {
      (void)parse_yaml_text(c.text, "key.yaml");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const YamlInputError& e) {
      EXPECT_EQ(e.key(), "(key)") << e.what();
      EXPECT_NE(std::string(e.what()).find(fmt::format(":{}:{}: ", c.line, c.column)),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("a key must be a plain word"), std::string::npos)
          << e.what();
    }
  }
  // A '?' inside a value stays text.
  EXPECT_EQ(parse_yaml_text("a: x ? y\nb: ?z\n", "key.yaml").root["b"].as<std::string>(), "?z");
}

TEST(yaml_reader, endless_document_stream_is_cut_and_refused) {
  // yaml-cpp 0.7 reads the ',' of line 4 (after the byte order mark, the quotes and the plain
  // scalar "$'", it is a token) as one more empty document, again and again (found by fuzzing):
  // the reader counts documents up to a bound and refuses the file at the second one.
  const std::string text = "\xef\xbb\xbf''\n''$'\n'',\n'v'`";
  try {
    (void)parse_yaml_text(text, "stream.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const YamlInputError& e) {
    EXPECT_NE(std::string(e.what()).find("stream.yaml:2:1: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("YAML documents in one file"), std::string::npos)
        << e.what();
  }
}

TEST(yaml_reader, control_bytes_are_refused_at_their_place) {
  // YAML allows no C0 control character but tab and line ends, nor DEL; yaml-cpp 0.7 takes a
  // NUL for a UTF-16/32 marker and loops without end on "\0, b" (found by fuzzing).
  struct Bad {
    std::string text;
    int line, column;
    const char* byte;
  };
  const Bad cases[] = {{std::string("\0, b\n", 5), 1, 1, "0x00"},
                       {std::string("a: 1\nb: x\0y\n", 12), 2, 5, "0x00"},
                       {"a: 1\n\x04, b\n", 2, 1, "0x04"},
                       {"a: \x7f\n", 1, 4, "0x7f"}};
  for (const Bad& c : cases) {
    try {
      (void)parse_yaml_text(c.text, "bytes.yaml");
      ADD_FAILURE() << "accepted byte " << c.byte;
    } catch (const YamlInputError& e) {
      EXPECT_NE(std::string(e.what()).find(fmt::format(":{}:{}: ", c.line, c.column)),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(std::string("byte ") + c.byte), std::string::npos)
          << e.what();
    }
  }
  // Tabs, CRLF line ends and UTF-8 text stay valid.
  const YamlFile f = parse_yaml_text("a:\t1\r\nb: \xc2\xb5m\r\n", "bytes.yaml");
  EXPECT_EQ(f.root["a"].as<int>(), 1);
  EXPECT_EQ(f.root["b"].as<std::string>(), "\xc2\xb5m");
}

TEST(yaml_reader, commas_inside_flow_collections_quotes_and_block_scalars_stay_valid) {
  // Leading commas in a multi-line flow list, in a quoted or block scalar's text, in a comment
  // and inside a plain value, and a quote and a bracket in a plain value's next line: valid
  // YAML, read as written.
  const YamlFile f = parse_yaml_text(
      "a: [1\n, 2]\n"
      "b: {x: 1\n  , y: 2}\n"
      "c: \"one\n  , two\"\n"
      "d: 'it''s\n  , three'\n"
      "e: |\n  , four\n"
      "# , a comment\n"
      "f: it's five, six  # , note\n"
      "g: x [y], z\n"
      "h: one\n  \"two [three\n",
      "commas.yaml");
  EXPECT_EQ(f.root["a"].size(), 2U);
  EXPECT_EQ(f.root["b"]["y"].as<int>(), 2);
  EXPECT_EQ(f.root["c"].as<std::string>(), "one , two");
  EXPECT_EQ(f.root["d"].as<std::string>(), "it's , three");
  EXPECT_EQ(f.root["e"].as<std::string>(), ", four\n");
  EXPECT_EQ(f.root["f"].as<std::string>(), "it's five, six");
  EXPECT_EQ(f.root["g"].as<std::string>(), "x [y], z");
  EXPECT_EQ(f.root["h"].as<std::string>(), "one \"two [three");
}

}  // namespace
}  // namespace ferro::scenarios
