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
The integrator, two ways (--integrator):
  epec     (default) PySPH's own, EPEC (two force evaluations a step).
  gray     ours, Gray 2001 (6.14)-(6.18) (pysph_gray.GrayPCStep): with --continuity xsph only the code differs.
What stays PySPH's in every variant: its kernel, neighbour search and pair sums are its own code.
"""
import os
import sys
import time

import numpy as np

from pysph.base.kernels import CubicSpline
from pysph.solver.application import Application
from pysph.sph.solid_mech.basic import get_particle_array_elastic_dynamics

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402
from pysph_gray import GrayPCIntegrator, GrayPCStep, HeldScheme, add_gray_pc_properties, add_xsph_properties  # noqa: E402


class PeerPlate(Application):
    def add_user_options(self, group):
        group.add_argument("--layout", required=True, help="folder with our layout.csv and settings.csv")
        group.add_argument("--trace", required=True, help="the tip trace to write (t,y_tip)")
        group.add_argument("--clamp", choices=["ours", "walls"], default="ours")
        group.add_argument("--continuity", choices=["v", "xsph"], default="v",
                           help="the velocity of continuity and the velocity gradient: PySPH's v or our XSPH velocity")
        group.add_argument("--integrator", choices=["epec", "gray"], default="epec",
                           help="PySPH's EPEC or Gray 2001's predictor-corrector (6.14)-(6.18), as ours")

    def consume_user_options(self):
        o = self.options
        self.settings = peer_io.settings(o.layout)
        self.layout = peer_io.read_table(os.path.join(o.layout, "layout.csv"))
        self.clamp = o.clamp
        self.continuity = o.continuity
        self.integrator = o.integrator
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
        add_xsph_properties(plate)
        add_gray_pc_properties(plate)
        self.tip = int(np.flatnonzero(tip[keep] > 0.5)[0])
        self.y0 = plate.y[self.tip]
        arrays = [plate]
        if self.clamp == "walls":
            w = ~keep
            wall = get_particle_array_elastic_dynamics(
                name="wall", x=x[w], y=y[w], m=m[w], rho=rho[w], h=np.full(w.sum(), s["h"]),
                constants=dict(E=s["E"], nu=s["nu"], rho_ref=s["rho0"]))
            add_xsph_properties(wall)  # zero: the walls do not move
            arrays.append(wall)
        if abs(plate.c0_ref[0] - s["c0"]) > 1e-12 * s["c0"]:
            sys.exit(f"pysph_plate: PySPH's sound speed {plate.c0_ref[0]} from E, nu is not our c0 {s['c0']}")
        return arrays

    def create_scheme(self):
        scheme = HeldScheme(elastic_solids=["plate"], solids=[], dim=2)
        scheme.held = ["plate"]
        return scheme

    def configure_scheme(self):
        self.scheme.continuity = self.continuity
        self._configure()

    def _configure(self):
        s = self.settings
        # With --clamp walls no particle of the plate array is held: HeldParticles then changes nothing.
        self.scheme.configure(solids=["wall"] if self.clamp == "walls" else [], artificial_stress_eps=s["eps_artificial"],
                              xsph_eps=s["eps_xsph"], alpha=s["alpha"], beta=s["beta"])
        gray = dict(integrator_cls=GrayPCIntegrator, extra_steppers={"plate": GrayPCStep()}) if self.integrator == "gray" else {}
        self.scheme.configure_solver(kernel=CubicSpline(dim=2), dt=s["dt"], tf=s["t_end"], pfreq=1 << 30,
                                     adaptive_timestep=False, **gray)

    def pre_step(self, solver):
        if not hasattr(self, "samples"):
            self.samples, self.next_sample, self.crossings, self.t_start = [], 0.0, 0, time.time()
            self.sample(solver.t)

    def sample(self, t):
        plate = self.particles[0]
        self.samples.append((t, plate.y[self.tip] - self.y0))
        self.next_sample += self.settings["sample_dt"]

    def post_step(self, solver):
        # PySPH calls post_step after the step and before it adds dt to solver.t (pysph/solver/solver.py, solve):
        # the particles are at t = solver.t + solver.dt, the sum our solver forms (t += dt). Labelled solver.t,
        # every sample was one step early and T = 2 t_1 2 dt short (1.4-1.8e-4 of T at n = 10, found on the rings).
        t = solver.t + solver.dt
        # Our sph::Cadence: a sample when t has reached the next multiple of sample_dt (to round-off).
        if t < self.next_sample - 1e-12:
            return
        self.sample(t)
        k = len(self.samples)
        if k > 2 and (self.samples[-1][1] > 0) != (self.samples[-2][1] > 0):
            self.crossings += 1
        if self.crossings >= self.settings["stop_after_crossings"]:
            solver.set_final_time(t)

    def write_trace(self, steps):
        wall = time.time() - self.t_start
        with open(self.trace_path, "w") as f:
            peer_io.write_header(f, {"peer": "pysph", "clamp": self.clamp, "continuity": self.continuity,
                                     "integrator": self.integrator, "steps": steps,
                                     "wall_s": f"{wall:.6g}",
                                     "particles": sum(pa.get_number_of_particles() for pa in self.particles)})
            f.write("t,y_tip\n")
            for t, y in self.samples:
                f.write(f"{t!r},{y!r}\n")


if __name__ == "__main__":
    app = PeerPlate()
    app.run()
    app.write_trace(app.solver.count)
