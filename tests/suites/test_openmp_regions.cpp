// The libraries' OpenMP regions run serially (suites::run_openmp_regions_serially): a CHOLMOD
// supernodal factorization then starts no OpenMP thread. Each case runs this program again as a
// child (the OpenMP runtime's state is per process) and reads how many threads the child had
// before and after one factorization.

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/SparseCore>

#include "platform/child_process.hpp"
#include "solver/linear_solver.hpp"
#include "solver/spare_cores.hpp"
#include "suites/run_environment.hpp"
#include "suites/runner.hpp"

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

/// One supernodal factorization per case, on the worker that runs it; records the most threads
/// the process had just after any of them.
class FactorizingExecutor : public cs::suites::GroupExecutor {
 public:
  explicit FactorizingExecutor(std::atomic<int>& most) : most_(most) {}
  cs::suites::CaseResult run(const cs::schema::CaseSpec&) override {
    cs::solver::LinearSolver solver;
    EXPECT_TRUE(solver.compute(grid_matrix(120)).ok());
    EXPECT_TRUE(solver.info().supernodal);
    for (int n = thread_count(), m = most_; n > m && !most_.compare_exchange_weak(m, n);) {
    }
    return {};
  }

 private:
  std::atomic<int>& most_;
};

/// The process's threads just after one supernodal factorization on the calling thread.
int factorize_and_count() {
  cs::solver::LinearSolver solver;
  EXPECT_TRUE(solver.compute(grid_matrix(120)).ok());
  EXPECT_TRUE(solver.info().supernodal);
  return thread_count();
}

/// The threads after factorizing on a core this thread lends and run_both() borrows, while
/// the borrowed core's thread is alive.
int threads_after_factorizing_on_a_borrowed_core() {
  const cs::solver::CoreLoan loan(1);
  const auto lender = std::this_thread::get_id();
  bool borrowed = false;
  int after = 0;
  cs::solver::run_both([] {},
                       [&] {
                         borrowed = std::this_thread::get_id() != lender;
                         after = factorize_and_count();
                       });
  EXPECT_TRUE(borrowed);
  return after;
}

/// The threads after factorizing: on this thread, (CS_OPENMP_BORROWED) on a borrowed core, or
/// (CS_OPENMP_WORKERS) on each of the two workers of a run of two models, the most the process
/// had after any factorization.
int threads_after_factorizing() {
  if (std::getenv("CS_OPENMP_BORROWED") != nullptr)
    return threads_after_factorizing_on_a_borrowed_core();
  if (std::getenv("CS_OPENMP_WORKERS") == nullptr)
    return factorize_and_count();
  std::atomic<int> most = 0;
  cs::schema::CaseSpec a, b;
  b.mesh = cs::schema::MeshLevel::M;  // another model: the two run on two workers
  cs::suites::RunnerOptions two_workers;
  two_workers.jobs = 2;
  cs::suites::run_cases(
      {a, b}, [&](const auto&) { return std::make_unique<FactorizingExecutor>(most); },
      two_workers);
  return most;
}

/// Not a test on its own: what a child run of this program reports to the tests below.
TEST(OpenmpRegions, Probe) {
  const char* file = std::getenv("CS_OPENMP_PROBE");
  if (file == nullptr)
    GTEST_SKIP() << "runs as a child of the tests below";
  const int serial =
      std::getenv("CS_OPENMP_SERIAL") ? int{cs::suites::run_openmp_regions_serially()} : -1;
  cs::suites::set_blas_threads(1);
  const int before = thread_count();
  const int after = threads_after_factorizing();
  std::ofstream(file) << serial << ' ' << before << ' ' << after << '\n';
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

/// libgomp keeps the setting per thread: the runner's workers must take it up themselves. A run
/// of two models on two workers then has the two workers' threads and no OpenMP team.
TEST(OpenmpRegions, TheRunnersWorkersStartNoOpenmpThread) {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr)
    GTEST_SKIP() << "OMP_THREAD_LIMIT is set: the user's limit is kept";
  const Probe serial = run_probe({{"CS_OPENMP_SERIAL", "1"}, {"CS_OPENMP_WORKERS", "1"}});
  EXPECT_EQ(serial.serial, 1);
  EXPECT_GT(serial.before, 0);
  EXPECT_LE(serial.after, serial.before + 2);
  // Without the call, each worker's factorization starts a team of its own.
  const Probe team = run_probe({{"CS_OPENMP_WORKERS", "1"}});
  EXPECT_GT(team.after, team.before + 2);
}

/// run_both() hands the setting to the thread of the core it borrows (a large model's second
/// side): the factorization there starts no team either, only that thread.
TEST(OpenmpRegions, ABorrowedCoresThreadStartsNoOpenmpThread) {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr)
    GTEST_SKIP() << "OMP_THREAD_LIMIT is set: the user's limit is kept";
  const Probe serial = run_probe({{"CS_OPENMP_SERIAL", "1"}, {"CS_OPENMP_BORROWED", "1"}});
  EXPECT_EQ(serial.serial, 1);
  EXPECT_GT(serial.before, 0);
  EXPECT_EQ(serial.after, serial.before + 1);
  // Without the call, the borrowed core's factorization starts CHOLMOD's team.
  const Probe team = run_probe({{"CS_OPENMP_BORROWED", "1"}});
  EXPECT_GT(team.after, team.before + 1);
}

TEST(OpenmpRegions, TheUsersThreadLimitIsKept) {
  const Probe user = run_probe({{"CS_OPENMP_SERIAL", "1"}, {"OMP_THREAD_LIMIT", "2"}});
  EXPECT_EQ(user.serial, 0);
  EXPECT_EQ(user.after, user.before + 1);  // a team of two: one more thread
}
