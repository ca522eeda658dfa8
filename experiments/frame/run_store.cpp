#include "frame/run_store.hpp"

#include <omp.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include "io/run_info.hpp"

namespace sph {

namespace {

std::string magic_of(const std::string& kind) { return "sph-" + kind + "-run-1"; }

std::string path_of(const std::string& dir, const std::string& kind, const std::string& key, const std::string& variant) {
  std::ostringstream s;
  s << dir << "/" << kind << "-" << std::hex << std::hash<std::string>{}(key) << (variant.empty() ? "" : "-" + variant)
    << ".run";
  return s.str();
}

// The instruction sets the build targets.
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

/// Removes the runs of `kind` stored by other code versions (a rebuilt driver can use none of an older
/// build's runs). Another build writing into the same folder at the same time loses reuse, not results.
void prune_other_versions(const std::string& dir, const std::string& kind) {
  const std::string magic = magic_of(kind), mine = std::string("code ") + code_version() + " ";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".run") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::string m, key;
    if (std::getline(in, m) && m == magic && std::getline(in, key) && key.rfind(mine, 0) != 0) {
      in.close();
      std::filesystem::remove(entry.path(), ec);
    }
  }
}

}  // namespace

std::string run_store_dir() {
  const char* dir = std::getenv("SPH_RUN_CACHE");
  if (!dir || !*dir) return "";
  const std::string version = code_version();
  const char* allow = std::getenv("SPH_RUN_CACHE_ALLOW_DIRTY");
  const bool dirty = version.find("dirty") != std::string::npos || version.find("unknown") != std::string::npos;
  if (dirty && !(allow && std::string(allow) == "1")) return "";
  return dir;
}

std::string exact_text(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);
  return b;
}

std::string run_store_key_prefix() {
  std::ostringstream k;
  k << "code " << code_version() << " isa " << isa() << " threads " << omp_get_max_threads();
  return k.str();
}

std::optional<std::string> run_store_read(const std::string& dir, const std::string& kind, const std::string& key,
                                          const std::string& variant) {
  if (dir.empty()) return std::nullopt;
  std::ifstream in(path_of(dir, kind, key, variant), std::ios::binary);
  if (!in) return std::nullopt;
  std::string magic, stored_key;
  if (!std::getline(in, magic) || magic != magic_of(kind) || !std::getline(in, stored_key) || stored_key != key)
    return std::nullopt;  // another key of the same hash, or another format: not ours
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void run_store_write(const std::string& dir, const std::string& kind, const std::string& key, const std::string& payload,
                     const std::string& variant) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string path = path_of(dir, kind, key, variant);
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << magic_of(kind) << "\n" << key << "\n";
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    if (!out) {
      std::remove(tmp.c_str());
      return;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::remove(tmp.c_str());
  prune_other_versions(dir, kind);
}

void store_put_text(std::ostream& o, const std::string& s) {
  store_put(o, static_cast<std::uint64_t>(s.size()));
  o.write(s.data(), static_cast<std::streamsize>(s.size()));
}

bool store_get_text(std::istream& i, std::string& s) {
  std::uint64_t n = 0;
  if (!store_get(i, n) || n > (std::uint64_t{1} << 34)) return false;  // a corrupt length: absent, not an allocation
  s.resize(n);
  return static_cast<bool>(i.read(s.data(), static_cast<std::streamsize>(n)));
}

void step_named_runs(const std::vector<std::string>& names, const std::vector<std::string>& planned,
                     const std::function<void(std::size_t)>& step) {
  for (const auto& name : names) {
    std::size_t i = 0;
    while (i < planned.size() && planned[i] != name) ++i;
    if (i == planned.size()) {
      std::fprintf(stderr, "run %s is not among this driver's runs (see --list-runs): nothing to step\n", name.c_str());
      continue;
    }
    if (run_store_dir().empty())
      std::fprintf(stderr, "run %s: the store of runs is off (SPH_RUN_CACHE unset or a dirty build): stepped for nothing\n",
                   name.c_str());
    step(i);
  }
}

}  // namespace sph
