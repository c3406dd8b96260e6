#include "sphmol/run/progress.hpp"

#include <cstdio>

namespace sphmol {

ProgressLine::ProgressLine(std::ostream* out, double t_start, double t_end)
    : out_(out), t_start_(t_start), t_end_(t_end), start_(Clock::now()), last_draw_(start_) {}

void ProgressLine::update(double t, double dt, long steps) {
  if (!out_) return;
  if (steps_at_start_ < 0) steps_at_start_ = steps;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 2.0 || std::chrono::duration<double>(now - last_draw_).count() < 0.25) return;
  last_draw_ = now;
  const double done = (t - t_start_) / (t_end_ - t_start_);
  const double rate = static_cast<double>(steps - steps_at_start_) / elapsed;
  const double eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
  const long e = static_cast<long>(eta + 0.5);
  char buf[160];
  std::snprintf(buf, sizeof buf, "\r\033[Kt = %.6g s (%5.1f%%)  dt = %.3e s  %.0f steps/s  ETA %ld:%02ld:%02ld", t,
                100.0 * done, dt, rate, e / 3600, (e / 60) % 60, e % 60);
  *out_ << buf << std::flush;
  shown_ = true;
}

void ProgressLine::clear() {
  if (out_ && shown_) *out_ << "\r\033[K" << std::flush;
  shown_ = false;
}

}  // namespace sphmol
