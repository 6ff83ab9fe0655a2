// The libraries' OpenMP regions run serially (suites::run_openmp_regions_serially): a CHOLMOD
// supernodal factorization then starts no OpenMP thread. Each case runs this program again as a
// child (the OpenMP runtime's state is per process) and reads how many threads the child had
// before and after one factorization.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/SparseCore>

#include "platform/child_process.hpp"
#include "solver/linear_solver.hpp"
#include "suites/run_environment.hpp"

namespace {

namespace fs = std::filesystem;

int thread_count() {
  int n = 0;
  for ([[maybe_unused]] const auto& task : fs::directory_iterator("/proc/self/task"))
    ++n;
  return n;
}

/// The 5-point Laplacian of an n x n grid plus the identity (lower triangle): SPD, with
/// supernodes large enough for CHOLMOD's supernodal factorization.
Eigen::SparseMatrix<double> grid_matrix(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n * n; ++i) {
    t.emplace_back(i, i, 5.0);
    if (i % n + 1 < n)
      t.emplace_back(i + 1, i, -1.0);
    if (i + n < n * n)
      t.emplace_back(i + n, i, -1.0);
  }
  Eigen::SparseMatrix<double> a(n * n, n * n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

struct Probe {
  int serial = -1;              ///< what run_openmp_regions_serially() returned (-1: not called)
  int before = -1, after = -1;  ///< the child's threads before and after one factorization
};

/// This program's probe, run as a child with `environment`.
Probe run_probe(std::vector<std::pair<std::string, std::string>> environment) {
  const fs::path out = fs::temp_directory_path() / ("cs-openmp-probe-" + std::to_string(getpid()));
  cs::platform::ChildOptions options;
  options.argv = {fs::read_symlink("/proc/self/exe").string(),
                  "--gtest_filter=OpenmpRegions.Probe"};
  environment.emplace_back("CS_OPENMP_PROBE", out.string());
  options.environment = std::move(environment);
  options.time_limit_seconds = 120;
  const auto result = cs::platform::run_child(options);
  EXPECT_TRUE(result.succeeded()) << result.describe();
  Probe p;
  std::ifstream(out) >> p.serial >> p.before >> p.after;
  fs::remove(out);
  return p;
}

}  // namespace

/// Not a test on its own: what a child run of this program reports to the tests below.
TEST(OpenmpRegions, Probe) {
  const char* file = std::getenv("CS_OPENMP_PROBE");
  if (file == nullptr)
    GTEST_SKIP() << "runs as a child of the tests below";
  const int serial =
      std::getenv("CS_OPENMP_SERIAL") ? int{cs::suites::run_openmp_regions_serially()} : -1;
  cs::suites::set_blas_threads(1);
  const Eigen::SparseMatrix<double> a = grid_matrix(120);
  cs::solver::LinearSolver solver;
  const int before = thread_count();
  ASSERT_TRUE(solver.compute(a).ok());
  ASSERT_TRUE(solver.info().supernodal);
  std::ofstream(file) << serial << ' ' << before << ' ' << thread_count() << '\n';
}

TEST(OpenmpRegions, ASupernodalFactorizationStartsNoOpenmpThread) {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr)
    GTEST_SKIP() << "OMP_THREAD_LIMIT is set: the user's limit is kept";
  const Probe serial = run_probe({{"CS_OPENMP_SERIAL", "1"}});
  EXPECT_EQ(serial.serial, 1);
  EXPECT_GT(serial.before, 0);
  EXPECT_EQ(serial.after, serial.before);
  // Without the call, the same factorization starts CHOLMOD's OpenMP team.
  const Probe team = run_probe({});
  EXPECT_GT(team.after, team.before);
}

TEST(OpenmpRegions, TheUsersThreadLimitIsKept) {
  const Probe user = run_probe({{"CS_OPENMP_SERIAL", "1"}, {"OMP_THREAD_LIMIT", "2"}});
  EXPECT_EQ(user.serial, 0);
  EXPECT_EQ(user.after, user.before + 1);  // a team of two: one more thread
}
