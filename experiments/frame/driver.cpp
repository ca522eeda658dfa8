#include "frame/driver.hpp"

#include "core/run_loop.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>

namespace sph {

namespace {

template <class T>
std::string to_text(const T& v) {
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) return format_number(static_cast<double>(v));
  else if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
  else if constexpr (std::is_same_v<T, std::string>) return v;
  else {
    std::ostringstream s;
    bool first = true;
    for (const auto& x : v) { s << (first ? "" : " ") << to_text(x); first = false; }
    return s.str();
  }
}

}  // namespace

DriverOption& DriverOption::expected(int min, int max) {
  o_->expected(min, max);
  return *this;
}
DriverOption& DriverOption::delimiter(char c) {
  o_->delimiter(c);
  return *this;
}
DriverOption& DriverOption::one_of(const std::vector<std::string>& allowed) {
  o_->check(CLI::IsMember(allowed));
  return *this;
}

DriverOption& DriverOption::bound(const char* relation, double limit, bool (*holds)(double, double)) {
  std::ostringstream want;
  want << relation << " " << format_number(limit);
  const std::string rule = want.str();
  for (const double v : current_())
    if (!holds(v, limit))
      throw std::logic_error(o_->get_name() + ": the default " + format_number(v) + " is not " + rule);
  // CLI11 applies the validator to each value of a list option: empty when it holds, else the message.
  o_->check(CLI::Validator(
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
  return *this;
}

DriverOption& DriverOption::above(double lo) { return bound(">", lo, [](double v, double l) { return v > l; }); }
DriverOption& DriverOption::at_least(double lo) { return bound(">=", lo, [](double v, double l) { return v >= l; }); }
DriverOption& DriverOption::below(double hi) { return bound("<", hi, [](double v, double l) { return v < l; }); }
DriverOption& DriverOption::at_most(double hi) { return bound("<=", hi, [](double v, double l) { return v <= l; }); }

Driver::~Driver() = default;

// The numbers a parameter holds (none for text): what a bound of DriverOption tests its default with.
template <class T>
std::vector<double> numbers_of(const T& v) {
  if constexpr (std::is_arithmetic_v<T>) return {static_cast<double>(v)};
  else if constexpr (std::is_same_v<T, std::string>) return {};
  else {
    std::vector<double> out;
    for (const auto& x : v)
      for (double y : numbers_of(x)) out.push_back(y);
    return out;
  }
}

template <class T>
DriverOption Driver::param(const std::string& name, T& var, const std::string& help) {
  auto* opt = app_->add_option("--" + name, var, help)->capture_default_str();
  recorders_.emplace_back(name, [&var] { return to_text(var); });
  return DriverOption(opt, [&var] { return numbers_of(var); });
}
// The parameter types of the drivers (a type missing here is a link error naming it).
template DriverOption Driver::param(const std::string&, bool&, const std::string&);
template DriverOption Driver::param(const std::string&, int&, const std::string&);
template DriverOption Driver::param(const std::string&, unsigned&, const std::string&);
template DriverOption Driver::param(const std::string&, long&, const std::string&);
template DriverOption Driver::param(const std::string&, double&, const std::string&);
template DriverOption Driver::param(const std::string&, std::string&, const std::string&);
template DriverOption Driver::param(const std::string&, std::vector<int>&, const std::string&);
template DriverOption Driver::param(const std::string&, std::vector<double>&, const std::string&);
template DriverOption Driver::param(const std::string&, std::vector<std::string>&, const std::string&);

bool Driver::given(const std::string& name) const { return app_->count("--" + name) > 0; }

Driver::Driver(std::string name, std::string target, std::string description)
    : name_(std::move(name)), target_(std::move(target)), description_(std::move(description)),
      app_(std::make_unique<CLI::App>(description_ + "\n(target " + target_ + "; writes CSV with a header recording every parameter)", name_)),
      out_("results/" + target_) {
  app_->add_flag("--quick", quick_, "reduced resolution/extent for CI; checks the same claims");
  app_->add_option("--out", out_, "output directory")->capture_default_str();
  recorders_.emplace_back("quick", [this] { return to_text(quick_); });
}

DriverOption Driver::flag(const std::string& name, bool& var, const std::string& help) {
  recorders_.emplace_back(name, [&var] { return to_text(var); });
  return DriverOption(app_->add_flag("--" + name, var, help), [] { return std::vector<double>{}; });
}

DriverOption Driver::location(const std::string& name, std::string& var, const std::string& help) {
  return DriverOption(app_->add_option("--" + name, var, help), [] { return std::vector<double>{}; });
}

int Driver::run(int argc, char** argv, const std::function<void()>& body) {
  try {
    app_->parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app_->exit(e);
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    const long long work0 = particle_steps_taken();
    prepare_output();
    body();
    if (!printing_only_)
      write_timing(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   particle_steps_taken() - work0);
    return 0;
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
