#include "gray2001/scenes/plate_run_cache.hpp"

#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <unistd.h>

#include "io/run_info.hpp"

namespace scenes {

namespace {

// A field added to one of these structs must be added to the key below: the sizes make the compiler say so.
static_assert(sizeof(PlateSpec) == 64, "PlateSpec changed: update plate_run_key");
static_assert(sizeof(sph::GrayParameters) == 96, "GrayParameters changed: update plate_run_key");
static_assert(sizeof(sph::GrayOptions) == 5, "GrayOptions changed: update plate_run_key");

constexpr char kMagic[] = "sph-plate-run-1";

std::string exact(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);  // hexadecimal: every bit of the double
  return b;
}

// Runs with and without the power budget are stored apart (the budget does not change the trajectory, but
// only a run that recorded it can serve a run that asks for it).
// The instruction set the build targets (-march=native): two hosts sharing a results folder (a cluster's
// network file system) build the same code version into different arithmetic (the AVX-512 pair loops).
const char* isa() {
  return ""
#if defined(__AVX512F__)
         "avx512f "
#endif
#if defined(__AVX2__)
         "avx2 "
#endif
#if defined(__FMA__)
         "fma "
#endif
         "base";
}

std::string path_of(const std::string& dir, const std::string& key, bool power_budget) {
  std::ostringstream s;
  s << dir << "/plate-" << std::hex << std::hash<std::string>{}(key) << (power_budget ? "-power" : "") << ".run";
  return s.str();
}

template <class T>
void put(std::ostream& o, const T& v) { o.write(reinterpret_cast<const char*>(&v), sizeof v); }
template <class T>
bool get(std::istream& i, T& v) { return static_cast<bool>(i.read(reinterpret_cast<char*>(&v), sizeof v)); }

/// The stored run under `key`, if its file exists and names exactly that key.
std::optional<StoredPlateRun> load(const std::string& dir, const std::string& key, bool power_budget) {
  std::ifstream in(path_of(dir, key, power_budget), std::ios::binary);
  if (!in) return std::nullopt;
  std::string magic, stored_key;
  if (!std::getline(in, magic) || magic != kMagic || !std::getline(in, stored_key) || stored_key != key)
    return std::nullopt;  // another key of the same hash, or another format: not ours
  StoredPlateRun r;
  std::uint64_t n = 0, particles = 0;
  std::uint8_t power = 0;
  if (!get(in, r.dt) || !get(in, r.t_end) || !get(in, r.fracture_time) || !get(in, particles) || !get(in, power) ||
      !get(in, n))
    return std::nullopt;
  r.particles = particles;
  r.power_budget = power != 0;
  r.trace.resize(n);
  r.steps.resize(n);
  for (std::uint64_t k = 0; k < n; ++k) {
    TipSample& t = r.trace[k];
    std::uint64_t fragments = 0;
    std::int64_t step = 0;
    if (!get(in, t.t) || !get(in, t.y) || !get(in, t.ke) || !get(in, t.ee) || !get(in, fragments) ||
        !get(in, t.p_art) || !get(in, t.p_visc) || !get(in, t.p_xsph) || !get(in, step))
      return std::nullopt;  // truncated: treat as absent
    t.fragments = fragments;
    r.steps[k] = step;
  }
  return r;
}

/// Removes the stored runs of other code versions (a full make figures stores ~10 MB; a rebuilt driver can use
/// none of an older build's runs). Another build writing into the same folder at the same time loses reuse, not
/// results.
void prune_other_versions(const std::string& dir) {
  const std::string mine = std::string("code ") + sph::code_version() + " ";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".run") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::string magic, key;
    if (std::getline(in, magic) && magic == kMagic && std::getline(in, key) && key.rfind(mine, 0) != 0) {
      in.close();
      std::filesystem::remove(entry.path(), ec);
    }
  }
}

}  // namespace

std::string plate_run_cache_dir() {
  const char* dir = std::getenv("SPH_RUN_CACHE");
  if (!dir || !*dir) return "";
  // A dirty or unknown version does not name one build: two builds would share keys. The unit test, one
  // process and one build, allows it with SPH_RUN_CACHE_ALLOW_DIRTY=1.
  const std::string version = sph::code_version();
  const char* allow = std::getenv("SPH_RUN_CACHE_ALLOW_DIRTY");
  const bool dirty = version.find("dirty") != std::string::npos || version.find("unknown") != std::string::npos;
  if (dirty && !(allow && std::string(allow) == "1")) return "";
  return dir;
}

std::string plate_run_key(const PlateRunSpec& s) {
  const PlateSpec& p = s.plate;
  const sph::GrayParameters& g = s.scheme;
  const sph::GrayOptions& o = s.options;
  std::ostringstream k;
  k << "code " << sph::code_version() << " isa " << isa() << " threads " << omp_get_max_threads()
    << " plate L " << exact(p.L) << " H " << exact(p.H) << " dp " << exact(p.dp) << " clamp " << exact(p.clamp_length)
    << " layers " << p.clamp_layers << " Vf " << exact(p.Vf) << " perturbation " << exact(p.perturbation)
    << " seed " << p.seed << " scheme rho0 " << exact(g.rho0) << " c0 " << exact(g.c0) << " mu " << exact(g.mu)
    << " h/dp " << exact(g.h_over_dp) << " eps " << exact(g.eps_artificial) << " n " << g.n_artificial
    << " xsph " << exact(g.eps_xsph) << " alpha " << exact(g.alpha) << " beta " << exact(g.beta)
    << " yield " << exact(g.yield_stress) << " cfl " << exact(g.cfl) << " skin " << exact(g.skin_over_h)
    << " options " << o.artificial_stress << o.xsph << o.viscosity << o.summation_density << o.plasticity
    << " sample_dt " << exact(s.sample_dt) << " link " << exact(s.fracture_link) << " check_dt "
    << exact(s.fracture_check_dt);
  return k.str();
}

std::optional<PlateRunResult> serve_plate_run(const PlateRunSpec& s, const std::string& dir) {
  // Served: runs that stop at a zero crossing, without a step limit or a stop after fracture.
  if (dir.empty() || s.stop_after_crossings < 0 || s.max_steps >= 0 || s.run_after_fracture >= 0) return std::nullopt;
  const std::string key = plate_run_key(s);
  auto stored = load(dir, key, true);
  if (!s.power_budget) {  // either store serves it: the longer one
    auto plain = load(dir, key, false);
    if (plain && (!stored || plain->trace.size() > stored->trace.size())) stored = std::move(plain);
  }
  if (!stored) return std::nullopt;
  // The loop's own rule (run_plate): a crossing when sample k and k - 1 differ in sign, from k = 2 on.
  // Every sample of the prefix must lie before both runs' t_end, so that no step of it was shortened.
  const double t_limit = std::min(s.t_end, stored->t_end) - 1e-12;
  int crossings = 0;
  for (std::size_t k = 0; k < stored->trace.size(); ++k) {
    if (!(stored->trace[k].t < t_limit)) return std::nullopt;
    if (k == 0) continue;  // the start sample: the loop decides nothing there
    if (k >= 2 && (stored->trace[k].y > 0) != (stored->trace[k - 1].y > 0)) ++crossings;
    if (crossings < s.stop_after_crossings) continue;
    PlateRunResult r;
    r.trace.assign(stored->trace.begin(), stored->trace.begin() + static_cast<long>(k) + 1);
    if (!s.power_budget)
      for (TipSample& t : r.trace) t.p_art = t.p_visc = t.p_xsph = NAN;
    r.steps = stored->steps[k];
    r.particles = stored->particles;
    r.dt = stored->dt;
    r.fracture_time = (stored->fracture_time >= 0 && stored->fracture_time <= r.trace.back().t) ? stored->fracture_time : -1;
    r.wall_s = 0;
    r.reused = true;
    return r;
  }
  return std::nullopt;  // the stored run is too short
}

void store_plate_run(const PlateRunSpec& s, const StoredPlateRun& run, const std::string& dir) {
  if (dir.empty() || run.trace.empty()) return;
  const std::string key = plate_run_key(s);
  if (const auto old = load(dir, key, run.power_budget); old && old->trace.size() >= run.trace.size())
    return;  // the stored run already holds this one
  std::filesystem::create_directories(dir);
  const std::string path = path_of(dir, key, run.power_budget);
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << kMagic << "\n" << key << "\n";
    put(out, run.dt);
    put(out, run.t_end);
    put(out, run.fracture_time);
    put(out, static_cast<std::uint64_t>(run.particles));
    put(out, static_cast<std::uint8_t>(run.power_budget));
    put(out, static_cast<std::uint64_t>(run.trace.size()));
    for (std::size_t k = 0; k < run.trace.size(); ++k) {
      const TipSample& t = run.trace[k];
      put(out, t.t); put(out, t.y); put(out, t.ke); put(out, t.ee);
      put(out, static_cast<std::uint64_t>(t.fragments));
      put(out, t.p_art); put(out, t.p_visc); put(out, t.p_xsph);
      put(out, static_cast<std::int64_t>(run.steps[k]));
    }
    if (!out) { std::remove(tmp.c_str()); return; }  // a full disk loses the reuse, not the run
  }
  std::filesystem::rename(tmp, path);  // atomic: a concurrent reader sees the old file or the new one
  prune_other_versions(dir);
}

}  // namespace scenes
