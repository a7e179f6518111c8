"""s89h2: tricks through the public API, classes 1, 2, 4, 5 of issue 20 (truth: by hand, and truth_numpy.py).

Class 1 (entries through a block / untyped spaces):
 c1-idcol (FALSE): e = first column of s.identity(n, '?') (an untyped space), tr((eᵀX)(Xᵀe)) = 1 at r = 1,
    i.e. X₁₁² = 1.  False: X₁₁² < 1 at a generic point (numpy).  True on the chart X₀ = E₁.
 c1-top (FALSE, r < n): Xᵀ·[I_r; 0_{(n−r)×r}] = I_r (the top r×r block of X is I), the block typed r ⊕ (n−r).
 c1-eig-a (FALSE, r = 1): tr(XᵀAX) = a₁ (s.a[0]).  False: Σ aᵢxᵢ² ≠ a₁.
 c1-eig-a-true (TRUE): tr A = Σ aᵢ.
 c1-diag-a-true (TRUE): s.mat(diag(a₁..aₙ), ('n','n')) − A = 0 (A is diag(a)); the chart moves A, so a
    false refutation would be a wrong verdict.
 c1-fresh-entry (FALSE, r = 1): tr(XᵀFX) = F₁₁ for a fresh generic n×n F.  False: xᵀFx ≠ F₁₁.
 c1-gp-entry (FALSE, r = 1): same with s.general_params('G', n, n, ('?','?')) (untyped sides).
 c1-zero-block-read (FALSE, r < n): block([[X, zeros(n, 1, ('?','?'))]])[0:1, 0:1] read as the 1×1 matrix
    and squared: (X₁₁)² − 1·… = tr(E XXᵀ)... written: tr(B[0:1,0:r] B[0:1,0:r]ᵀ) = 1 (first row of X is a unit vector).
    False for r < n (numpy).
 c1-resolvent-entry (FALSE, r = 1): tr(Xᵀ R(λ) X) = R(λ)₁₁.
Class 2 (floats in disguise) and 5 (underflow / overflow):
 c2-pow-underflow (FALSE): (½)^1100 · tr PᵀP = 0 (a power node, not a constant, below the float range).
 c2-pow-overflow-true (TRUE): 2^1100 · (tr XᵀX − r) = 0 (inf·0 in float64).
 c2-pow-neg (FALSE): (2^−1)^1100 built by s.q(2)**(-1100) · tr PᵀP = 0.
 c2-big-cancel (FALSE): (c + 1)·t − c·t with c = 2^60 (exact int), t = tr PᵀP: residual t ≠ 0; float absorbs 1.
 c2-frac-from-float (TRUE): Fraction.from_float(0.1)·10·2^55... exact: Fraction.from_float(0.1) − 3602879701896397/2^55 = 0 times tr PᵀP.
 c2-tiny-sum (FALSE): (2^-1074 + 2^-1074 − 2^-1073 + 2^-2000)·tr(PᵀP) = 2^-2000 tr PᵀP ≠ 0.
Class 4 (state across calls):
 c4-id-parity (no truth of its own: recorded): a residual chosen by id(object()) % 2 (differs between traces).
 c4-hash-seed (recorded): a residual chosen by hash('s89') % 2 (same within one interpreter, differs between
    interpreters: PYTHONHASHSEED).  A verdict is the graph's; `check` must reject a mismatched digest.
"""
from fractions import Fraction

from stiefelsym import admissible, block, claim

R1 = admissible(n_max=3, n_min=2, r_max=1, condition="r = 1, n >= 2")
RLT = admissible(n_max=3, where=lambda n, r: r < n, condition="r < n")
ANY = admissible(n_max=3)


def _trP(s):
    return s.tr(s.P.T @ s.P)


@claim("c1-idcol", kind="id", sizes=R1)
def c1_idcol(s):
    """FALSE: X₁₁² = 1 at r = 1 (first column of an untyped identity)."""
    e = s.identity(s.n, "?")[:, 0:1]
    v = e.T @ s.X
    return {"x11^2-1": s.tr(v @ v.T) - 1}


@claim("c1-top", kind="id", sizes=RLT)
def c1_top(s):
    """FALSE: the top r×r block of X is I_r."""
    top = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    return {"top": s.X.T @ top - s.Ir}


@claim("c1-eig-a", kind="id", sizes=R1)
def c1_eig_a(s):
    """FALSE: tr(XᵀAX) = a₁ at r = 1."""
    return {"r": s.tr(s.X.T @ s.A @ s.X) - s.a[0]}


@claim("c1-eig-a-true", kind="id", sizes=ANY)
def c1_eig_a_true(s):
    """TRUE: tr A = Σ aᵢ."""
    return {"r": s.tr(s.A) - sum(s.a)}


@claim("c1-diag-a-true", kind="id", sizes=ANY)
def c1_diag_a_true(s):
    """TRUE: diag(a) = A."""
    a = s.a
    n = len(a)
    D = s.mat([[a[i] if i == j else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    return {"r": D - s.A}


@claim("c1-fresh-entry", kind="id", sizes=R1)
def c1_fresh_entry(s):
    """FALSE: xᵀFx = F₁₁ (F fresh generic)."""
    F = s.fresh("n", "n")
    return {"r": s.tr(s.X.T @ F @ s.X) - F[0, 0]}


@claim("c1-gp-entry", kind="id", sizes=R1)
def c1_gp_entry(s):
    """FALSE: xᵀGx = G₁₁ (G a block of parameters on untyped sides)."""
    G = s.general_params("G", s.n, s.n, ("?", "?"))
    return {"r": s.tr(s.X.T @ G @ s.X) - G[0, 0]}


@claim("c1-zero-block-read", kind="id", sizes=RLT)
def c1_zero_block_read(s):
    """FALSE (r < n): the first row of X is a unit vector."""
    B = block([[s.X, s.zeros(s.n, 1, ("?", "?"))]])
    row = B[0:1, 0:1] if False else B[0:1, :]
    return {"r": s.tr(row @ row.T) - 1}


@claim("c1-resolvent-entry", kind="id", sizes=R1)
def c1_resolvent_entry(s):
    """FALSE: xᵀR(λ)x = R(λ)₁₁."""
    R = s.resolvent(s.lam)
    return {"r": s.tr(s.X.T @ R @ s.X) - R[0, 0]}


@claim("c2-pow-underflow", kind="id", sizes=ANY)
def c2_pow_underflow(s):
    """FALSE: (½)^1100 · tr PᵀP = 0."""
    return {"r": s.q(1, 2) ** 1100 * _trP(s)}


@claim("c2-pow-overflow-true", kind="id", sizes=ANY)
def c2_pow_overflow_true(s):
    """TRUE: 2^1100 · (tr XᵀX − r) = 0."""
    return {"r": s.q(2) ** 1100 * (s.tr(s.X.T @ s.X) - s.r)}


@claim("c2-pow-neg", kind="id", sizes=ANY)
def c2_pow_neg(s):
    """FALSE: 2^−1100 · tr PᵀP = 0."""
    return {"r": s.q(2) ** (-1100) * _trP(s)}


@claim("c2-big-cancel", kind="id", sizes=ANY)
def c2_big_cancel(s):
    """FALSE: (c+1)t − ct = 0 with c = 2^60, t = tr PᵀP."""
    c = 2 ** 60
    t = _trP(s)
    return {"r": (c + 1) * t - c * t}


@claim("c2-frac-from-float", kind="id", sizes=ANY)
def c2_frac_from_float(s):
    """TRUE: (Fraction.from_float(0.1) − 3602879701896397/2^55)·tr PᵀP = 0."""
    return {"r": (Fraction.from_float(0.1) - Fraction(3602879701896397, 2 ** 55)) * _trP(s)}


@claim("c2-tiny-sum", kind="id", sizes=ANY)
def c2_tiny_sum(s):
    """FALSE: (2^-1074 + 2^-1074 − 2^-1073 + 2^-2000)·tr PᵀP = 2^-2000·tr PᵀP ≠ 0."""
    t = _trP(s)
    e = Fraction(1, 2 ** 1074)
    return {"r": e * t + e * t - 2 * e * t + Fraction(1, 2 ** 2000) * t}


@claim("c4-id-parity", kind="id", sizes=ANY)
def c4_id_parity(s):
    """Recorded: tr XᵀX − r (TRUE) or tr XᵀX (FALSE) by id(object()) parity."""
    extra = 0 if (id(object()) >> 4) % 2 else s.q(1) * s.r
    return {"r": s.tr(s.X.T @ s.X) - s.r + extra}


@claim("c4-hash-seed", kind="id", sizes=ANY)
def c4_hash_seed(s):
    """Recorded: tr XᵀX − r (TRUE) or tr XᵀX − r + 1 (FALSE) by hash('s89') parity (PYTHONHASHSEED)."""
    extra = s.q(0) if hash("s89") % 2 else s.q(1)
    return {"r": s.tr(s.X.T @ s.X) - s.r + extra}
