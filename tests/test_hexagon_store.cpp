// The hexagon's runs in the store of runs (experiments/hoover2004/scenes/hexagon_store.hpp; issue 17: H-72's
// combinations as jobs of their own): a stored run is served with every number of the stepped one, bit for bit; the
// key names every parameter of the setup and every option of the variant; the store is off without a directory.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <cstring>
#include <set>

#include "frame/run_store.hpp"
#include "hoover2004/scenes/hexagon_store.hpp"
#include "run_store_fixture.hpp"

namespace {

using sph::scenes::HexagonRun;
using sph::scenes::HexagonSetup;
using sph::scenes::HexagonVariant;

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

HexagonSetup small_hexagon() {
  HexagonSetup s;
  s.shells = 3;
  s.dt = 0.2;
  s.revolutions = 0.1;
  s.sample_every = 5;
  s.snapshot_angles = {0.0, 0.1 * 2 * std::acos(-1.0)};
  s.track_advection_torque = true;
  return s;
}

HexagonVariant shepard() { return {"cont/shepard/pair_torque", sph::scenes::spam_options_from_label("cont/shepard/pair_torque")}; }

class HexagonStore : public RunStoreTest {
 protected:
  HexagonStore() : RunStoreTest("hexagon_store") {}
};

void expect_identical(const HexagonRun& a, const HexagonRun& b) {
  EXPECT_EQ(a.variant, b.variant);
  for (auto f : {&HexagonRun::t, &HexagonRun::L, &HexagonRun::K, &HexagonRun::U, &HexagonRun::shape_rms, &HexagonRun::angle,
                 &HexagonRun::gauss_D, &HexagonRun::gauss_beta, &HexagonRun::snapshot_angles,
                 &HexagonRun::advection_torque_integral})
    EXPECT_TRUE(same_bits(a.*f, b.*f));
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    ASSERT_EQ(a.snapshots[k].size(), b.snapshots[k].size());
    for (std::size_t i = 0; i < a.snapshots[k].size(); ++i) EXPECT_TRUE(a.snapshots[k][i] == b.snapshots[k][i]) << k << " " << i;
    EXPECT_TRUE(same_bits(a.snapshot_density[k], b.snapshot_density[k])) << k;
  }
  EXPECT_TRUE(std::memcmp(&a.L0, &b.L0, sizeof a.L0) == 0 && std::memcmp(&a.E0, &b.E0, sizeof a.E0) == 0);
  EXPECT_EQ(a.failed, b.failed);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.gauss_floor_hits, b.gauss_floor_hits);
  EXPECT_EQ(a.reflections, b.reflections);
}

}  // namespace

TEST_F(HexagonStore, AServedRunIsTheSteppedRunBitForBit) {
  const auto s = small_hexagon();
  for (const HexagonVariant& v : {shepard(), HexagonVariant{"md", {}}}) {
    store_off();
    const HexagonRun stepped = sph::scenes::run_hexagon_stored(s, v);
    ASSERT_GT(stepped.t.size(), 3u);
    ASSERT_EQ(stepped.snapshots.size(), 2u);
    store_on();
    EXPECT_FALSE(sph::run_store_read(dir_.string(), "hexagon", sph::scenes::hexagon_run_key(s, v)).has_value());  // off: not kept
    const HexagonRun first = sph::scenes::run_hexagon_stored(s, v);
    const HexagonRun served = sph::scenes::run_hexagon_stored(s, v);
    expect_identical(served, stepped);
    EXPECT_EQ(served.wall_s, first.wall_s);  // the stepping run's time
  }
}

TEST_F(HexagonStore, TheKeyNamesEveryParameterAndOption) {
  const auto s = small_hexagon();
  const auto v = shepard();
  std::set<std::string> keys{sph::scenes::hexagon_run_key(s, v)};
  std::size_t expected = 1;
  auto changed = [&](auto&& set) { auto q = s; set(q); keys.insert(sph::scenes::hexagon_run_key(q, v)); ++expected; };
  changed([](auto& q) { q.shells = 4; });
  changed([](auto& q) { q.vmax = 0.2; });
  changed([](auto& q) { q.dt = 0.1; });
  changed([](auto& q) { q.revolutions = 0.2; });
  changed([](auto& q) { q.sample_every = 10; });
  changed([](auto& q) { q.snapshot_angles.push_back(1.0); });
  changed([](auto& q) { q.params.mass = 2; });
  changed([](auto& q) { q.params.h = 2.5; });
  changed([](auto& q) { q.params.lambda = 0.5; });
  changed([](auto& q) { q.params.eta = 0.5; });
  changed([](auto& q) { q.params.viscosity_coefficient = 1; });
  changed([](auto& q) { q.params.viscosity_length = 2; });
  changed([](auto& q) { q.params.closest_distance = 0.5; });
  changed([](auto& q) { q.params.gauss_floor = 1e-10; });
  changed([](auto& q) { q.params.skin_over_h = 0; });
  changed([](auto& q) { q.params.box.xmax = 5; });
  changed([](auto& q) { q.params.box.periodic_x = true; });
  changed([](auto& q) { q.track_advection_torque = false; });
  auto option = [&](auto&& set) { auto w = v; set(w.options); keys.insert(sph::scenes::hexagon_run_key(s, w)); ++expected; };
  option([](auto& o) { o.density = sph::SpamDensity::Summation; });
  option([](auto& o) { o.advection = sph::SpamAdvection::MonaghanArithmetic; });
  option([](auto& o) { o.chain_rule = true; });
  option([](auto& o) { o.torque = sph::SpamTorque::Gauss; });
  option([](auto& o) { o.viscosity = true; });
  option([](auto& o) { o.closest_approach = true; });
  keys.insert(sph::scenes::hexagon_run_key(s, {"md", v.options}));
  ++expected;
  EXPECT_EQ(keys.size(), expected);
}
