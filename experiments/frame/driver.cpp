#include "frame/driver.hpp"

#include "frame/option_text.hpp"

#include "core/run_loop.hpp"
#include "frame/progress.hpp"
#include "io/atomic_output.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <exception>
#include <fstream>
#include <iostream>

namespace sph {

using namespace option_text;  // to_text, help_text, numbers_of, is_text

namespace detail {

struct OptionState {
  CLI::Option* o;
  std::string help;  // the help as registered, before the quick value is appended
  struct Bound {
    std::string rule;  // e.g. "> 0"
    double limit;
    bool (*holds)(double, double);
  };
  std::vector<Bound> bounds;
  std::vector<double> quick_numbers;  // of the quick value, for bounds declared after it
  std::function<void()> apply_quick;  // gives the variable its quick value; empty: none declared
};

namespace {

// Throws std::logic_error if a number of the option's `what` (its default or quick value) breaks the bound.
void check_declared(const OptionState& s, const OptionState::Bound& b, const std::vector<double>& numbers, const char* what) {
  for (const double v : numbers)
    if (!b.holds(v, b.limit))
      throw std::logic_error(s.o->get_name() + ": the " + what + " " + format_number(v) + " is not " + b.rule);
}

}  // namespace

// A bound: the default (`current`) and any quick value must keep it, every value given must (CLI11 validator).
// On a text option it is a defect of the driver (every value would be refused as not a number): one_of is meant.
void add_bound(OptionState& s, const char* relation, double limit, bool (*holds)(double, double),
               const std::vector<double>& current, bool text) {
  std::ostringstream want;
  want << relation << " " << format_number(limit);
  const std::string rule = want.str();
  if (text) throw std::logic_error(s.o->get_name() + ": a bound " + rule + " on a text option (one_of lists its values)");
  const OptionState::Bound b{rule, limit, holds};
  check_declared(s, b, current, "default");
  check_declared(s, b, s.quick_numbers, "quick value");
  s.bounds.push_back(b);
  // CLI11 applies the validator to each value of a list option: empty when it holds, else the message.
  s.o->check(CLI::Validator(
      [=](std::string& text) -> std::string {
        double v;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return text + " is not a number";
        }
        if (used != text.size()) return text + " is not a number";
        if (!std::isfinite(v)) return text + " is not a finite number";
        if (!holds(v, limit)) return text + " is out of range: it must be " + rule;
        return "";
      },
      rule));
}

}  // namespace detail

template <class T>
DriverOption<T>& DriverOption<T>::expected(int min, int max) {
  s_->o->expected(min, max);
  return *this;
}
template <class T>
DriverOption<T>& DriverOption<T>::delimiter(char c) {
  s_->o->delimiter(c);
  return *this;
}
template <class T>
DriverOption<T>& DriverOption<T>::one_of(const std::vector<std::string>& allowed) {
  s_->o->check(CLI::IsMember(allowed));
  return *this;
}

template <class T>
DriverOption<T>& DriverOption<T>::above(double lo) {
  detail::add_bound(*s_, ">", lo, [](double v, double l) { return v > l; }, numbers_of(*var_), is_text<T>);
  return *this;
}
template <class T>
DriverOption<T>& DriverOption<T>::at_least(double lo) {
  detail::add_bound(*s_, ">=", lo, [](double v, double l) { return v >= l; }, numbers_of(*var_), is_text<T>);
  return *this;
}
template <class T>
DriverOption<T>& DriverOption<T>::below(double hi) {
  detail::add_bound(*s_, "<", hi, [](double v, double l) { return v < l; }, numbers_of(*var_), is_text<T>);
  return *this;
}
template <class T>
DriverOption<T>& DriverOption<T>::at_most(double hi) {
  detail::add_bound(*s_, "<=", hi, [](double v, double l) { return v <= l; }, numbers_of(*var_), is_text<T>);
  return *this;
}

template <class T>
DriverOption<T>& DriverOption<T>::quick(const T& v) {
  const std::vector<double> numbers = numbers_of(v);
  for (const auto& b : s_->bounds) detail::check_declared(*s_, b, numbers, "quick value");
  s_->quick_numbers = numbers;
  s_->apply_quick = [var = var_, v] { *var = v; };
  s_->o->description(s_->help + " (--quick: " + help_text(v) + ")");
  return *this;
}

// The parameter types of the drivers (a type missing here is a link error naming it).
template class DriverOption<bool>;
template class DriverOption<int>;
template class DriverOption<unsigned>;
template class DriverOption<long>;
template class DriverOption<double>;
template class DriverOption<std::string>;
template class DriverOption<std::vector<int>>;
template class DriverOption<std::vector<double>>;
template class DriverOption<std::vector<std::string>>;

Driver::~Driver() = default;

detail::OptionState& Driver::add_state(CLI::Option* o, const std::string& help) {
  options_.push_back(std::make_unique<detail::OptionState>(detail::OptionState{o, help, {}, {}, {}}));
  return *options_.back();
}

template <class T>
DriverOption<T> Driver::param(const std::string& name, T& var, const std::string& help) {
  auto* opt = app_->add_option("--" + name, var, help)->capture_default_str();
  recorders_.emplace_back(name, [&var] { return to_text(var); });
  return DriverOption<T>(add_state(opt, help), var);
}
template DriverOption<bool> Driver::param(const std::string&, bool&, const std::string&);
template DriverOption<int> Driver::param(const std::string&, int&, const std::string&);
template DriverOption<unsigned> Driver::param(const std::string&, unsigned&, const std::string&);
template DriverOption<long> Driver::param(const std::string&, long&, const std::string&);
template DriverOption<double> Driver::param(const std::string&, double&, const std::string&);
template DriverOption<std::string> Driver::param(const std::string&, std::string&, const std::string&);
template DriverOption<std::vector<int>> Driver::param(const std::string&, std::vector<int>&, const std::string&);
template DriverOption<std::vector<double>> Driver::param(const std::string&, std::vector<double>&, const std::string&);
template DriverOption<std::vector<std::string>> Driver::param(const std::string&, std::vector<std::string>&, const std::string&);

bool Driver::given(const std::string& name) const { return app_->count("--" + name) > 0; }

Driver::Driver(std::string name, std::string target, std::string description)
    : name_(std::move(name)), target_(std::move(target)), description_(std::move(description)),
      app_(std::make_unique<CLI::App>(description_ + "\n(target " + target_ + "; writes CSV with a header recording every parameter)", name_)),
      out_("results/" + target_) {
  app_->add_flag("--quick", quick_, "reduced resolution/extent for CI; checks the same claims");
  app_->add_option("--out", out_, "output directory")->capture_default_str();
  recorders_.emplace_back("quick", [this] { return to_text(quick_); });
}

DriverOption<bool> Driver::flag(const std::string& name, bool& var, const std::string& help) {
  recorders_.emplace_back(name, [&var] { return to_text(var); });
  return DriverOption<bool>(add_state(app_->add_flag("--" + name, var, help), help), var);
}

DriverOption<std::string> Driver::location(const std::string& name, std::string& var, const std::string& help) {
  return DriverOption<std::string>(add_state(app_->add_option("--" + name, var, help), help), var);
}

int Driver::run(int argc, char** argv, const std::function<void()>& body) {
  // Last in --help, and not recorded in the headers: it bounds how long a run may take, not what it computes.
  double max_run_hours = 24.0;
  app_->add_option("--max-run-hours", max_run_hours, "refuse a run whose time to go, estimated after its first "
                   "seconds, exceeds this (0: no limit)")->capture_default_str()->check(CLI::NonNegativeNumber);
  try {
    app_->parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app_->exit(e);
  }
  Progress::run_limit_s() = max_run_hours * 3600.0;
  std::signal(SIGXFSZ, SIG_IGN);  // a file-size limit (ulimit -f) then fails the write (EFBIG), named, not a kill
  try {
    if (quick_)
      for (const auto& s : options_)
        if (s->apply_quick && s->o->count() == 0) s->apply_quick();  // not given: the quick value
    const auto start = std::chrono::steady_clock::now();
    const long long work0 = particle_steps_taken();
    prepare_output();
    body();
    if (values_) values_->close();  // complete before the record that says the run is
    throw_if_output_failed();
    if (!printing_only_)
      write_timing(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   particle_steps_taken() - work0);
    return 0;
  } catch (const RunTooLong& e) {  // named with the parameters given, which made it that long
    std::cerr << name_ << ": refused: " << e.what() << "; parameters given:";
    for (const auto& [k, f] : recorders_)
      if (given(k)) std::cerr << " --" << k << " " << f();
    std::cerr << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << name_ << ": error: " << e.what() << "\n";
    return 1;
  }
}

std::filesystem::path Driver::completion_record() const { return out_ / ("timing_" + name_ + ".csv"); }

void Driver::prepare_output() const {
  // The output folder must be writable before anything runs: a run of hours must not fail at its first file.
  std::error_code ec;
  std::filesystem::create_directories(out_, ec);
  const auto probe = out_ / (".write_probe_" + name_);
  bool writable = !ec;
  if (writable) {
    std::ofstream f(probe);
    writable = static_cast<bool>(f << "probe\n");
  }
  std::filesystem::remove(probe, ec);
  if (!writable)
    throw std::runtime_error("--out " + out_.string() + ": cannot write into this folder" + (ec ? " (" + ec.message() + ")" : ""));
  std::filesystem::remove(completion_record(), ec);
  if (ec) throw std::runtime_error("cannot remove the completion record " + completion_record().string() + ": " + ec.message());
}

void Driver::retarget(const std::string& target) {
  target_ = target;
  if (!given("out")) out_ = "results/" + target_;
  prepare_output();
}

void Driver::write_timing(double wall_s, long long particle_steps) const {
  CsvWriter t(completion_record(), info(), {"target", "driver", "wall_s", "particle_steps", "threads"});
  t.row(target_, name_, wall_s, static_cast<double>(particle_steps), omp_get_max_threads());
  t.close();
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
