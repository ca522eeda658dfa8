#include "frame/driver.hpp"

#include "core/run_loop.hpp"

#include <omp.h>

#include <chrono>
#include <exception>
#include <iostream>

namespace sph {

Driver::Driver(std::string name, std::string target, std::string description)
    : name_(std::move(name)), target_(std::move(target)), description_(std::move(description)),
      app_(description_ + "\n(target " + target_ + "; writes CSV with a header recording every parameter)", name_),
      out_("results/" + target_) {
  app_.add_flag("--quick", quick_, "reduced resolution/extent for CI; checks the same claims");
  app_.add_option("--out", out_, "output directory")->capture_default_str();
  recorders_.emplace_back("quick", [this] { return to_text(quick_); });
}

CLI::Option* Driver::flag(const std::string& name, bool& var, const std::string& help) {
  recorders_.emplace_back(name, [&var] { return to_text(var); });
  return app_.add_flag("--" + name, var, help);
}

int Driver::run(int argc, char** argv, const std::function<void()>& body) {
  try {
    app_.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app_.exit(e);
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    const long long work0 = particle_steps_taken();
    body();
    write_timing(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                 particle_steps_taken() - work0);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << name_ << ": error: " << e.what() << "\n";
    return 1;
  }
}

void Driver::write_timing(double wall_s, long long particle_steps) const {
  CsvWriter t(out_ / ("timing_" + name_ + ".csv"), info(), {"target", "driver", "wall_s", "particle_steps", "threads"});
  t.row(target_, name_, wall_s, static_cast<double>(particle_steps), omp_get_max_threads());
}

RunInfo Driver::info() const {
  RunInfo r{name_, target_, description_, {}, {}};
  for (const auto& [k, f] : recorders_) {
    r.parameters.emplace_back(k, f());
    if (given(k)) r.given.push_back(k);
  }
  return r;
}

CsvWriter Driver::csv(const std::string& filename, std::vector<std::string> columns) const {
  std::filesystem::create_directories(out_);
  return CsvWriter(out_ / filename, info(), std::move(columns));
}

void Driver::value(const std::string& quantity, double v, const std::string& note) {
  if (!values_) values_ = std::make_unique<CsvWriter>(out_ / ("values_" + name_ + ".csv"), info(),
                                                      std::vector<std::string>{"quantity", "value", "note"});
  values_->row(quantity, v, note);
}

}  // namespace sph
