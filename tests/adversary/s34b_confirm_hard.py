"""Round 4b: the exact confirmation of a float / ball `numeric` under a hard case.

Under `--hard CASE` the confirmation evaluates the claim at the hard case's exact point mod p, which is
chosen, not random: a residual that vanishes there (while not identically 0), or a "nonzero" residual
that float64 sees through an absorption and that vanishes identically, is not refuted there.  Each claim
is false."""

from stiefelsym import admissible, claim

SIZES = admissible(n_max=3)


@claim("adv-s34b-hard-zero-at-pole", kind="id", sizes=SIZES)
def vanishes_at_the_hard_lambda(s):
    """(λ − a_1 − 10^-12)X = 0: false, it holds only at the near-pole hard case's λ."""
    return {"X": (s.lam - s.a[0] - s.q(1, 10**12)) * s.X}


@claim("adv-s34b-hard-zero-at-pole-8", kind="id", sizes=SIZES)
def vanishes_at_the_hard_lambda_8(s):
    """tr((λ − a_1 − 10^-8)Φ Φᵀ) = 0: false, it holds only at near-pole-1e-8's λ."""
    return {"tr": s.tr((s.lam - s.a[0] - s.q(1, 10**8)) * (s.Phi @ s.Phi.T))}


@claim("adv-s34b-hard-nonzero-absorbed", kind="not", expect="nonzero", sizes=SIZES)
def absorbed_nonzero(s):
    """"(cX + X) − cX − X is not 0" for c = 10^20: false, it is identically 0 (float64 absorbs X in cX and
    sees −X)."""
    c = 10 ** 20
    return {"X": (s.X * c + s.X) - s.X * c - s.X + s.lam * (s.X - s.X)}


@claim("adv-s34b-hard-nonzero-absorbed-tr", kind="not", expect="nonzero", sizes=SIZES)
def absorbed_nonzero_trace(s):
    """"(c tr PᵀP + tr XᵀX) − c tr PᵀP − r ≠ 0" for c = 10^30: false, it is 0 on T*V."""
    c = 10 ** 30
    u, v = s.tr(s.P.T @ s.P), s.tr(s.X.T @ s.X)
    return {"tr": (c * u + v) - c * u - s.tr(s.Ir) + s.lam * 0}
