#pragma once
// Cores a program lends to the parallel steps of one solve.
//
// Some steps of a solve can run on a second thread without changing a single bit of their
// result: the two halves of a split nested dissection (fill_reducing_ordering.hpp) are ordered
// independently, so ordering them one after the other or at once gives the same permutation;
// the two sides of the largest models are condensed independently (contact/condensation.hpp);
// the assembly's element matrices are computed in two halves and added in element order
// (assembly.hpp).
// Such a step borrows a spare core when one is idle and runs alone otherwise. The program says
// how many cores are idle: `case` lends the cores it does not use itself; `run` lends those its
// jobs leave unused, and each a finished worker frees once fewer workers than cores are left.
// No value ever depends on whether a core was free.

#include <atomic>
#include <functional>

namespace cs::solver {

/// Adds `n` idle cores to the pool; a negative n takes them back. The count is exact: cores
/// taken back while borrowed leave it below zero until the borrowers return them.
void lend_spare_cores(int n);

/// Cores lent to the pool for this object's lifetime: the constructor, lend() and
/// lend_up_to() add them, the destructor takes all of them back.
class CoreLoan {
 public:
  explicit CoreLoan(int n = 0) { lend(n); }
  ~CoreLoan() { lend_spare_cores(-lent_.load()); }
  CoreLoan(const CoreLoan&) = delete;
  CoreLoan& operator=(const CoreLoan&) = delete;

  /// Lends `n` more (n >= 0).
  void lend(int n) {
    lent_ += n;
    lend_spare_cores(n);
  }

  /// Lends what brings this loan up to `total` cores; nothing if it holds that many already.
  void lend_up_to(int total) {
    int now = lent_.load();
    while (now < total && !lent_.compare_exchange_weak(now, total)) {
    }
    if (now < total)
      lend_spare_cores(total - now);
  }

 private:
  std::atomic<int> lent_{0};
};

/// The number of idle cores in the pool now (0 while it is below zero).
int spare_cores();

/// One core borrowed from the pool for the borrower's lifetime, or none when the pool was
/// empty; returned on destruction.
class SpareCore {
 public:
  SpareCore();  ///< tries to borrow one
  ~SpareCore();
  SpareCore(const SpareCore&) = delete;
  SpareCore& operator=(const SpareCore&) = delete;

  /// Whether a core was borrowed.
  explicit operator bool() const { return borrowed_; }

 private:
  bool borrowed_ = false;
};

/// Runs first() on this thread and second() on a borrowed spare core when one is idle (and a
/// thread can be started), else second() after first(). Both have run when it returns; an
/// exception of either is rethrown (first()'s when both throw; on one thread, a throwing
/// first() leaves second() unrun). The borrowed core's thread runs the libraries' OpenMP
/// regions as this thread does: libgomp keeps max-active-levels per thread, and a new thread
/// would otherwise start CHOLMOD's team of four for every supernodal factorization, whose
/// spinning threads take the core that first() runs on.
void run_both(const std::function<void()>& first, const std::function<void()>& second);

}  // namespace cs::solver
