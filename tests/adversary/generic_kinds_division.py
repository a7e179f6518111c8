"""Adversary (generic kinds): division by scalars that vanish identically only because a generic matrix is skew
(tr K = 0, tr(S K) = 0, xᵀ K x = 0): a claim undefined at every point must not be proved, checked or numeric."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-div-trK", paper="adv", kind="id", sizes=S)
def div_trK(s):
    """Undefined: tr(K)·X / tr(K) − X (tr K = 0 for K skew)."""
    K = s.generic("K", "n", "n", "skew")
    return {"x": s.X * K.trace() / K.trace() - s.X}


@claim("adv-gk-div-trSK", paper="adv", kind="id", sizes=S)
def div_trSK(s):
    """Undefined: tr(SK)² / tr(SK) (= 0 where defined; tr(SK) = 0 everywhere)."""
    S_, K = s.generic("S", "n", "n", "sym"), s.generic("K", "n", "n", "skew")
    c = (S_ @ K).trace()
    return {"x": c * c / c}


@claim("adv-gk-div-xKx", paper="adv", kind="id", sizes=S)
def div_xKx(s):
    """Undefined: 1/tr(Xᵀ K X) · tr(Xᵀ K X) − 1."""
    K = s.generic("K", "n", "n", "skew")
    c = (s.X.T @ K @ s.X).trace()
    return {"x": c / c - 1}


@claim("adv-gk-div-ok", paper="adv", kind="id", sizes=S)
def div_ok(s):
    """True and defined: tr(S²)/tr(S²) = 1 (S symmetric generic: tr S² > 0 generically)."""
    S_ = s.generic("S", "n", "n", "sym")
    c = (S_ @ S_).trace()
    return {"x": c / c - 1}
