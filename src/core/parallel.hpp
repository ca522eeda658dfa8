// When a loop over particles runs in parallel. Below kParallelMin particles an OpenMP region costs more
// than it saves (the 217-particle hexagon; the 72-variant sweep parallelises over whole runs instead), so
// the per-particle loops of the library carry `if (n >= kParallelMin)`. A loop whose particles are
// independent gives the same result either way.
#pragma once

namespace sph {

inline constexpr long kParallelMin = 1000;

}  // namespace sph
