// The solver protocol end to end (docs/solver-protocol.md): a stand-in code registered by one
// folder (tests/apps/data/patch_code: a manifest and a script that solves the uniform patch test
// exactly) is run and graded by `contact-suite run --solver patchcode --solver-dir DIR`, with
// no edit anywhere else; every way a code can fail becomes that case's status and reason.
//
// Requirements:
//  - a new code is one folder: `list` shows it with its options, `run` runs it and grades both
//    stress bases (common: our patch recovery of its displacements; own: its stresses) to
//    machine precision, the case ids carrying its own option labels;
//  - a non-zero exit, a time-out, NaN, a missing node, an unparsable value, a file written
//    outside the case directory, a node given twice, an own-basis stress missing on the sampled
//    surface and a pressure off the contact surface each make that case failed (timeout) with
//    the reason, and the run still writes results.json;
//  - a manifest with an unknown key or family, a number out of range or a time limit beyond a
//    day is refused with exit 2 and one line.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"

namespace cs::apps::testing {
namespace {

namespace fs = std::filesystem;

/// A solver folder holding a copy of the stand-in with `manifest` (the committed one if empty).
void make_code_folder(const fs::path& dir, const std::string& manifest = "") {
  const fs::path source = fs::path(CONTACT_SUITE_SOURCE_DIR) / "tests/apps/data/patch_code";
  fs::create_directories(dir);
  fs::copy_file(source / "patch_solver.py", dir / "patch_solver.py");
  if (manifest.empty())
    fs::copy_file(source / "manifest.json", dir / "manifest.json");
  else
    std::ofstream(dir / "manifest.json") << manifest;
}

std::map<std::string, nlohmann::json> cases_by_id(const fs::path& results) {
  std::ifstream in(results);
  const auto doc = nlohmann::json::parse(in);
  std::map<std::string, nlohmann::json> out;
  for (const auto& c : doc.at("cases"))
    out[c.at("id").get<std::string>()] = c;
  return out;
}

/// `run` of the stand-in code in `folder` with `options` on P_p's `meshes` and `elements` (rigid
/// target), one job, no report, into `out`, then `extra` arguments.
std::vector<std::string> patch_code_run(const fs::path& folder, const std::string& options,
                                        const fs::path& out,
                                        const std::vector<std::string>& extra = {},
                                        const std::string& meshes = "C",
                                        const std::string& elements = "Q4") {
  std::vector<std::string> args{"run",
                                "--solver",
                                "patchcode",
                                "--solver-dir",
                                folder.string(),
                                "--solver-options",
                                options,
                                "--problems",
                                "P_p",
                                "--meshes",
                                meshes,
                                "--elements",
                                elements,
                                "--target",
                                "rigid",
                                "--jobs",
                                "1",
                                "--no-report",
                                "--out",
                                out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(SolverProtocolCli, ListShowsARegisteredCode) {
  TempDir dir;
  make_code_folder(dir.path() / "patch_code");
  const auto r = run_cli({"list", "--solver-dir", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("patchcode:exact"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lagrange_multiplier"), std::string::npos) << r.out;
}

TEST(SolverProtocolCli, StandInCodeIsRunAndGradedOnBothBases) {
  TempDir dir;
  make_code_folder(dir.path() / "codes" / "patch_code");
  const fs::path out = dir.path() / "out";
  const auto r = run_cli(patch_code_run(dir.path() / "codes", "exact", out, {}, "C,M", "Q4,Q8"));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto cases = cases_by_id(out / "results.json");
  ASSERT_EQ(cases.size(), 8u);  // 2 meshes x 2 elements x 2 bases
  for (const std::string basis : {"", "/own"}) {
    const std::string id = "P_p/M/Q8/LMP/ns/rigid" + basis + "/@patchcode:exact";
    ASSERT_TRUE(cases.contains(id)) << id;
    const auto& c = cases.at(id);
    EXPECT_EQ(c.at("status"), "converged") << c.dump();
    const auto& q = c.at("quantities").at("sigma_z_max");
    // The exact field: both bases reproduce sigma_z = -p to rounding (machine precision x
    // the recovery's few hundred operations).
    EXPECT_NEAR(q.at("error_percent").get<double>(), 0.0, 1e-9) << c.dump();
  }
}

// Requirement: a run of another code leaves nothing in the temporary directory once its cases
// converged (their directories and the process's run directory are removed), and keeps a
// failed case's files there, under the path results.json's kept_files names (not the reason,
// which stays the same from run to run).
TEST(SolverProtocolCli, RunDirectoryIsRemovedUnlessACaseKeepsItsFiles) {
  TempDir dir;
  make_code_folder(dir.path() / "patch_code");
  const auto run = [&](const std::string& option, const fs::path& scratch) {
    fs::create_directories(scratch);
    return run_cli(patch_code_run(dir.path() / "patch_code", option,
                                  scratch.parent_path() / (option + "-out")),
                   scratch);
  };
  const fs::path clean = dir.path() / "clean";
  ASSERT_EQ(run("exact", clean).exit_code, 0);
  EXPECT_TRUE(fs::is_empty(clean));
  const fs::path kept = dir.path() / "kept";
  ASSERT_EQ(run("exit3", kept).exit_code, 1);
  ASSERT_FALSE(fs::is_empty(kept));
  const auto cases = cases_by_id(dir.path() / "exit3-out" / "results.json");
  ASSERT_FALSE(cases.empty());
  const auto& failed = cases.begin()->second;
  const std::string reason = failed.at("reason"), kept_files = failed.at("kept_files");
  EXPECT_EQ(kept_files.rfind(kept.string(), 0), 0u) << kept_files;
  EXPECT_TRUE(fs::is_directory(kept_files)) << kept_files;
  EXPECT_EQ(reason.find(kept.string()), std::string::npos) << reason;
}

// Requirement: a path that is not UTF-8 (a temporary directory named in Latin-1) in a failed
// case's kept_files still gives a results file: the byte reads U+FFFD. Fails if writing
// results.json throws on it (an internal error, exit 3, the whole run lost).
TEST(SolverProtocolCli, APathThatIsNotUtf8StillGivesResults) {
  TempDir dir;
  make_code_folder(dir.path() / "patch_code");
  const fs::path scratch = dir.path() / "caf\xe9";
  fs::create_directories(scratch);
  const auto r =
      run_cli(patch_code_run(dir.path() / "patch_code", "exit3", dir.path() / "out"), scratch);
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto cases = cases_by_id(dir.path() / "out" / "results.json");
  ASSERT_FALSE(cases.empty());
  for (const auto& [id, c] : cases) {
    const std::string kept = c.at("kept_files");
    EXPECT_NE(kept.find("caf\xef\xbf\xbd"), std::string::npos) << id << ": " << kept;
  }
}

// Requirement: a temporary directory that does not exist is bad input: exit 2 and one line
// naming TMPDIR before any case runs, and no output directory.
TEST(SolverProtocolCli, UnusableTemporaryDirectoryIsExit2) {
  TempDir dir;
  make_code_folder(dir.path() / "patch_code");
  const fs::path out = dir.path() / "out";
  const auto r =
      run_cli(patch_code_run(dir.path() / "patch_code", "exact", out), dir.path() / "missing");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("TMPDIR=" + (dir.path() / "missing").string()), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// A case that runs past the time limit is stopped and is a time-out; `sleep` takes 60 s. It runs
// alone, so that its short limit cannot catch a quick failure on a loaded machine.
TEST(SolverProtocolCli, ACaseBeyondTheTimeLimitIsATimeout) {
  TempDir dir;
  make_code_folder(dir.path() / "patch_code");
  const fs::path out = dir.path() / "out";
  const auto r =
      run_cli(patch_code_run(dir.path() / "patch_code", "sleep", out, {"--time-limit", "1"}));
  ASSERT_EQ(r.exit_code, 1) << r.err << r.out;  // the case failed, results written
  const auto cases = cases_by_id(out / "results.json");
  const auto& c = cases.at("P_p/C/Q4/PM/ns/rigid/@patchcode:sleep");
  EXPECT_EQ(c.at("status"), "timeout");
  EXPECT_NE(c.at("reason").get<std::string>().find("timed out"), std::string::npos)
      << c.at("reason");
}

// The time limit leaves the stand-in's quick failures room on a loaded machine (at 2 s, one of
// them timed out while two battery processes shared the two cores); none of them waits for it.
// The `exit3` stand-in ends its stderr with bytes that are not UTF-8: taken into the reason as
// they were, they made writing results.json throw (an internal error, no results).
TEST(SolverProtocolCli, EveryFailureIsTheCaseStatusWithItsReason) {
  TempDir dir;
  make_code_folder(dir.path() / "patch_code");
  const fs::path out = dir.path() / "out";
  const auto r = run_cli(patch_code_run(
      dir.path() / "patch_code",
      "exit3,nan,missing_node,unparsable,outside,no_stresses,multiline,"
      "surface_stress_missing,pressure_twice,pressure_off_surface,bad_count,deep_status",
      out, {"--time-limit", "8"}));
  ASSERT_EQ(r.exit_code, 1) << r.err << r.out;  // cases failed, results written
  const auto cases = cases_by_id(out / "results.json");
  const std::map<std::string, std::pair<std::string, std::string>> expected{
      {"PM/ns/rigid/@patchcode:exit3",
       {"failed", "exited with status 3: patch solver: cannot solve this case (r?gime ?)"}},
      {"PM/ns/rigid/@patchcode:nan", {"failed", "is not finite"}},
      {"PM/ns/rigid/@patchcode:missing_node", {"failed", "is missing"}},
      {"PM/ns/rigid/@patchcode:unparsable", {"failed", "'1.2.3' is not a number"}},
      {"PM/ns/rigid/@patchcode:outside", {"failed", "wrote outside the case directory"}},
      {"AL/ss/rigid/own/@patchcode:no_stresses", {"failed", "no stresses.csv"}},
      {"AL/ss/rigid/@patchcode:no_stresses", {"converged", ""}},
      // a code's reason on one line: it goes into progress lines and Markdown tables
      {"PM/ns/rigid/@patchcode:multiline", {"not_converged", "iteration cap reached at step 3"}},
      // the own basis needs the code's stress at every node of the sampled surface
      {"AL/ss/rigid/own/@patchcode:surface_stress_missing",
       {"failed", "stresses.csv: node 1 of the sampled surface is missing"}},
      {"AL/ss/rigid/@patchcode:surface_stress_missing", {"converged", ""}},
      {"PM/ns/rigid/@patchcode:pressure_twice", {"failed", "is given twice"}},
      {"PM/ns/rigid/@patchcode:pressure_off_surface", {"failed", "is not on the contact surface"}},
      {"PM/ns/rigid/@patchcode:bad_count", {"failed", "iterations is 1e+20, not a count"}},
      {"PM/ns/rigid/@patchcode:deep_status", {"failed", "nests deeper than 64 levels"}},
  };
  for (const auto& [tail, want] : expected) {
    const std::string id = "P_p/C/Q4/" + tail;
    ASSERT_TRUE(cases.contains(id)) << id;
    EXPECT_EQ(cases.at(id).at("status"), want.first) << id;
    EXPECT_NE(cases.at(id).at("reason").get<std::string>().find(want.second), std::string::npos)
        << id << ": " << cases.at(id).at("reason");
  }
}

bool getfem_available() {
  return std::system("/usr/bin/python3 -c 'import getfem' >/dev/null 2>&1") == 0;
}

/// The arguments of a GetFEM run of `options` on one problem's `meshes` (both bases: one run of
/// GetFEM serves them; one job).
std::vector<std::string> getfem_run(const std::string& options, const std::string& problem,
                                    const std::string& meshes, const std::string& element,
                                    const std::string& target, const fs::path& out) {
  return {"run",   "--solver", "getfem", "--solver-options", options, "--problems",
          problem, "--meshes", meshes,   "--elements",       element, "--target",
          target,  "--jobs",   "1",      "--no-report",      "--out", out.string()};
}

/// The cases, by id, of `contact-suite run` with getfem_run's arguments in a scratch directory;
/// a run that exits otherwise than `exit_code` fails the calling test and gives no case.
std::map<std::string, nlohmann::json> getfem_cases(const std::string& options,
                                                   const std::string& problem,
                                                   const std::string& meshes,
                                                   const std::string& element,
                                                   const std::string& target, int exit_code = 0) {
  TempDir dir;
  const fs::path out = dir.path() / "out";
  const auto r = run_cli(getfem_run(options, problem, meshes, element, target, out));
  if (r.exit_code != exit_code) {
    ADD_FAILURE() << "exit " << r.exit_code << " (expected " << exit_code << ")\n"
                  << r.err << r.out;
    return {};
  }
  return cases_by_id(out / "results.json");
}

// GetFEM through its committed adapter (adapters/getfem/) on the smallest case: the patch test
// is exact for every method, so the common and own bases reproduce sigma_z = -p to GetFEM's
// Newton tolerance (residual 1e-9: 1e-6 % leaves a margin of three decades).
TEST(SolverProtocolCli, GetfemSolvesThePatchTest) {
  if (!getfem_available())
    GTEST_SKIP() << "python3-getfem is not installed";
  const auto cases = getfem_cases("nodal_al", "P_p", "C", "Q4", "rigid");
  for (const std::string id :
       {"P_p/C/Q4/AL/ns/rigid/@getfem:nodal_al", "P_p/C/Q4/AL/ns/rigid/own/@getfem:nodal_al"}) {
    ASSERT_TRUE(cases.contains(id)) << id;
    EXPECT_EQ(cases.at(id).at("status"), "converged");
    EXPECT_NEAR(cases.at(id).at("quantities").at("sigma_z_max").at("error_percent").get<double>(),
                0.0, 1e-6)
        << id;
  }
}

// The integral augmented Lagrangian's contact pressure is its multiplier where the brick's
// contact test holds: on H_p C Q4 (a = 1 lies on a node, sides 0.25 a) the contact edge is read
// halfway between the last loaded node (x = a) and the next, 1.125 a, as for the nodal brick;
// the raw multiplier, oscillating about zero past the edge, read 2.0 a.
TEST(SolverProtocolCli, GetfemIntegralContactHalfWidth) {
  if (!getfem_available())
    GTEST_SKIP() << "python3-getfem is not installed";
  const auto cases = getfem_cases("integral_al,nodal_al", "H_p", "C", "Q4", "rigid");
  for (const std::string id :
       {"H_p/C/Q4/AL/ss/rigid/@getfem:integral_al", "H_p/C/Q4/AL/ns/rigid/@getfem:nodal_al"}) {
    ASSERT_TRUE(cases.contains(id)) << id;
    EXPECT_EQ(cases.at(id).at("quantities").at("contact_half_width").at("value").get<double>(),
              1.125)
        << id;
  }
}

// Penalty and Nitsche write the traction their law imposes as their contact pressure
// (adapters/getfem: law_pressure), so the tensile check reads the law, as it does for ours. On
// F_p C Q8 that traction never pulls, nor presses beyond the punch, and at the punch's centre it
// equals the normal stress there (measured: 0.1 %). Caught: a wrong penalty r or gap sign (the
// centre pressure), a wrong sign of Nitsche's gap term (its open gap then presses outside the
// punch: 8e5 p), a wrong normal stress. Not caught: a factor on Nitsche's gamma, whose gap term
// all but vanishes where contact holds (gamma0/2 moves nothing here at the 1 % level). Read from
// the solution's nodal forces instead, Nitsche's pressure held its consistency terms: 0.0077 p
// of tension on this mesh.
TEST(SolverProtocolCli, GetfemPenaltyAndNitschePressureIsTheirLaw) {
  if (!getfem_available())
    GTEST_SKIP() << "python3-getfem is not installed";
  const auto cases = getfem_cases("penalty,nitsche", "F_p", "C", "Q8", "rigid");
  for (const std::string id :
       {"F_p/C/Q8/PM/ss/rigid/@getfem:penalty", "F_p/C/Q8/AL/ss/rigid/@getfem:nitsche"}) {
    ASSERT_TRUE(cases.contains(id)) << id;
    const auto& c = cases.at(id);
    EXPECT_LT(c.at("interface").at("max_tensile_over_p").get<double>(), 1e-12) << id;
    EXPECT_LT(c.at("interface").at("max_outside_over_p").get<double>(), 1e-12) << id;
    const auto& profile = c.at("profile");
    ASSERT_FALSE(profile.at("pressure_over_p").empty()) << id;
    const double pressure = profile.at("pressure_over_p").at(0).get<double>();
    const double sigma_z = profile.at("sigma_z_over_p").at(0).get<double>();
    EXPECT_NEAR(pressure / sigma_z, 1.0, 0.01) << id << ": " << pressure << " against " << sigma_z;
  }
}

// GetFEM between two meshes (IF_p: the shaft in the ring, the overlap alone loads the fit): its
// nodal brick's mean pressure, read from its displacements along the bore's normal, converges
// to the exact one at the second order (measured: -0.159 % on C, -0.039 % on M); Nitsche, which
// GetFEM 5.4 offers between two bodies only as a large-sliding brick and the manifest declares
// for a rigid obstacle only, is left out by `run` and counted (no failed case).
TEST(SolverProtocolCli, GetfemInterferenceFitBetweenTwoMeshes) {
  if (!getfem_available())
    GTEST_SKIP() << "python3-getfem is not installed";
  TempDir dir;
  const fs::path out = dir.path() / "out";
  const auto r = run_cli(getfem_run("nodal_al,nitsche", "IF_p", "C,M", "Q4", "discretized", out));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.err.find("4 cases left out, not supported by getfem: a meshed target with option "
                       "nitsche"),
            std::string::npos)
      << r.err;
  const auto cases = cases_by_id(out / "results.json");
  EXPECT_EQ(cases.size(), 4u);  // nodal_al on C and M, both bases
  const auto mean_error = [&](const std::string& mesh) {
    const std::string id = "IF_p/" + mesh + "/Q4/AL/ns/@getfem:nodal_al";
    EXPECT_TRUE(cases.contains(id)) << id;
    return cases.contains(id)
               ? cases.at(id).at("quantities").at("p_mean").at("error_percent").get<double>()
               : 0.0;
  };
  const double coarse = mean_error("C"), medium = mean_error("M");
  EXPECT_LT(std::abs(medium), 0.1);
  const double order = std::log2(coarse / medium);  // M halves C's sides
  EXPECT_GT(order, 1.5) << coarse << " then " << medium;
  EXPECT_LT(order, 2.5) << coarse << " then " << medium;
}

// GetFEM 5.4's integral and penalized bricks between two meshes project the target's
// displacement onto the slave's integration points only within 5 % of the target element's
// radius estimate; IF_p's overlap (0.001 b) exceeds that on F, where the projected FEM has no
// DOF and the brick divided 0 by 0 (the case read "getfem killed by signal 8"). The adapter
// checks the projection first: the case fails with why, in numbers, and GetFEM never crashes.
TEST(SolverProtocolCli, GetfemTwoMeshOverlapBeyondItsProjectionFailsWithWhy) {
  if (!getfem_available())
    GTEST_SKIP() << "python3-getfem is not installed";
  const auto cases = getfem_cases("integral_al", "IF_p", "F", "Q4", "discretized", 1);
  for (const std::string id :
       {"IF_p/F/Q4/AL/ss/@getfem:integral_al", "IF_p/F/Q4/AL/ss/own/@getfem:integral_al"}) {
    ASSERT_TRUE(cases.contains(id)) << id;
    EXPECT_EQ(cases.at(id).at("status"), "failed") << id;
    const auto reason = cases.at(id).at("reason").get<std::string>();
    EXPECT_NE(reason.find("getfem exited with status 1: getfem adapter: GetFEM 5.4's projected "
                          "FEM accepts no integration point: the initial overlap (1.0e-03) "
                          "exceeds its fixed window of 5 % of the target element size"),
              std::string::npos)
        << id << ": " << reason;
    EXPECT_EQ(reason.find("signal"), std::string::npos) << id << ": " << reason;
  }
}

// Requirement: an option that supports less than its code (the manifest's per-option
// `supports`) has the cases it does not support left out of `run`, counted on stderr with the
// reason; a selection of only such cases is refused with exit 2 and one line; `case` still runs
// nothing and fails the case with the reason.
TEST(SolverProtocolCli, OptionSupportsLeaveItsOtherCasesOut) {
  TempDir dir;
  std::ifstream committed(fs::path(CONTACT_SUITE_SOURCE_DIR) /
                          "tests/apps/data/patch_code/manifest.json");
  auto manifest = nlohmann::json::parse(committed);
  manifest["options"].push_back({{"label", "exact_q4"},
                                 {"family", "lagrange_multiplier"},
                                 {"discretization", "ns"},
                                 {"supports", {"plane_strain", "rigid_target", "Q4"}}});
  make_code_folder(dir.path() / "patch_code", manifest.dump());
  const fs::path out = dir.path() / "out";
  const auto r =
      run_cli(patch_code_run(dir.path() / "patch_code", "exact,exact_q4", out, {}, "C", "Q4,Q8"));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.err.find("2 cases left out, not supported by patchcode: Q8 elements with option "
                       "exact_q4"),
            std::string::npos)
      << r.err;
  const auto cases = cases_by_id(out / "results.json");
  EXPECT_EQ(cases.size(), 6u);  // exact on Q4 and Q8, exact_q4 on Q4; both bases
  EXPECT_TRUE(cases.contains("P_p/C/Q4/LMP/ns/rigid/@patchcode:exact_q4"));
  EXPECT_FALSE(cases.contains("P_p/C/Q8/LMP/ns/rigid/@patchcode:exact_q4"));

  const auto none = run_cli(
      patch_code_run(dir.path() / "patch_code", "exact_q4", dir.path() / "none", {}, "C", "Q8"));
  EXPECT_EQ(none.exit_code, 2) << none.err;
  EXPECT_EQ(std::count(none.err.begin(), none.err.end(), '\n'), 1) << none.err;
  EXPECT_NE(none.err.find("nothing to run: not supported by patchcode: Q8 elements with option "
                          "exact_q4"),
            std::string::npos)
      << none.err;
  EXPECT_FALSE(fs::exists(dir.path() / "none" / "results.json"));
}

// Requirement: under load control (S: a total load, the depth unknown) GetFEM carries the given
// load: its nodal augmented Lagrangian enforces non-penetration exactly at the nodes, as our
// Lagrange multipliers ns do, so on the same mesh and rigid punch their peak stresses agree to
// the Newton tolerance (measured: 8.7e-6 relative on S(1) C Q4); a load off by a fraction would
// scale the stress by that fraction.
TEST(SolverProtocolCli, GetfemLoadControlCarriesTheTotalLoad) {
  if (!getfem_available())
    GTEST_SKIP() << "python3-getfem is not installed";
  TempDir dir;
  std::map<std::string, nlohmann::json> cases;
  for (const std::string solver : {"getfem", "builtin"}) {
    const fs::path out = dir.path() / solver;
    std::vector<std::string> args{
        "run", "--solver",   solver, "--problems",  "S_1",   "--meshes",
        "C",   "--elements", "Q4",   "--target",    "rigid", "--recovery",
        "spr", "--jobs",     "1",    "--no-report", "--out", out.string()};
    const std::vector<std::string> option =
        solver == "getfem" ? std::vector<std::string>{"--solver-options", "nodal_al"}
                           : std::vector<std::string>{"--algorithms", "LMP", "--contacts", "ns"};
    args.insert(args.end() - 3, option.begin(), option.end());
    const auto r = run_cli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    cases.merge(cases_by_id(out / "results.json"));
  }
  const auto value = [&](const std::string& id) {
    EXPECT_TRUE(cases.contains(id)) << id;
    return cases.contains(id)
               ? cases.at(id).at("quantities").at("sigma_c").at("value").get<double>()
               : 0.0;
  };
  const double theirs = value("S_1/C/Q4/AL/ns/rigid/@getfem:nodal_al");
  const double ours = value("S_1/C/Q4/LMP/ns/rigid");
  EXPECT_NEAR(theirs / ours, 1.0, 1e-4) << theirs << " against " << ours;
}

// Requirement: `case` finds a code by --solver-dir as `run` does, and a relative folder in
// CONTACT_SUITE_SOLVER_DIRS means a folder of the caller's working directory, not of the case
// directory the code runs in. Fails if `case` lacks --solver-dir, or if the relative folder is
// handed on as written (the code's script is then not found and the case fails).
TEST(SolverProtocolCli, CaseTakesASolverDirAndRelativeFoldersAreTheCallers) {
  TempDir dir;
  make_code_folder(dir.path() / "codes" / "patch_code");
  const std::vector<std::string> one_case{"case",     "P_p",   "--mesh",   "C",
                                          "--target", "rigid", "--solver", "patchcode:exact"};
  auto with_dir = one_case;
  with_dir.insert(with_dir.end(), {"--solver-dir", (dir.path() / "codes").string()});
  auto r = run_cli(with_dir);
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("@patchcode:exact  converged"), std::string::npos) << r.out;

  const fs::path here = fs::current_path();
  fs::current_path(dir.path());
  ::setenv("CONTACT_SUITE_SOLVER_DIRS", "codes", 1);
  r = run_cli(one_case);
  ::unsetenv("CONTACT_SUITE_SOLVER_DIRS");
  fs::current_path(here);
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("@patchcode:exact  converged"), std::string::npos) << r.out;
}

TEST(SolverProtocolCli, BadManifestIsExit2AndOneLine) {
  const std::string good = R"({"name": "x", "command": ["true"], "version_command": ["true"],
    "options": [{"label": "a", "family": "penalty", "discretization": "ns"}],
    "supports": ["plane_strain"]})";
  const std::map<std::string, std::string> bad{
      {"unknown key", R"({"name": "x", "colour": "red", "command": ["true"],
        "version_command": ["true"], "options": [{"label": "a", "family": "penalty",
        "discretization": "ns"}], "supports": ["plane_strain"]})"},
      {"unknown family", R"({"name": "x", "command": ["true"], "version_command": ["true"],
        "options": [{"label": "a", "family": "hard", "discretization": "ns"}],
        "supports": ["plane_strain"]})"},
      {"option supports more than the code", R"({"name": "x", "command": ["true"],
        "version_command": ["true"], "options": [{"label": "a", "family": "penalty",
        "discretization": "ns", "supports": ["plane_strain", "Q8"]}],
        "supports": ["plane_strain"]})"},
      {"option supports an unknown capability", R"({"name": "x", "command": ["true"],
        "version_command": ["true"], "options": [{"label": "a", "family": "penalty",
        "discretization": "ns", "supports": ["3d"]}], "supports": ["plane_strain"]})"},
      {"a number out of range", R"({"name": "x", "command": ["true"], "version_command": ["true"],
        "time_limit_seconds": 1e999, "options": [{"label": "a", "family": "penalty",
        "discretization": "ns"}], "supports": ["plane_strain"]})"},
      {"nested 100,000 deep", R"({"name": "x", "command": ["true"], "version_command": ["true"],
        "options": [{"label": "a", "family": "penalty", "discretization": "ns"}],
        "supports": ["plane_strain"], "description": )" +
                                  std::string(100000, '[') + std::string(100000, ']') + "}"},
      {"a time limit that would overflow the clock", R"({"name": "x", "command": ["true"],
        "version_command": ["true"], "time_limit_seconds": 1e10, "options": [{"label": "a",
        "family": "penalty", "discretization": "ns"}], "supports": ["plane_strain"]})"},
  };
  for (const auto& [what, manifest] : bad) {
    TempDir dir;
    make_code_folder(dir.path() / "x", manifest);
    const auto r = run_cli({"list", "--solver-dir", dir.path().string()});
    EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": " << r.err;
    EXPECT_NE(r.err.find("manifest.json"), std::string::npos) << what << ": " << r.err;
  }
  TempDir dir;
  make_code_folder(dir.path() / "x", good);
  EXPECT_EQ(run_cli({"list", "--solver-dir", dir.path().string()}).exit_code, 0);
}

}  // namespace
}  // namespace cs::apps::testing
