// Requirement (issue 13, results import): the import layout is read by one pure function that
// accepts the documented file and refuses every malformed one with a message naming the line
// and column; values written by the suite read back bit for bit; and grading imported values
// reproduces, exactly, the grades the solver that produced them got (a quantity means the same
// for every solver).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "suites/import_csv.hpp"
#include "suites/imported_results.hpp"
#include "suites/model_export.hpp"
#include "suites/problem_executor.hpp"

namespace cs::suites {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_import_csv(text, "f.csv");
  } catch (const ImportError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ImportCsv, ReadsTheLayoutInAnyColumnOrder) {
  const std::string text =
      "\xEF\xBB\xBF# exported by a test\r\n"
      "x, sigma_x ,case_id,contact_pressure,sigma_z\r\n"
      "\r\n"
      "0,-1.5,H_p/C/Q4/PM/ss,1.25,-1.27\r\n"
      "+0.5,-1e-3,P_p/C/Q4/AL/ss,,-1\n"
      "  # a comment between rows\n"
      "0.25,2,H_p/C/Q4/PM/ss,0,3";  // no final newline
  const auto cases = parse_import_csv(text, "f.csv");
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].case_id, "H_p/C/Q4/PM/ss");
  EXPECT_EQ(cases[0].line, 4);
  ASSERT_EQ(cases[0].rows.size(), 2u);
  EXPECT_EQ(cases[0].rows[0].x, 0.0);
  EXPECT_EQ(cases[0].rows[0].sigma_x, -1.5);
  EXPECT_EQ(cases[0].rows[0].sigma_z, -1.27);
  EXPECT_EQ(cases[0].rows[0].contact_pressure, 1.25);
  EXPECT_EQ(cases[0].rows[1].line, 7);
  EXPECT_EQ(cases[0].rows[1].contact_pressure, 0.0);
  EXPECT_EQ(cases[1].case_id, "P_p/C/Q4/AL/ss");
  EXPECT_EQ(cases[1].rows[0].x, 0.5);
  EXPECT_FALSE(cases[1].rows[0].contact_pressure.has_value());  // empty: not reported
}

TEST(ImportCsv, EveryMalformedFileIsRefusedNamingLineAndColumn) {
  const std::string h = "case_id,x,sigma_z,sigma_x,contact_pressure\n";
  const std::vector<std::pair<std::string, std::string>> bad{
      {"", "f.csv: empty file"},
      {"\n  \n# only a comment\n", "f.csv: empty file"},
      {h, "f.csv:1: no data rows"},
      {"case_id,x,sigma_z,sigma_x\nA,0,1,2\n", "f.csv:1: missing column 'contact_pressure'"},
      {"case_id,x,sigma_z,sigma_x,contact_pressure,tau\n", "f.csv:1: column 6 (header): unknown"},
      {"case_id,x,sigma_z,x,contact_pressure\n", "column 4 (header): column 'x' is given twice"},
      {"case_id,x,sigma_z,sigma_x,Contact_Pressure\n", "unknown column 'Contact_Pressure'"},
      {h + "A,0,1,2\n", "f.csv:2: 4 fields, the header has 5"},
      {h + "A,0,1,2,3,4\n", "f.csv:2: 6 fields"},
      {h + ",0,1,2,3\n", "f.csv:2: column 1 (case_id): empty case id"},
      {h + "A,abc,1,2,3\n", "f.csv:2: column 2 (x): 'abc' is not a number"},
      {h + "A,0,,2,3\n", "column 3 (sigma_z): empty value"},
      {h + "A,0,1,1.5.2,3\n", "column 4 (sigma_x): '1.5.2' is not a number"},
      {h + "A,0,1,2,nan\n", "column 5 (contact_pressure): 'nan' is not a finite number"},
      {h + "A,inf,1,2,3\n", "column 2 (x): 'inf' is not a finite number"},
      {h + "A,0,-inf,2,3\n", "'-inf' is not a finite number"},
      {h + "A,0,1e999,2,3\n", "'1e999' is out of the range of a double"},
      {h + "A,0,1,2,0x10\n", "'0x10' is not a number"},
      {h + "A,0,1,2,++1\n", "'++1' is not a number"},
      {h + "A,0,1,2,+-1\n", "'+-1' is not a number"},
      {h + "A,0,1 2,2,3\n", "'1 2' is not a number"},
      {h + "\"A\",0,1,2,3\n", "f.csv:2: quoted fields are not supported"},
      {h + "A,0,1,2,3\nB,0,1,2,3\nA,0,4,5,6\n",
       "f.csv:4: duplicate node: case 'A' already has "
       "x = 0 on line 2"},
      {h + "A,0,1,2,3\nA,-0,1,2,3\n", "f.csv:3: duplicate node"},
      {h + "A,0,1,2,\x01\n", "'?' is not a number"},
  };
  for (const auto& [text, expected] : bad) {
    const std::string what = error_of(text);
    EXPECT_NE(what.find(expected), std::string::npos) << text << "\n -> " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(ImportCsv, WrittenValuesReadBackBitForBit) {
  ImportedCase c{"H_p/F/Q8/LMP/ns/fkn=0.1", 0, {}};
  const double values[] = {0.1 + 0.2, -1.0 / 3.0, 5e-324, -1.7976931348623157e308, 1e-17, 0.0};
  for (double v : values)
    c.rows.push_back({v, -v * 0.5, std::nextafter(v, 1.0), std::optional<double>(v / 7.0), 0});
  c.rows.push_back({42.0, 1.0, 2.0, std::nullopt, 0});
  const auto back = parse_import_csv(import_csv_text({c}), "w.csv");
  ASSERT_EQ(back.size(), 1u);
  ASSERT_EQ(back[0].rows.size(), c.rows.size());
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    EXPECT_EQ(back[0].rows[i].x, c.rows[i].x);
    EXPECT_EQ(back[0].rows[i].sigma_z, c.rows[i].sigma_z);
    EXPECT_EQ(back[0].rows[i].sigma_x, c.rows[i].sigma_x);
    EXPECT_EQ(back[0].rows[i].contact_pressure, c.rows[i].contact_pressure);
  }
}

// Requirement: arbitrary bytes give a result or an ImportError, never a crash or another
// exception (the contract a fuzz target relies on). 3000 mutations of a valid file, seeded.
TEST(ImportCsv, ArbitraryBytesGiveRowsOrAnImportError) {
  const std::string good =
      "case_id,x,sigma_z,sigma_x,contact_pressure\nA/B,0,1,2,3\nA/B,0.5,-1e-3,2,\n";
  std::mt19937 random(13);
  int refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = good;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < edits; ++k) {
      const std::size_t at = random() % (text.size() + 1);
      const char byte = static_cast<char>(random() % 256);
      if (random() % 2 == 0 && at < text.size())
        text[at] = byte;
      else
        text.insert(at, 1, byte);
    }
    try {
      parse_import_csv(text, "fuzz");
    } catch (const ImportError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 1000);
}

/// The import rows of a solved case, as `run --surface-csv` writes them.
ImportedCase rows_of(const CaseResult& r, const std::string& id) {
  ImportedCase c{id, 1, {}, {}};
  int line = 2;
  for (const auto& n : r.surface_nodes)
    c.rows.push_back({n.x, n.sigma_z, n.sigma_x, n.contact_pressure, line++});
  return c;
}

// Requirement: the built-in solver's surface values, imported, give the same value, error,
// grade and contact pressure for every quantity, exactly (the same doubles through the same
// sampling).
TEST(ImportedResults, BuiltinValuesImportedGradeExactlyAsTheBuiltinRun) {
  for (const auto problem : {ProblemId::P_p, ProblemId::H_p, ProblemId::F_p}) {
    CaseSpec spec;
    spec.problem = problem;
    spec.mesh = MeshLevel::C;
    spec.algorithm = Algorithm::PM;
    spec.contact = ContactKind::ns;
    ProblemExecutor executor(spec);
    const CaseResult direct = executor.run(spec);
    ASSERT_EQ(direct.status, CaseStatus::converged);
    ASSERT_FALSE(direct.surface_nodes.empty());
    const auto imported = rows_of(direct, case_id(spec));
    const auto graded = grade_imported({imported}, "roundtrip", "t.csv");
    ASSERT_EQ(graded.size(), 1u);
    const CaseResult& g = graded[0];
    EXPECT_EQ(case_id(g.spec), case_id(spec) + "/@roundtrip");
    EXPECT_EQ(g.status, CaseStatus::converged);
    ASSERT_EQ(g.quantities.size(), direct.quantities.size());
    for (std::size_t q = 0; q < g.quantities.size(); ++q) {
      const auto &a = g.quantities[q], &b = direct.quantities[q];
      EXPECT_EQ(a.quantity, b.quantity);
      EXPECT_EQ(a.value, b.value) << to_string(problem);
      EXPECT_EQ(a.grade, b.grade);
      EXPECT_EQ(a.contact_pressure, b.contact_pressure) << to_string(problem);
      EXPECT_TRUE(a.error_percent == b.error_percent ||
                  (std::isnan(a.error_percent) && std::isnan(b.error_percent)));
    }
    EXPECT_EQ(g.profile.sigma_z_over_p, direct.profile.sigma_z_over_p);
  }
}

std::string grade_error(const std::vector<ImportedCase>& cases, const std::string& name = "x") {
  try {
    grade_imported(cases, name, "t.csv");
  } catch (const SuiteInputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ImportedResults, RowsThatDoNotMatchTheSurfaceAreRefused) {
  CaseSpec spec;
  spec.problem = ProblemId::P_p;
  spec.algorithm = Algorithm::PM;
  ProblemExecutor executor(spec);
  const auto good = rows_of(executor.run(spec), case_id(spec));
  ASSERT_GT(good.rows.size(), 3u);

  auto missing = good;
  missing.rows.pop_back();
  EXPECT_NE(grade_error({missing}).find("t.csv:1: case 'P_p/C/Q4/PM/ss': no row for the surface "
                                        "node"),
            std::string::npos)
      << grade_error({missing});
  auto off_node = good;
  off_node.rows[1].x += 0.3 * (good.rows[2].x - good.rows[1].x);
  EXPECT_NE(grade_error({off_node}).find("t.csv:3: case 'P_p/C/Q4/PM/ss': x = "),
            std::string::npos);
  auto twice = good;
  twice.rows[1].x = good.rows[0].x * (1 + 1e-9) + 1e-12;  // the same node within tolerance
  EXPECT_NE(grade_error({twice}).find("again (line 2)"), std::string::npos) << grade_error({twice});

  const std::vector<std::pair<std::string, std::string>> ids{
      {"P_p/C/Q4/PM/ss/@calculix", "without its option"},
      {"P_p/C/Q4/PM/ss/@abaqus", "names a solver"},
      {"P_x/C/Q4/PM/ss", "unknown case id: case id 'P_x/C/Q4/PM/ss': unknown problem"},
      {"P_p/C/Q4/PM/ss/nonsense=1", "unknown case id"},
      {"IF_p/C/Q4/PM/ss", "nodal forces"},
      {"FP_p/C/Q4/PM/ss", "has friction"},
      {"P_p/C/Q4/PM/ss/fkn=10.0", "'P_p/C/Q4/PM/ss/fkn=10'"},
  };
  for (const auto& [id, expected] : ids) {
    auto c = good;
    c.case_id = id;
    EXPECT_NE(grade_error({c}).find(expected), std::string::npos) << id << ": " << grade_error({c});
  }
}

// Requirement (issue 24): the optional per-case columns are read (own option label, time,
// iterations, equations, memory); the option is part of the case (one id, two options: two
// cases), the others may be given on one row of a case only and must agree where two rows give
// them; all are checked as labels, counts and amounts, and written back so that they read back
// the same.
TEST(ImportCsv, OptionalPerCaseColumns) {
  const std::string h =
      "case_id,x,sigma_z,sigma_x,contact_pressure,option,wall_seconds,"
      "iterations,n_equations,peak_rss_mb\n";
  const auto cases = parse_import_csv(
      h + "H_p/C/Q4/AL/ss,0,-1,-1,1,nitsche,2.5,7,1234,88.5\n"
          "H_p/C/Q4/AL/ss,0.5,-1,-1,1,nitsche,,,,\n"
          "H_p/C/Q4/AL/ss,0,-1,-1,1,integral_al,,,,\n",  // the same id, another option
      "f.csv");
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[1].values.option, "integral_al");
  EXPECT_EQ(cases[1].rows.size(), 1u);
  const ImportedCaseValues& v = cases[0].values;
  EXPECT_EQ(v.option, "nitsche");
  EXPECT_EQ(v.wall_seconds, 2.5);
  EXPECT_EQ(v.iterations, 7);
  EXPECT_EQ(v.n_equations, 1234);
  EXPECT_EQ(v.peak_rss_mb, 88.5);
  const auto again = parse_import_csv(import_csv_text(cases), "again.csv");
  ASSERT_EQ(again.size(), 2u);
  EXPECT_EQ(again[0].values, v);
  EXPECT_EQ(again[0].rows.size(), 2u);
  EXPECT_EQ(again[1].values, cases[1].values);
  // Only some optional columns, in any order.
  const auto some = parse_import_csv(
      "iterations,case_id,x,sigma_z,sigma_x,contact_pressure\n3,P_p/C/Q4/PM/ss,0,-1,-1,\n", "f");
  EXPECT_EQ(some[0].values.iterations, 3);
  EXPECT_FALSE(some[0].values.option.has_value());
  for (const auto& [rows, expected] : std::vector<std::pair<std::string, std::string>>{
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,a b,,,,\n",
            "f.csv:2: column 6 (option): 'a b' is not an option label"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,,-1,,,\n", "column 7 (wall_seconds): '-1' is negative"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,,,2.5,,\n", "column 8 (iterations): '2.5' is not a whole"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,,,,-3,\n", "column 9 (n_equations): '-3' is not a whole"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,,,,,nan\n", "column 10 (peak_rss_mb): 'nan' is not a"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,,,4,,\nH_p/C/Q4/AL/ss,1,-1,-1,1,,,5,,\n",
            "f.csv:3: column 8 (iterations): case 'H_p/C/Q4/AL/ss': iterations differs"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1,a,,,,\nH_p/C/Q4/AL/ss,0,-1,-1,1,a,,,,\n",
            "duplicate node: case 'H_p/C/Q4/AL/ss' (option a) already has x = 0 on line 2"},
           {"H_p/C/Q4/AL/ss,0,-1,-1,1\n", "5 fields, the header has 10"},
       })
    EXPECT_NE(error_of(h + rows).find(expected), std::string::npos) << rows << error_of(h + rows);
}

// Requirement (issue 24): grading records the target and the stress basis each id names or the
// command line states, the code's own option label (as <name>:<label>), and the case's time,
// iterations, equations and memory; a rigid target is graded on the rigid case's surface; an id
// that contradicts the stated target or basis, and two ids that become one case, are refused.
TEST(ImportedResults, TargetBasisLabelAndCostAreRecorded) {
  CaseSpec spec;
  spec.problem = ProblemId::H_p;
  spec.algorithm = Algorithm::PM;
  spec.target = TargetKind::Rigid;
  ProblemExecutor executor(spec);
  const CaseResult direct = executor.run(spec);
  ASSERT_EQ(direct.status, CaseStatus::converged) << direct.reason;
  CaseSpec unstated = spec;
  unstated.target = TargetKind::Discretized;
  ImportedCase c = rows_of(direct, case_id(unstated));  // the id does not say rigid
  c.values.option = "my-penalty";
  c.values.wall_seconds = 1.5;
  c.values.iterations = 9;
  c.values.n_equations = 321;
  c.values.peak_rss_mb = 12.0;
  const auto graded = grade_imported({c}, "code", "t.csv", {TargetKind::Rigid, Recovery::own});
  ASSERT_EQ(graded.size(), 1u);
  const CaseResult& g = graded[0];
  EXPECT_EQ(case_id(g.spec), "H_p/C/Q4/PM/ss/rigid/own/@code:my-penalty");
  EXPECT_EQ(g.wall_seconds, 1.5);
  EXPECT_EQ(g.iterations, 9);
  EXPECT_EQ(g.n_equations, 321);
  EXPECT_EQ(g.peak_rss_mb, 12.0);
  ASSERT_EQ(g.quantities.size(), direct.quantities.size());
  for (std::size_t q = 0; q < g.quantities.size(); ++q)  // the rigid case's sampling, exactly
    EXPECT_EQ(g.quantities[q].value, direct.quantities[q].value);

  ImportedCase rigid = rows_of(direct, case_id(spec));  // the id says rigid
  const auto error = [&](const std::vector<ImportedCase>& cases, const ImportBasis& basis) {
    try {
      grade_imported(cases, "code", "t.csv", basis);
    } catch (const SuiteInputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(error({rigid}, {TargetKind::Discretized, std::nullopt})
                .find("names a rigid target, --target discretized"),
            std::string::npos);
  CaseSpec extrapolated = spec;
  extrapolated.recovery = Recovery::extrapolated;
  EXPECT_NE(error({rows_of(direct, case_id(extrapolated))}, {std::nullopt, Recovery::own})
                .find("names the stress basis extrapolated, --recovery own"),
            std::string::npos);
  CaseSpec own = spec;
  own.recovery = Recovery::own;
  EXPECT_NE(
      error({rigid, rows_of(direct, case_id(own))}, {std::nullopt, Recovery::own}).find("again"),
      std::string::npos);
}

TEST(ImportedResults, SolverNamesAreChecked) {
  const std::vector<std::string> registered{"calculix", "getfem"};
  for (const char* ok : {"abaqus-2024", "ANSYS_2023R2", "ccx.2.21", "a", "getfem2"})
    EXPECT_NO_THROW(require_imported_solver_name(ok, registered)) << ok;
  for (const std::string& bad :
       std::vector<std::string>{"", "builtin", "calculix", "getfem", "imported", "a b", "a/b",
                                "a,b", "x\ny", "caf\xc3\xa9", std::string(65, 'a')})
    EXPECT_THROW(require_imported_solver_name(bad, registered), SuiteInputError) << bad;
}

TEST(ModelExport, FilesDescribeTheModelTheSolverRuns) {
  CaseSpec spec;
  spec.problem = ProblemId::H_a;
  spec.element = Element::Q8;
  const ProblemSetup setup = build_problem(spec);
  const auto files = model_files(setup);
  ASSERT_EQ(files.size(), 10u);
  EXPECT_EQ(model_directory_name(spec), "H_a_C_Q8");
  spec.overrides = {{"fkn", 10.0}, {"nu", 0.2}};
  EXPECT_EQ(model_directory_name(spec), "H_a_C_Q8_nu=0.2");  // fkn: the same model
  auto text = [&](const std::string& name) {
    for (const auto& f : files) {
      if (f.name == name)
        return f.text;
    }
    return std::string();
  };
  EXPECT_NE(text("model.csv").find("analysis,axisymmetric\n"), std::string::npos);
  EXPECT_NE(text("model.csv").find("force_basis,per_radian\n"), std::string::npos);
  EXPECT_EQ(text("nodes.csv").rfind("id,x,y\n", 0), 0u);
  // One line per node and element, plus the header.
  const std::string nodes = text("nodes.csv"), elements = text("elements.csv");
  EXPECT_EQ(std::count(nodes.begin(), nodes.end(), '\n'), setup.model.mesh.n_nodes() + 1);
  EXPECT_EQ(std::count(elements.begin(), elements.end(), '\n'), setup.model.mesh.n_elements() + 1);
  // The loads sum to the solver's applied load (z: the y column).
  double fy = 0.0;
  std::istringstream loads(text("loads.csv"));
  std::string line;
  std::getline(loads, line);
  while (std::getline(loads, line))
    fy += std::stod(line.substr(line.rfind(',') + 1));
  EXPECT_NE(fy, 0.0);
  EXPECT_NE(text("mesh.vtu").find("<VTKFile"), std::string::npos);
  EXPECT_NE(cases_csv_rows(spec, setup, "models/H_a_C_Q8").find(",sigma_z,at_axis,"),
            std::string::npos)
      << cases_csv_rows(spec, setup, "models/H_a_C_Q8");
}

}  // namespace
}  // namespace cs::suites
