"""Inverse statements whose op scales by a parameter that vanishes for some admissible value
(tr A, det A, a_1, kappa + 1/2, lambda, a scalar c, a_1 - a_2): op is then NOT invertible there."""
from stiefelsym import Inverse, claim, det

SZ = [(3, 2)]


def make(scale):
    def op(s, x):
        return x * scale(s)

    def inv(s, y):
        return y / scale(s)
    return op, inv


def _claim(cid, scale, words):
    op, inv = make(scale)

    def f(s):
        return {"inv": Inverse(op, inv, on="Sym(r)")}
    f.__doc__ = words
    f.__name__ = cid.replace("-", "_")
    return claim(cid, kind="id", sizes=SZ)(f)


_claim("s76-inv-trA", lambda s: s.tr(s.A), "x ↦ tr(A) x invertible (false where tr A = 0).")
_claim("s76-inv-detA", lambda s: det(s, s.A), "x ↦ det(A) x invertible (false where det A = 0; A⁻¹ is refused).")
_claim("s76-inv-a1", lambda s: s.a[0], "x ↦ a₁ x invertible (false where a₁ = 0).")
_claim("s76-inv-kappa", lambda s: s.kappa + s.q(1, 2), "x ↦ (κ + ½) x invertible (false at κ = −½).")
_claim("s76-inv-lam", lambda s: s.lam, "x ↦ λ x invertible (false at λ = 0).")
_claim("s76-inv-c", lambda s: s.scalar("c"), "x ↦ c x invertible (false at c = 0).")
_claim("s76-inv-a1a2", lambda s: s.a[0] - s.a[1], "x ↦ (a₁ − a₂) x invertible (a_i distinct: true).")
_claim("s76-inv-trA2", lambda s: s.tr(s.A @ s.A) + 1, "x ↦ (tr A² + 1) x invertible (true over the reals).")
