#pragma once
// A one-line progress display on a terminal: simulated time, percent, step size, steps/s, ETA,
// redrawn in place (carriage return) at most 4 times a second, and only once a run has taken 2 s
// (short runs stay quiet). The caller enables it only when stderr is a terminal and not --quiet.
#include <chrono>
#include <ostream>

namespace sphmol {

class ProgressLine {
 public:
  ProgressLine(std::ostream* out, double t_start, double t_end);
  void update(double t, double dt, long steps);
  // Erases the line (before another log line, and at the end).
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream* out_;
  double t_start_, t_end_;
  Clock::time_point start_, last_draw_;
  long steps_at_start_ = -1;
  bool shown_ = false;
};

}  // namespace sphmol
