#pragma once
// Progress of a run: a bar with counts and an ETA on a terminal, one plain line per finished
// case otherwise (logs, CI). Not thread-safe by itself: the runner serializes its callback.

#include <chrono>
#include <cstdio>
#include <string>

#include "suites/case_result.hpp"

namespace cs::suites {

class ProgressReporter {
 public:
  /// Reports on `out` (usually stderr); `interactive` selects the bar (a terminal).
  ProgressReporter(std::size_t total, std::FILE* out, bool interactive);

  /// Records one finished case and redraws the bar or prints its line.
  void case_done(const CaseResult& result);
  /// Ends the bar with a newline and prints the totals.
  void finish();

  /// "1:02:03" / "2:03" / "5 s": a duration for humans.
  static std::string format_duration(double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  std::size_t total_;
  std::FILE* out_;
  bool interactive_;
  Clock::time_point start_;
  std::size_t done_ = 0, converged_ = 0, not_converged_ = 0, failed_ = 0;
};

}  // namespace cs::suites
