#!/usr/bin/env python3
"""Gray, Monaghan & Swift 2001's oscillating plate in PySPH (Debian python3-pysph), from our particles.

Reads the scene we build (build/bin/peer_plate --action layout: layout.csv, settings.csv) and runs it with PySPH's own
implementation of the same paper, pysph.sph.solid_mech.basic.ElasticSolidsScheme: its equations, its cubic
spline, its EPEC integrator, with our parameters (h, W(dp) of the artificial stress, eps = 0.3, n = 4, XSPH
eps = 0.5, Monaghan's alpha = beta = 1, K = rho0 c0^2 through E and nu, our time step). Writes the tip trace
(t, y_tip every sample_dt, as our plate runs sample it) to --trace and stops at the tip's stop_after_crossings-th
zero crossing, counted as scenes::run_plate counts them, or at t_end.

The clamp, two ways (--clamp):
  ours     (default) the held particles are in the elastic body: their density and stress evolve, they do not
           move (an equation after the scheme's sets their accelerations and XSPH velocity to zero), as in
           our GraySolver (Motion::Fixed).
  walls    PySPH's own oscillating_plate.py: the held particles are a separate 'solids' array, sigma = 0 and
           rho = rho0 throughout.
The velocity of continuity (3.8) and of the velocity gradient (3.10), two ways (--continuity):
  v        (default) PySPH's own: the particle velocity v.
  xsph     ours, Gray 2001 (3.6) ("differentiate the XSPH velocity"): vhat = v + eps sum m_b v_ba W_ab / rho_ab,
           summed first (XSPHVelocity, a group before the velocity gradient), then continuity and the velocity
           gradient of vhat (ContinuityXSPH, VelocityGradient2DXSPH): with it the peer runs our equations.
What stays PySPH's and differs from ours: its integrator is EPEC (two force evaluations a step), ours the
predictor-corrector of src/core/predictor_corrector.hpp; its kernel and pair sums are its own code.
"""
import os
import sys
import time

import numpy as np

from pysph.base.kernels import CubicSpline
from pysph.solver.application import Application
from pysph.sph.equation import Equation, Group
from pysph.sph.solid_mech.basic import ElasticSolidsScheme, get_particle_array_elastic_dynamics

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402


class HeldParticles(Equation):
    """The clamp of our GraySolver (Motion::Fixed): a held particle neither accelerates nor moves."""

    def post_loop(self, d_idx, d_fixed, d_au, d_av, d_aw, d_ax, d_ay, d_az):
        if d_fixed[d_idx] > 0.5:
            d_au[d_idx] = 0.0
            d_av[d_idx] = 0.0
            d_aw[d_idx] = 0.0
            d_ax[d_idx] = 0.0
            d_ay[d_idx] = 0.0
            d_az[d_idx] = 0.0


class XSPHVelocity(Equation):
    """Gray 2001 (3.6): vhat_a = v_a + eps sum_b m_b (v_b - v_a) W_ab / rho_ab, rho_ab = (rho_a + rho_b) / 2."""

    def __init__(self, dest, sources, eps):
        self.eps = eps
        super().__init__(dest, sources)

    def initialize(self, d_idx, d_vhx, d_vhy):
        d_vhx[d_idx] = 0.0
        d_vhy[d_idx] = 0.0

    def loop(self, d_idx, s_idx, s_m, d_vhx, d_vhy, WIJ, RHOIJ1, VIJ):
        tmp = -self.eps * s_m[s_idx] * WIJ * RHOIJ1
        d_vhx[d_idx] += tmp * VIJ[0]
        d_vhy[d_idx] += tmp * VIJ[1]

    def post_loop(self, d_idx, d_vhx, d_vhy, d_u, d_v):
        d_vhx[d_idx] += d_u[d_idx]
        d_vhy[d_idx] += d_v[d_idx]


class VelocityGradient2DXSPH(Equation):
    """(3.10) of the XSPH velocity: d vhat^i / d x^j = sum_b (m_b / rho_b) (vhat_b - vhat_a)^i d_j W_ab."""

    def initialize(self, d_idx, d_v00, d_v01, d_v10, d_v11):
        d_v00[d_idx] = 0.0
        d_v01[d_idx] = 0.0
        d_v10[d_idx] = 0.0
        d_v11[d_idx] = 0.0

    def loop(self, d_idx, s_idx, s_m, s_rho, d_vhx, d_vhy, s_vhx, s_vhy, d_v00, d_v01, d_v10, d_v11, DWIJ):
        tmp = s_m[s_idx] / s_rho[s_idx]
        dx = s_vhx[s_idx] - d_vhx[d_idx]
        dy = s_vhy[s_idx] - d_vhy[d_idx]
        d_v00[d_idx] += tmp * dx * DWIJ[0]
        d_v01[d_idx] += tmp * dx * DWIJ[1]
        d_v10[d_idx] += tmp * dy * DWIJ[0]
        d_v11[d_idx] += tmp * dy * DWIJ[1]


class ContinuityXSPH(Equation):
    """(3.8) of the XSPH velocity: d rho_a / dt = sum_b m_b (vhat_a - vhat_b) . grad_a W_ab."""

    def initialize(self, d_idx, d_arho):
        d_arho[d_idx] = 0.0

    def loop(self, d_idx, s_idx, s_m, d_vhx, d_vhy, s_vhx, s_vhy, d_arho, DWIJ):
        d_arho[d_idx] += s_m[s_idx] * ((d_vhx[d_idx] - s_vhx[s_idx]) * DWIJ[0] + (d_vhy[d_idx] - s_vhy[s_idx]) * DWIJ[1])


class HeldScheme(ElasticSolidsScheme):
    """ElasticSolidsScheme's equations with HeldParticles last in its second group; with continuity = "xsph" the
    XSPH velocity is summed in a group of its own first, and continuity and the velocity gradient take it."""

    continuity = "v"

    def get_equations(self):
        eqs = super().get_equations()
        eqs[-1].equations.append(HeldParticles(dest="plate", sources=None))
        if self.continuity == "xsph":
            sources = self.solids + self.elastic_solids
            swap = {"VelocityGradient2D": VelocityGradient2DXSPH, "ContinuityEquation": ContinuityXSPH}
            for g in eqs:
                g.equations = [swap[type(e).__name__](dest=e.dest, sources=e.sources) if type(e).__name__ in swap else e
                               for e in g.equations]
            eqs.insert(0, Group(equations=[XSPHVelocity(dest=d, sources=sources, eps=self.xsph_eps)
                                           for d in self.elastic_solids]))
        return eqs


class PeerPlate(Application):
    def add_user_options(self, group):
        group.add_argument("--layout", required=True, help="folder with our layout.csv and settings.csv")
        group.add_argument("--trace", required=True, help="the tip trace to write (t,y_tip)")
        group.add_argument("--clamp", choices=["ours", "walls"], default="ours")
        group.add_argument("--continuity", choices=["v", "xsph"], default="v",
                           help="the velocity of continuity and the velocity gradient: PySPH's v or our XSPH velocity")

    def consume_user_options(self):
        o = self.options
        self.settings = peer_io.settings(o.layout)
        self.layout = peer_io.read_table(os.path.join(o.layout, "layout.csv"))
        self.clamp = o.clamp
        self.continuity = o.continuity
        self.trace_path = o.trace

    def create_particles(self):
        s = self.settings
        col = lambda name: np.array([float(r[name]) for r in self.layout])
        x, y, u, v, m, rho, fixed, tip = (col(c) for c in ("x", "y", "u", "v", "m", "rho", "fixed", "tip"))
        consts = dict(wdeltap=s["W_dp"], n=int(s["n_artificial"]), rho_ref=s["rho0"], E=s["E"], nu=s["nu"])
        keep = fixed < 0.5 if self.clamp == "walls" else np.ones_like(x, dtype=bool)
        plate = get_particle_array_elastic_dynamics(
            name="plate", x=x[keep], y=y[keep], u=u[keep], v=v[keep], m=m[keep], rho=rho[keep],
            h=np.full(keep.sum(), s["h"]), constants=consts)
        plate.add_property("fixed")
        plate.fixed[:] = fixed[keep]
        for name in ("vhx", "vhy"):
            plate.add_property(name)
        self.tip = int(np.flatnonzero(tip[keep] > 0.5)[0])
        self.y0 = plate.y[self.tip]
        arrays = [plate]
        if self.clamp == "walls":
            w = ~keep
            wall = get_particle_array_elastic_dynamics(
                name="wall", x=x[w], y=y[w], m=m[w], rho=rho[w], h=np.full(w.sum(), s["h"]),
                constants=dict(E=s["E"], nu=s["nu"], rho_ref=s["rho0"]))
            for name in ("vhx", "vhy"):
                wall.add_property(name)  # zero: the walls do not move
            arrays.append(wall)
        if abs(plate.c0_ref[0] - s["c0"]) > 1e-12 * s["c0"]:
            sys.exit(f"pysph_plate: PySPH's sound speed {plate.c0_ref[0]} from E, nu is not our c0 {s['c0']}")
        return arrays

    def create_scheme(self):
        return HeldScheme(elastic_solids=["plate"], solids=[], dim=2)

    def configure_scheme(self):
        self.scheme.continuity = self.continuity
        self._configure()

    def _configure(self):
        s = self.settings
        # With --clamp walls no particle of the plate array is held: HeldParticles then changes nothing.
        self.scheme.configure(solids=["wall"] if self.clamp == "walls" else [], artificial_stress_eps=s["eps_artificial"],
                              xsph_eps=s["eps_xsph"], alpha=s["alpha"], beta=s["beta"])
        self.scheme.configure_solver(kernel=CubicSpline(dim=2), dt=s["dt"], tf=s["t_end"], pfreq=1 << 30,
                                     adaptive_timestep=False)

    def pre_step(self, solver):
        if not hasattr(self, "samples"):
            self.samples, self.next_sample, self.crossings, self.t_start = [], 0.0, 0, time.time()
            self.sample(solver)

    def sample(self, solver):
        plate = self.particles[0]
        self.samples.append((solver.t, plate.y[self.tip] - self.y0))
        self.next_sample += self.settings["sample_dt"]

    def post_step(self, solver):
        # Our sph::Cadence: a sample when t has reached the next multiple of sample_dt (to round-off).
        if solver.t < self.next_sample - 1e-12:
            return
        self.sample(solver)
        k = len(self.samples)
        if k > 2 and (self.samples[-1][1] > 0) != (self.samples[-2][1] > 0):
            self.crossings += 1
        if self.crossings >= self.settings["stop_after_crossings"]:
            solver.set_final_time(solver.t)

    def write_trace(self, steps):
        wall = time.time() - self.t_start
        with open(self.trace_path, "w") as f:
            peer_io.write_header(f, {"peer": "pysph", "clamp": self.clamp, "continuity": self.continuity, "steps": steps,
                                     "wall_s": f"{wall:.6g}",
                                     "particles": sum(pa.get_number_of_particles() for pa in self.particles)})
            f.write("t,y_tip\n")
            for t, y in self.samples:
                f.write(f"{t!r},{y!r}\n")


if __name__ == "__main__":
    app = PeerPlate()
    app.run()
    app.write_trace(app.solver.count)
