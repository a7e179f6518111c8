# ruff: noqa
"""True identities with constants that are not binary fractions or lie outside float64's range: ball must not refute them."""
from fractions import Fraction
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


def _mk(cid, f, doc):
    @claim(cid, paper="r65", kind="id", sizes=SZ)
    def c(s):
        return f(s)
    c.__doc__ = doc
    return c


_mk("bc-third", lambda s: {"r": (s.X * s.q(1, 3)) * 3 - s.X}, "X/3·3 = X")
_mk("bc-tenth", lambda s: {"r": s.tr(s.X.T @ s.X) * s.q(1, 10) * 10 - s.tr(s.Ir)}, "tr(XᵀX)/10·10 = r")
_mk("bc-div7", lambda s: {"r": (s.P / 7) * 7 - s.P}, "P/7·7 = P")
_mk("bc-huge", lambda s: {"r": (s.X * s.q(10**400, 1)) * s.q(1, 10**400) - s.X}, "(10^400 X) 10^-400 = X")
_mk("bc-tiny", lambda s: {"r": (s.X * s.q(1, 10**400)) * s.q(10**400, 1) - s.X}, "(10^-400 X) 10^400 = X")
_mk("bc-tiny-sum", lambda s: {"r": (s.X + s.X * s.q(1, 10**400)) - s.X * s.q(10**400 + 1, 10**400)}, "X + 10^-400X = (1+10^-400)X")
_mk("bc-big-sum", lambda s: {"r": (s.X * s.q(10**30, 1) + s.X) - s.X * s.q(10**30 + 1, 1)}, "10^30X + X = (10^30+1)X")
_mk("bc-third-pow", lambda s: {"r": s.tr(s.X.T @ s.X) ** 3 * s.q(1, 27) - (s.tr(s.Ir) * s.q(1, 3)) ** 3}, "(r/3)^3")
_mk("bc-inv", lambda s: {"r": (s.Ir * 3 + s.X.T @ s.X).inv() * 4 - s.Ir}, "(3I + XᵀX)^{-1}·4 = I")
_mk("bc-inv3", lambda s: {"r": (s.X.T @ s.X * 3).inv() * 3 - s.Ir}, "(3XᵀX)^{-1}·3 = I")
_mk("bc-inv10", lambda s: {"r": (s.X.T @ s.X * s.q(1, 10)).inv() * s.q(1, 10) - s.Ir}, "(XᵀX/10)^{-1}/10 = I")
_mk("bc-res", lambda s: {"r": s.resolvent(s.q(1, 3)) @ (s.In * s.q(1, 3) - s.A) - s.In}, "R(1/3)(1/3 − A) = I")
_mk("bc-pow-neg", lambda s: {"r": s.tr(s.X.T @ s.X * 3) ** -1 * s.tr(s.Ir) * 3 - 1}, "(3r)^{-1}·r·3 = 1")
