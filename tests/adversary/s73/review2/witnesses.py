# ruff: noqa
"""Stop 73, second review: failing claims of a claims file whose residual has several nonzero entries of very
different sizes (the witness names the largest, `_telling_entry`), for `stiefelsym check` and the witness scripts."""
from stiefelsym import admissible, claim, comm


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("rv2-prep-wrong-sign", paper="prep", kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: True, erratum="dΦ/dt = [A, XXᵀ] (the commutator reversed)")
def prep_wrong_sign(s):
    """False: dΦ/dt = [A, XXᵀ] along the Neumann flow (the true statement is [XXᵀ, A]; [XXᵀ, A] ≠ 0 for n ≥ 2, and
    at n = 1 both sides vanish)."""
    flow = s.dirac_flow(H)
    return {"prep": s.d(lambda t: t.Phi, flow) - comm(s.A, s.X @ s.X.T)}


@claim("rv2-mixed-sizes", paper="cond_XP", kind="id", sizes=admissible(n_max=4),
       fails_at=lambda n, r: True, erratum="XᵀX = (1 + 10⁻³⁰)I and XᵀP + PᵀX = PᵀP")
def mixed_sizes(s):
    """False: two residuals, one tiny (10⁻³⁰ I_r) and one large (PᵀP), and a true one (XᵀP + PᵀX)."""
    return {"tiny": s.X.T @ s.X - s.Ir * (1 + s.q(1, 10 ** 30)), "cond": s.X.T @ s.P + s.P.T @ s.X,
            "big": s.X.T @ s.P + s.P.T @ s.X - s.P.T @ s.P}
