// Requirement: the .frd reader returns CalculiX's node coordinates and the last increment's
// result blocks exactly as written; every malformed, truncated or garbled file gives a
// CalculixOutputError with a one-line message (never a crash, never another exception); the
// .12d expansion map brings node-to-surface contact results back to the deck's nodes; and the
// results of ccx's own output map onto our node indices.
//
// The data files are ccx 2.20 output of test::patch_model (2 x 2 block on a 1-element indenter,
// node-to-surface, K = 1000 E / h) written by this adapter.

#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/expansion_map.hpp"
#include "adapters/calculix/frd_reader.hpp"
#include "adapters/calculix/result_mapping.hpp"
#include "calculix_test_support.hpp"
#include "support/tolerance.hpp"

namespace cs::adapters::calculix {
namespace {

using cs::testing::Near;

std::string data(const std::string& name) {
  return read_text_file(std::string(CONTACT_SUITE_SOURCE_DIR) + "/tests/adapters/data/" + name);
}

test::PatchSpec data_spec(solver::ElementType type) {
  test::PatchSpec s;
  s.type = type;
  s.nx = 2;
  s.nz = 2;
  s.indenter_nx = 1;
  return s;
}

TEST(FrdReader, ReadsNodesAndBlocksOfCcxOutput) {
  const FrdFile frd = parse_frd(data("patch_q4_ns.frd"));
  const solver::Model model = test::patch_model(data_spec(solver::ElementType::Q4));
  ASSERT_EQ(frd.nodes.ids.size(), static_cast<std::size_t>(model.mesh.n_nodes()));
  EXPECT_EQ(frd.nodes.ids.front(), 1);
  EXPECT_EQ(frd.nodes.coordinates[3 * 2], 1.0);  // node 3: (1, 0, 0), the block's corner
  for (const char* name : {"DISP", "STRESS", "FORC", "CONTACT", "ERROR"})
    EXPECT_NE(frd.last_block(name), nullptr) << name;
  EXPECT_EQ(frd.last_block("NONE"), nullptr);
  const FrdResultBlock& stress = *frd.last_block("STRESS");
  EXPECT_EQ(stress.components,
            (std::vector<std::string>{"SXX", "SYY", "SZZ", "SXY", "SYZ", "SZX"}));
  EXPECT_EQ(stress.n_nodes(), model.mesh.n_nodes());
  EXPECT_EQ(stress.time, 1.0);
  const FrdResultBlock& disp = *frd.last_block("DISP");
  EXPECT_EQ(disp.components, (std::vector<std::string>{"D1", "D2", "D3"}));  // ALL not stored
  const FrdResultBlock& contact = *frd.last_block("CONTACT");
  EXPECT_EQ(contact.component("CPRESS"), 3);
  EXPECT_EQ(contact.n_nodes(), 6);  // 3 slave nodes x 2 expanded copies (front, back)
}

TEST(FrdReader, MapsOntoOurNodes) {
  const solver::Model model = test::patch_model(data_spec(solver::ElementType::Q4));
  CalculixResult result;
  map_results(parse_frd(data("patch_q4_ns.frd")), parse_expansion(data("patch_q4_ns.12d")), model,
              test::patch_pair(), result);
  // sigma_z = -p in the block to CalculiX's residual tolerance (see test_calculix_runs.cpp).
  for (int n = 0; n < model.mesh.n_nodes(); ++n) {
    if (model.mesh.nodes[n].y() >= 0.0) {
      EXPECT_TRUE(Near(result.nodal_stress[n].sigma_z, -1.0, {2e-3, 0})) << n;
    }
  }
  ASSERT_EQ(result.contact.size(), 3u);
  for (const auto& c : result.contact) {
    EXPECT_TRUE(c.reported);
    EXPECT_TRUE(Near(c.pressure, 1.0, {1e-3, 0}));      // Q4 node-to-surface: exact
    EXPECT_TRUE(Near(c.penetration, 5e-7, {0.01, 0}));  // p / K, K = 1000 E / 0.5
  }
  EXPECT_LT(result.contact[0].position.x(), result.contact[2].position.x());  // along x
}

TEST(ExpansionMap, MapsEveryExpandedCopyToItsNode) {
  // Q8 -> C3D20: corners have three copies (two faces and mid-thickness), mid-sides two.
  const ExpansionMap q8 = parse_expansion(data("patch_q8_ns.12d"));
  EXPECT_EQ(deck_node(q8, 30), 1);
  EXPECT_EQ(deck_node(q8, 31), 1);
  EXPECT_EQ(deck_node(q8, 32), 1);
  EXPECT_EQ(deck_node(q8, 33), 2);  // mid-side node 2: copies 33 and 35
  EXPECT_EQ(deck_node(q8, 35), 2);
  EXPECT_EQ(q8.count(34), 0u);     // mid-thickness copy of a mid-side node: not used
  EXPECT_EQ(deck_node(q8, 7), 7);  // a deck node maps to itself
  const ExpansionMap q4 = parse_expansion(data("patch_q4_ns.12d"));
  EXPECT_EQ(q4.size(), 2u * 13u);  // 13 nodes x 2 faces
}

TEST(ExpansionMap, Q8ContactResultsReachTheSlaveNodes) {
  const solver::Model model = test::patch_model(data_spec(solver::ElementType::Q8));
  CalculixResult result;
  map_results(parse_frd(data("patch_q8_ns.frd")), parse_expansion(data("patch_q8_ns.12d")), model,
              test::patch_pair(), result);
  ASSERT_EQ(result.contact.size(), 5u);
  for (const auto& c : result.contact)
    EXPECT_TRUE(c.reported) << c.node;
  // CalculiX's node-to-surface pressures on quadratic faces alternate between corner and
  // mid-side nodes (its spring areas split a face evenly; the consistent forces do not).
  EXPECT_TRUE(Near(result.contact[0].pressure, 0.642, {0.01, 0}));
  EXPECT_TRUE(Near(result.contact[1].pressure, 1.388, {0.01, 0}));
}

TEST(FrdReader, ReadsTouchingFieldsNanAndThreeDigitExponents) {
  const std::string text =
      "    1C\n"
      "    2C                             2                                     1\n"
      " -1         1 1.00000E+00-2.00000E+00 0.00000E+00\n"
      " -1         2 1.00000E-100-2.0E+00 3\n"
      " -3\n"
      "  100CL  101 2.000000000           2                     0    2           1\n"
      " -4  STRESS      7    1\n"
      " -5  S1          1    4    1    1\n -5  S2          1    4    1    1\n"
      " -5  S3          1    4    1    1\n -5  S4          1    4    1    1\n"
      " -5  S5          1    4    1    1\n -5  S6          1    4    1    1\n"
      " -5  S7          1    4    1    1\n"
      " -1         1 1.00000E+00-2.00000E+00 3.00000E+00 4.0 5.0 6.0\n"
      " -2           7.00000E+00\n"
      " -1         2         NaN        -inf 0 0 0 0\n"
      " -2           1\n"
      " -3\n"
      " 9999\n";
  const FrdFile frd = parse_frd(text);
  EXPECT_EQ(frd.nodes.coordinates[1], -2.0);
  EXPECT_EQ(frd.nodes.coordinates[3], 1e-100);
  const FrdResultBlock& b = *frd.last_block("STRESS");
  EXPECT_EQ(b.time, 2.0);
  EXPECT_EQ(b.value(0, 6), 7.0);  // the continuation record
  EXPECT_TRUE(std::isnan(b.value(1, 0)));
  EXPECT_EQ(b.value(1, 1), -INFINITY);
}

TEST(FrdReader, LastBlockIsTheLastIncrement) {
  auto with = [](const std::string& time, const std::string& value) {
    return "  100CL  101 " + time + "           1                     0    1           1\n" +
           " -4  DISP        1    1\n -5  D1          1    2    1    0\n -1         1 " + value +
           "\n -3\n";
  };
  const std::string text =
      "    2C        1                                     1\n"
      " -1         1 0.0 0.0 0.0\n -3\n" +
      with("0.500000000", "1.0") + with("1.000000000", "2.0") + " 9999\n";
  const FrdFile frd = parse_frd(text);
  ASSERT_EQ(frd.blocks.size(), 2u);
  EXPECT_EQ(frd.last_block("DISP")->value(0, 0), 2.0);
  EXPECT_EQ(frd.last_block("DISP")->time, 1.0);
}

void expect_output_error(const std::string& text, const std::string& fragment) {
  try {
    parse_frd(text, "t.frd");
    FAIL() << "no error for: " << text.substr(0, 200);
  } catch (const CalculixOutputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;  // one line
    EXPECT_EQ(message.rfind("t.frd: line ", 0), 0u) << message;
  }
}

TEST(FrdReader, MalformedFilesAreTypedErrors) {
  const std::string good = data("patch_q4_ns.frd");
  expect_output_error("", "no end record");
  expect_output_error(good.substr(0, good.rfind(" 9999")), "no end record");
  expect_output_error(good.substr(0, good.find(" -3")), "truncated file");
  std::string binary = good;
  binary.replace(binary.find("                                     1\n"), 39,
                 "                                     2\n");
  expect_output_error(binary, "binary results are not supported");
  std::string missing_row = good;
  const std::size_t row = missing_row.find(" -1         3 ");
  missing_row.erase(row, missing_row.find('\n', row) - row + 1);
  expect_output_error(missing_row, "declares 13 nodes but holds 12");
  std::string bad_number = good;
  bad_number.replace(bad_number.find("5.00000E-01"), 11, "5.0000#E-01");
  expect_output_error(bad_number, "bad number");
  expect_output_error("    7X\n", "unexpected record");
  expect_output_error(" 9999\n", "no node block");
}

TEST(FrdReader, EveryTruncationIsATypedError) {
  const std::string good = data("patch_q8_ns.frd");
  ASSERT_NO_THROW(parse_frd(good));
  // Cut after every line and at 400 random bytes: an error, or (only for cuts inside the last
  // line, which then still ends the file) a parse. Nothing else.
  std::vector<std::size_t> cuts;
  for (std::size_t i = 0; i < good.size(); ++i) {
    if (good[i] == '\n')
      cuts.push_back(i + 1);
  }
  std::mt19937 rng(42);
  for (int k = 0; k < 400; ++k)
    cuts.push_back(std::uniform_int_distribution<std::size_t>(0, good.size() - 1)(rng));
  int errors = 0;
  for (std::size_t cut : cuts) {
    if (cut >= good.rfind(" 9999"))
      continue;
    try {
      parse_frd(good.substr(0, cut));
      ADD_FAILURE() << "a file cut at byte " << cut << " parsed";
    } catch (const CalculixOutputError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 500);
}

TEST(FrdReader, GarbledFilesNeverEscapeTheTypedError) {
  const std::string good = data("patch_q4_ns.frd");
  std::mt19937 rng(7);
  const std::string alphabet = " -+.0123456789E\nCX9\r\t\0\xff";
  int parsed = 0, rejected = 0;
  for (int k = 0; k < 3000; ++k) {
    std::string text = good;
    const int edits = 1 + k % 8;
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
      text[at] = alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
    }
    try {
      const FrdFile frd = parse_frd(text);
      for (const auto& b : frd.blocks)  // a parse is internally consistent
        ASSERT_EQ(b.values.size(), b.node_ids.size() * b.components.size());
      ++parsed;
    } catch (const CalculixOutputError&) {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 0);
  EXPECT_EQ(parsed + rejected, 3000);
}

TEST(ExpansionMap, MalformedTextIsATypedError) {
  const std::string good = data("patch_q4_ns.12d");
  EXPECT_TRUE(parse_expansion("").empty());
  EXPECT_THROW(parse_expansion(good.substr(0, good.size() / 2)), CalculixOutputError);
  EXPECT_THROW(parse_expansion("garbage"), CalculixOutputError);
  EXPECT_THROW(parse_expansion(" ELEMENT 1 with nodes:\n 1 2 3\n topology:\n 4 5 6\n"),
               CalculixOutputError);
}

TEST(ResultMapping, WrongModelIsLoud) {
  // The .frd of the 2 x 2 patch against a model with other coordinates: refused.
  test::PatchSpec other = data_spec(solver::ElementType::Q4);
  other.a = 2.0;
  CalculixResult result;
  EXPECT_THROW(
      map_results(parse_frd(data("patch_q4_ns.frd")), parse_expansion(data("patch_q4_ns.12d")),
                  test::patch_model(other), test::patch_pair(), result),
      CalculixOutputError);
  // ... a NaN coordinate ...
  std::string nan_node = data("patch_q4_ns.frd");
  nan_node.replace(nan_node.find(" 5.00000E-01"), 12, "         NaN");
  EXPECT_THROW(
      map_results(parse_frd(nan_node), {}, test::patch_model(data_spec(solver::ElementType::Q4)),
                  test::patch_pair(), result),
      CalculixOutputError);
  // ... a NaN displacement (a diverged solve writes one as a value) ...
  std::string nan_value = data("patch_q4_ns.frd");
  const std::size_t row = nan_value.find("\n -1", nan_value.find(" -4  DISP")) + 1;
  nan_value.replace(row + 13, 12, "         NaN");  // " -1", a 10-wide node id, then D1
  try {
    map_results(parse_frd(nan_value), parse_expansion(data("patch_q4_ns.12d")),
                test::patch_model(data_spec(solver::ElementType::Q4)), test::patch_pair(), result);
    ADD_FAILURE() << "a NaN displacement was mapped";
  } catch (const CalculixOutputError& e) {
    EXPECT_NE(std::string(e.what()).find("block 'DISP' gives node 1 a D1 that is not finite"),
              std::string::npos)
        << e.what();
  }
  // ... and against a model with fewer nodes.
  test::PatchSpec smaller = data_spec(solver::ElementType::Q4);
  smaller.nx = 1;
  EXPECT_THROW(map_results(parse_frd(data("patch_q4_ns.frd")), {}, test::patch_model(smaller),
                           test::patch_pair(), result),
               CalculixOutputError);
}

}  // namespace
}  // namespace cs::adapters::calculix
