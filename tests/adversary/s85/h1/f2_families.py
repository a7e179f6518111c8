"""Free method: the declared families r = k / r = n (admissible(r_in=..., r_is_n=..., r_min=r_max=...)).

Truths (by hand; numpy in truth.py): at r = 1, XᵀP = 0 (XᵀP + PᵀX = 2XᵀP = 0) and Ψ = 0; at r = 2 any two 2×2
skew matrices commute ([Ψ, η] = 0) and Ψ² = ½tr(Ψ²) I_2; at r = n, XXᵀ = I_n; at r = 3 none of these.

fam-r3-tr-t   r_in=(3,): tr I_r − 3 = 0                               TRUE
fam-r3-tr-f   r_in=(3,): tr I_r − 2 = 0                               FALSE
fam-r3-comm-f r_in=(3,): [Ψ, η] = 0                                   FALSE (so(3) not abelian)
fam-r2n-comm-f r_in=(2, "n"), n_min=2: [Ψ, η] = 0                     FALSE at (3,3) (Ψ generic skew 3x3 at r=n)
fam-r2-comm-t r_in=(2,): [Ψ, η] = 0                                   TRUE
fam-r1n-xtp-f r_in=(1, "n"): XᵀP = 0                                  FALSE at (2,2)
fam-r1-xtp-t  r_min=r_max=1: XᵀP = 0                                  TRUE
fam-rn-tr-t   r_is_n: tr I_n − tr I_r = 0                             TRUE
fam-rn-xxt-lt-f r_in=("n",), where r<n (admits nothing): XXᵀ − I_n  vacuous (no size) -- the free verdict is
              about no size at all; any "proved" is vacuous
fam-r2-big-f  r_in=(2,), n_min=2: Ψ² − ½tr(Ψ²)I_r = 0 TRUE; twin with factor 1/3 FALSE
fam-rin-r1-and-rmin2  r_in=(1,), r_min=2: admits nothing (vacuous)
"""
from stiefelsym import admissible, claim, comm


@claim("fam-r3-tr-t", kind="id", sizes=admissible(n_max=4, r_in=(3,)))
def r3_tr_t(s):
    return {"x": s.tr(s.Ir) - 3}


@claim("fam-r3-tr-f", kind="id", sizes=admissible(n_max=4, r_in=(3,)))
def r3_tr_f(s):
    return {"x": s.tr(s.Ir) - 2}


@claim("fam-r3-comm-f", kind="id", sizes=admissible(n_max=4, r_in=(3,)))
def r3_comm_f(s):
    return {"x": comm(s.Psi, s.eta)}


@claim("fam-r2n-comm-f", kind="id", sizes=admissible(n_max=3, n_min=2, r_in=(2, "n")))
def r2n_comm_f(s):
    return {"x": comm(s.Psi, s.eta)}


@claim("fam-r2-comm-t", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def r2_comm_t(s):
    return {"x": comm(s.Psi, s.eta)}


@claim("fam-r1n-xtp-f", kind="id", sizes=admissible(n_max=3, r_in=(1, "n")))
def r1n_xtp_f(s):
    return {"x": s.X.T @ s.P}


@claim("fam-r1-xtp-t", kind="id", sizes=admissible(n_max=3, r_min=1, r_max=1))
def r1_xtp_t(s):
    return {"x": s.X.T @ s.P}


@claim("fam-rn-tr-t", kind="id", sizes=admissible(n_max=3, r_is_n=True))
def rn_tr_t(s):
    return {"x": s.tr(s.In) - s.tr(s.Ir)}


@claim("fam-r2-sq-t", kind="id", sizes=admissible(n_max=4, n_min=2, r_in=(2,)))
def r2_sq_t(s):
    return {"x": s.Psi @ s.Psi - s.tr(s.Psi @ s.Psi) / 2 * s.Ir}


@claim("fam-r2-sq-f", kind="id", sizes=admissible(n_max=4, n_min=2, r_in=(2,)))
def r2_sq_f(s):
    return {"x": s.Psi @ s.Psi - s.tr(s.Psi @ s.Psi) / 3 * s.Ir}


@claim("fam-r2-n2-f", kind="id", sizes=admissible(n_max=4, n_min=2, r_in=(2,)))
def r2_n2_f(s):
    # X Xᵀ = I_n holds at (2,2) only: false for the family r = 2 (n >= 3)
    return {"x": s.X @ s.X.T - s.In}
