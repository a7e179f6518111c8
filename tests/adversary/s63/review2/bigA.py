# ruff: noqa: F841, E702, F401, E731, E741
"""Review2 s63, batch A: huge and tiny exact constants against float, ball, modular, exact.
T = true, F = false (numpy_truth.py checks each)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3, n_min=3, r_min=2, r_max=2)
C = 2 ** 15000
B = 2 ** 1100          # beyond float64, within arb's exponents
M = 2 ** 600           # product beyond float64 (2^1200), each factor inside


def mk(cid, f, sizes=S, kind="id", **kw):
    claim(cid, paper="t", kind=kind, section="2", sizes=sizes, **kw)(f)


# T: absorption that cancels exactly
mk("a-T-absorb-huge", lambda s: {"r": (s.X * C + s.X) - s.X * C - s.X})
# F: absorbed X
mk("a-F-absorb-huge", lambda s: {"r": (s.X * C + s.X) - s.X * C})
mk("a-F-absorb-1100", lambda s: {"r": (s.X * B + s.P) - s.X * B})
# F: product of two in-range constants overflows float64 only in the product
mk("a-F-absorb-prod", lambda s: {"r": (s.X * M) * M + s.P - (s.X * M) * M})
# F: tiny residual X / 2^15000 (underflows float64 to an exact 0?)
mk("a-F-tiny-huge", lambda s: {"r": s.X * s.q(1, C)})
mk("a-F-tiny-1100", lambda s: {"r": s.P * s.q(1, B)})
mk("a-F-tiny-div", lambda s: {"r": s.P / C})
# T: tiny times huge
mk("a-T-tiny-times-huge", lambda s: {"r": (s.X * s.q(1, C)) * C - s.X})
# F: q(C+1, C) - 1, X times it
mk("a-F-q-near-one", lambda s: {"r": s.X * s.q(C + 1, C) - s.X})
# F: near cancellation of two huge constants with a difference of 1 (c1 - c2 = 1)
mk("a-F-two-huge", lambda s: {"r": s.X * (C + 1) - s.X * C})
# T: same with difference 0 by different routes
mk("a-T-two-huge", lambda s: {"r": s.X * (C + 1) - s.X * C - s.X})
# F: constant-only residual of huge size, tr(X^T X) * C - r*C - 1  (= -1)
mk("a-F-const-only", lambda s: {"r": s.tr(s.X.T @ s.X) * C - s.tr(s.Ir) * C - 1})
# F: constant-only tiny residual: tr(XᵀX)/C - r/C - 1/C^2
mk("a-F-const-tiny", lambda s: {"r": s.tr(s.X.T @ s.X) / C - s.tr(s.Ir) / C - s.q(1, C * C)})
# F: scalar huge denominator constants combined: (1/C + 1/C) - 2/C + 1/C^3 ... times tr(P^T P)
mk("a-F-scalar-tiny-P", lambda s: {"r": s.tr(s.P.T @ s.P) * s.q(1, C * C * C)})
# nonzero-claims (kind not): X * 2^-15000 is NOT zero (true not-claim)
mk("a-Tnot-tiny", lambda s: {"r": s.X * s.q(1, C)}, kind="not", expect="nonzero")
# nonzero-claim that is false: (C X + X) - C X - X is zero
mk("a-Fnot-absorb", lambda s: {"r": (s.X * C + s.X) - s.X * C - s.X}, kind="not", expect="nonzero")
# power of a huge constant: (C)^3 / C^3 X - X = 0 true
mk("a-T-pow-const", lambda s: {"r": s.X * (C ** 3) / (C ** 3) - s.X})
