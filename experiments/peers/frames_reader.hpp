// A peer's particle frames, for the scenes whose measurement needs every particle (the rings, the slab):
// a CSV with columns t,id,x,y,u,v ('#' lines first, then the header line), long format, the rows of one frame
// together and the frames in increasing t; id is the particle's row in our layout.csv (0-based), every
// particle once in every frame, in any order. Streamed: one frame in memory at a time, so a run of a few
// hundred frames of 10^4 particles is read without holding the file. Anything else in the file (a missing or
// repeated id, a non-finite number, t going back, a short line) stops with the file, line and reason: a
// peer's trace is never measured from a partial frame.
#pragma once

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace peers {

struct Frame {
  double t = 0;
  std::vector<sph::Vec2> x, v;  ///< indexed by our layout's particle index
};

/// Calls `f` for every frame of `path`, each with all `particles` particles; returns the number of frames.
inline std::size_t for_each_frame(const std::string& path, std::size_t particles,
                                  const std::function<void(const Frame&)>& f) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the frames file");
  std::string line;
  long lineno = 0;
  auto fail = [&](const std::string& why) { throw std::runtime_error(path + ":" + std::to_string(lineno) + ": " + why); };
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("t,id,x,y,u,v", 0) != 0) fail("the header must be t,id,x,y,u,v, not '" + line + "'");
    break;
  }
  Frame fr;
  fr.x.assign(particles, sph::Vec2::Constant(NAN));
  fr.v.assign(particles, sph::Vec2::Constant(NAN));
  std::vector<char> seen(particles, 0);
  std::size_t count = 0, frames = 0;
  bool open = false;
  auto flush = [&] {
    if (count != particles)
      fail("the frame at t = " + std::to_string(fr.t) + " has " + std::to_string(count) + " particles, the layout " +
           std::to_string(particles));
    f(fr);
    ++frames;
    std::fill(seen.begin(), seen.end(), 0);
    count = 0;
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    double c[6];
    const char* p = line.c_str();
    for (int k = 0; k < 6; ++k) {
      char* end = nullptr;
      c[k] = std::strtod(p, &end);
      if (end == p || (k < 5 && *end != ',')) fail("expected 6 numbers t,id,x,y,u,v");
      if (!std::isfinite(c[k])) fail("a non-finite number");
      p = end + (k < 5 ? 1 : 0);
    }
    if (open && c[0] != fr.t) {
      if (c[0] < fr.t) fail("t goes back");
      flush();
    }
    open = true;
    fr.t = c[0];
    const double id = c[1];
    if (id < 0 || id >= static_cast<double>(particles) || id != std::floor(id)) fail("id out of the layout's range");
    const std::size_t a = static_cast<std::size_t>(id);
    if (seen[a]) fail("particle " + std::to_string(a) + " twice in one frame");
    seen[a] = 1;
    ++count;
    fr.x[a] = {c[2], c[3]};
    fr.v[a] = {c[4], c[5]};
  }
  if (open) flush();
  return frames;
}

}  // namespace peers
