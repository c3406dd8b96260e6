#pragma once
// SIGINT/SIGTERM during a run: the handler only records the signal; the run loop checks it between
// steps, writes a checkpoint and the summary so far ("status": "interrupted") and returns, and
// sph-mol exits with 128 + the signal number (130 for SIGINT, 143 for SIGTERM), the shell convention.
// Over MPI ranks every rank installs the handlers, and the run loop stops where the ranks agree
// (run/partitioned_run.hpp: PartitionedRun::check).
namespace sphmol {

// Installs the handlers for its lifetime (restores the previous ones after, and forgets the signal).
class SignalGuard {
 public:
  SignalGuard();
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;
};

// The signal received since the guard was installed, or 0 (also when no guard is installed).
int pending_signal();

}  // namespace sphmol
