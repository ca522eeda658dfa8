"""The equations the peers' PySPH scripts add to PySPH's ElasticSolidsScheme (Gray, Monaghan & Swift 2001), shared
by experiments/peers/pysph_plate.py and pysph_rings.py (issue 44):

  HeldParticles            the clamp of our GraySolver (Motion::Fixed): a held particle neither accelerates nor moves
  XSPHVelocity             Gray 2001 (3.6): the XSPH velocity vhat, summed in a group before the rates
  VelocityGradient2DXSPH   (3.10) of vhat, in place of PySPH's VelocityGradient2D (of v)
  ContinuityXSPH           (3.8) of vhat, in place of PySPH's ContinuityEquation (of v)
  HeldScheme               ElasticSolidsScheme with HeldParticles for the arrays in `held`, and with continuity =
                           "xsph" the three above in place of PySPH's: then PySPH runs our equations (Gray 2001
                           "differentiate the XSPH velocity"), and only the integrator (EPEC) and the code differ
  GrayPCStep,              Gray 2001's predictor-corrector (6.14)-(6.18) in place of EPEC (integrator = "gray"):
  GrayPCIntegrator         with continuity = "xsph" PySPH then runs our equations and our integrator, and only the
                           code differs (its kernel, neighbour search and sums, in their order)
"""
from pysph.sph.equation import Equation, Group
from pysph.sph.integrator import Integrator
from pysph.sph.integrator_step import IntegratorStep
from pysph.sph.solid_mech.basic import ElasticSolidsScheme

# The rates at the start of a step, kept by GrayPCStep's predictor for its corrector.
GRAY_PC_PROPERTIES = ("au_0", "av_0", "arho_0", "as00_0", "as01_0", "as11_0")


def add_xsph_properties(pa):
    """The properties XSPHVelocity writes and the XSPH continuity reads (zero on an array that does not move)."""
    for name in ("vhx", "vhy"):
        pa.add_property(name)


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
    """ElasticSolidsScheme's equations with HeldParticles last in its second group for every array named in `held`
    (each needs a property 'fixed'); with continuity = "xsph" the XSPH velocity is summed in a group of its own
    first, and continuity and the velocity gradient take it (every elastic and solid array needs properties vhx,
    vhy: add_xsph_properties)."""

    continuity = "v"
    held = []

    def get_equations(self):
        eqs = super().get_equations()
        for name in self.held:
            eqs[-1].equations.append(HeldParticles(dest=name, sources=None))
        if self.continuity == "xsph":
            sources = self.solids + self.elastic_solids
            swap = {"VelocityGradient2D": VelocityGradient2DXSPH, "ContinuityEquation": ContinuityXSPH}
            for g in eqs:
                g.equations = [swap[type(e).__name__](dest=e.dest, sources=e.sources) if type(e).__name__ in swap else e
                               for e in g.equations]
            eqs.insert(0, Group(equations=[XSPHVelocity(dest=d, sources=sources, eps=self.xsph_eps)
                                           for d in self.elastic_solids]))
        return eqs


def add_gray_pc_properties(pa):
    """The start-of-step rates GrayPCStep keeps (one per integrated field)."""
    for name in GRAY_PC_PROPERTIES:
        pa.add_property(name)


class GrayPCStep(IntegratorStep):
    """Gray, Monaghan & Swift 2001 (6.14)-(6.18), as src/core/predictor_corrector.hpp runs it (2D): the predictor
    moves the particles with the XSPH velocity (d_ax, d_ay: XSPHCorrection's, zero for a held particle) and the
    acceleration at the start of the step, and its positions are final (6.15); the corrector corrects velocity,
    density and stress by half a step times the change of their rates (6.17)-(6.18)."""

    def stage1(self, d_idx, d_x, d_y, d_u, d_v, d_rho, d_s00, d_s01, d_s11, d_ax, d_ay, d_au, d_av, d_arho,
               d_as00, d_as01, d_as11, d_au_0, d_av_0, d_arho_0, d_as00_0, d_as01_0, d_as11_0, dt):
        d_au_0[d_idx] = d_au[d_idx]
        d_av_0[d_idx] = d_av[d_idx]
        d_arho_0[d_idx] = d_arho[d_idx]
        d_as00_0[d_idx] = d_as00[d_idx]
        d_as01_0[d_idx] = d_as01[d_idx]
        d_as11_0[d_idx] = d_as11[d_idx]
        half_dt2 = 0.5 * dt * dt
        d_x[d_idx] += dt * d_ax[d_idx] + half_dt2 * d_au[d_idx]
        d_y[d_idx] += dt * d_ay[d_idx] + half_dt2 * d_av[d_idx]
        d_u[d_idx] += dt * d_au[d_idx]
        d_v[d_idx] += dt * d_av[d_idx]
        d_rho[d_idx] += dt * d_arho[d_idx]
        d_s00[d_idx] += dt * d_as00[d_idx]
        d_s01[d_idx] += dt * d_as01[d_idx]
        d_s11[d_idx] += dt * d_as11[d_idx]

    def stage2(self, d_idx, d_u, d_v, d_rho, d_s00, d_s01, d_s11, d_au, d_av, d_arho, d_as00, d_as01, d_as11,
               d_au_0, d_av_0, d_arho_0, d_as00_0, d_as01_0, d_as11_0, dt):
        half_dt = 0.5 * dt
        d_u[d_idx] += half_dt * (d_au[d_idx] - d_au_0[d_idx])
        d_v[d_idx] += half_dt * (d_av[d_idx] - d_av_0[d_idx])
        d_rho[d_idx] += half_dt * (d_arho[d_idx] - d_arho_0[d_idx])
        d_s00[d_idx] += half_dt * (d_as00[d_idx] - d_as00_0[d_idx])
        d_s01[d_idx] += half_dt * (d_as01[d_idx] - d_as01_0[d_idx])
        d_s11[d_idx] += half_dt * (d_as11[d_idx] - d_as11_0[d_idx])


class GrayPCIntegrator(Integrator):
    """Evaluate, predict (6.14)-(6.16), evaluate at the predicted state, correct (6.17)-(6.18): two evaluations a
    step, as ours (the first at the corrected state of the step before)."""

    def one_timestep(self, t, dt):
        self.compute_accelerations()
        self.stage1()
        self.update_domain()
        self.do_post_stage(dt, 1)
        self.compute_accelerations()
        self.stage2()
        self.update_domain()
        self.do_post_stage(dt, 2)
