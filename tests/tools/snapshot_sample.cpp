// Writes a known HDF5 + XDMF snapshot series (tests/test_paraview.py reads it with ParaView's own XDMF reader):
// three snapshots at t = 0, 0.25 and 1.5 of 7 particles whose fields are closed forms of the particle index i
// and the time t, so the reader's arrays can be compared with what they must be:
//   position (0.5 i, -i + t), velocity (t + i, 2 i), density 1000 + i + t, stress (xx, yy, xy) = (i, -i, 0.5 i + t).
// The third snapshot records positions only (a partial snapshot, as a run may write).
// Usage: snapshot_sample <file.h5>
#include <cstdio>

#include "io/hdf5_snapshot.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: snapshot_sample <file.h5>\n");
    return 2;
  }
  sph::RunInfo info;
  info.driver = "snapshot_sample";
  info.target = "test";
  info.description = "a known snapshot series for the ParaView reader test";
  sph::SnapshotSeries series(argv[1], info);
  const double times[3] = {0.0, 0.25, 1.5};
  for (int s = 0; s < 3; ++s) {
    sph::Snapshot sn;
    const double t = times[s];
    sn.time = t;
    sn.step = 10 * s;
    for (int i = 0; i < 7; ++i) {
      sn.position.emplace_back(0.5 * i, -i + t);
      if (s == 2) continue;
      sn.velocity.emplace_back(t + i, 2.0 * i);
      sn.density.push_back(1000.0 + i + t);
      sn.sxx.push_back(i);
      sn.syy.push_back(-i);
      sn.sxy.push_back(0.5 * i + t);
    }
    series.write(sn);
  }
  return 0;
}
