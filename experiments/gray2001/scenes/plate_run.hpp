// Running the oscillating plate: the solver set-up shared by the plate drivers and the tip trace
// analysis (zero crossings, period, amplitude decay, fracture).
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "gray2001/scenes/plate.hpp"
#include "io/csv.hpp"
#include "updated_lagrangian/gray_solver.hpp"

namespace scenes {

struct PlateRunSpec {
  PlateSpec plate;
  sph::GrayParameters scheme;      ///< the scheme's parameters (their defaults and sources: parameters.hpp)
  sph::GrayOptions options;
  double t_end = 2000;
  long max_steps = -1;             ///< stop after this many steps (smoke runs); -1: no limit
  double sample_dt = 1.0;          ///< interval of the recorded tip trace
  double fracture_link = 1.5;      ///< fracture when the free particles split at this link distance / dp
  double fracture_check_dt = 10.0;
  double run_after_fracture = -1;  ///< stop this long after the first fracture; < 0: never stop
  int stop_after_crossings = -1;   ///< stop once the tip has crossed its start line this often; < 0: never
  bool power_budget = false;       ///< record GraySolver::power_budget() at every sample (a pass over the pairs)
};

/// p_art, p_visc, p_xsph: the power of the artificial stress, the viscosity and XSPH's velocity
/// (GraySolver::PowerBudget; NaN unless PlateRunSpec::power_budget).
struct TipSample { double t, y, ke, ee; std::size_t fragments; double p_art = NAN, p_visc = NAN, p_xsph = NAN; };

struct PlateRunResult {
  std::vector<TipSample> trace;    ///< y is the tip displacement from its initial position
  long steps = 0;
  std::size_t particles = 0;
  double dt = 0, wall_s = 0;
  double fracture_time = -1;       ///< first time the free particles were in more than one piece
  std::string blow_up;             ///< message if the run blew up
};

/// Fig 4's plate run (Gray 2001 Sec 7.1): L = 20, H = 2, n particles across, the tip's first period (stops at
/// its second zero crossing; t_end = 2 `periods` thin-plate periods is only a bound), sampled every 0.5, checked
/// for fracture every 100, with the power budget recorded. G-fig4's study and the Table 1-2 driver's coarse
/// reference both build it here (each steps it: a few seconds at n = 10).
PlateRunSpec fig4_plate_run(int n, double Vf, double clamp_length, const sph::GrayParameters& scheme, double periods = 1.0);

/// Tables 1-2's run of one row (Gray 2001 Sec 7.1): L = 20, thickness H at spacing dp, sampled every 0.5, checked
/// for fracture every 100 (as Fig 4's: a row is a prefix of Fig 4's run of its plate), stopped at the tip's `crossings`-th
/// zero crossing, at most `periods` thin-plate periods (7.1) of the 3D moduli of K = rho0 c0^2 and scheme.mu.
/// The Table 1-2 driver and make peers' plate (experiments/peers/peer_plate.cpp) both build it here.
PlateRunSpec table_plate_run(double H, double Vf, double dp, double clamp_length, const sph::GrayParameters& scheme,
                             double periods, int crossings);

/// Runs the plate; `snapshot(t, solver, body)` is called every sample if given (for HDF5 output).
PlateRunResult run_plate(const PlateRunSpec& s,
                         const std::function<void(const sph::GraySolver&, const sph::ElasticBody&)>& on_sample = {},
                         const std::string& progress_label = "plate");

/// Columns of a configuration frame CSV (long format, one row per particle per frame).
std::vector<std::string> frame_columns();
/// Appends the particles of the current state to a frame CSV: t, x, y, sigma_xx, sigma_yy, sigma_xy, fixed.
void write_frame(sph::CsvWriter& out, const sph::GraySolver& solver, const sph::ElasticBody& body);

/// Times at which the tip crosses its initial position (linear interpolation), after t = 0.
std::vector<double> zero_crossings(const std::vector<TipSample>& trace);
/// Period from the crossings, counting t = 0 as crossing 0 (the tip starts at its rest position):
/// the mean of the full periods c[i+2] - c[i]; with a single crossing, twice it (the zero crossings of
/// a damped linear oscillation are equally spaced); NaN without crossings.
double period_from_crossings(const std::vector<double>& crossings);
/// Extremes of the tip displacement between successive crossings (alternating sign).
std::vector<double> half_cycle_extremes(const std::vector<TipSample>& trace);

}  // namespace scenes
