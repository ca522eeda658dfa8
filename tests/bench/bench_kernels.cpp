// Micro-benchmarks (Google Benchmark) of the inner-loop building blocks: kernel evaluation and the
// cell-list build and query. Run with `make bench`; never part of the tests.
#include <benchmark/benchmark.h>

#include <random>

#include "core/kernels.hpp"
#include "core/neighbours.hpp"

namespace {

template <class K>
void BM_KernelGradient(benchmark::State& state) {
  const K k(2);
  std::vector<double> r(4096);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, k.support() * 1.2);
  for (double& x : r) x = u(rng);
  double acc = 0;
  for (auto _ : state) {
    for (double x : r) acc += k.F(x, 1.2);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(r.size()));
}
BENCHMARK_TEMPLATE(BM_KernelGradient, sph::CubicSpline);
BENCHMARK_TEMPLATE(BM_KernelGradient, sph::Lucy);
BENCHMARK_TEMPLATE(BM_KernelGradient, sph::ModifiedMollifier);

void BM_CellListBuildAndQuery(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double dp = 1.0 / n, h = 1.5 * dp;
  const auto x = sph::lattice_block(sph::LatticeKind::Square, n, n, dp);
  sph::CellList2D cells({0, 0, 1, 1, true, true}, 2 * h);
  long pairs = 0;
  for (auto _ : state) {
    cells.build(x);
    for (std::size_t i = 0; i < x.size(); ++i) cells.for_each_neighbour(x, i, 2 * h, [&](std::size_t, const sph::Vec2&, double) { ++pairs; });
    benchmark::DoNotOptimize(pairs);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(x.size()));
}
BENCHMARK(BM_CellListBuildAndQuery)->Arg(64)->Arg(128)->Arg(256);

}  // namespace
