"""s88h2 adversarial claims: steering through the API, and large common polynomial factors in products.

 s88h2a-block-entry (TRUE): entries of a block matrix read through M[i, j]: 𝓛*[r, 0] = 1 + (PᵀRP)₁₁ and
   𝓛*[0, r] = −(XᵀRX)₁₁.
 s88h2a-block-entry-twin (FALSE): 𝓛*[r, 0] = −(XᵀRX)₁₁ (the transposed position).
 s88h2a-block-slice (TRUE): 𝓛*[0:r, r:2r] = −XᵀRX.   -twin (FALSE): 𝓛*[r:2r, 0:r] = −XᵀRX.
 s88h2a-odd-constants (TRUE): Fraction(1, 3)·3·tr𝓛*² − tr𝓛*² = 0, True·X − X = 0.
 s88h2a-int64 (TRUE): numpy.int64(2)·𝓛* − 𝓛* − 𝓛* = 0 (refused by the tracer: an honest refusal).  -twin (FALSE): Fraction(1, 2)·tr𝓛*² − tr𝓛*² (tr𝓛*² ≠ 0).
 s88h2a-float-const (FALSE): numpy.float64(0.0)·(tr 𝓛*²) + 1 (a float in a claim: must be refused or fail).
 s88h2a-swallow (FALSE at fixed sizes, n ≥ 2): reads X[0,0] inside try/except, returning 0 if the read raises
   (the free method refuses coordinates), else X[0,0]·X[1,0] − 1·X[0,0]·X[1,0] + X[0,0]·(1 − X[0,0]) ... a false
   residual X[0,0] − X[1,0].  A proof of it by any method is a wrong verdict for the claim as written where
   it reads the point.
 s88h2a-state (TRUE at every call?): a module-level counter; returns a true residual on odd calls and a false
   one (X − X + Xᵀ... = tr XᵀX − r + 1) on even calls: the verdict depends on how often the engine calls
   the claim (recorded, not a statement of truth).
 s88h2a-scalar-name (TRUE, not): s.scalar("lam") is not λ: s.scalar("lam") − λ ≠ 0 (expect nonzero).
 s88h2a-generic-same-name (TRUE?): s.generic("G","n","n") twice with one name: same parameters? (recorded).
 s88h2a-common-det (TRUE): v = det(M)·w (every entry of v a multiple of det M, M = 𝒱ᵀB𝒱 at r = 1),
   ⟨v, Bv⟩ − det(M)²⟨w, Bw⟩ = 0.  -twin (FALSE): ⟨v, Bv⟩ − det(M)⟨w, Bw⟩.
 s88h2a-common-den (TRUE): S = R(λI − A)W₁ (a matrix over the denominator of R whose numerators share it),
   S W₂ − W₁W₂ = 0, SᵀW₃ (transpose view taken before the product cancels S) − W₁ᵀW₃ = 0, S[0,0] − (W₁)₀₀ = 0.
   -twin (FALSE): S W₂ − W₂W₁.
 s88h2a-content-big (TRUE): a = D₁D₂·H₁, b = D₁·H₂ with D_i = det G_i of generic matrices (every entry of each
   operand shares the determinant factors): a b − D₁²D₂·H₁H₂ = 0.  -twin (FALSE): … − D₁D₂²·H₁H₂.
 s88h2a-content-partial (TRUE): as content-big, but one entry of a lacks D₂ (the _common_part path).
 s88h2a-content-factor (TRUE): the two smallest entries of a share g = D₁D₂D₃, the others share nothing
   (the content step factors g and gives up): a b − (a b computed entrywise) = 0 (forms compared, 0).
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from stiefelsym import admissible, block, claim, det

ANY = admissible(n_max=4)
N2 = admissible(n_max=4, n_min=2, condition="n >= 2")
R1 = admissible(n_max=4, r_max=1, condition="r = 1")
FIX = [(2, 1), (3, 1), (4, 1)]


def Ldual(s):
    R = s.resolvent(s.lam)
    X, P = s.X, s.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]])


@claim("s88h2a-block-entry", kind="id", section="8", sizes=ANY)
def block_entry(s):
    """𝓛*[r, 0] = 1 + (PᵀRP)₁₁, 𝓛*[0, r] = −(XᵀRX)₁₁ (TRUE)."""
    L, R, r = Ldual(s), s.resolvent(s.lam), int(s.r)
    return {"L[r,0]": L[r, 0] - (1 + (s.P.T @ R @ s.P)[0, 0]), "L[0,r]": L[0, r] + (s.X.T @ R @ s.X)[0, 0]}


@claim("s88h2a-block-entry-twin", kind="id", section="8", sizes=ANY)
def block_entry_twin(s):
    """FALSE twin: 𝓛*[r, 0] = −(XᵀRX)₁₁."""
    L, R, r = Ldual(s), s.resolvent(s.lam), int(s.r)
    return {"L[r,0]": L[r, 0] + (s.X.T @ R @ s.X)[0, 0]}


@claim("s88h2a-block-slice", kind="id", section="8", sizes=ANY)
def block_slice(s):
    """𝓛*[0:r, r:2r] = −XᵀRX (TRUE)."""
    L, R, r = Ldual(s), s.resolvent(s.lam), int(s.r)
    return {"slice": L[0:r, r:2 * r] + s.X.T @ R @ s.X}


@claim("s88h2a-block-slice-twin", kind="id", section="8", sizes=ANY)
def block_slice_twin(s):
    """FALSE twin: 𝓛*[r:2r, 0:r] = −XᵀRX."""
    L, R, r = Ldual(s), s.resolvent(s.lam), int(s.r)
    return {"slice": L[r:2 * r, 0:r] + s.X.T @ R @ s.X}


@claim("s88h2a-odd-constants", kind="id", section="8", sizes=ANY)
def odd_constants(s):
    """numpy.int64, Fraction and bool constants (TRUE)."""
    L = Ldual(s)
    t = s.tr(L @ L)
    return {"Fraction": t * Fraction(1, 3) * 3 - t, "bool": s.X * True - s.X}


@claim("s88h2a-int64", kind="id", section="8", sizes=ANY)
def int64_const(s):
    """numpy.int64(2)·𝓛* − 𝓛* − 𝓛* = 0 (TRUE; refused: exact constants are int and Fraction)."""
    L = Ldual(s)
    return {"int64": L * np.int64(2) - L - L}


@claim("s88h2a-odd-constants-twin", kind="id", section="8", sizes=ANY)
def odd_constants_twin(s):
    """FALSE twin: Fraction(1, 2)·tr𝓛*² = tr𝓛*²."""
    L = Ldual(s)
    t = s.tr(L @ L)
    return {"Fraction": t * Fraction(1, 2) - t}


@claim("s88h2a-float-const", kind="id", section="8", sizes=ANY)
def float_const(s):
    """FALSE: numpy.float64(0.0)·tr𝓛*² + 1 = 0 (a float constant)."""
    L = Ldual(s)
    return {"float": np.float64(0.0) * s.tr(L @ L) + 1}


@claim("s88h2a-swallow", kind="id", section="8", sizes=N2)
def swallow(s):
    """FALSE where the point is read: X[0,0] − X[1,0] = 0; the read is inside try/except (0 if it raises)."""
    try:
        res = s.X[0, 0] - s.X[1, 0]
    except Exception:
        res = s.q(0)
    return {"x00 - x10": res}


_CALLS = [0]


@claim("s88h2a-state", kind="id", section="8", sizes=ANY)
def state(s):
    """Odd calls: tr XᵀX − r (TRUE); even calls: tr XᵀX − r + 1 (FALSE).  Recorded, no truth of its own."""
    _CALLS[0] += 1
    extra = s.q(0) if _CALLS[0] % 2 else s.q(1)
    return {"trXX - r": s.tr(s.X.T @ s.X) - s.r + extra}


@claim("s88h2a-scalar-name", kind="not", expect="nonzero", section="8", sizes=ANY)
def scalar_name(s):
    """TRUE: s.scalar('lam') is a parameter of the claim's own, not λ: s.scalar('lam') − λ ≠ 0."""
    return {"lam' - lam": s.scalar("lam") - s.lam}


@claim("s88h2a-generic-same-name", kind="id", section="8", sizes=ANY)
def generic_same_name(s):
    """Recorded: s.generic('G','n','n') twice with the same name gives the same matrix (G − G = 0)."""
    return {"G - G": s.generic("G", "n", "n") - s.generic("G", "n", "n")}


def _tangent(s):
    zr = s.zeros(s.r, s.r, ("r", "r"))
    V = block([[s.X, s.P], [zr, s.Ir]])
    zn = s.zeros(s.n, s.r, ("n", "r"))
    B = block([[s.resolvent(s.lam), zn], [zn.T, s.Ir]])
    M = V.T @ B @ V
    adj = s.mat([[M[1, 1], -M[0, 1]], [-M[1, 0], M[0, 0]]], ("r+r", "r+r"))
    e1 = s.mat([[s.q(1)], [s.q(0)]], ("r+r", "?"))
    return V @ adj @ e1, B, det(s, M)


@claim("s88h2a-common-det", kind="geo", section="8", sizes=R1)
def common_det(s):
    """v = det(M)w: ⟨v, Bv⟩ = det(M)²⟨w, Bw⟩ (TRUE)."""
    w, B, d = _tangent(s)
    v = w * d
    return {"<v,Bv>": s.tr(v.T @ B @ v) - d * d * s.tr(w.T @ B @ w)}


@claim("s88h2a-common-det-twin", kind="geo", section="8", sizes=R1)
def common_det_twin(s):
    """FALSE twin: ⟨v, Bv⟩ = det(M)⟨w, Bw⟩."""
    w, B, d = _tangent(s)
    v = w * d
    return {"<v,Bv>": s.tr(v.T @ B @ v) - d * s.tr(w.T @ B @ w)}


def _common_den(s, twin):
    R = s.resolvent(s.lam)
    W1, W2, W3 = s.generic("W1", "n", "n"), s.generic("W2", "n", "n"), s.generic("W3", "n", "r")
    lamI = s.lam * s.In
    S = R @ (lamI - s.A) @ W1
    St = S.T                                      # a view taken before the product below
    first = S @ W2 - (W2 @ W1 if twin else W1 @ W2)
    return {"S W2": first, "S^T W3": St @ W3 - W1.T @ W3, "S[0,0]": S[0, 0] - W1[0, 0],
            "S W2 again": S @ W2 - W1 @ W2}


@claim("s88h2a-common-den", kind="id", section="8", sizes=ANY)
def common_den(s):
    """S = R(λI − A)W₁ = W₁: S W₂ = W₁W₂, SᵀW₃ = W₁ᵀW₃, S₀₀ = (W₁)₀₀ (TRUE)."""
    return _common_den(s, False)


@claim("s88h2a-common-den-twin", kind="id", section="8", sizes=admissible(n_max=4, n_min=2))
def common_den_twin(s):
    """FALSE twin (n ≥ 2): S W₂ = W₂W₁."""
    return _common_den(s, True)


def _big(s, twin):
    G1, G2 = s.generic("G1", "n", "n"), s.generic("G2", "n", "n")
    H1, H2 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n")
    D1, D2 = det(s, G1), det(s, G2)
    a = H1 * (D1 * D2)
    b = H2 * D1
    expect = (H1 @ H2) * (D1 * D2 * (D2 if twin else D1))
    return {"ab": a @ b - expect}


@claim("s88h2a-content-big", kind="id", section="8", sizes=FIX)
def content_big(s):
    """a = D₁D₂H₁, b = D₁H₂: ab = D₁²D₂H₁H₂ (TRUE)."""
    return _big(s, False)


@claim("s88h2a-content-big-twin", kind="id", section="8", sizes=FIX)
def content_big_twin(s):
    """FALSE twin: ab = D₁D₂²H₁H₂."""
    return _big(s, True)


def _partial(s, twin):
    n = int(s.n)
    G1, G2, G3 = s.generic("G1", "n", "n"), s.generic("G2", "n", "n"), s.generic("G3", "n", "n")
    H1, H2 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n")
    D1, D2, D3 = det(s, G1), det(s, G2), det(s, G3)
    # every entry D1 D2 h, except the last one: D1 (D3 h + 1) (larger, lacks D2)
    rows = [[H1[i, j] * (D1 * D2) for j in range(n)] for i in range(n)]
    rows[n - 1][n - 1] = D1 * (D3 * H1[n - 1, n - 1] + 1)
    a = s.mat(rows, ("n", "n"))
    b = H2 * D1
    # the product entrywise: (a b)_ij = Σ_k a_ik b_kj
    exp_rows = []
    for i in range(n):
        row = []
        for j in range(n):
            acc = s.q(0)
            for k in range(n):
                acc = acc + rows[i][k] * (H2[k, j] * D1)
            row.append(acc + (1 if twin and i == j == 0 else 0))
        exp_rows.append(row)
    return {"ab": a @ b - s.mat(exp_rows, ("n", "n"))}


@claim("s88h2a-content-partial", kind="id", section="8", sizes=FIX)
def content_partial(s):
    """One entry lacks D₂: a b equals the entrywise sums (TRUE)."""
    return _partial(s, False)


@claim("s88h2a-content-partial-twin", kind="id", section="8", sizes=FIX)
def content_partial_twin(s):
    """FALSE twin: the (0,0) entry off by 1."""
    return _partial(s, True)
