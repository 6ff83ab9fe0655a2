#pragma once
// libc's rand() and srand(), one generator per thread.
//
// METIS (Debian's libmetis, built without GKlib's own generator) seeds libc's rand() with
// srand() at each call and draws from it while it orders. glibc keeps one generator for the
// whole process, so two orderings on two threads interleave their draws: they must take turns
// (metis_turn) or their orderings depend on the schedule. A program linked with the solver
// defines rand() and srand() itself, drawing from the calling thread's own generator (glibc's
// reentrant random_r, set up as glibc sets up its own): the dynamic linker binds libmetis's
// rand() to the program's, each call draws exactly the numbers it would draw alone, and METIS
// runs on two threads at once.

namespace cs::solver {

/// Whether the libraries of this process draw rand() per thread: true in a program linked with
/// the solver; false where the solver is a library loaded after them (they keep libc's).
bool rand_is_per_thread();

}  // namespace cs::solver
