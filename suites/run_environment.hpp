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

/// Makes the libraries' OpenMP regions run on the calling thread alone (max-active-levels 0),
/// unless the user set OMP_THREAD_LIMIT. CHOLMOD 3 runs the clearing and scattering loops of
/// every supernodal factorization as OpenMP regions of a fixed 4 threads
/// (CHOLMOD_OMP_NUM_THREADS, compiled into the library), for any matrix of more than 128 rows.
/// The loops are short and memory-bound; with fewer cores than threads, or two workers
/// factorizing at once, the threads wait for each other (libgomp spins, then sleeps on a futex)
/// longer than the loops take. The dense kernels, where a factorization spends its time, are
/// threaded by OpenBLAS (set_blas_threads), which this does not touch. Returns false when no
/// OpenMP runtime is loaded or the user's limit is kept. Call once, before any factorization.
/// libgomp keeps the setting per thread (max-active-levels-var belongs to the thread's data
/// environment): a thread started later inherits the runtime's default, not this, and calls
/// keep_openmp_regions_serial_here().
bool run_openmp_regions_serially();

/// On a thread started after run_openmp_regions_serially() (the runner's workers): runs the
/// libraries' OpenMP regions met on this thread serially too, if the process asked for it.
void keep_openmp_regions_serial_here();

}  // namespace cs::suites
