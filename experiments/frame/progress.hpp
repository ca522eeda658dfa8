// Progress of a long run on stderr: at most one line every `interval_s` seconds (10 by default) with the
// simulated time, the step, the share done and the expected remaining wall time. Runs shorter than the
// interval print nothing, so quick runs and tests stay quiet.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace sph {

class Progress {
 public:
  Progress(std::string label, double t_end, double interval_s = 10.0)
      : label_(std::move(label)), t_end_(t_end), interval_(interval_s), start_(Clock::now()), last_(start_) {}

  /// Call once per step; prints only when `interval_s` has passed since the last line.
  void update(double t, long step) {
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_).count() < interval_) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double share = t_end_ > 0 ? t / t_end_ : 0.0;
    const double eta = share > 0 ? elapsed * (1.0 - share) / share : 0.0;
    std::fprintf(stderr, "%s: t = %.4g / %.4g (%.0f%%), step %ld, %.0f s elapsed, ~%.0f s to go\n", label_.c_str(), t,
                 t_end_, 100.0 * share, step, elapsed, eta);
  }
  double elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  double t_end_, interval_;
  Clock::time_point start_, last_;
};

}  // namespace sph
