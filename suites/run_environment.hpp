#pragma once
// What a run records about where it ran: machine, compiler, library versions, BLAS.

#include <nlohmann/json.hpp>

namespace cs::suites {

/// The environment of this process as a JSON object (results.json `run.environment`).
nlohmann::json run_environment();

/// This build's version: the project version and, in a git checkout, the commit.
std::string contact_suite_version();

/// The current UTC time in ISO 8601 ("2026-11-22T10:00:00Z").
std::string utc_now_iso8601();

/// Sets the number of OpenBLAS threads if the BLAS in use is OpenBLAS (looked up at run time);
/// returns false when it is not. Parallel runs use one BLAS thread per worker.
bool set_blas_threads(int threads);

/// The number of OpenBLAS threads; 1 when the BLAS in use is not OpenBLAS.
int blas_threads();

}  // namespace cs::suites
