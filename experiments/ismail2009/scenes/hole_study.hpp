// The resolution study of the sheet with a hole (I-hole; its driver ismail2009_fig5_13to5_15_hole_resolution.cpp
// documents the runs, their parameters' sources and what they measured): the plan of its named runs (the unit of
// a run job, frame/run_jobs.hpp), and its output files and values from the runs' results.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/csv.hpp"
#include "ismail2009/scenes/hole.hpp"

namespace sph {
class Driver;
}

namespace scenes {

/// The study's runs (the driver's parameters).
struct HoleStudySpec {
  std::vector<int> ns, plain_ns;  ///< particles along a side: the controlled runs (the study), the plain runs
  std::vector<double> gammas;     ///< control strengths of the gamma sweep, at gamma_n
  int gamma_n = 0;
  int linear_n = 0;               ///< the linear (Hooke, 1% of the load) run; 0 = none
  std::vector<int> edge_ns;       ///< the edge-stability runs at the default step; empty or {0} = none
  int edge_n = 0;                 ///< the edge-stability variants (step, passes, nu, closure)
  int eigen_n = 0;                ///< the spectrum of the linearised operator and its 30-pass run; 0 = none
  HoleParams p;                   ///< the study's sheet
  bool edges() const { return !edge_ns.empty() && edge_ns.front() != 0; }
};

/// Every run of the study once, named, in the study's order (the outputs are written in it).
struct HoleStudyPlan {
  std::vector<std::pair<std::string, HoleParams>> runs;
  /// A gamma of the study's own (or 0) at one of its n is that controlled (or plain) run: named once, read twice.
  std::map<std::string, std::string> same_as;
  std::vector<std::string> names() const;
  /// The plan's run of `name` (or of the run it is the same as).
  const std::pair<std::string, HoleParams>& run(const std::string& name) const;
};
HoleStudyPlan plan_hole_study(const HoleStudySpec& s);

/// The study's files and values from its runs' results (result[name] for every run of the plan).
class HoleStudyOutput {
 public:
  /// Opens resolution.csv and history.csv (one row per run, its samples; written by series()).
  HoleStudyOutput(sph::Driver& d, const HoleStudySpec& s, const HoleStudyPlan& plan,
                  const std::map<std::string, HoleResult>& result);
  /// The linear-elastic concentration of this geometry by finite elements, refined to convergence: fem.csv (meshes
  /// of 2m x m elements) and the fem_* values. Returns the concentration of every mesh.
  std::vector<double> fem_reference(const std::vector<int>& fem_m);
  /// The controlled, plain, gamma and linear series: their rows and values (kf: fem_reference's concentrations).
  void series(const std::vector<double>& kf);
  /// Issue 15 (b): the edge-stability runs (edge_stability.csv) and the spectrum; nothing when there are none.
  void edges();

 private:
  /// The run `name` of `series`: its rows of resolution.csv and history.csv; refuses a non-finite run.
  HoleResult resolution_row(const std::string& series, const std::string& name);
  /// The edge run edge_<run>_n<n> (run = series when empty): its row of edge_stability.csv; its growth rate.
  double edge_row(const std::string& series, int n, const std::string& run = "");
  std::vector<double> controlled(const std::vector<double>& kf, double& top_at_linear_n);
  void plain(const std::vector<double>& top);
  void linear(const std::vector<double>& kf, double top_at_linear_n);
  void spectrum();

  sph::Driver& d_;
  const HoleStudySpec& s_;
  const HoleStudyPlan& plan_;
  const std::map<std::string, HoleResult>& result_;
  sph::CsvWriter out_, hist_;
  std::optional<sph::CsvWriter> edge_csv_;
};

}  // namespace scenes
