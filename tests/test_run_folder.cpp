// Run jobs and the run that collects them (experiments/frame/run_jobs.hpp, run_folder.hpp; issue 45): a result written
// into a run job's folder is read back with every bit (the scenes' results, with NaN, infinities, signed zeros,
// subnormals and texts that need quoting), a main run's snapshots and frames are written again as they were, and the
// collecting run refuses, naming the file, a folder without its completion record, a missing file, a file of another
// code version, driver or target, of other parameters, of another thread count, a cell that is not a number, and
// (for a modified tree's code version) a file older than the binary.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "frame/run_jobs.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "gray2001/scenes/run_files.hpp"
#include "hoover2004/scenes/hexagon_files.hpp"
#include "io/hdf5_snapshot.hpp"
#include "ismail2009/scenes/hole_files.hpp"

namespace fs = std::filesystem;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A driver of the test's own (target T, one parameter --x, the run jobs' options) whose body gets the driver and its
// jobs; returns the exit code and keeps what it printed on stderr.
struct Outcome { int code; std::string err; };
Outcome drive(const std::vector<std::string>& args, const std::function<void(sph::Driver&, const sph::RunJobs&)>& body) {
  sph::Driver d("test_runs", "T", "a driver of the run-folder test");
  double x = 1;
  d.param("x", x, "a parameter");
  const sph::RunJobs jobs(d);
  std::vector<std::string> words{"test_runs"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  testing::internal::CaptureStderr();
  const int code = d.run(static_cast<int>(argv.size()), argv.data(), [&] { body(d, jobs); });
  return {code, testing::internal::GetCapturedStderr()};
}

class RunFolders : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("sph_run_folder_" + std::to_string(::getpid()));
    fs::remove_all(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path runs() const { return root_ / "runs"; }
  // A run job of run `name` whose body writes what `write` writes.
  Outcome job(const std::string& name, const std::function<void(sph::Driver&)>& write, std::vector<std::string> extra = {}) {
    std::vector<std::string> args{"--out", (runs() / name).string(), "--step-runs", name};
    args.insert(args.end(), extra.begin(), extra.end());
    return drive(args, [&](sph::Driver& d, const sph::RunJobs& jobs) {
      EXPECT_TRUE(jobs.handled({"other", name}, [&](std::size_t i) {
        EXPECT_EQ(i, 1u);
        write(d);
      }));
    });
  }
  // The collecting run, reading run `name` with `read`; fails the test if it would step it.
  template <class R>
  Outcome collect(const std::string& name, const std::function<R(const sph::RunFolder&)>& read, R& out,
                  std::vector<std::string> extra = {}) {
    std::vector<std::string> args{"--out", (root_ / "collected").string(), "--runs-from", runs().string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return drive(args, [&](sph::Driver&, const sph::RunJobs& jobs) {
      EXPECT_FALSE(jobs.handled({name}, [](std::size_t) { ADD_FAILURE() << "stepped in the collecting run"; }));
      out = jobs.result(name, read, [&] { ADD_FAILURE() << "stepped instead of read"; return R{}; });
    });
  }
  fs::path root_;
};

scenes::PlateRunResult crafted_plate() {
  scenes::PlateRunResult r;
  r.trace = {{0.0, 0.0, 1.5, 2.5, 1},
             {0.5, -0.0, 4.9e-324, 1.7976931348623157e308, 3, 0.1, -0.2, NAN},
             {1.0, 1.0 / 3.0, INFINITY, -INFINITY, 2, -NAN, 1e-310, 2.0 / 3.0}};
  r.steps = 123456789012L;
  r.particles = 4321;
  r.dt = 0.1;
  r.wall_s = 2.5;
  r.fracture_time = -1;
  r.blow_up = "density below 5%, \"here\",\nat t = 3";
  return r;
}

void expect_plate(const scenes::PlateRunResult& a, const scenes::PlateRunResult& b) {
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t k = 0; k < a.trace.size(); ++k) {
    const auto &x = a.trace[k], &y = b.trace[k];
    for (auto f : {&scenes::TipSample::t, &scenes::TipSample::y, &scenes::TipSample::ke, &scenes::TipSample::ee,
                   &scenes::TipSample::p_art, &scenes::TipSample::p_visc, &scenes::TipSample::p_xsph})
      EXPECT_TRUE(same_bits(x.*f, y.*f) || (std::isnan(x.*f) && std::isnan(y.*f) && std::signbit(x.*f) == std::signbit(y.*f)))
          << "sample " << k << ": " << x.*f << " against " << y.*f;
    EXPECT_EQ(x.fragments, y.fragments);
  }
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.particles, b.particles);
  EXPECT_TRUE(same_bits(a.dt, b.dt) && same_bits(a.wall_s, b.wall_s) && same_bits(a.fracture_time, b.fracture_time));
  EXPECT_EQ(a.blow_up, b.blow_up);
}

auto read_plate = [](const sph::RunFolder& f) { return scenes::read_plate_run(f, "plate"); };

// Replaces the first match of `from` in `file` by `to`.
void edit(const fs::path& file, const std::string& from, const std::string& to) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  in.close();
  const std::string text = std::regex_replace(s.str(), std::regex(from), to, std::regex_constants::format_first_only);
  ASSERT_NE(text, s.str()) << "nothing to edit in " << file;
  std::ofstream(file) << text;
}

}  // namespace

TEST_F(RunFolders, APlateRunIsReadBackWithEveryBit) {
  const auto crafted = crafted_plate();
  ASSERT_EQ(job("n10", [&](sph::Driver& d) { scenes::write_plate_run(d, "plate", crafted); }).code, 0);
  scenes::PlateRunResult read;
  const auto c = collect<scenes::PlateRunResult>("n10", read_plate, read);
  ASSERT_EQ(c.code, 0) << c.err;
  expect_plate(read, crafted);
  // A run as stepped, too: a few steps of a coarse plate.
  sph::GrayParameters scheme;
  auto spec = scenes::table_plate_run(2.0, 0.01, 0.5, 2.0, scheme, 1.0, 1);
  spec.max_steps = 30;
  spec.sample_dt = 0.1;
  spec.power_budget = true;
  const auto stepped = scenes::run_plate(spec);
  ASSERT_GT(stepped.trace.size(), 3u);
  ASSERT_EQ(job("stepped", [&](sph::Driver& d) { scenes::write_plate_run(d, "plate", stepped); }).code, 0);
  ASSERT_EQ(collect<scenes::PlateRunResult>("stepped", read_plate, read).code, 0);
  expect_plate(read, stepped);
}

TEST_F(RunFolders, TheOtherScenesAreReadBackWithEveryBit) {
  scenes::SlabRunResult slab;
  slab.trace = {{0.0, 0.0, 0.0, 1.0, 2.0, 0.1, 1.5, 0.2, 0.03, 0.04, 1.6, 1, 0},
                {2.0, 1e-5, 3.3e-6, NAN, -0.0, INFINITY, -1.0, 0.2, 0.03, 0.05, 1.4, 2, 1}};
  slab.steps = 77;
  slab.particles = 12000;
  slab.dt = 0.01;
  slab.fracture_time = 2.0;
  slab.crack_x = NAN;
  slab.opening_from_junction = 0.25;
  slab.blow_up = "";
  scenes::RingsRunResult rings;
  rings.trace = {{0.0, 1.0, 0.9, 0.0, 0.059, -0.059, -2.0, 2.0, INFINITY, 0, 1, 1, 0, 1.0},
                 {1.0, 0.8, 0.7, 0.1, 0.01, -0.01, -1.0, 1.0, 0.05, 1, 2, 1, 3, 0.97}};
  rings.steps = 5;
  rings.max_fragments = 2;
  rings.restitution = -1;
  rings.blow_up = "speed above 100 c0";
  scenes::HoleResult hole;
  hole.particles = 441;
  hole.steps = 1000;
  hole.peak_sigma1 = 1.5e7;
  hole.fastest_X = sph::Vec2(0.03, -0.0);
  hole.finite = false;
  hole.history = {{0.0, 0.0, 0.0, 0.0}, {1e-4, 2e6, 3e6, NAN}};
  sph::scenes::HexagonRun hex;
  hex.variant = "cont/shepard/pair_torque";
  hex.t = {0, 1, 2};
  hex.L = {1, 1 + 1e-15, NAN};
  hex.K = hex.U = hex.shape_rms = hex.angle = hex.gauss_D = hex.gauss_beta = {0.5, 0.25, -0.0};
  hex.advection_torque_integral = {0, 1e-300, 2};
  hex.snapshot_angles = {0.0, 6.28};
  hex.snapshots = {{sph::Vec2(0, 0), sph::Vec2(1, 0)}, {sph::Vec2(0, 1), sph::Vec2(-1, 0)}};
  hex.snapshot_density = {{1.1, 1.2}, {1.3, 1.4}};
  hex.L0 = 1;
  hex.failed = true;
  hex.failed_at = 1.5;
  hex.reflections = 9;
  sph::scenes::HexagonRun md = hex;
  md.variant = "md";
  md.advection_torque_integral.clear();  // molecular dynamics tracks none
  ASSERT_EQ(job("all", [&](sph::Driver& d) {
              scenes::write_slab_run(d, "slab", slab);
              scenes::write_rings_run(d, "rings", rings);
              scenes::write_hole_run(d, "hole", hole);
              sph::scenes::write_hexagon_run(d, "spam", hex);
              sph::scenes::write_hexagon_run(d, "md", md);
            }).code, 0);
  struct All {
    scenes::SlabRunResult slab;
    scenes::RingsRunResult rings;
    scenes::HoleResult hole;
    sph::scenes::HexagonRun hex, md;
  } got;
  const auto c = collect<All>("all", [](const sph::RunFolder& f) {
    return All{scenes::read_slab_run(f, "slab"), scenes::read_rings_run(f, "rings"), scenes::read_hole_run(f, "hole"),
               sph::scenes::read_hexagon_run(f, "spam"), sph::scenes::read_hexagon_run(f, "md")};
  }, got);
  ASSERT_EQ(c.code, 0) << c.err;
  auto same = [](double a, double b) { return same_bits(a, b) || (std::isnan(a) && std::isnan(b)); };
  ASSERT_EQ(got.slab.trace.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto &x = got.slab.trace[k], &y = slab.trace[k];
    for (auto f : {&scenes::SlabSample::t, &scenes::SlabSample::extension, &scenes::SlabSample::strain, &scenes::SlabSample::ke,
                   &scenes::SlabSample::ee, &scenes::SlabSample::neck_width, &scenes::SlabSample::neck_x,
                   &scenes::SlabSample::median_width, &scenes::SlabSample::closest, &scenes::SlabSample::widest_gap,
                   &scenes::SlabSample::gap_x})
      EXPECT_TRUE(same(x.*f, y.*f)) << k;
    EXPECT_EQ(x.pieces, y.pieces);
    EXPECT_EQ(x.parted, y.parted);
  }
  for (auto f : {&scenes::SlabRunResult::dt, &scenes::SlabRunResult::wall_s, &scenes::SlabRunResult::first_split_time,
                 &scenes::SlabRunResult::fracture_time, &scenes::SlabRunResult::crack_x, &scenes::SlabRunResult::crack_from_junction,
                 &scenes::SlabRunResult::neck_before_fracture, &scenes::SlabRunResult::onset_strain,
                 &scenes::SlabRunResult::onset_time, &scenes::SlabRunResult::clumping_time, &scenes::SlabRunResult::opening_time,
                 &scenes::SlabRunResult::opening_from_junction})
    EXPECT_TRUE(same(got.slab.*f, slab.*f));
  EXPECT_EQ(got.slab.steps, slab.steps);
  EXPECT_EQ(got.slab.particles, slab.particles);
  EXPECT_EQ(got.slab.blow_up, slab.blow_up);
  ASSERT_EQ(got.rings.trace.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto &x = got.rings.trace[k], &y = rings.trace[k];
    for (auto f : {&scenes::RingsSample::t, &scenes::RingsSample::ke, &scenes::RingsSample::ke_com, &scenes::RingsSample::ee,
                   &scenes::RingsSample::v_left, &scenes::RingsSample::v_right, &scenes::RingsSample::x_left,
                   &scenes::RingsSample::x_right, &scenes::RingsSample::min_distance, &scenes::RingsSample::main_share})
      EXPECT_TRUE(same(x.*f, y.*f)) << k;
    EXPECT_EQ(x.contact, y.contact);
    EXPECT_EQ(x.fragments_left, y.fragments_left);
    EXPECT_EQ(x.fragments_right, y.fragments_right);
    EXPECT_EQ(x.stray, y.stray);
  }
  for (auto f : {&scenes::RingsRunResult::dt, &scenes::RingsRunResult::wall_s, &scenes::RingsRunResult::contact_start,
                 &scenes::RingsRunResult::contact_end, &scenes::RingsRunResult::rebound_speed, &scenes::RingsRunResult::restitution,
                 &scenes::RingsRunResult::fracture_time, &scenes::RingsRunResult::min_main_share})
    EXPECT_TRUE(same(got.rings.*f, rings.*f));
  EXPECT_EQ(got.rings.steps, rings.steps);
  EXPECT_EQ(got.rings.max_fragments, rings.max_fragments);
  EXPECT_EQ(got.rings.max_stray, rings.max_stray);
  EXPECT_EQ(got.rings.blow_up, rings.blow_up);
  for (auto f : {&scenes::HoleResult::wall_s, &scenes::HoleResult::build_s, &scenes::HoleResult::peak_sigma1,
                 &scenes::HoleResult::sigma1_hole_top, &scenes::HoleResult::peak_sigma1_dynamic,
                 &scenes::HoleResult::smoothed_peak_sigma1, &scenes::HoleResult::smoothed_sigma1_hole_top,
                 &scenes::HoleResult::settle_change, &scenes::HoleResult::zigzag, &scenes::HoleResult::speed_rise,
                 &scenes::HoleResult::rest_speed_ratio, &scenes::HoleResult::growth_rate})
    EXPECT_TRUE(same(got.hole.*f, hole.*f));
  EXPECT_TRUE(same(got.hole.fastest_X.x(), hole.fastest_X.x()) && same(got.hole.fastest_X.y(), hole.fastest_X.y()));
  EXPECT_EQ(got.hole.particles, hole.particles);
  EXPECT_EQ(got.hole.steps, hole.steps);
  EXPECT_EQ(got.hole.finite, hole.finite);
  ASSERT_EQ(got.hole.history.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    for (auto f : {&scenes::HoleResult::Sample::t, &scenes::HoleResult::Sample::smoothed_top, &scenes::HoleResult::Sample::peak,
                   &scenes::HoleResult::Sample::vmax})
      EXPECT_TRUE(same(got.hole.history[k].*f, hole.history[k].*f)) << k;
  for (const auto& [a, b] : {std::pair{&got.hex, &hex}, std::pair{&got.md, &md}}) {
    EXPECT_EQ(a->variant, b->variant);
    for (auto f : {&sph::scenes::HexagonRun::t, &sph::scenes::HexagonRun::L, &sph::scenes::HexagonRun::K,
                   &sph::scenes::HexagonRun::U, &sph::scenes::HexagonRun::shape_rms, &sph::scenes::HexagonRun::angle,
                   &sph::scenes::HexagonRun::gauss_D, &sph::scenes::HexagonRun::gauss_beta,
                   &sph::scenes::HexagonRun::snapshot_angles, &sph::scenes::HexagonRun::advection_torque_integral}) {
      ASSERT_EQ((a->*f).size(), (b->*f).size()) << b->variant;
      for (std::size_t k = 0; k < (a->*f).size(); ++k) EXPECT_TRUE(same((a->*f)[k], (b->*f)[k])) << k;
    }
    ASSERT_EQ(a->snapshots.size(), b->snapshots.size());
    for (std::size_t s = 0; s < a->snapshots.size(); ++s) {
      ASSERT_EQ(a->snapshots[s].size(), b->snapshots[s].size());
      for (std::size_t i = 0; i < a->snapshots[s].size(); ++i) {
        EXPECT_TRUE(a->snapshots[s][i] == b->snapshots[s][i]);
        EXPECT_TRUE(same(a->snapshot_density[s][i], b->snapshot_density[s][i]));
      }
    }
    EXPECT_TRUE(same(a->L0, b->L0) && same(a->E0, b->E0) && same(a->failed_at, b->failed_at) && same(a->wall_s, b->wall_s));
    EXPECT_EQ(a->failed, b->failed);
    EXPECT_EQ(a->steps, b->steps);
    EXPECT_EQ(a->gauss_floor_hits, b->gauss_floor_hits);
    EXPECT_EQ(a->reflections, b->reflections);
  }
}

TEST_F(RunFolders, SnapshotsAndFramesAreWrittenAgainUnderTheCollectingRunsHeader) {
  sph::Snapshot s0, s1;
  s0.time = 0;
  s0.position = {sph::Vec2(0, 0), sph::Vec2(1, 0.5)};
  s0.velocity = {sph::Vec2(0, 1e-300), sph::Vec2(-0.0, 2)};
  s0.density = {1, 1.0 / 3.0};
  s0.sxx = s0.syy = s0.sxy = {0.1, -0.2};
  s1 = s0;
  s1.time = 50;
  s1.step = 5000;
  ASSERT_EQ(job("eps0.3", [&](sph::Driver& d) {
              sph::SnapshotSeries series(d.out_dir() / "snapshots_eps0.3.h5", d.info());
              series.write(s0);
              series.write(s1);
              auto frames = d.csv("frames_eps0.3.csv", {"t", "x", "y", "fixed"});
              frames.row(0.0, 1.0 / 3.0, -0.0, 1);
              frames.row(50.0, 5e-324, 1e300, 0);
            }).code, 0);
  const auto out = drive({"--out", (root_ / "collected").string(), "--runs-from", runs().string()},
                         [&](sph::Driver& d, const sph::RunJobs& jobs) {
                           const auto f = jobs.folder("eps0.3");
                           ASSERT_TRUE(f.has_value());
                           sph::rewrite_snapshots(*f, d, "snapshots_eps0.3.h5");
                           sph::rewrite_table(*f, d, "frames_eps0.3.csv");
                         });
  ASSERT_EQ(out.code, 0) << out.err;
  const fs::path again = root_ / "collected" / "snapshots_eps0.3.h5";
  ASSERT_EQ(sph::count_snapshots(again), 2u);
  const auto r1 = sph::read_snapshot(again, 1);
  EXPECT_EQ(r1.time, 50.0);
  EXPECT_EQ(r1.step, 5000);
  EXPECT_TRUE(r1.position == s1.position && r1.velocity == s1.velocity && r1.density == s1.density && r1.sxy == s1.sxy);
  EXPECT_TRUE(fs::exists(root_ / "collected" / "snapshots_eps0.3.xdmf"));
  for (const auto& [k, v] : sph::snapshot_header(again))
    if (k == "param.step-runs") {
      EXPECT_EQ(v, "");  // the collecting run's header, not the job's
    }
  std::ifstream frames(root_ / "collected" / "frames_eps0.3.csv");
  std::string line, rows;
  bool job_header = false;
  while (std::getline(frames, line)) {
    if (line.rfind("# param.step-runs = eps0.3", 0) == 0) job_header = true;
    if (line[0] != '#') rows += line + "\n";
  }
  EXPECT_FALSE(job_header);
  EXPECT_EQ(rows, "t,x,y,fixed\n0,0.33333333333333331,-0,1\n50,4.94065645841e-324,1e+300,0\n");
}

TEST_F(RunFolders, AFolderIsRefusedByTheNameOfWhatIsWrongWithIt) {
  const auto crafted = crafted_plate();
  auto write = [&](sph::Driver& d) { scenes::write_plate_run(d, "plate", crafted); };
  scenes::PlateRunResult read;
  auto refused = [&](const std::string& why, const std::string& file, const std::string& words) {
    const auto c = collect<scenes::PlateRunResult>("r", read_plate, read);
    EXPECT_EQ(c.code, 1) << why;
    EXPECT_NE(c.err.find((runs() / "r" / file).string()), std::string::npos) << why << ": " << c.err;
    EXPECT_NE(c.err.find(words), std::string::npos) << why << ": " << c.err;
    EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << why << ": one line: " << c.err;
  };
  refused("no run job", "timing_test_runs.csv", "did not run or did not complete");
  // An interrupted job: its files, but no completion record.
  EXPECT_EQ(job("r", [&](sph::Driver& d) { write(d); throw std::runtime_error("interrupted"); }).code, 1);
  refused("interrupted", "timing_test_runs.csv", "did not run or did not complete");
  auto fresh = [&](std::vector<std::string> extra = {}) {
    fs::remove_all(runs() / "r");
    ASSERT_EQ(job("r", write, extra).code, 0);
  };
  fresh();
  ASSERT_EQ(collect<scenes::PlateRunResult>("r", read_plate, read).code, 0);
  fs::remove(runs() / "r" / "plate_trace.csv");
  refused("a file missing", "plate_trace.csv", "missing");
  fresh();
  edit(runs() / "r" / "plate_run.csv", "# code_version = .*", "# code_version = 0123456789ab");
  refused("another code version", "plate_run.csv", "code version 0123456789ab");
  fresh();
  edit(runs() / "r" / "plate_trace.csv", "# target = T", "# target = U");
  refused("another target", "plate_trace.csv", "for U");
  fresh({"--x", "2"});
  refused("other parameters", "timing_test_runs.csv", "--x 2, this run has --x 1");
  fresh();
  edit(runs() / "r" / "plate_trace.csv", "# param.x = 1", "# param.y = 1");
  refused("a parameter of another driver version", "plate_trace.csv", "--x");
  fresh();
  edit(runs() / "r" / "timing_test_runs.csv", ",[0-9]+\n$", ",64\n");
  refused("another thread count", "timing_test_runs.csv", "64 threads");
  fresh();
  edit(runs() / "r" / "plate_trace.csv", "\n0.5,", "\n0.5x,");
  refused("not a number", "plate_trace.csv", "row 2, column t: '0.5x' is not a number");
  // A file older than the binary: stale when the code version names no one build (a modified tree's).
  fresh();
  const auto built = fs::last_write_time("/proc/self/exe");
  fs::last_write_time(runs() / "r" / "plate_run.csv", built - std::chrono::hours(1));
  const std::string version = sph::code_version();
  if (version.find("dirty") != std::string::npos || version.rfind("unknown", 0) == 0)
    refused("older than a dirty build", "plate_run.csv", "written before this binary was built");
  else
    EXPECT_EQ(collect<scenes::PlateRunResult>("r", read_plate, read).code, 0);
}

TEST_F(RunFolders, ARunJobStepsOnlyARunOfItsDriver) {
  const auto c = drive({"--out", (runs() / "x").string(), "--step-runs", "x"}, [](sph::Driver&, const sph::RunJobs& jobs) {
    jobs.handled({"a", "b"}, [](std::size_t) { ADD_FAILURE() << "stepped"; });
  });
  EXPECT_EQ(c.code, 1);
  EXPECT_NE(c.err.find("--step-runs x: not among this driver's runs"), std::string::npos) << c.err;
  testing::internal::CaptureStdout();
  const auto listed = drive({"--out", (runs() / "list").string(), "--list-runs", "true"}, [](sph::Driver&, const sph::RunJobs& jobs) {
    EXPECT_TRUE(jobs.handled({"a", "b"}, [](std::size_t) { ADD_FAILURE() << "stepped"; }));
  });
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "a\nb\n");
  EXPECT_EQ(listed.code, 0);
  EXPECT_FALSE(fs::exists(runs() / "list" / "timing_test_runs.csv"));  // nothing ran: no completion record
  // Without --runs-from, a run is stepped where it is needed.
  const auto whole = drive({"--out", (root_ / "whole").string()}, [](sph::Driver&, const sph::RunJobs& jobs) {
    EXPECT_FALSE(jobs.folder("a").has_value());
    EXPECT_EQ(jobs.result("a", [](const sph::RunFolder&) { return 1; }, [] { return 2; }), 2);
  });
  EXPECT_EQ(whole.code, 0);
}
