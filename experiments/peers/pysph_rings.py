#!/usr/bin/env python3
"""Gray, Monaghan & Swift 2001's colliding rubber rings (Sec 7.2, Figs 6-7) in PySPH (Debian python3-pysph), from our
particles.

Reads the rings we build (build/bin/peer_rings --action layout: layout.csv, settings.csv) and runs them with PySPH's
own implementation of the same paper, pysph.sph.solid_mech.basic.ElasticSolidsScheme (as PySPH's own
examples/solid_mech/rings.py does, both rings one particle array): its equations, its cubic spline, its EPEC
integrator, with our parameters (h, W(dp) of the artificial stress, eps = 0 or 0.3, n = 4, XSPH eps = 0.5, Monaghan's
alpha = beta = 1, K = rho0 c0^2 through E and nu) and our time step, fixed. Writes the frames of every particle
(experiments/peers/frames_reader.hpp: t,id,x,y,u,v, id = our layout's row) every sample_dt by our sph::Cadence rule
(the first step's state and then whenever t has reached the next multiple of sample_dt, as pysph_plate.py samples),
for build/bin/peer_rings --action measure.
The run stops as scenes::run_rings does: run_after_contact after the rings have separated (run_after_contact < 0:
never), or at t_max. Contact for the stop is tested here on any pair of the two rings closer than the kernel support
2h, which is in contact whenever our measurement (the rings' main pieces only) is, so the run never stops before
run_rings would; peer_rings --action measure cuts the frames at run_rings's own stop.
The velocity of continuity (3.8) and of the velocity gradient (3.10), two ways (--continuity):
  v        (default) PySPH's own: the particle velocity v.
  xsph     ours, Gray 2001 (3.6): the XSPH velocity (experiments/peers/pysph_gray.py): PySPH then runs our equations.
What stays PySPH's and differs from ours: its integrator is EPEC (two force evaluations a step), ours the
predictor-corrector of src/core/predictor_corrector.hpp; its kernel and pair sums are its own code.
"""
import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

from pysph.base.kernels import CubicSpline
from pysph.solver.application import Application
from pysph.sph.solid_mech.basic import get_particle_array_elastic_dynamics

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402
from pysph_gray import HeldScheme, add_xsph_properties  # noqa: E402


class PeerRings(Application):
    def add_user_options(self, group):
        group.add_argument("--layout", required=True, help="folder with our layout.csv and settings.csv")
        group.add_argument("--frames", required=True, help="the frames file to write (t,id,x,y,u,v)")
        group.add_argument("--continuity", choices=["v", "xsph"], default="v",
                           help="the velocity of continuity and the velocity gradient: PySPH's v or our XSPH velocity")

    def consume_user_options(self):
        o = self.options
        self.settings = peer_io.settings(o.layout)
        self.layout = peer_io.read_table(os.path.join(o.layout, "layout.csv"))
        self.continuity = o.continuity
        self.frames_path = o.frames
        need = ("h", "W_dp", "n_artificial", "rho0", "c0", "E", "nu", "eps_artificial", "eps_xsph", "alpha", "beta", "dt",
                "t_max", "sample_dt", "run_after_contact", "support", "particles")
        missing = [k for k in need if k not in self.settings]
        if missing:
            sys.exit(f"pysph_rings: {o.layout}/settings.csv lacks {', '.join(missing)}")
        if len(self.layout) != int(self.settings["particles"]):
            sys.exit(f"pysph_rings: layout.csv has {len(self.layout)} particles, settings.csv says {self.settings['particles']:g}")

    def create_particles(self):
        s = self.settings
        col = lambda name: np.array([float(r[name]) for r in self.layout])
        x, y, u, v, m, rho, ring = (col(c) for c in ("x", "y", "u", "v", "m", "rho", "ring"))
        consts = dict(wdeltap=s["W_dp"], n=int(s["n_artificial"]), rho_ref=s["rho0"], E=s["E"], nu=s["nu"])
        pa = get_particle_array_elastic_dynamics(name="rings", x=x, y=y, u=u, v=v, m=m, rho=rho,
                                                 h=np.full(x.size, s["h"]), constants=consts)
        add_xsph_properties(pa)
        pa.add_property("layout_id", type="int")  # our layout's row, carried with the particle
        pa.layout_id[:] = np.arange(x.size)
        pa.add_property("ring", type="int")
        pa.ring[:] = ring.astype(int)
        if abs(pa.c0_ref[0] - s["c0"]) > 1e-12 * s["c0"]:
            sys.exit(f"pysph_rings: PySPH's sound speed {pa.c0_ref[0]} from E, nu is not our c0 {s['c0']}")
        return [pa]

    def create_scheme(self):
        return HeldScheme(elastic_solids=["rings"], solids=[], dim=2)

    def configure_scheme(self):
        s = self.settings
        self.scheme.continuity = self.continuity
        self.scheme.configure(artificial_stress_eps=s["eps_artificial"], xsph_eps=s["eps_xsph"], alpha=s["alpha"],
                              beta=s["beta"])
        self.scheme.configure_solver(kernel=CubicSpline(dim=2), dt=s["dt"], tf=s["t_max"], pfreq=1 << 30,
                                     adaptive_timestep=False)

    def in_contact(self):
        """Some pair of particles of the two rings closer than the kernel support (the stop's test; see above)."""
        pa = self.particles[0]
        left = pa.ring == 0
        pts = np.column_stack([pa.x, pa.y])
        d, _ = cKDTree(pts[~left]).query(pts[left], k=1, distance_upper_bound=self.settings["support"])
        return bool(np.any(d < self.settings["support"]))

    def pre_step(self, solver):
        if not hasattr(self, "writer"):
            self.t_start, self.next_sample = time.time(), 0.0
            self.contact_start = self.contact_end = -1.0
            self.frame_count = 0
            self.writer = peer_io.FrameWriter(self.frames_path, [], {
                "peer": "pysph", "code_version": self.version(), "continuity": self.continuity,
                "eps": self.settings["eps_artificial"], "dt": repr(self.settings["dt"])})
            self.sample(solver.t)

    @staticmethod
    def version():
        import pysph
        return pysph.__version__

    def sample(self, t):
        pa = self.particles[0]
        self.writer.ids = [int(i) for i in pa.layout_id]
        self.writer.frame(t, pa.x, pa.y, pa.u, pa.v)
        self.frame_count += 1
        self.next_sample += self.settings["sample_dt"]
        contact = self.in_contact()
        if contact and self.contact_start < 0:
            self.contact_start = t
        if not contact and self.contact_start >= 0 and self.contact_end < 0:
            self.contact_end = t

    def post_step(self, solver):
        # PySPH calls this after the integrator's step and before it adds dt to solver.t: the particles are at
        # t = solver.t + solver.dt (the sum our solver forms, t += dt). Our sph::Cadence: a sample when t has reached
        # the next multiple of sample_dt (to round-off).
        t = solver.t + solver.dt
        if t < self.next_sample - 1e-12:
            return
        self.sample(t)
        after = self.settings["run_after_contact"]
        if self.contact_end >= 0 and after >= 0 and t >= self.contact_end + after:
            solver.set_final_time(t)  # the loop ends once solver.t has become t

    def finish(self, steps):
        wall = time.time() - self.t_start
        self.writer.close()
        # The run's totals, for make peers' rows (the frames file's header is written before them).
        with open(self.frames_path + ".run", "w") as f:
            peer_io.write_header(f, {"peer": "pysph", "continuity": self.continuity, "steps": steps,
                                     "wall_s": f"{wall:.6g}", "particles": self.particles[0].get_number_of_particles(),
                                     "frames": self.frame_count, "t_last": repr(self.solver.t)})


if __name__ == "__main__":
    app = PeerRings()
    app.run()
    app.finish(app.solver.count)
