// The hexagon's runs in the store of runs (frame/run_store.hpp): a run of a variant (SPAM or molecular dynamics)
// stepped once is served again, bit for bit, to any driver that runs the same variant on the same setup, and
// H-72's 72 combinations are jobs of their own (Makefile run_rules; issue 17) that its collecting run reads back.
// The key holds every field of HexagonSetup, the variant's name and every field of its SpamOptions; a stored run
// is the whole HexagonRun (series, snapshots and counters).
#pragma once

#include <string>

#include "hoover2004/scenes/hexagon.hpp"

namespace sph::scenes {

/// The text of the key: the build, the thread count, every field of s and of v.
std::string hexagon_run_key(const HexagonSetup& s, const HexagonVariant& v);

/// The run of v on s served when the store holds it, else stepped (run_hexagon_md or run_hexagon_spam) and stored
/// when the store is on. A served run's wall_s is the stepping run's.
HexagonRun run_hexagon_stored(const HexagonSetup& s, const HexagonVariant& v);

}  // namespace sph::scenes
