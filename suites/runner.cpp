#include "suites/runner.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include "platform/available_cores.hpp"
#include "solver/spare_cores.hpp"
#include "suites/run_environment.hpp"

namespace cs::suites {
namespace {

/// The cases sharing one model, as indices into the run's case list.
struct Group {
  std::vector<std::size_t> members;
  double cost = 1.0;
  double memory = 0.0;  ///< estimated, for the memory-aware schedule
};

/// Hands out groups in order, holding back one whose estimated memory would take the running
/// total beyond the budget (unless nothing runs): the next one that fits goes first.
class GroupQueue {
 public:
  GroupQueue(const std::vector<const Group*>& groups, double budget)
      : groups_(groups), started_(groups.size(), false), budget_(budget) {}

  /// The next group to run, or nullopt when every group has started or `stop` says so.
  std::optional<std::size_t> take(const std::function<bool()>& stop) {
    std::unique_lock lock(mutex_);
    for (;;) {
      if (stop && stop())
        return std::nullopt;
      bool any_left = false;
      for (std::size_t g = 0; g < groups_.size(); ++g) {
        if (started_[g])
          continue;
        any_left = true;
        const double need = groups_[g]->memory;
        if (running_ == 0 || budget_ <= 0.0 || memory_ + need <= budget_) {
          started_[g] = true;
          ++running_;
          memory_ += need;
          return g;
        }
      }
      if (!any_left)
        return std::nullopt;
      changed_.wait(lock);
    }
  }

  void finished(std::size_t g) {
    {
      std::lock_guard lock(mutex_);
      --running_;
      memory_ -= groups_[g]->memory;
    }
    changed_.notify_all();
  }

 private:
  const std::vector<const Group*>& groups_;
  std::vector<bool> started_;
  double budget_;
  int running_ = 0;
  double memory_ = 0.0;
  std::mutex mutex_;
  std::condition_variable changed_;
};

bool is_contact_only_parameter(const std::string& name) {
  return name == "fkn" || name == "ftoln" || name == "pinball";
}

CaseResult failed_result(const CaseSpec& spec, const std::string& reason) {
  CaseResult r;
  r.spec = spec;
  r.status = CaseStatus::failed;
  r.reason = reason.empty() ? "unknown failure" : reason;
  return r;
}

/// Runs one group: build its executor, run each member; every failure becomes a result.
void run_group(const Group& group, const std::vector<CaseSpec>& cases,
               const ExecutorFactory& make_executor, std::vector<CaseResult>& results,
               const std::function<void(const CaseResult&)>& done) {
  using Clock = std::chrono::steady_clock;
  std::unique_ptr<GroupExecutor> executor;
  std::string build_error;
  const auto build_start = Clock::now();
  try {
    executor = make_executor(cases[group.members.front()]);
  } catch (const std::exception& e) {
    build_error = e.what();
  } catch (...) {
    build_error = "unknown exception while building the model";
  }
  // The model is built once for the group; its cost is charged to the first case.
  double build_seconds = std::chrono::duration<double>(Clock::now() - build_start).count();
  for (std::size_t index : group.members) {
    const CaseSpec& spec = cases[index];
    CaseResult result;
    const auto start = Clock::now();
    if (!executor) {
      result = failed_result(spec, "model could not be built: " + build_error);
    } else {
      try {
        result = executor->run(spec);
        result.spec = spec;
      } catch (const std::exception& e) {
        result = failed_result(spec, e.what());
      } catch (...) {
        result = failed_result(spec, "unknown exception");
      }
    }
    result.wall_seconds =
        std::chrono::duration<double>(Clock::now() - start).count() + build_seconds;
    build_seconds = 0.0;
    // An external solver reports its own child process's peak; keep the larger.
    result.peak_rss_mb = std::max(result.peak_rss_mb, peak_rss_mb());
    results[index] = std::move(result);
    done(results[index]);
  }
}

}  // namespace

std::string model_key(const CaseSpec& spec) {
  CaseSpec s = spec;
  s.algorithm = Algorithm::AL;
  s.contact = ContactKind::ss;
  s.recovery = Recovery::spr;  // post-processing: the model and its solve are shared
  std::erase_if(s.overrides, [](const auto& kv) { return is_contact_only_parameter(kv.first); });
  return case_id(s);
}

std::vector<std::vector<std::size_t>> group_by_model(const std::vector<CaseSpec>& cases) {
  std::map<std::string, std::size_t> slot;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto [it, fresh] = slot.try_emplace(model_key(cases[i]), groups.size());
    if (fresh)
      groups.emplace_back();
    groups[it->second].push_back(i);
  }
  return groups;
}

std::vector<CaseResult> run_cases(const std::vector<CaseSpec>& cases,
                                  const ExecutorFactory& make_executor,
                                  const RunnerOptions& options) {
  std::map<std::string, Group> by_key;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string key = model_key(cases[i]);
    auto [it, inserted] = by_key.try_emplace(key);
    if (inserted) {
      order.push_back(key);
      if (options.group_cost)
        it->second.cost = options.group_cost(cases[i]);
      if (options.group_memory)
        it->second.memory = options.group_memory(cases[i]);
    }
    it->second.members.push_back(i);
  }
  std::vector<const Group*> groups;
  for (const auto& key : order)
    groups.push_back(&by_key.at(key));
  // Largest first (stable: equal costs keep the study's order), so no big group runs last.
  std::stable_sort(groups.begin(), groups.end(),
                   [](const Group* a, const Group* b) { return a->cost > b->cost; });

  std::vector<CaseResult> results(cases.size());
  std::mutex done_mutex;
  auto done = [&](const CaseResult& r) {
    if (!options.on_case_done)
      return;
    std::lock_guard lock(done_mutex);
    options.on_case_done(r);
  };
  GroupQueue queue(groups, options.group_memory ? options.memory_budget : 0.0);
  auto worker = [&] {
    while (const auto g = queue.take(options.should_stop)) {
      run_group(*groups[*g], cases, make_executor, results, done);
      queue.finished(*g);
    }
  };
  const int cores = platform::available_cores();
  int jobs = options.jobs > 0 ? options.jobs : cores;
  jobs = std::clamp(jobs, 1, std::max<int>(1, static_cast<int>(groups.size())));
  // Cores no worker uses go to the steps of a solve that split without changing a value
  // (solver/spare_cores.hpp): those --jobs leaves idle, and each that a finished worker frees
  // once fewer workers than cores are left (with --jobs above the core count, not before).
  solver::CoreLoan loan(std::max(0, cores - jobs));
  std::atomic<int> working = jobs;
  auto lending_worker = [&] {
    worker();
    loan.lend_up_to(std::max(0, cores - --working));
  };
  if (jobs == 1) {
    lending_worker();
  } else {
    std::vector<std::jthread> threads;
    for (int j = 0; j < jobs; ++j) {
      threads.emplace_back([&] {
        keep_openmp_regions_serial_here();  // the setting is per thread
        lending_worker();
      });
    }
  }
  return results;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace cs::suites
