#pragma once
// How long an idle OpenMP thread spins before it sleeps. libgomp spins 300,000 iterations at every
// barrier by default, then sleeps; when the partner thread has been descheduled by another process,
// the spinning waiter burns the very core that partner needs, and a step of 15 barriers then runs
// several times slower than on one thread. A short spin keeps the quiet-machine speed (the partner
// usually arrives within a few microseconds) and gives the core away soon under load.
//
// libgomp reads OMP_WAIT_POLICY and GOMP_SPINCOUNT once, when it is loaded: before main() and before
// any constructor of the executable (its own initialiser runs first), so setenv() in the process is
// too late. The program therefore sets GOMP_SPINCOUNT and executes itself once more, with the same
// arguments and no shell. A user who sets either variable keeps it, and no re-execution happens.
#include <unistd.h>

#include <cstdlib>

namespace sphmol {

// Spin iterations before a waiting thread sleeps (libgomp's default: 300,000); the measurements that
// chose it are in docs/performance.md.
inline constexpr const char* bounded_spin_count = "1000";

// Whether the program should choose the spin itself: more than one thread, and the user chose neither
// OMP_WAIT_POLICY nor GOMP_SPINCOUNT (an empty value counts as set: libgomp would read it).
inline bool should_bound_openmp_spin(int threads, const char* wait_policy, const char* spin_count) {
  return threads > 1 && wait_policy == nullptr && spin_count == nullptr;
}

// For more than one thread, when the user chose no wait policy: sets GOMP_SPINCOUNT and replaces the
// process by a new run of the same executable (/proc/self/exe) with the same argv; the new process
// finds the variable set and goes on. Returns only when nothing was executed: false if the
// re-execution failed (the run goes on with libgomp's default spin), true otherwise.
inline bool bound_openmp_spin(int threads, char** argv) {
  if (!should_bound_openmp_spin(threads, std::getenv("OMP_WAIT_POLICY"), std::getenv("GOMP_SPINCOUNT"))) return true;
  // The variable set here is the guard against a loop: the re-executed program sees it and stays.
  if (::setenv("GOMP_SPINCOUNT", bounded_spin_count, 0) != 0) return false;
  ::execv("/proc/self/exe", argv);
  ::unsetenv("GOMP_SPINCOUNT");  // not executed (no /proc?): the environment stays the user's
  return false;
}

}  // namespace sphmol
