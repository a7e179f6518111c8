# ruff: noqa: F841, E702, F401, E731, E741
"""Review2 s63, batch D: FALSE claims (residuals that are nonzero rational functions) whose degree bound
is compared with the true numerator degree computed by sympy on the same Cayley chart (degree_truth.py).
Each residual is written so that its value is a known closed form."""
from stiefelsym import admissible, claim, comm, det, elementary

SM = admissible(n_max=3, n_min=2, r_max=1)          # (2,1), (3,1)


def mk(cid, f, sizes=SM, kind="id", **kw):
    claim(cid, paper="t", kind=kind, section="2", sizes=sizes, **kw)(f)


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


# 1. inverse of an r x r matrix
mk("d-inv-r", lambda s: {"r": (s.X.T @ s.A @ s.X + s.P.T @ s.P + s.Ir * s.lam).inv()})
# 2. inverse of an n x n matrix
mk("d-inv-n", lambda s: {"r": (s.A + s.P @ s.P.T + s.In * s.lam).inv()})
# 3. resolvent sandwiched
mk("d-resolvent", lambda s: {"r": s.P.T @ s.resolvent(s.lam) @ s.P})
# 4. determinant (fixed sizes)
mk("d-det", lambda s: {"r": det(s, s.A + s.P @ s.P.T + s.In * s.lam)})
# 5. derivative along the Neumann Dirac flow of tr(X^T A^2 X) (=  2 tr(X^T A^2 P) on T*V)
mk("d-flow", lambda s: {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.A @ t.X), s.dirac_flow(H))})
# 6. Dirac bracket
mk("d-bracket", lambda s: {"r": s.bracket(lambda t: t.tr(t.X.T @ t.A @ t.A @ t.X), lambda t: t.tr(t.P.T @ t.A @ t.P))})
# 7. elementary symmetric functions of an n x n matrix
mk("d-elem", lambda s: {"r": elementary(s, s.A @ s.P @ s.P.T, 2)[2]})
# 8. negative power
mk("d-negpow", lambda s: {"r": s.tr(s.X.T @ s.A @ s.X + s.P.T @ s.P) ** -2})
# 9. nested inverse
mk("d-nested", lambda s: {"r": ((s.A + s.In * s.lam).inv() @ s.P @ s.P.T + s.In).inv()})
# 10. division by a trace
mk("d-divtrace", lambda s: {"r": s.P / s.tr(s.P.T @ s.A @ s.P + s.Ir)})
# 11. derivative along a tangent vector that divides
mk("d-tangent-div", lambda s: {"r": s.d(lambda t: (t.X.T @ t.A @ t.X + t.P.T @ t.P).inv(), {"X": s.P, "P": s.A @ s.X})})
# 12. second derivative along the flow
mk("d-second", lambda s: {"r": s.d(lambda t: t.d(lambda u: u.tr(u.X.T @ u.A @ u.A @ u.X), t.dirac_flow(H)), s.dirac_flow(H))})
# 13. resolvent of a moving parameter mu = tr(P^T P)
mk("d-res-moving", lambda s: {"r": s.X.T @ s.resolvent(s.tr(s.P.T @ s.P)) @ s.X})
# 14. gradient
mk("d-grad", lambda s: {"r": s.gradient(lambda t: t.tr(t.X.T @ t.A @ t.X) ** 3)["X"]})
