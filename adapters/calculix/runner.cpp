#include "adapters/calculix/runner.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "adapters/calculix/calculix_error.hpp"
#include "adapters/calculix/expansion_map.hpp"
#include "adapters/calculix/frd_reader.hpp"
#include "adapters/calculix/input_deck.hpp"
#include "adapters/calculix/result_mapping.hpp"
#include "platform/child_process.hpp"

namespace cs::adapters::calculix {
namespace {

namespace fs = std::filesystem;

bool is_executable_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && access(path.c_str(), X_OK) == 0;
}

void write_deck_file(const fs::path& path, const std::string& deck) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << deck;
  out.close();
  if (!out)
    throw CalculixError(fmt::format("CalculiX: cannot write the deck '{}'", path.string()));
}

/// Makes the job directory and removes the outputs of an earlier run of the same job.
void prepare_directory(const fs::path& dir, const std::string& job) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw CalculixError(
        fmt::format("CalculiX: cannot create the job directory '{}'", dir.string()));
  for (const char* ext : {".frd", ".dat", ".sta", ".cvg", ".12d", ".log"})
    fs::remove(dir / (job + ext), ec);
}

platform::ChildOptions ccx_command(const CalculixOptions& options, const fs::path& dir) {
  platform::ChildOptions child;
  child.argv = {options.executable, "-i", options.job_name};
  child.working_directory = dir;
  child.environment = {{"OMP_NUM_THREADS", "1"}, {"CCX_NPROC_EQUATION_SOLVER", "1"}};
  child.stdout_path = dir / (options.job_name + ".log");
  child.stderr_path = child.stdout_path;
  child.time_limit_seconds = options.time_limit_seconds;
  return child;
}

std::string read_if_present(const fs::path& path) {
  std::error_code ec;
  return fs::exists(path, ec) ? read_text_file(path) : std::string();
}

/// Reads the .frd (and .12d) of a converged run into `result`; a parse failure is a status.
void read_results(const solver::Model& model, const solver::ContactPair& pair, const fs::path& stem,
                  CalculixResult& result) {
  try {
    const FrdFile frd = read_frd(fs::path(stem).replace_extension(".frd"));
    const ExpansionMap expansion = read_expansion(fs::path(stem).replace_extension(".12d"));
    map_results(frd, expansion, model, pair, result);
  } catch (const CalculixOutputError& e) {
    result.status = CalculixStatus::Failed;
    result.reason = std::string("cannot read the results: ") + e.what();
    result.nodal_stress.clear();
    result.displacement.clear();
    result.reaction.clear();
    result.contact.clear();
  }
}

}  // namespace

void require_ccx(const std::string& executable) {
  const std::string missing = fmt::format(
      "CalculiX: '{}' not found in PATH (install the Debian package calculix-ccx)", executable);
  if (executable.empty())
    throw CalculixError(missing);
  if (executable.find('/') != std::string::npos) {
    if (!is_executable_file(executable))
      throw CalculixError(fmt::format("CalculiX: '{}' is not an executable file", executable));
    return;
  }
  const char* path = std::getenv("PATH");
  std::string_view dirs = path != nullptr ? path : "";
  while (true) {
    const std::size_t colon = dirs.find(':');
    const std::string_view dir = dirs.substr(0, colon);
    if (is_executable_file(fs::path(dir.empty() ? "." : std::string(dir)) / executable))
      return;
    if (colon == std::string_view::npos)
      throw CalculixError(missing);
    dirs.remove_prefix(colon + 1);
  }
}

CalculixResult run_calculix(const solver::Model& model, const solver::ContactPair& pair,
                            const CalculixOptions& options, const fs::path& work_dir) {
  require_ccx(options.executable);
  const std::string deck = input_deck(model, pair, options);  // throws on bad input
  prepare_directory(work_dir, options.job_name);
  const fs::path stem = work_dir / options.job_name;
  write_deck_file(fs::path(stem).replace_extension(".inp"), deck);

  const platform::ChildResult child = platform::run_child(ccx_command(options, work_dir));
  CalculixResult result;
  result.job_directory = work_dir;
  result.wall_seconds = child.wall_seconds;
  result.peak_rss_mb = child.peak_rss_mb;
  const std::string log = read_if_present(fs::path(stem).replace_extension(".log"));
  const RunOutcome outcome = classify_run(child, log);
  result.status = outcome.status;
  result.reason = outcome.reason;
  const StaSummary sta = parse_sta(read_if_present(fs::path(stem).replace_extension(".sta")));
  if (sta.attempts > 0) {
    result.increments = sta.increments;
    result.iterations = sta.iterations;
  }
  if (result.converged())
    read_results(model, pair, stem, result);
  return result;
}

}  // namespace cs::adapters::calculix
