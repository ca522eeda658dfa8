// Output files: CSV (header metadata, quoting, exact numbers) through read_csv, and HDF5 snapshots with
// their XDMF sidecar; both appear whole or not at all (written as .part, renamed when closed), and a failed
// write (a file-size limit here, as a full disk would) is an error naming the file.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <regex>
#include <csignal>
#include <set>
#include <sstream>
#include <system_error>
#include <sys/resource.h>
#include <unistd.h>

#include "io/atomic_output.hpp"
#include "io/csv.hpp"
#include "io/hdf5_snapshot.hpp"
#include "io/run_info.hpp"

namespace {

namespace fs = std::filesystem;
using sph::Vec2;

// The folder of this process's scratch files, removed when the process exits (ctest runs each test in a
// process of its own: each left a folder in the temporary directory before).
struct ScratchRoot {
  fs::path dir;
  ~ScratchRoot() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
};

fs::path scratch(const std::string& name) {
  static const ScratchRoot root{fs::path(::testing::TempDir()) / ("sph_test_io_" + std::to_string(::getpid()))};
  fs::create_directories(root.dir);
  return root.dir / name;
}

sph::RunInfo sample_info() {
  sph::RunInfo info;
  info.driver = "test_driver";
  info.target = "T-io";
  info.description = "round trip, with a comma";
  info.parameters = {{"n", "200"}, {"kernel", "cubic_spline"}, {"h_over_dp", "1.5"}, {"note", "a = b, \"c\""}};
  return info;
}

double parse(const std::string& s) { return std::strtod(s.c_str(), nullptr); }
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(FormatNumber, RoundTripsExactlyAndStaysShortForSimpleValues) {
  EXPECT_EQ(sph::format_number(0.1), "0.1");
  EXPECT_EQ(sph::format_number(2.0), "2");
  EXPECT_EQ(sph::format_number(-1.5e-7), "-1.5e-07");
  const double special[] = {1.0 / 3.0, M_PI, 0.1 + 0.2, 1e-300, 5e-324, -0.0, 1e300, 123456789012345678.0,
                            std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                            std::nextafter(1.0, 2.0), std::numeric_limits<double>::infinity()};
  for (double v : special) EXPECT_TRUE(same_bits(parse(sph::format_number(v)), v)) << sph::format_number(v);
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isnan(v)) continue;
    ASSERT_TRUE(same_bits(parse(sph::format_number(v)), v)) << sph::format_number(v);
  }
  EXPECT_TRUE(std::isnan(parse(sph::format_number(std::nan("")))));
}

TEST(Csv, RoundTripThroughReadCsv) {
  const fs::path path = scratch("sub/dir/table.csv");  // parent directories are created
  const std::string before = sph::utc_timestamp();
  const std::vector<std::string> cols{"x", "label, with comma", "say \"hi\"", "y"};
  const double xs[] = {0.1, 1.0 / 3.0, -2.5e-310, 6.02214076e23, -0.0};
  const std::string labels[] = {"plain", "a,b", "quote \" inside", "\"fully quoted\"", "two\nlines"};
  {
    sph::CsvWriter w(path, sample_info(), cols);
    for (int i = 0; i < 5; ++i) w.row(xs[i], labels[i], std::string("s") + std::to_string(i), i * 7);
  }
  const std::string after = sph::utc_timestamp();
  const sph::CsvTable t = sph::read_csv(path);
  EXPECT_EQ(t.meta_value("driver"), "test_driver");
  EXPECT_EQ(t.meta_value("target"), "T-io");
  EXPECT_EQ(t.meta_value("description"), "round trip, with a comma");
  EXPECT_EQ(t.meta_value("code_version"), sph::code_version());
  EXPECT_FALSE(std::string(sph::code_version()).empty());
  const std::string date = t.meta_value("date");
  EXPECT_TRUE(std::regex_match(date, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"))) << date;
  EXPECT_LE(before, date);  // ISO 8601 UTC strings order like the times they denote
  EXPECT_LE(date, after);
  EXPECT_EQ(t.meta_value("param.n"), "200");
  EXPECT_EQ(t.meta_value("param.h_over_dp"), "1.5");
  EXPECT_EQ(t.meta_value("param.note"), "a = b, \"c\"");
  // Parameters in declaration order, after the fixed keys; then the names given on the command line.
  std::vector<std::string> keys;
  for (const auto& [k, v] : t.meta) keys.push_back(k);
  const std::vector<std::string> expected_keys{"driver", "target", "description", "code_version", "date",
                                               "param.n", "param.kernel", "param.h_over_dp", "param.note", "given"};
  EXPECT_EQ(keys, expected_keys);
  EXPECT_THROW(t.meta_value("param.missing"), std::out_of_range);

  EXPECT_EQ(t.columns, cols);
  EXPECT_EQ(t.column("say \"hi\""), 2u);
  EXPECT_THROW(t.column("z"), std::out_of_range);
  ASSERT_EQ(t.rows.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(t.rows[i].size(), 4u) << "row " << i;
    EXPECT_TRUE(same_bits(parse(t.rows[i][0]), xs[i])) << t.rows[i][0];
    EXPECT_EQ(t.rows[i][1], labels[i]);
    EXPECT_EQ(t.rows[i][2], "s" + std::to_string(i));
    EXPECT_EQ(t.rows[i][3], std::to_string(i * 7));
  }
}

TEST(Csv, HeaderValuesWithLineBreaksDoNotCorruptTheTable) {
  const fs::path path = scratch("multiline_header.csv");
  sph::RunInfo info = sample_info();
  info.description = "first line\nsecond line";
  info.parameters.push_back({"list", "1\n2"});
  { sph::CsvWriter w(path, info, {"a", "b"}); w.row(1, 2); }
  const sph::CsvTable t = sph::read_csv(path);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_NE(t.meta_value("description").find("first line"), std::string::npos);
  EXPECT_NE(t.meta_value("description").find("second line"), std::string::npos);
  EXPECT_EQ(t.meta_value("param.list").size(), 3u);
}

TEST(Csv, HeaderRecordsWhichParametersWereGivenOnTheCommandLine) {
  sph::RunInfo info = sample_info();
  const fs::path none = scratch("given_none.csv");
  { sph::CsvWriter w(none, info, {"a"}); w.row(1); }
  EXPECT_EQ(sph::read_csv(none).meta_value("given"), "");
  info.given = {"n", "h_over_dp"};
  const fs::path some = scratch("given_some.csv");
  { sph::CsvWriter w(some, info, {"a"}); w.row(1); }
  EXPECT_EQ(sph::read_csv(some).meta_value("given"), "n h_over_dp");
}

TEST(Csv, RowWithTheWrongNumberOfCellsThrows) {
  const fs::path path = scratch("wrong.csv");
  sph::CsvWriter w(path, sample_info(), {"a", "b", "c"});
  EXPECT_NO_THROW(w.row(1, 2, 3));
  EXPECT_THROW(w.row(1, 2), std::logic_error);
  EXPECT_THROW(w.row(1, 2, 3, 4), std::logic_error);
  EXPECT_THROW(w.write_cells({"1"}), std::logic_error);
}

TEST(Csv, ReadingARaggedFileThrows) {
  const fs::path path = scratch("ragged.csv");
  { std::ofstream f(path); f << "# driver = x\na,b,c\n1,2,3\n4,5\n"; }
  EXPECT_THROW(sph::read_csv(path), std::runtime_error);
  { std::ofstream f(path); f << "a,b\n1,\"2,3\",4\n"; }
  EXPECT_THROW(sph::read_csv(path), std::runtime_error);
  { std::ofstream f(path); f << "a,b\n1,\"unterminated\n"; }
  EXPECT_THROW(sph::read_csv(path), std::runtime_error);
  EXPECT_THROW(sph::read_csv(scratch("does_not_exist.csv")), std::runtime_error);
}

sph::Snapshot make_snapshot(std::size_t n, double t, long step, bool with_all, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  sph::Snapshot s;
  s.time = t;
  s.step = step;
  for (std::size_t i = 0; i < n; ++i) s.position.emplace_back(g(rng), g(rng));
  if (with_all) {
    for (std::size_t i = 0; i < n; ++i) {
      s.velocity.emplace_back(g(rng), g(rng));
      s.density.push_back(1000 + g(rng));
      s.sxx.push_back(g(rng) * 1e9);
      s.syy.push_back(g(rng) * 1e9);
      s.sxy.push_back(g(rng) * 1e9);
    }
  }
  return s;
}

void expect_equal(const sph::Snapshot& a, const sph::Snapshot& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.step, b.step);
  ASSERT_EQ(a.position.size(), b.position.size());
  for (std::size_t i = 0; i < a.position.size(); ++i) EXPECT_EQ(a.position[i], b.position[i]);
  ASSERT_EQ(a.velocity.size(), b.velocity.size());
  for (std::size_t i = 0; i < a.velocity.size(); ++i) EXPECT_EQ(a.velocity[i], b.velocity[i]);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.sxx, b.sxx);
  EXPECT_EQ(a.syy, b.syy);
  EXPECT_EQ(a.sxy, b.sxy);
}

TEST(Hdf5Snapshot, RoundTripOfTwoSnapshotsAndTheXdmfSidecar) {
  const fs::path h5 = scratch("series/run.h5");
  const sph::Snapshot s0 = make_snapshot(37, 0.0, 0, true, 1);
  const sph::Snapshot s1 = make_snapshot(41, 1.25e-3, 123456789, true, 2);
  const sph::Snapshot s2 = make_snapshot(5, 2.5e-3, 123456790, false, 3);  // positions only
  {
    sph::SnapshotSeries series(h5, sample_info());
    series.write(s0);
    series.write(s1);
    EXPECT_EQ(series.count(), 2u);
    // Readable while the series is still open (post-processing during a run), under its temporary name;
    // the final name appears only when the series is complete.
    EXPECT_FALSE(fs::exists(h5));
    EXPECT_EQ(sph::count_snapshots(sph::partial_path(h5)), 2u);
    expect_equal(sph::read_snapshot(sph::partial_path(h5), 1), s1);
    series.write(s2);
    sph::Snapshot bad = s0;
    bad.density.pop_back();
    EXPECT_THROW(series.write(bad), std::invalid_argument);
    EXPECT_EQ(series.count(), 3u);
  }
  EXPECT_FALSE(fs::exists(sph::partial_path(h5)));
  EXPECT_FALSE(fs::exists(sph::partial_path(fs::path(h5).replace_extension(".xdmf"))));
  EXPECT_EQ(sph::count_snapshots(h5), 3u);
  expect_equal(sph::read_snapshot(h5, 0), s0);
  expect_equal(sph::read_snapshot(h5, 1), s1);
  expect_equal(sph::read_snapshot(h5, 2), s2);
  EXPECT_THROW(sph::read_snapshot(h5, 3), std::runtime_error);

  // Root attributes record the run.
  hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const char* a : {"driver", "target", "code_version", "date", "param.n", "param.note"})
    EXPECT_GT(H5Aexists(f, a), 0) << a;

  // The XDMF sidecar references every dataset of every snapshot, each of which exists with the stated
  // dimensions, and gives each snapshot its time.
  const fs::path xdmf = fs::path(h5).replace_extension(".xdmf");
  ASSERT_TRUE(fs::exists(xdmf));
  std::stringstream buf;
  buf << std::ifstream(xdmf).rdbuf();
  const std::string text = buf.str();
  const std::regex item(R"re(<DataItem Dimensions="(\d+)(?: (\d+))?"[^>]*>run\.h5:/(snapshot_\d{6})/(\w+)</DataItem>)re");
  std::set<std::string> referenced;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), item); it != std::sregex_iterator(); ++it) {
    const std::string path = "/" + (*it)[3].str() + "/" + (*it)[4].str();
    referenced.insert(path);
    ASSERT_GT(H5Lexists(f, ("/" + (*it)[3].str()).c_str(), H5P_DEFAULT), 0) << path;
    ASSERT_GT(H5Lexists(f, path.c_str(), H5P_DEFAULT), 0) << path;
    hid_t set = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
    hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
    EXPECT_EQ(std::to_string(dims[0]), (*it)[1].str()) << path;
    EXPECT_EQ(rank == 2 ? std::to_string(dims[1]) : std::string(), (*it)[2].str()) << path;
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(f);
  const std::set<std::string> expected{
      "/snapshot_000000/position", "/snapshot_000000/velocity", "/snapshot_000000/density", "/snapshot_000000/stress",
      "/snapshot_000001/position", "/snapshot_000001/velocity", "/snapshot_000001/density", "/snapshot_000001/stress",
      "/snapshot_000002/position"};
  EXPECT_EQ(referenced, expected);
  EXPECT_NE(text.find("<Time Value=\"0.00125\"/>"), std::string::npos);
  EXPECT_NE(text.find("<Time Value=\"0.0025\"/>"), std::string::npos);
  EXPECT_NE(text.find("NumberOfElements=\"41\""), std::string::npos);
}

TEST(Hdf5Snapshot, ReopeningTruncatesTheSeries) {
  const fs::path h5 = scratch("trunc.h5");
  {
    sph::SnapshotSeries series(h5, sample_info());
    series.write(make_snapshot(4, 0.0, 0, true, 4));
    series.write(make_snapshot(4, 1.0, 1, true, 5));
  }
  {
    sph::SnapshotSeries series(h5, sample_info());
    series.write(make_snapshot(6, 2.0, 2, false, 6));
  }
  EXPECT_EQ(sph::count_snapshots(h5), 1u);
  EXPECT_EQ(sph::read_snapshot(h5, 0).position.size(), 6u);
}

// A file appears under its name only when complete; a writer left by an exception leaves the previous complete
// file as it was and no temporary one (a run killed at any instant leaves the previous file or none).
TEST(AtomicOutput, ACsvAppearsWhenClosedAndAFailedRunKeepsThePreviousFile) {
  const fs::path path = scratch("atomic/values.csv");
  {
    sph::CsvWriter w(path, sample_info(), {"a"});
    w.row(1);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(sph::partial_path(path)));
  }
  ASSERT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(sph::partial_path(path)));
  try {
    sph::CsvWriter w(path, sample_info(), {"a"});
    w.row(2);
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(sph::partial_path(path)));
  const sph::CsvTable t = sph::read_csv(path);
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0][0], "1");
  // close() says when it is done; a moved writer is closed once, by its new owner.
  sph::CsvWriter a(path, sample_info(), {"a"});
  a.row(3);
  sph::CsvWriter b = std::move(a);
  b.close();
  EXPECT_EQ(sph::read_csv(path).rows[0][0], "3");
  EXPECT_THROW(b.row(4), std::logic_error);
}

TEST(AtomicOutput, ASeriesLeftByAnExceptionLeavesThePreviousOne) {
  const fs::path h5 = scratch("atomic/series.h5");
  { sph::SnapshotSeries s(h5, sample_info()); s.write(make_snapshot(3, 0.0, 0, true, 7)); }
  try {
    sph::SnapshotSeries s(h5, sample_info());
    s.write(make_snapshot(5, 0.0, 0, true, 8));
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(sph::partial_path(h5)));
  EXPECT_EQ(sph::count_snapshots(h5), 1u);
  EXPECT_EQ(sph::read_snapshot(h5, 0).position.size(), 3u);
}

// A write beyond a file-size limit (as one onto a full disk) fails with the file's name and errno, and leaves
// neither the file nor its temporary; the limit is the process's, restored at the end.
TEST(AtomicOutput, AWriteBeyondAFileSizeLimitIsAnErrorNamingTheFile) {
  const fs::path path = scratch("atomic/big.csv");
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    sph::CsvWriter w(path, sample_info(), {"x"});
    for (int i = 0; i < 10000; ++i) w.row(1.0 / 3.0 + i);
    w.close();
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  EXPECT_NE(message.find(sph::partial_path(path).string()), std::string::npos) << message;
  EXPECT_NE(message.find("errno 27"), std::string::npos) << message;  // EFBIG
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(sph::partial_path(path)));
}

}  // namespace
