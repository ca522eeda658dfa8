// Progress of a long run on stderr: at most one line every `interval_s` seconds (10 by default) with the
// simulated time, the step, the share done and the expected remaining wall time in human units. Runs shorter
// than the interval print nothing, so quick runs and tests stay quiet.
//
// The run-length guard (issue 47 item 1): after kEstimateAfter seconds of stepping, the remaining time is
// estimated from the steps taken (the measured throughput of this machine and the run's own time step) and a
// run that would take longer than the limit stops with RunTooLong, before it has spent more than those seconds:
// `--cfl 1e-30` or `--t-max 1e300` is refused, not started for 1e27 s. The limit is the driver's --max-run-hours
// (Driver::run sets it; default 24 h, 0 = none). The estimate is taken against t_end, the run's upper end: a
// run whose own stop rule would end it sooner (the rings parting) is refused all the same, and runs with the flag.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace sph {

/// A duration in the unit a reader takes in at once: "42 s", "12 min", "3.4 h", "2.1 days", "3.2e+19 years".
inline std::string human_duration(double s) {
  char text[64];
  if (!std::isfinite(s)) return "forever";
  if (s < 120) std::snprintf(text, sizeof text, "%.0f s", s);
  else if (s < 7200) std::snprintf(text, sizeof text, "%.0f min", s / 60);
  else if (s < 2 * 86400) std::snprintf(text, sizeof text, "%.1f h", s / 3600);
  else if (s < 365.25 * 86400) std::snprintf(text, sizeof text, "%.1f days", s / 86400);
  else std::snprintf(text, sizeof text, "%.2g years", s / (365.25 * 86400));
  return text;
}

/// A run refused by the run-length guard; the driver adds the parameters given on its command line.
struct RunTooLong : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Progress {
 public:
  /// The longest run allowed, in seconds of wall time (0 or less: no limit); set once by the driver frame.
  static double& run_limit_s() {
    static double limit = 0.0;
    return limit;
  }
  static constexpr double kEstimateAfter = 2.0;  ///< seconds of stepping before the estimate is trusted

  Progress(std::string label, double t_end, double interval_s = 10.0)
      : label_(std::move(label)), t_end_(t_end), interval_(interval_s), start_(Clock::now()), last_(start_) {}

  /// Call once per step; prints only when `interval_s` has passed since the last line.
  void update(double t, long step) {
    const auto now = Clock::now();
    const double since_last = std::chrono::duration<double>(now - last_).count();
    if (since_last < kEstimateAfter || (estimated_ && since_last < interval_)) return;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double share = t_end_ > 0 ? t / t_end_ : 0.0;
    const double eta = share > 0 ? elapsed * (1.0 - share) / share : HUGE_VAL;
    if (!estimated_) {
      estimated_ = true;
      const double limit = run_limit_s();
      if (limit > 0 && eta > limit)
        throw RunTooLong(label_ + ": would take ~" + human_duration(eta) + " more (t = " + number(t) + " of " +
                         number(t_end_) + " after " + std::to_string(step) + " steps in " + human_duration(elapsed) +
                         "), over the limit of " + human_duration(limit) +
                         ": --max-run-hours 0 runs it anyway (t_end is the run's upper end; it may stop sooner)");
      if (elapsed < interval_) return;
    }
    last_ = now;
    std::fprintf(stderr, "%s: t = %.4g / %.4g (%.0f%%), step %ld, %s elapsed, ~%s to go\n", label_.c_str(), t, t_end_,
                 100.0 * share, step, human_duration(elapsed).c_str(), human_duration(eta).c_str());
  }
  double elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  static std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
  }
  std::string label_;
  double t_end_, interval_;
  Clock::time_point start_, last_;
  bool estimated_ = false;
};

}  // namespace sph
