#include "hoover2004/scenes/hexagon_files.hpp"

#include <stdexcept>

namespace sph::scenes {

namespace {

// The fields of each table, once, by name (frame/run_folder.hpp): the columns written and read back.
// advection_samples: the length of advection_torque_integral (0 for molecular dynamics, else one per sample).
struct Scalars {
  HexagonRun run;  // its series and snapshots are the other tables'
  std::size_t advection_samples = 0;
};
const auto scalars = [](auto& s, auto&& f) {
  auto& r = s.run;
  return f("variant", r.variant) && f("L0", r.L0) && f("E0", r.E0) && f("failed", r.failed) &&
         f("failed_at", r.failed_at) && f("steps", r.steps) && f("wall_s", r.wall_s) &&
         f("gauss_floor_hits", r.gauss_floor_hits) && f("reflections", r.reflections) &&
         f("advection_samples", s.advection_samples);
};
struct Sample { double t, L, K, U, shape_rms, angle, gauss_D, gauss_beta, advection_torque_integral; };
const auto sample = [](auto& s, auto&& f) {
  return f("t", s.t) && f("L", s.L) && f("K", s.K) && f("U", s.U) && f("shape_rms", s.shape_rms) && f("angle", s.angle) &&
         f("gauss_D", s.gauss_D) && f("gauss_beta", s.gauss_beta) && f("advection_torque_integral", s.advection_torque_integral);
};
struct Kept { std::size_t snapshot; double angle, x, y, density; };
const auto kept = [](auto& k, auto&& f) {
  return f("snapshot", k.snapshot) && f("angle", k.angle) && f("x", k.x) && f("y", k.y) && f("density", k.density);
};

}  // namespace

void write_hexagon_run(const Driver& d, const std::string& name, const HexagonRun& r) {
  write_rows(d, name + "_run.csv", std::vector<Scalars>{{r, r.advection_torque_integral.size()}}, scalars);
  std::vector<Sample> samples(r.t.size());
  for (std::size_t k = 0; k < samples.size(); ++k)
    samples[k] = {r.t[k], r.L[k], r.K[k], r.U[k], r.shape_rms[k], r.angle[k], r.gauss_D[k], r.gauss_beta[k],
                  k < r.advection_torque_integral.size() ? r.advection_torque_integral[k] : 0.0};
  write_rows(d, name + "_trace.csv", samples, sample);
  std::vector<Kept> positions;
  for (std::size_t s = 0; s < r.snapshots.size(); ++s)
    for (std::size_t i = 0; i < r.snapshots[s].size(); ++i)
      positions.push_back({s, r.snapshot_angles[s], r.snapshots[s][i].x(), r.snapshots[s][i].y(), r.snapshot_density[s][i]});
  write_rows(d, name + "_snapshots.csv", positions, kept);
}

HexagonRun read_hexagon_run(const RunFolder& folder, const std::string& name) {
  const Scalars s = read_row<Scalars>(folder, name + "_run.csv", scalars);
  HexagonRun r = s.run;
  for (const Sample& x : read_rows<Sample>(folder, name + "_trace.csv", sample)) {
    r.t.push_back(x.t); r.L.push_back(x.L); r.K.push_back(x.K); r.U.push_back(x.U); r.shape_rms.push_back(x.shape_rms);
    r.angle.push_back(x.angle); r.gauss_D.push_back(x.gauss_D); r.gauss_beta.push_back(x.gauss_beta);
    if (r.advection_torque_integral.size() < s.advection_samples) r.advection_torque_integral.push_back(x.advection_torque_integral);
  }
  for (const Kept& k : read_rows<Kept>(folder, name + "_snapshots.csv", kept)) {
    if (k.snapshot == r.snapshots.size()) {  // the first particle of the next snapshot
      r.snapshot_angles.push_back(k.angle);
      r.snapshots.emplace_back();
      r.snapshot_density.emplace_back();
    }
    if (k.snapshot + 1 != r.snapshots.size())
      throw std::runtime_error((folder.dir() / (name + "_snapshots.csv")).string() + ": snapshots out of order");
    r.snapshots.back().emplace_back(k.x, k.y);
    r.snapshot_density.back().push_back(k.density);
  }
  return r;
}

}  // namespace sph::scenes
