#!/usr/bin/env python3
"""Gray, Monaghan & Swift 2001's slab under tension (Sec 7.3, Figs 8-10) in PySPH (Debian python3-pysph), from our particles.

Reads the scene we build (build/bin/peer_slab --action layout: layout.csv, settings.csv) and runs it with PySPH's own
implementation of the same paper, pysph.sph.solid_mech.basic.ElasticSolidsScheme (its equations, its cubic spline,
its EPEC integrator), with our parameters (h, W(dp), eps, n = 4, XSPH eps = 0.5, alpha = beta = 1, K = rho0 c0^2
through E and nu, our time step). Writes every particle every sample_dt (--frames, the format of
experiments/peers/frames_reader.hpp: peer_slab --action measure measures them with our functions) and stops as
scenes::run_slab does: at t_max, or run_after_fracture after the sample at which the two driven bands are first in
different pieces (links shorter than fracture_link dp; checked here only to know when to stop, the measurement
is ours). --info gets steps, wall time, particles and how the run ended.

The driven bands (layout column band = -1 / +1) move as our Motion::Driven (src/updated_lagrangian/elastic_body.hpp,
pair_terms.hpp): their acceleration is the prescribed band x end_accel along x whatever the forces, they move with
their own velocity (not the XSPH one), and their density and stress evolve like every other particle's (an equation
after the scheme's sets au, av and ax, ay). With EPEC's stages (x = x0 + dt/2 ax, then x = x0 + dt ax(t + dt/2))
a band's position is x0 + v0 t + a t^2 / 2 exactly, as ours.

Plasticity, two ways (--plasticity):
  pysph  PySPH's own: pysph.sph.solid_mech.hvi.VonMisesPlasticity2D(flow_stress = yield) in a group before the
         scheme's, as PySPH's examples (taylor_bar.py, impact.py) place it. Its surface is
         3/2 (s00^2 + 2 s01^2 + s11^2) = Y^2: the in-plane S:S only, without the s22 that its own stress rate carries
         (s22 = -(s00 + s11)); and it scales the stress of the evaluation only: the integrator saved the stress
         at the start of the step (SolidMechStep.initialize) and both stages add their increments to that saved,
         unreturned stress, so the stored stress is never returned (it grows as the elastic trial) and each
         evaluation sees the return of that trial.
  ours   src/core/materials.hpp von_mises_return as our GraySolver applies it: sqrt(3 J2) = Y with
         J2 = (sxx^2 + syy^2 + szz^2)/2 + sxy^2, szz = -(sxx + syy), the stored stress scaled after each stage (our
         solver: after the predictor and after the corrector), so the next stage and the next step start from it.
  Each of the two differences has a variant of its own, to tell their effects apart:
  pysph_stored  PySPH's surface (no s22), applied to the stored stress after each stage (as ours)
  ours_eval     our surface (with szz), applied as PySPH places it (the evaluation's copy only)
The velocity of continuity and of the velocity gradient (--continuity), as experiments/peers/pysph_plate.py:
  v      PySPH's own (the particle velocity);  xsph   ours, the XSPH velocity (3.6).
  The XSPH equations are imported from pysph_plate.py for now (the merge moves them to pysph_gray.py).
What stays PySPH's: EPEC (two evaluations a step; ours: the predictor-corrector of src/core/predictor_corrector.hpp),
its kernel and pair sums, its artificial stress code (3x3 eigen decomposition; ours closed-form 2x2).
"""
import os
import sys
import time
from math import sqrt  # noqa: F401  (VonMisesWithSzz: PySPH translates the equation's sqrt)

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from pysph.base.kernels import CubicSpline
from pysph.solver.application import Application
from pysph.sph.equation import Equation, Group
from pysph.sph.solid_mech.basic import ElasticSolidsScheme, get_particle_array_elastic_dynamics
from pysph.sph.solid_mech.hvi import VonMisesPlasticity2D

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402
from pysph_gray import XSPHVelocity, VelocityGradient2DXSPH, ContinuityXSPH  # noqa: E402

PLASTICITY = ["pysph", "ours", "pysph_stored", "ours_eval"]


class DrivenBands(Equation):
    """Our Motion::Driven: a band particle accelerates at its prescribed drive and moves with its own velocity."""

    def post_loop(self, d_idx, d_band, d_drive, d_u, d_v, d_au, d_av, d_aw, d_ax, d_ay, d_az):
        if d_band[d_idx] != 0.0:
            d_au[d_idx] = d_drive[d_idx]
            d_av[d_idx] = 0.0
            d_aw[d_idx] = 0.0
            d_ax[d_idx] = d_u[d_idx]
            d_ay[d_idx] = d_v[d_idx]
            d_az[d_idx] = 0.0


class VonMisesWithSzz(Equation):
    """Our return (materials.hpp von_mises_return) as a PySPH equation: sqrt(3 J2) = Y with szz = -(sxx + syy)."""

    def __init__(self, dest, sources, flow_stress):
        self.Y2 = float(flow_stress * flow_stress)
        self.Y = float(flow_stress)
        super().__init__(dest, sources)

    def loop(self, d_idx, d_s00, d_s01, d_s02, d_s11, d_s12, d_s22):
        sxx = d_s00[d_idx]
        syy = d_s11[d_idx]
        szz = -(sxx + syy)
        sxy = d_s01[d_idx]
        j3 = 3.0 * (0.5 * (sxx * sxx + syy * syy + szz * szz) + sxy * sxy)
        if j3 > self.Y2:
            scale = self.Y / sqrt(j3)
            d_s00[d_idx] = scale * d_s00[d_idx]
            d_s01[d_idx] = scale * d_s01[d_idx]
            d_s02[d_idx] = scale * d_s02[d_idx]
            d_s11[d_idx] = scale * d_s11[d_idx]
            d_s12[d_idx] = scale * d_s12[d_idx]
            d_s22[d_idx] = scale * d_s22[d_idx]


def stored_return(pa, Y, with_szz):
    """The radial return of the stored stress of array pa, in place (numpy on PySPH's own buffers)."""
    sxx, syy, sxy = pa.s00, pa.s11, pa.s01
    if with_szz:  # ours: materials.hpp plane_strain_J2, in its order of operations
        szz = -(sxx + syy)
        j3 = 3.0 * (0.5 * (sxx * sxx + syy * syy + szz * szz) + sxy * sxy)
    else:  # hvi.VonMisesPlasticity2D's J = s00^2 + 2 s01^2 + s11^2 against 2/3 Y^2, i.e. 3/2 J = Y^2
        j3 = 1.5 * (sxx * sxx + 2.0 * sxy * sxy + syy * syy)
    over = j3 > Y * Y
    if not over.any():
        return 0
    scale = Y / np.sqrt(j3[over])
    for name in ("s00", "s01", "s02", "s11", "s12", "s22"):
        arr = getattr(pa, name)
        arr[over] *= scale
    return int(over.sum())


class DrivenScheme(ElasticSolidsScheme):
    """ElasticSolidsScheme's equations with DrivenBands last in its second group; optionally the XSPH velocity of
    continuity and the velocity gradient (pysph_plate.py's equations) and a return inside the evaluation."""

    continuity = "v"
    plasticity = "pysph"
    yield_stress = 0.0

    def get_equations(self):
        eqs = super().get_equations()
        eqs[-1].equations.append(DrivenBands(dest="slab", sources=None))
        if self.continuity == "xsph":
            sources = self.solids + self.elastic_solids
            swap = {"VelocityGradient2D": VelocityGradient2DXSPH, "ContinuityEquation": ContinuityXSPH}
            for g in eqs:
                g.equations = [swap[type(e).__name__](dest=e.dest, sources=e.sources) if type(e).__name__ in swap else e
                               for e in g.equations]
            eqs.insert(0, Group(equations=[XSPHVelocity(dest=d, sources=sources, eps=self.xsph_eps)
                                           for d in self.elastic_solids]))
        # In the evaluation: a group of its own first, so the artificial stress and the stress rate see the return.
        if self.plasticity == "pysph":
            eqs.insert(0, Group(equations=[VonMisesPlasticity2D(dest="slab", sources=None, flow_stress=self.yield_stress)]))
        elif self.plasticity == "ours_eval":
            eqs.insert(0, Group(equations=[VonMisesWithSzz(dest="slab", sources=None, flow_stress=self.yield_stress)]))
        return eqs


class PeerSlab(Application):
    def add_user_options(self, group):
        group.add_argument("--layout", required=True, help="folder with our layout.csv and settings.csv")
        group.add_argument("--frames", required=True, help="the frames file to write (t,id,x,y,u,v)")
        group.add_argument("--info", required=True, help="the run's facts to write (name,value)")
        group.add_argument("--plasticity", choices=PLASTICITY, default="pysph")
        group.add_argument("--continuity", choices=["v", "xsph"], default="v",
                           help="the velocity of continuity and the velocity gradient: PySPH's v or our XSPH velocity")

    def consume_user_options(self):
        o = self.options
        self.settings = peer_io.settings(o.layout)
        self.layout = peer_io.read_table(os.path.join(o.layout, "layout.csv"))
        self.plasticity, self.continuity = o.plasticity, o.continuity
        self.frames_path, self.info_path = o.frames, o.info
        s = self.settings
        for k in ("h", "W_dp", "rho0", "c0", "E", "nu", "yield_stress", "eps_artificial", "n_artificial", "eps_xsph",
                  "alpha", "beta", "end_accel", "dt", "t_max", "sample_dt", "run_after_fracture", "fracture_link", "dp"):
            if k not in s:
                sys.exit(f"pysph_slab: settings.csv has no '{k}'")
        if not s["yield_stress"] > 0:
            sys.exit("pysph_slab: the slab needs a yield stress > 0")

    def create_particles(self):
        s = self.settings
        col = lambda name: np.array([float(r[name]) for r in self.layout])
        x, y, u, v, m, rho, band = (col(c) for c in ("x", "y", "u", "v", "m", "rho", "band"))
        if not np.all(np.isin(band, (-1.0, 0.0, 1.0))):
            sys.exit("pysph_slab: layout band must be -1, 0 or +1")
        # eps = 0 (standard SPH): wdeltap < 0 is PySPH's switch that leaves the R_ab f^n term out (R would be 0).
        wdeltap = s["W_dp"] if s["eps_artificial"] > 0 else -1.0
        consts = dict(wdeltap=wdeltap, n=int(s["n_artificial"]), rho_ref=s["rho0"], E=s["E"], nu=s["nu"])
        slab = get_particle_array_elastic_dynamics(name="slab", x=x, y=y, u=u, v=v, m=m, rho=rho,
                                                   h=np.full(x.size, s["h"]), constants=consts)
        for name in ("band", "drive", "lid", "vhx", "vhy"):
            slab.add_property(name)
        slab.band[:] = band
        slab.drive[:] = band * s["end_accel"]
        slab.lid[:] = np.arange(x.size)  # our layout's row: PySPH keeps the order, the frames do not rely on it
        if abs(slab.c0_ref[0] - s["c0"]) > 1e-12 * s["c0"]:
            sys.exit(f"pysph_slab: PySPH's sound speed {slab.c0_ref[0]} from E, nu is not our c0 {s['c0']}")
        if abs(slab.G[0] - s["mu"]) > 1e-12 * s["mu"]:
            sys.exit(f"pysph_slab: PySPH's shear modulus {slab.G[0]} from E, nu is not our mu {s['mu']}")
        self.left0 = int(np.flatnonzero(band < 0)[0])   # scenes::run_slab: left_band.front(), right_band.front()
        self.right0 = int(np.flatnonzero(band > 0)[0])
        return [slab]

    def create_scheme(self):
        return DrivenScheme(elastic_solids=["slab"], solids=[], dim=2)

    def configure_scheme(self):
        s = self.settings
        self.scheme.continuity = self.continuity
        self.scheme.plasticity = self.plasticity
        self.scheme.yield_stress = s["yield_stress"]
        self.scheme.configure(artificial_stress_eps=s["eps_artificial"], xsph_eps=s["eps_xsph"], alpha=s["alpha"],
                              beta=s["beta"])
        self.scheme.configure_solver(kernel=CubicSpline(dim=2), dt=s["dt"], tf=s["t_max"], pfreq=1 << 30,
                                     adaptive_timestep=False)

    # ---------------------------------------------------------------- the return on the stored stress
    def post_stage(self, current_time, dt, stage):
        if self.plasticity in ("ours", "pysph_stored"):
            stored_return(self.particles[0], self.settings["yield_stress"], self.plasticity == "ours")

    # ---------------------------------------------------------------- samples, frames, stop
    def start(self):
        pa = self.particles[0]
        meta = {"peer": "pysph", "plasticity": self.plasticity, "continuity": self.continuity,
                "particles": pa.get_number_of_particles(), "dt": repr(self.settings["dt"])}
        self.writer = peer_io.FrameWriter(self.frames_path, pa.lid.astype(int), meta)
        self.next_sample, self.fracture_time, self.blow_up, self.t_start = 0.0, None, "", time.time()

    def pre_step(self, solver):
        if not hasattr(self, "writer"):
            self.start()
            self.sample(solver, solver.t)  # t = 0, as run_slab samples before the first step

    def post_step(self, solver):
        # PySPH calls post_step before it adds dt to solver.t: the state is at solver.t + solver.dt (the same sum).
        t = solver.t + solver.dt
        if t < self.next_sample - 1e-12:  # our sph::Cadence
            return
        self.sample(solver, t)
        s = self.settings
        stop = bool(self.blow_up)
        if self.fracture_time is not None and s["run_after_fracture"] >= 0 and t >= self.fracture_time + s["run_after_fracture"]:
            stop = True
        if stop:
            solver.set_final_time(t)

    def sample(self, solver, t):
        pa = self.particles[0]
        s = self.settings
        x, y, u, v, rho = pa.x, pa.y, pa.u, pa.v, pa.rho
        # Our GraySolver's check_state (blow_up): non-finite, rho < 0.05 rho0 or |v| > 100 c0; the frame is not written.
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y)) and np.all(np.isfinite(u)) and np.all(np.isfinite(v))
                and np.all(np.isfinite(rho)) and np.all(np.isfinite(pa.s00))):
            self.blow_up = f"non-finite state at t = {t}"
        elif rho.min() < 0.05 * s["rho0"] or (u * u + v * v).max() > (100 * s["c0"]) ** 2:
            self.blow_up = f"rho or |v| out of range at t = {t}"
        if self.blow_up:
            return
        self.writer.frame(t, x, y, u, v)
        self.next_sample += s["sample_dt"]
        if self.fracture_time is None and self.parted(x, y):
            self.fracture_time = t

    def parted(self, x, y):
        """scenes::run_slab's fracture: the two bands' first particles in different pieces, linked below fracture_link dp."""
        link = np.nextafter(self.settings["fracture_link"] * self.settings["dp"], 0.0)  # ours: r < link
        pairs = cKDTree(np.column_stack([x, y])).query_pairs(link, output_type="ndarray")
        n = x.size
        g = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n)) if len(pairs) else coo_matrix((n, n))
        _, label = connected_components(g, directed=False)
        return label[self.left0] != label[self.right0]

    def finish(self, steps):
        self.writer.close()
        wall = time.time() - self.t_start
        pa = self.particles[0]
        sxx, syy, sxy = pa.s00, pa.s11, pa.s01
        szz = -(sxx + syy)
        vm = np.sqrt(3.0 * (0.5 * (sxx * sxx + syy * syy + szz * szz) + sxy * sxy))
        rows = {"peer": "pysph", "plasticity": self.plasticity, "continuity": self.continuity,
                "particles": pa.get_number_of_particles(), "steps": steps, "wall_s": f"{wall:.6g}",
                "t_end": repr(self.solver.t), "fracture_time_peer_check": -1 if self.fracture_time is None else self.fracture_time,
                "blow_up": self.blow_up or "none",
                # The stored stress at the end, on our surface: above the yield where the return never reaches it.
                "max_stored_von_mises_over_yield": f"{vm.max() / self.settings['yield_stress']:.6g}"}
        with open(self.info_path, "w") as f:
            f.write("name,value\n")
            for k, val in rows.items():
                f.write(f"{k},{val}\n")


if __name__ == "__main__":
    app = PeerSlab()
    app.run()
    app.finish(app.solver.count)
