#pragma once
// How a ccx run ended, from the child's exit, ccx's own messages (stdout) and its .sta file.
//
//   converged      ccx exited with status 0 after "Job finished";
//   not converged  ccx stopped on its convergence control: "*ERROR: too many cutbacks",
//                  "increment size smaller than minimum", "too many iterations" ... (ccx
//                  exits 201 and writes the best solution so far); the reason is ccx's message;
//   failed         anything else: ccx could not start, rejected the input ("*ERROR reading
//                  *SURFACE ..."), crashed on a signal, was interrupted, or its results could
//                  not be read; the reason is ccx's first *ERROR message or what happened;
//   timeout        stopped at the time limit.
//
// .sta rows ("STEP INC ATT ITRS TOT-TIME STEP-TIME INC-TIME", an ATT ending in U marks an
// attempt that did not converge) give the increments and the Newton iterations.

#include <string>
#include <string_view>

#include "platform/child_process.hpp"

namespace cs::adapters::calculix {

enum class CalculixStatus { Converged, NotConverged, Failed, Timeout };

/// "converged", "not converged", "failed", "timeout".
const char* to_string(CalculixStatus status);

/// What the .sta file tells about the increments.
struct StaSummary {
  int attempts = 0;    ///< rows: every attempt of every increment
  int increments = 0;  ///< converged attempts
  int iterations = 0;  ///< Newton iterations of all attempts
};

/// Parses the rows of a .sta file; lines that are not rows are ignored, and so is a row with a
/// count out of range (step, increment or attempt below 1, iterations below 0). The iterations
/// saturate at INT_MAX.
StaSummary parse_sta(std::string_view text);

/// ccx's first "*ERROR ..." message with its continuation lines joined into one line, runs of
/// spaces collapsed (at most 300 characters), or "" if there is none.
std::string first_error_message(std::string_view ccx_output);

/// Status and reason of a run.
struct RunOutcome {
  CalculixStatus status = CalculixStatus::Failed;
  std::string reason;  ///< empty when converged
};

/// Classifies a finished run (see the file comment).
RunOutcome classify_run(const platform::ChildResult& child, std::string_view ccx_output);

}  // namespace cs::adapters::calculix
