#include "suites/run_environment.hpp"

#include <dlfcn.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>

#include <fmt/format.h>
#include <gsl/gsl_version.h>
#include <Eigen/Core>

#include "solver/openmp_levels.hpp"

#ifndef CONTACT_SUITE_VERSION
#define CONTACT_SUITE_VERSION "unknown"
#endif

namespace cs::suites {
namespace {

/// Whether the process asked for serial OpenMP regions (run_openmp_regions_serially).
std::atomic<bool> openmp_regions_serial = false;

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos)
        return line.substr(colon + 2);
    }
  }
  return "unknown";
}

double memory_gib() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  return static_cast<double>(pages) * static_cast<double>(page_size) / (1024.0 * 1024 * 1024);
}

std::string blas_name() {
  using ConfigFn = char* (*)();
  if (auto fn = reinterpret_cast<ConfigFn>(dlsym(RTLD_DEFAULT, "openblas_get_config"))) {
    return std::string("OpenBLAS ") + fn();
  }
  return "reference BLAS (OpenBLAS not found)";
}

}  // namespace

nlohmann::json run_environment() {
  utsname un{};
  uname(&un);
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  return {{"contact_suite_version", contact_suite_version()},
          {"hostname", host},
          {"os", fmt::format("{} {} {}", un.sysname, un.release, un.machine)},
          {"cpu", cpu_model()},
          {"cores", static_cast<int>(std::thread::hardware_concurrency())},
          {"memory_gib", memory_gib()},
          {"compiler", fmt::format("GCC {}", __VERSION__)},
          {"eigen",
           fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
          {"gsl", GSL_VERSION},
          {"blas", blas_name()},
          // glibc's tunables in force, e.g. the huge pages of suites/huge_pages.hpp ("" if unset)
          {"glibc_tunables", std::getenv("GLIBC_TUNABLES") ? std::getenv("GLIBC_TUNABLES") : ""}};
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

bool set_blas_threads(int threads) {
  using SetFn = void (*)(int);
  if (auto fn = reinterpret_cast<SetFn>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) {
    fn(threads);
    return true;
  }
  return false;
}

int blas_threads() {
  using GetFn = int (*)();
  if (auto fn = reinterpret_cast<GetFn>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")))
    return fn();
  return 1;
}

bool run_openmp_regions_serially() {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr || !solver::set_openmp_active_levels(0))
    return false;  // (0: each parallel region runs on the thread that meets it)
  openmp_regions_serial = true;
  return true;
}

void keep_openmp_regions_serial_here() {
  if (openmp_regions_serial)
    run_openmp_regions_serially();
}

std::string contact_suite_version() {
  return CONTACT_SUITE_VERSION;
}

}  // namespace cs::suites
