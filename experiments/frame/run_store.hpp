// The store of runs: a simulation run that several drivers (or a driver and the jobs that stepped its runs
// beforehand, Makefile run_rules) need is stepped once, stored, and served again instead of stepped, bit for
// bit. One file per run, <dir>/<kind>-<hash of key>[-<variant>].run: a line "sph-<kind>-run-1", the key (the
// text of everything that decides the run's numbers, starting with run_store_key_prefix()), then the kind's own
// payload. The scenes that store runs (gray2001/scenes/plate_run_cache.hpp, ismail2009/scenes/hole_store.hpp)
// say what their keys hold and when a stored run may serve.
//
// Off unless the environment names a directory, SPH_RUN_CACHE (the Makefile sets <results>/.run_cache), and
// only for a clean code version (not '-dirty', not 'unknown'), so that two different builds never share a key
// (a unit test, one process and one build, sets SPH_RUN_CACHE_ALLOW_DIRTY=1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <istream>
#include <functional>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/run_loop.hpp"
#include "core/types.hpp"

namespace sph {

/// The directory of the store, or "" when it is off.
std::string run_store_dir();

/// Every bit of a double, as text (hexadecimal floating point).
std::string exact_text(double v);

/// "code <version> isa <instruction sets> threads <T>": what every key starts with. The build (-march=native: two
/// hosts sharing a results folder build the same code version into different arithmetic) and the thread count
/// (the order of the sums) decide the bits of a run.
std::string run_store_key_prefix();

/// The payload stored under (kind, key, variant), if its file exists and names exactly that key.
std::optional<std::string> run_store_read(const std::string& dir, const std::string& kind, const std::string& key,
                                          const std::string& variant = "");

/// Stores the payload under (kind, key, variant), atomically (a concurrent reader, another job of the same
/// pipeline, sees the old file or the new one), and removes the runs of this kind stored by other code
/// versions. A full disk loses the reuse, not the run.
void run_store_write(const std::string& dir, const std::string& kind, const std::string& key, const std::string& payload,
                     const std::string& variant = "");

/// A run job's work (Makefile run_rules: a driver given the names of some of its planned runs): steps
/// step(i) for each name that is planned[i], in the order given, into the store; a name not planned (e.g. a
/// full-resolution run's name given to a --quick run) is reported and skipped, and a store that is off is reported
/// (the run is then stepped for nothing).
void step_named_runs(const std::vector<std::string>& names, const std::vector<std::string>& planned,
                     const std::function<void(std::size_t)>& step);

/// Payloads in binary: every bit of a value (the same host reads them back: the key names its build).
template <class T>
void store_put(std::ostream& o, const T& v) { o.write(reinterpret_cast<const char*>(&v), sizeof v); }
template <class T>
bool store_get(std::istream& i, T& v) { return static_cast<bool>(i.read(reinterpret_cast<char*>(&v), sizeof v)); }
/// A text in a payload: its length, then its bytes.
void store_put_text(std::ostream& o, const std::string& s);
bool store_get_text(std::istream& i, std::string& s);

/// The field visitors of a whole-result store: a scene lists its result's fields once, as
/// `fields(result, f) = f(r.a) && f(r.b) && ...`, and the same list writes and reads the payload. A value is its
/// bytes (trivially copyable: the same host reads it back), a text and a vector their length and their elements.
struct StoreWriter {
  std::ostream& o;
  template <class T>
  bool operator()(const T& v) {
    // Vec2: two doubles (Eigen does not declare its fixed-size vectors trivially copyable).
    static_assert(std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec2>, "a field the store writes as its bytes");
    store_put(o, v);
    return true;
  }
  bool operator()(const std::string& v) { store_put_text(o, v); return true; }
  template <class T>
  bool operator()(const std::vector<T>& v) {
    store_put(o, static_cast<std::uint64_t>(v.size()));
    for (const auto& x : v) (*this)(x);
    return true;
  }
};
struct StoreReader {
  std::istream& i;
  template <class T>
  bool operator()(T& v) { return store_get(i, v); }
  bool operator()(std::string& v) { return store_get_text(i, v); }
  template <class T>
  bool operator()(std::vector<T>& v) {
    std::uint64_t n = 0;
    if (!store_get(i, n) || n > (std::uint64_t{1} << 32)) return false;  // a corrupt length: absent, not an allocation
    v.resize(n);
    for (auto& x : v)
      if (!(*this)(x)) return false;
    return true;
  }
};

/// A run kept whole in the store (a sweep point, a hexagon variant: issue 17's run jobs and the drivers that
/// collect them): served when the store holds (kind, key) and its payload reads whole, else step() is called and
/// its result stored when the store is on. `fields` lists the result's fields (above); served(result) is called on
/// a served run (it may mark it as such) and returns its particle-steps, which count as reused work; the served run
/// says so on stderr, and its wall time is the stepping run's.
template <class Result, class Fields, class Step, class Served>
Result served_or_stepped(const std::string& kind, const std::string& key, const std::string& label, Fields&& fields,
                         Step&& step, Served&& served) {
  const std::string dir = run_store_dir();
  if (const auto payload = run_store_read(dir, kind, key)) {
    std::istringstream in(*payload);
    Result r;
    if (fields(r, StoreReader{in})) {  // else truncated: stepped again
      particle_steps_reused() += served(r);
      std::fprintf(stderr, "%s: a stored run (%s), not stepped again\n", label.c_str(), dir.c_str());
      return r;
    }
  }
  Result r = step();
  if (!dir.empty()) {
    std::ostringstream out;
    fields(static_cast<const Result&>(r), StoreWriter{out});
    run_store_write(dir, kind, key, out.str());
  }
  return r;
}

}  // namespace sph
