#include "solver/per_thread_rand.hpp"

#include <dlfcn.h>

#include <array>
#include <cstdint>
#include <cstdlib>

namespace {

/// One thread's generator: glibc's reentrant one (random_r), set up as glibc sets up the
/// generator of rand() before any srand(): initstate(1, state, 128).
struct Generator {
  std::array<char, 128> state{};
  random_data data{};
  Generator() { initstate_r(1, state.data(), state.size(), &data); }
};

Generator& this_threads_generator() {
  thread_local Generator generator;
  return generator;
}

}  // namespace

/// glibc's rand(), drawn from the calling thread's generator: the same numbers as glibc's
/// rand() for the same seeds, each thread's sequence its own.
extern "C" int rand() noexcept {
  std::int32_t r = 0;
  random_r(&this_threads_generator().data, &r);
  return r;
}

/// glibc's srand(), seeding the calling thread's generator only.
extern "C" void srand(unsigned seed) noexcept {
  srandom_r(seed, &this_threads_generator().data);
}

namespace cs::solver {

bool rand_is_per_thread() {
  // The rand() the libraries loaded with the program bind to lives in the object that holds
  // this function: this file's, where the program links it; libc's where the solver is a
  // library loaded later (the Python module).
  Dl_info bound{}, here{};
  const void* found = dlsym(RTLD_DEFAULT, "rand");
  return found != nullptr && dladdr(found, &bound) != 0 &&
         dladdr(reinterpret_cast<void*>(&rand_is_per_thread), &here) != 0 &&
         bound.dli_fbase == here.dli_fbase;
}

}  // namespace cs::solver
