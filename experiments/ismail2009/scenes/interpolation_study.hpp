// The interpolation study of Ismail 2009 Figs 2.10-2.20 (the driver ismail2009_fig2_10to2_20_interpolation.cpp
// chooses the panels and covers and documents their sources): SPH interpolation of known 1D functions and of their
// first and second derivatives, eqs (2.24)-(2.25), on each panel for each cover size and under both normalisation
// readings; the curves and errors written for the plots, and the measures of the text's claims.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sph {
class Driver;
}

namespace scenes::interpolation {

/// A known function and its first and second derivatives.
struct Exact {
  std::function<double(double)> f, df, d2f;
};

/// One panel of the figures: the function on (a, b) at spacing ps, with or without ghost particles.
struct Panel {
  std::string id, description;
  Exact exact;
  double a, b, ps;
  bool ghosts;
  double edge_width_ps = -1;  // falling edges only
};

struct Errors {
  double max[3], rms[3];  // f, f', f''
};

/// The exact and SPH values at the real particles of one panel and cover, and their errors.
struct Curve {
  std::vector<double> x, f, df, d2f, sf, sdf, sd2f;
  double end_weight_deficit = 0, end_relerr_f = 0;  // left end particle (meaningful without ghosts)
  Errors err{};
};

/// The name of a cover in files and value names: "c" and the cover in spacings (c1.5).
std::string cover_label(double cover);

/// (x - 0.5)^4.
Exact quartic();
/// sin x.
Exact sine();
/// The falling edge on (0, 1) of `width` spacings, centred midway between the particles at 0.5 and
/// 0.5 + ps, so that both corners lie midway between particles for any whole width.
Panel edge_panel(const std::string& id, const std::string& description, double ps, double width);

/// Every panel and cover under both normalisations ("integral", "discrete"): results[norm][panel][cover]; and
/// sweep[norm][edge width][cover], the falling edge at every width from a step to sweep_max_width spacings, to
/// locate where the 1.5 cover stops being best.
struct Study {
  std::map<std::string, std::map<std::string, std::map<double, Curve>>> results;
  std::map<std::string, std::map<double, std::map<double, Errors>>> sweep;
};
Study run_study(const std::string& kernel_name, const std::vector<Panel>& panels, const std::vector<double>& covers,
                double edge_ps, int sweep_max_width);

/// panels.csv: the panels' settings.
void write_panels(sph::Driver& d, const std::vector<Panel>& panels);
/// edge_width_sweep.csv, and for every panel exact_<panel>.csv (the function on a fine grid), curves_<panel>.csv
/// (at the particles, the `normalisation` reading) and its rows of errors.csv (both readings); the values of the
/// max and RMS errors of the `normalisation` reading.
void write_curves(sph::Driver& d, const std::vector<Panel>& panels, const std::vector<double>& covers,
                  const Study& study, const std::string& normalisation);
/// The measures of the text's claims (interpolation_claims.cpp) under both normalisation readings (suffix _discrete for the alternative):
/// the lattice gradient error, the boundary droop and the ghosts, refinement, the rank of the 1.5 cover, the
/// falling edges and the compromise cover (within `fairly_good_factor` of the best cover counts as fairly good).
void write_claims(sph::Driver& d, const std::string& kernel_name, const std::vector<Panel>& panels,
                  const std::vector<double>& covers, const Study& study, double fairly_good_factor);

}  // namespace scenes::interpolation
