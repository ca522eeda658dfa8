// The --quick value declared with a parameter (experiments/frame/driver.hpp, DriverOption::quick; issue 45): under
// --quick and only when the option is not given, the variable takes it after parsing and before the body, so every
// output header records it; a quick value outside the option's bounds is a driver defect (std::logic_error), in
// whichever order the two are declared; a handle kept after other options are declared still sets it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "io/csv.hpp"

namespace fs = std::filesystem;

namespace {

struct Seen {
  int code = -1;
  int n = 0;
  std::vector<double> list;
  bool flag = true;
  int late = 0;
  std::string header_n;  // param.n in the header of a file the body writes
};

// A driver with --n (quick 50), --list (quick: none), --flag (quick false) and --late (a handle, quick 3, set after
// the others are declared), run with `args`.
Seen drive(std::vector<std::string> args) {
  const fs::path out = fs::temp_directory_path() / ("sph_driver_quick_" + std::to_string(::getpid()));
  fs::remove_all(out);
  sph::Driver d("test_quick", "T", "a driver of the quick-value test");
  int n = 200;
  std::vector<double> list{0.1, 0.2};
  bool flag = true;
  int late = 10;
  d.param("n", n, "a resolution").positive().quick(50);
  d.param("list", list, "a list").non_negative().quick({});
  d.param("flag", flag, "a switch").quick(false);
  auto handle = d.param("late", late, "declared before its quick value").positive();
  double other = 1;
  d.param("other", other, "declared in between");
  handle.quick(3);
  Seen seen;
  std::vector<std::string> words{"test_quick", "--out", out.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  seen.code = d.run(static_cast<int>(argv.size()), argv.data(), [&] {
    seen.n = n;
    seen.list = list;
    seen.flag = flag;
    seen.late = late;
    auto f = d.csv("x.csv", {"x"});
    f.row(1.0);
  });
  seen.header_n = sph::read_csv(out / "x.csv").meta_value("param.n");
  fs::remove_all(out);
  return seen;
}

}  // namespace

TEST(DriverQuick, DefaultsWithoutQuick) {
  const Seen s = drive({});
  EXPECT_EQ(s.code, 0);
  EXPECT_EQ(s.n, 200);
  EXPECT_EQ(s.list, (std::vector<double>{0.1, 0.2}));
  EXPECT_TRUE(s.flag);
  EXPECT_EQ(s.late, 10);
  EXPECT_EQ(s.header_n, "200");
}

TEST(DriverQuick, QuickValuesBeforeTheBodyAndInTheHeader) {
  const Seen s = drive({"--quick"});
  EXPECT_EQ(s.code, 0);
  EXPECT_EQ(s.n, 50);
  EXPECT_TRUE(s.list.empty());
  EXPECT_FALSE(s.flag);
  EXPECT_EQ(s.late, 3);
  EXPECT_EQ(s.header_n, "50");
}

TEST(DriverQuick, AGivenOptionKeepsItsValue) {
  const Seen s = drive({"--quick", "--n", "7", "--list", "0.5", "--late", "4"});
  EXPECT_EQ(s.code, 0);
  EXPECT_EQ(s.n, 7);
  EXPECT_EQ(s.list, (std::vector<double>{0.5}));
  EXPECT_FALSE(s.flag);
  EXPECT_EQ(s.late, 4);
  EXPECT_EQ(s.header_n, "7");
  // Given with the value of the default: still given, so not the quick value.
  EXPECT_EQ(drive({"--quick", "--n", "200"}).n, 200);
}

TEST(DriverQuick, AQuickValueOutOfItsBoundsIsADefect) {
  sph::Driver d("test_quick_bounds", "T", "quick values out of bounds");
  int a = 1, b = 1;
  std::vector<double> c{1.0};
  EXPECT_THROW(d.param("a", a, "bound first").positive().quick(0), std::logic_error);
  EXPECT_THROW(d.param("b", b, "quick first").quick(-1).at_least(0), std::logic_error);
  EXPECT_THROW(d.param("c", c, "a list").at_most(2).quick({1.0, 3.0}), std::logic_error);
  double e = 0.5;
  EXPECT_NO_THROW(d.param("e", e, "within").above(0).below(1).quick(0.25));
}

// A numeric bound on a text option refused every value as not a number (I-bar's --modulus, H-fig3's --density
// could not be given at all): a driver defect, found when the option is declared.
TEST(DriverQuick, ANumericBoundOnATextOptionIsADefect) {
  sph::Driver d("test_text_bound", "T", "text options");
  std::string s = "sum";
  std::vector<std::string> names{"a"};
  EXPECT_THROW(d.param("s", s, "a name").positive(), std::logic_error);
  EXPECT_THROW(d.param("names", names, "names").at_least(0), std::logic_error);
  std::string t = "sum";
  EXPECT_NO_THROW(d.param("t", t, "a name").one_of({"sum", "cont"}));
}
