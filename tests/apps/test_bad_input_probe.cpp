// Requirement (issue 16): every subcommand answers bad input with a one-line error and exit 2 —
// never exit 3 (reserved for real bugs), a signal, a NaN printed as a result, or a file left
// behind. The probe set: names, numbers, lists, paths with control characters, malformed and
// mistyped results/baseline files, shard specifications, merges that must be refused.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli_support.hpp"
#include "platform/child_process.hpp"

namespace cs::apps::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Args = std::vector<std::string>;

struct Probe {
  Args args;
};

/// Runs the executable without a shell in `dir`; returns how it ended and what it printed.
platform::ChildResult run_in(const fs::path& dir, const Args& args, std::string& out,
                             std::string& err) {
  platform::ChildOptions o;
  o.argv = {CONTACT_SUITE_EXE};
  o.argv.insert(o.argv.end(), args.begin(), args.end());
  o.working_directory = dir;
  o.stdout_path = dir / ".probe.out";
  o.stderr_path = dir / ".probe.err";
  o.time_limit_seconds = 60;
  const auto r = platform::run_child(o);
  out = read_text(o.stdout_path);
  err = read_text(o.stderr_path);
  fs::remove(o.stdout_path);
  fs::remove(o.stderr_path);
  return r;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.insert(fs::relative(e.path(), dir).string());
  return names;
}

class BadInputProbe : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    std::string out, err;
    const auto r = run_in(
        dir_->path(),
        {"run", "--problems", "P_p", "--meshes", "C", "--elements", "Q4", "--algorithms", "AL",
         "--contacts", "ss", "--out", "good", "--jobs", "1", "--no-report", "--surface-csv"},
        out, err);
    ASSERT_EQ(r.exit_code, 0) << err;
    good_ = json::parse(read_text(dir_->path() / "good" / "results.json"));
    write("b.json", R"({"schema": "contact-suite/baseline", "schema_version": 3})");
  }
  static void TearDownTestSuite() { delete dir_; }

  static void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_->path() / name) << text;
  }
  /// A copy of the good results file with one change, written as `name`.
  static std::string mutated(const std::string& name, const std::function<void(json&)>& change) {
    json j = good_;
    change(j);
    write(name, j.dump());
    return name;
  }

  static TempDir* dir_;
  static json good_;
};
TempDir* BadInputProbe::dir_ = nullptr;
json BadInputProbe::good_;

std::vector<Probe> name_probes() {
  std::vector<Probe> p;
  for (const char* bad : {"H_x", "h_p", "", "P_p ", "S_1/3", "F", "P'", "all", "-", "\n"})
    p.push_back({{"case", bad}});
  for (const auto& [opt, bad] :
       std::vector<std::pair<std::string, std::string>>{{"--mesh", "XF"},
                                                        {"--mesh", "c"},
                                                        {"--mesh", ""},
                                                        {"--element", "Q9"},
                                                        {"--element", "q4"},
                                                        {"--algorithm", "LM"},
                                                        {"--algorithm", "al"},
                                                        {"--algorithm", ""},
                                                        {"--contact", "SS"},
                                                        {"--contact", "nts"},
                                                        {"--target", "soft"},
                                                        {"--recovery", "smoothed"},
                                                        {"--recovery", ""}})
    p.push_back({{"case", "H_p", opt, bad}});
  return p;
}

std::vector<Probe> set_probes() {
  std::vector<Probe> p;
  for (const char* bad :
       {"nu", "nu=", "=1", "nu=abc", "nu=1/0", "nu=nan", "nu=inf", "nu=-inf", "nu=1e999",
        "nu=1e-400", "nu=0.5", "nu=0.6", "nu=-0.1", "p_over_E=0", "p_over_E=1", "E_ratio=0.5",
        "fkn=0", "fkn=-1", "ftoln=0", "pinball=0", "pinball=-1", "re_over_b=1", "unknown=1",
        "nu=0x", "nu=1,2", "nu==1", "nu=0.3 ",
        // accepted before, though the numerics cannot deliver them (converged, wrong):
        "fkn=1e300", "fkn=1e5", "p_over_E=1e-22", "p_over_E=1e-300", "ftoln=2", "pinball=1e9"})
    p.push_back({{"case", "H_p", "--set", bad}});
  // the block's extent (#12): below 1, absurdly large, not a number, or on a patch test
  for (const char* bad : {"extent=0", "extent=-2", "extent=0.5", "extent=65", "extent=1e9",
                          "extent=abc", "extent=nan"})
    p.push_back({{"case", "S_1", "--set", bad}});
  p.push_back({{"case", "P_p", "--set", "extent=2"}});
  // the half-space gap switch: only 0 or 1, and only where there is an indenter's curve (H, S, F)
  for (const char* bad : {"half_space_gap=0.5", "half_space_gap=2", "half_space_gap=-1"})
    p.push_back({{"case", "S_1", "--set", bad}});
  p.push_back({{"case", "P_p", "--set", "half_space_gap=1"}});
  p.push_back({{"run", "--problems", "H_p,P_p", "--meshes", "C", "--set", "extent=2"}});
  p.push_back({{"case", "H_p", "--set", "nu=0.2", "--set", "nu=0.3"}});
  p.push_back({{"run", "--problems", "H_p", "--set", "nu=0.2", "--set", "nu=0.2"}});
  return p;
}

/// Issue 15: friction (mu < 0, non-finite or absurd; a load at or past mu P where the oracle
/// needs stick; friction with MPC) and the interference fits (an interference that is not small
/// against the radii, beyond the oracle's delta/b <= 1e-2; radii out of range; a rigid shaft).
std::vector<Probe> friction_and_fit_probes() {
  std::vector<Probe> p;
  for (const char* bad :
       {"mu=-0.1", "mu=0", "mu=nan", "mu=inf", "mu=1e6", "tau_over_mu_p=1", "tau_over_mu_p=2"})
    p.push_back({{"case", "FP_p", "--set", bad}});
  for (const char* bad : {"mu=-1", "mu=1e300", "Q_over_mu_P=1", "Q_over_mu_P=1.5"})
    p.push_back({{"case", "CM_p", "--set", bad}});
  p.push_back({{"case", "FP_p", "--algorithm", "MPC"}});
  p.push_back({{"case", "CM_p", "--algorithm", "MPC"}});
  for (const char* problem : {"IF_p", "IF_a"}) {
    for (const char* bad :
         {"delta_over_b=0.02", "delta_over_b=0", "delta_over_b=-1e-3", "delta_over_b=nan",
          "b_over_c=1", "b_over_c=0", "p_over_E=1e-3", "mu=0.3"})
      p.push_back({{"case", problem, "--set", bad}});
    p.push_back({{"case", problem, "--target", "rigid"}});
  }
  return p;
}

/// `run --sweep`: unknown key, empty list, empty item, out of range, duplicates, and a key
/// both swept and set (issue 14).
std::vector<Probe> sweep_probes() {
  std::vector<Probe> p;
  for (const char* bad :
       {"unknown=1,2", "fkn=", "fkn", "=1,2", "fkn=1,,10", "fkn=,1", "fkn=1,", "fkn=1,1e5",
        "fkn=0,1", "nu=0.2,0.5", "E_ratio=0.5,1", "ftoln=2", "pinball=1e9", "fkn=1,abc",
        "fkn=1,nan", "fkn=1,1", "re_over_b=1,2", "extent=2,0", "extent=2,65"})
    p.push_back({{"run", "--problems", "H_p", "--meshes", "C", "--sweep", bad, "--out", "o"}});
  p.push_back({{"run", "--problems", "H_p", "--meshes", "C", "--sweep", "fkn=1,10", "--sweep",
                "fkn=100", "--out", "o"}});
  p.push_back({{"run", "--problems", "H_p", "--meshes", "C", "--sweep", "fkn=1,10", "--set",
                "fkn=100", "--out", "o"}});
  return p;
}

std::vector<Probe> run_probes() {
  std::vector<Probe> p;
  for (const char* jobs : {"0", "-1", "", "99999", "abc", "1.5"})
    p.push_back({{"run", "--problems", "P_p", "--meshes", "C", "--jobs", jobs, "--out", "o"}});
  for (const char* list : {"H_p,,S_1", ",", "H_p,", ",H_p", "H_p,XYZ"})
    p.push_back({{"run", "--problems", list, "--meshes", "C", "--out", "o"}});
  for (const char* list : {"C,,M", ","})
    p.push_back({{"run", "--problems", "P_p", "--meshes", list, "--out", "o"}});
  for (const char* shard : {"0/3", "4/3", "a/b", "3", "", "1/0", "-1/3", "1/3/5", "2/1", "1/99999"})
    p.push_back({{"run", "--problems", "P_p", "--meshes", "C", "--shard", shard, "--out", "o"}});
  for (const char* out : {"bad\nname", "tab\tname", "x/y/z", "b.json", "esc\x1b"})
    p.push_back({{"run", "--problems", "P_p", "--meshes", "C", "--elements", "Q4", "--out", out}});
  for (const char* vtu : {"", ".", "/nonexistent/dir/x.vtu", "new\nline.vtu"})
    p.push_back({{"case", "P_p", "--vtu", vtu}});
  p.push_back({{"run", "--target", "soft"}});
  p.push_back({{"run", "--recovery", "spr,,extrapolated"}});
  // CLI11's ranges let NaN through: every number option checks for it.
  for (const char* gib : {"nan", "inf", "-1", "0", "", "1x"})
    p.push_back({{"run", "--problems", "P_p", "--meshes", "C", "--max-memory", gib, "--out", "o"}});
  // A count takes whole numbers; an interference below round-off is refused, not graded.
  p.push_back({{"case", "CM_p", "--set", "q_increments=1.5"}});
  p.push_back({{"case", "IF_a", "--set", "delta_over_b=1e-20"}});
  // `case` refuses what `run` leaves out (an option a code does not offer, for the case or its
  // load path) and parameters the exact solution refuses: bad input, not a failed case.
  p.push_back({{"case", "H_p", "--solver", "calculix:hard-ss", "--target", "rigid"}});
  p.push_back({{"case", "FP_p", "--solver", "calculix:hard-ss"}});
  p.push_back({{"case", "S_1", "--set", "re_over_b=1e-9"}});
  // A load whose contact band the Steuermann mesh cannot resolve (it needs one level more than
  // the nested refinement takes): refused with the band's width, not an internal mesh error.
  p.push_back({{"case", "S_1", "--target", "rigid", "--set", "p_over_E=1e-12"}});
  p.push_back({{"run", "--problems", "P_p", "--meshes", "C", "--junit", "", "--out", "o"}});
  for (const char* dir : {"/nonexistent", "", "/etc/hostname"}) {
    p.push_back({{"list", "--solver-dir", dir}});
    p.push_back({{"run", "--problems", "P_p", "--meshes", "C", "--solver-dir", dir, "--out", "o"}});
  }
  // An empty number is not 0.
  p.push_back({{"oracle", "hertz-plane", "--R", "1", "--E", "1", "--nu", "", "--load", "1"}});
  p.push_back({{"oracle", "sadowsky", "--a", "1", "--load", "1", "--at", ""}});
  for (const char* seconds : {"nan", "inf", "0", "1e9"})
    p.push_back(
        {{"run", "--problems", "P_p", "--meshes", "C", "--time-limit", seconds, "--out", "o"}});
  return p;
}

/// `grade --import`: every bad input of issue 13 (missing, unknown or repeated columns, unknown
/// case ids, non-numeric or non-finite values, duplicate nodes), rows that miss the surface,
/// bad solver names; `export` of cases the layout cannot describe.
std::vector<Probe> import_export_probes(const fs::path& dir) {
  const std::string surface = read_text(dir / "good" / "surface.csv");
  const std::string h = "case_id,x,sigma_z,sigma_x,contact_pressure\n";
  const std::string id = "P_p/C/Q4/AL/ss";
  const std::string first_row = surface.substr(h.size(), surface.find('\n', h.size()) - h.size());
  const std::string rest = first_row.substr(first_row.find(','));  // ",x,..."
  const std::vector<std::string> files{
      "",
      "\n# nothing\n",
      h,
      "case_id,x,sigma_z,sigma_x\n" + id + ",0,1,2\n",
      "case_id,x,sigma_z,sigma_x,contact_pressure,extra\n",
      "case_id,x,x,sigma_z,sigma_x,contact_pressure\n",
      h + "H_x/C/Q4/AL/ss" + rest + "\n",
      h + id + "/@calculix" + rest + "\n",
      h + "FP_p/C/Q4/AL/ss" + rest + "\n",
      h + id + "/rigid" + rest + "\n",
      h + id + "/nu=0.7" + rest + "\n",
      h + id + "/unknown=1" + rest + "\n",
      h + "p_p/C/Q4/AL/ss" + rest + "\n",
      h + id + ",abc,1,2,3\n",
      h + id + ",0,1,2,three\n",
      h + id + ",0,nan,2,3\n",
      h + id + ",0,1,inf,3\n",
      h + id + ",0,1,2,1e999\n",
      h + id + ",0,1,2\n",
      surface + first_row + "\n",                                      // a duplicate node
      surface.substr(0, surface.rfind('\n', surface.size() - 2) + 1),  // a node missing
      h + id + ",0.123456,1,2,3\n" + surface.substr(h.size()),         // no such node
  };
  std::vector<Probe> p;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string name = "import" + std::to_string(i) + ".csv";
    std::ofstream(dir / name) << files[i];
    p.push_back({{"grade", "--import", name, "--solver-name", "x", "--out", "graded"}});
  }
  for (const char* name :
       {"", "builtin", "calculix", "getfem", "imported", "a b", "a/b", "new\nline"})
    p.push_back({{"grade", "--import", "good/surface.csv", "--solver-name", name, "--out", "g"}});
  for (const char* file : {"missing.csv", ".", "bad\nname.csv"})
    p.push_back({{"grade", "--import", file, "--solver-name", "x", "--out", "g"}});
  p.push_back({{"grade", "--import", "good/surface.csv", "--out", "g"}});
  p.push_back({{"grade", "--solver-name", "x", "--out", "g"}});
  p.push_back({{"grade", "--import", "good/surface.csv", "--solver-name", "x", "--out", "x\ty"}});
  for (const Args& a : std::vector<Args>{{"--target", "rigid"},
                                         {"--problems", "FP_p"},
                                         {"--problems", "H_p,CM_p"},
                                         {"--problems", "H_p,,S_1"},
                                         {"--meshes", ","},
                                         {"--set", "unknown=1"},
                                         {"--set", "nu=0.5"},
                                         {"--out", "bad\nout"},
                                         {"--out", "b.json"}}) {
    Args args{"export", "--problems", "P_p", "--meshes", "C", "--elements", "Q4", "--out", "e"};
    args.insert(args.end(), a.begin(), a.end());
    p.push_back({args});
  }
  return p;
}

std::vector<Probe> oracle_probes() {
  std::vector<Probe> p;
  for (const Args& a : std::vector<Args>{{"oracle", "hertz-plane", "--R", "-1"},
                                         {"oracle", "hertz-plane", "--R", "nan"},
                                         {"oracle", "hertz-axi", "--nu", "0.5"},
                                         {"oracle", "steuermann", "--b", "0"},
                                         {"oracle", "steuermann", "--re", "-1"},
                                         {"oracle", "sadowsky", "--a", "0"},
                                         {"oracle", "harding-sneddon", "--a", "-1"},
                                         {"oracle", "mcewen", "--at", "x"},
                                         {"oracle", "boussinesq", "--at", "0,0"},
                                         {"oracle", "nonsense"}})
    p.push_back({a});
  return p;
}

TEST_F(BadInputProbe, EveryProbeExitsTwoWithOneLineAndLeavesNoFile) {
  std::vector<Probe> probes;
  for (auto&& list : {name_probes(), set_probes(), friction_and_fit_probes(), sweep_probes(),
                      run_probes(), oracle_probes(), import_export_probes(dir_->path())})
    probes.insert(probes.end(), list.begin(), list.end());
  // Results files that must be refused by report, gate and merge.
  const std::vector<std::function<void(json&)>> mutations{
      [](json& j) { j["schema_version"] = "3"; },
      [](json& j) { j["schema_version"] = 4294967298ULL; },
      [](json& j) { j["schema_version"] = 2; },
      [](json& j) { j["schema"] = "x"; },
      [](json& j) { j["cases"][0]["overrides"] = "fkn"; },
      [](json& j) { j["cases"][0]["reason"] = 1; },
      [](json& j) { j["cases"][0]["iterations"] = "many"; },
      [](json& j) { j["cases"][0]["algorithm"] = "ALM"; },
      [](json& j) { j["cases"][0]["problem"] = 7; },
      [](json& j) { j["cases"].push_back(j["cases"][0]); },
      [](json& j) { j["cases"][0]["quantities"]["sigma_z_max"]["value"] = "1"; },
      [](json& j) { j["cases"][0]["quantities"]["sigma_z_max"]["study_exact"] = "1"; },
      [](json& j) { j["rows"][0]["grade"] = "z"; },
      [](json& j) { j.erase("cases"); },
      [](json& j) { j["problems"] = json::array(); },
      [](json& j) { j["run"]["jobs"] = -2; },
      [](json& j) { j["run"]["sweep"] = "fkn"; },
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", ""}, {"values", {1}}}});
      },
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", "fkn"}, {"values", json::array()}}});
      },
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", "fkn"}, {"values", {1, 1}}}});
      },
      [](json& j) {
        j["run"]["sweep"] = json::array({{{"key", "fkn"}, {"values", {"1"}}}});
      },
      [](json& j) {
        j["run"]["sweep"] =
            json::array({{{"key", "fkn"}, {"values", {1}}}, {{"key", "fkn"}, {"values", {2}}}});
      },
  };
  for (std::size_t i = 0; i < mutations.size(); ++i) {
    std::string name = "m";  // (appended, not concatenated: GCC 12 warns -Wrestrict here)
    name += std::to_string(i);
    name += ".json";
    const std::string f = mutated(name, mutations[i]);
    probes.push_back({{"report", "--results", f, "--out", "rep", "--no-figures"}});
    probes.push_back({{"gate", "--baseline", "good/results.json", "--results", f}});
    probes.push_back({{"merge", "mrg", f, "--no-report"}});
  }
  write("notjson.json", "{\"schema\": ");
  write("huge.json", R"({"schema": "contact-suite/results", "schema_version": 1e999})");
  for (const char* f : {"missing.json", ".", "notjson.json", "huge.json"}) {
    probes.push_back({{"report", "--results", f, "--out", "rep"}});
    probes.push_back(
        {{"report", "--results", "good/results.json", "--cost-run", f, "--out", "rep"}});
    probes.push_back({{"gate", "--baseline", f, "--results", "good/results.json"}});
  }
  probes.push_back({{"gate", "--baseline", "b.json", "--results", "good/results.json"}});
  probes.push_back({{"merge", "mrg", "good/results.json", "good/results.json"}});
  probes.push_back({{"merge", "mrg"}});
  probes.push_back({{"report", "--results", "good/results.json", "--out", "bad\nout"}});
  probes.push_back({{"report", "--results", "good/results.json", "--out", "r2", "--bench",
                     "notjson.json", "--no-figures"}});
  // several results files: the same file twice (every case in both), a missing second file;
  // mesh pictures from a directory that is not an export
  probes.push_back({{"report", "--results", "good/results.json", "--results", "good/results.json",
                     "--out", "r3", "--no-figures"}});
  probes.push_back({{"report", "--results", "good/results.json", "--results", "none.json", "--out",
                     "r4", "--no-figures"}});
  probes.push_back(
      {{"report", "--results", "good/results.json", "--mesh-pictures", "good", "--out", "r5"}});

  ASSERT_GE(probes.size(), 190u);
  const auto before = listing(dir_->path());
  int failures = 0;
  for (const auto& probe : probes) {
    std::string out, err, what;
    for (const auto& a : probe.args)
      what += " [" + a + "]";
    const auto r = run_in(dir_->path(), probe.args, out, err);
    EXPECT_EQ(r.signal, 0) << what;
    EXPECT_EQ(r.exit_code, 2) << what << "\n" << err;
    EXPECT_NE(err.find("contact-suite: error: "), std::string::npos) << what << "\n" << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << "one line:" << what << "\n" << err;
    EXPECT_EQ(out.find("nan"), std::string::npos) << what;
    const auto after = listing(dir_->path());
    EXPECT_EQ(after, before) << "stray files after" << what;
    failures += r.exit_code != 2;
  }
  EXPECT_EQ(failures, 0) << "of " << probes.size() << " probes";
}

}  // namespace
}  // namespace cs::apps::testing
