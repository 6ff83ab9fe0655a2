#include "suites/progress.hpp"

#include <cmath>

#include <fmt/format.h>

namespace cs::suites {

ProgressReporter::ProgressReporter(std::size_t total, std::FILE* out, bool interactive)
    : total_(total), out_(out), interactive_(interactive), start_(Clock::now()) {}

std::string ProgressReporter::format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0)
    return "?";
  const long s = std::lround(seconds);
  if (s < 60)
    return fmt::format("{} s", s);
  if (s < 3600)
    return fmt::format("{}:{:02}", s / 60, s % 60);
  return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

void ProgressReporter::case_done(const CaseResult& r) {
  ++done_;
  switch (r.status) {
    case CaseStatus::converged:
      ++converged_;
      break;
    case CaseStatus::not_converged:
      ++not_converged_;
      break;
    case CaseStatus::failed:
    case CaseStatus::timeout:
      ++failed_;
      break;
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (!interactive_) {
    fmt::print(out_, "[{:>{}}/{}] {:<32} {:<13} {:8.2f} s{}\n", done_,
               std::to_string(total_).size(), total_, case_id(r.spec), to_string(r.status),
               r.wall_seconds, r.reason.empty() ? "" : "  (" + r.reason + ")");
    std::fflush(out_);
    return;
  }
  constexpr int kWidth = 30;
  const double fraction = total_ ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0;
  const int filled = static_cast<int>(std::floor(fraction * kWidth));
  const double eta = done_ ? elapsed / static_cast<double>(done_) * (total_ - done_) : NAN;
  fmt::print(out_,
             "\r[{}{}] {}/{}  converged {}  not converged {}  failed {}  {} elapsed  ETA {}  ",
             std::string(filled, '#'), std::string(kWidth - filled, '.'), done_, total_, converged_,
             not_converged_, failed_, format_duration(elapsed), format_duration(eta));
  std::fflush(out_);
}

void ProgressReporter::finish() {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (interactive_)
    fmt::print(out_, "\n");
  fmt::print(out_, "{} cases in {}: {} converged, {} not converged, {} failed\n", done_,
             format_duration(elapsed), converged_, not_converged_, failed_);
  std::fflush(out_);
}

}  // namespace cs::suites
