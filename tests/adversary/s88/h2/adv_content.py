# ruff: noqa: F841
"""s88h2 common-factor claims aimed at the content step of exact products (polyfield._dot_content, _content,
_common_part: commits c0aecb37, 21581d9f).  D_i = det G_i of generic n×n matrices (24 terms at n = 4,
irreducible), H_i generic matrices.  All residuals are polynomial identities checked by hand.

 s88h2c-big (TRUE): a = (D₁D₂)H₁, b = (D₁D₂)H₂: ab = (D₁D₂)²H₁H₂.   -twin (FALSE): … (D₁D₂)²H₂H₁ (n ≥ 2).
 s88h2c-partial (TRUE): as big, but a's last entry is D₁(D₃h + 1) (lacks D₂: the content falls back to the part
   of the gcd that divides it, _common_part): ab equals its entrywise sums Σ_k a_ik b_kj.
   -twin (FALSE): the (0, 0) entry off by 1.
 s88h2c-factor (TRUE): the first two entries of a are gH₁₁, gH₁₂ with g = D₁D₂D₃ (13,824 terms), every other
   entry is D₄D₅D₆h (as large, no common factor with g), b = D₇H₂: ab equals its entrywise sums.  The content
   step takes the gcd g of the two smallest entries, fails to divide the third, factors g (_common_part) and
   gives up — pure overhead.   -twin (FALSE): the (0, 0) entry off by 1.
 s88h2c-factor-small (TRUE): as factor with b = H₂ + H₄ + H₅ (2.65M term products, just over CONTENT_TERMS).
   -twin (FALSE).  (factor, factor-small, partial at (4,1): the entrywise expansion exceeds the 4 GiB budget
   under main AND base: inconclusive in both, not a regression.)
 s88h2c-sparse3 / sparse4 (TRUE): a with three nonzero entries gH, gH, OH (g = k determinants); sparse4 aborts
   (memory) before any product in main and base alike.  -twin (FALSE).
 s88h2c-cancel3 (TRUE): a row 0 = [g x, g y, O z, O w] (g = D₁D₂D₃, O = F₁F₂F₃ coprime, 13,824 terms each), other
   rows 0; b column j = [y c_j, −x c_j, w d_j, −z d_j] (c_j, d_j sums of 10 generic scalars): ab = 0 identically.
   The two smallest entries share g, the third does not: _content factors g (_common_part) and gives up.
   -twin (FALSE): b[1, 0] = +x c₀, so (ab)₀₀ = 2g x y c₀ ≠ 0.
 s88h2c-cancel3x (TRUE): as cancel3 with g, O times a 3×3 determinant (82,944 terms): ab = 0.  -twin (FALSE).
 s88h2c-cancel4 (TRUE): g = 4 determinants (331,776 terms), m = 1; aborts (memory) before the product in both.
 s88h2c-chain (TRUE): a second nonzero row with partial common factors (g shrinks twice): ab = 0.  -twin (FALSE).
"""
from __future__ import annotations

from stiefelsym import claim, det

FIX = [(4, 1)]
FIX3 = [(3, 1), (4, 1)]


def D(s, name):
    return det(s, s.generic(name, "n", "n"))


def entrywise(s, rows, brows, twin):
    n = len(rows)
    out = []
    for i in range(n):
        row = []
        for j in range(len(brows[0])):
            acc = s.q(0)
            for k in range(len(brows)):
                acc = acc + rows[i][k] * brows[k][j]
            row.append(acc + (1 if twin and i == j == 0 else 0))
        out.append(row)
    return s.mat(out, ("n", "n"))


def _big(s, twin):
    H1, H2 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n")
    g = D(s, "G1") * D(s, "G2")
    a, b = H1 * g, H2 * g
    return {"ab": a @ b - (H2 @ H1 if twin else H1 @ H2) * (g * g)}


@claim("s88h2c-big", kind="id", section="8", sizes=FIX3)
def big(s):
    """ab = (D₁D₂)²H₁H₂ (TRUE)."""
    return _big(s, False)


@claim("s88h2c-big-twin", kind="id", section="8", sizes=FIX3)
def big_twin(s):
    """FALSE twin: (D₁D₂)²H₂H₁."""
    return _big(s, True)


def _partial(s, twin):
    n = int(s.n)
    H1, H2 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n")
    D1, D2, D3 = D(s, "G1"), D(s, "G2"), D(s, "G3")
    rows = [[H1[i, j] * (D1 * D2) for j in range(n)] for i in range(n)]
    rows[n - 1][n - 1] = D1 * (D3 * H1[n - 1, n - 1] + 1)
    brows = [[H2[i, j] * (D1 * D2) for j in range(n)] for i in range(n)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b - entrywise(s, rows, brows, twin)}


@claim("s88h2c-partial", kind="id", section="8", sizes=FIX3)
def partial(s):
    """One entry of a lacks D₂: ab = entrywise sums (TRUE)."""
    return _partial(s, False)


@claim("s88h2c-partial-twin", kind="id", section="8", sizes=FIX3)
def partial_twin(s):
    """FALSE twin: (0, 0) off by 1."""
    return _partial(s, True)


def _factor(s, twin):
    n = int(s.n)
    H1, H2, H3 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n"), s.generic("H3", "n", "n")
    g = D(s, "G1") * D(s, "G2") * D(s, "G3")
    other = D(s, "G4") * D(s, "G5") * D(s, "G6")
    rows = [[H3[i, j] * other for j in range(n)] for i in range(n)]
    rows[0][0], rows[0][1] = H1[0, 0] * g, H1[0, 1] * g
    D7 = D(s, "G7")
    brows = [[H2[i, j] * D7 for j in range(n)] for i in range(n)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b - entrywise(s, rows, brows, twin)}


@claim("s88h2c-factor", kind="id", section="8", sizes=FIX)
def factor(s):
    """Two smallest entries share g = D₁D₂D₃, the rest nothing: ab = entrywise sums (TRUE)."""
    return _factor(s, False)


@claim("s88h2c-factor-twin", kind="id", section="8", sizes=FIX)
def factor_twin(s):
    """FALSE twin: (0, 0) off by 1."""
    return _factor(s, True)


def _sparse(s, twin, k):
    """a has three nonzero entries, a[0,0] = gH1₀₀, a[0,1] = gH1₀₁ (g = D₁⋯D_k), a[0,2] = D_{k+1}⋯D_{2k}H1₀₂
    (as large, coprime to g); b = H₂ (one term per entry).  ab = entrywise sums."""
    n = int(s.n)
    H1, H2 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n")
    g, other = s.q(1), s.q(1)
    for i in range(k):
        g = g * D(s, f"G{i}")
        other = other * D(s, f"F{i}")
    rows = [[s.q(0)] * n for _ in range(n)]
    rows[0][0], rows[0][1], rows[0][2] = H1[0, 0] * g, H1[0, 1] * g, H1[0, 2] * other
    brows = [[H2[i, j] for j in range(n)] for i in range(n)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b - entrywise(s, rows, brows, twin)}


@claim("s88h2c-sparse4", kind="id", section="8", sizes=FIX)
def sparse4(s):
    """g = D₁D₂D₃D₄ (331,776 terms at n = 4): ab = entrywise sums (TRUE)."""
    return _sparse(s, False, 4)


@claim("s88h2c-sparse4-twin", kind="id", section="8", sizes=FIX)
def sparse4_twin(s):
    """FALSE twin: (0, 0) off by 1."""
    return _sparse(s, True, 4)


@claim("s88h2c-sparse3", kind="id", section="8", sizes=FIX)
def sparse3(s):
    """g = D₁D₂D₃ (13,824 terms): ab = entrywise sums (TRUE; under the content threshold? recorded)."""
    return _sparse(s, False, 3)


def _factor_small(s, twin):
    n = int(s.n)
    H1, H2, H3 = s.generic("H1", "n", "n"), s.generic("H2", "n", "n"), s.generic("H3", "n", "n")
    H4, H5 = s.generic("H4", "n", "n"), s.generic("H5", "n", "n")
    g = D(s, "G1") * D(s, "G2") * D(s, "G3")
    other = D(s, "G4") * D(s, "G5") * D(s, "G6")
    rows = [[H3[i, j] * other for j in range(n)] for i in range(n)]
    rows[0][0], rows[0][1] = H1[0, 0] * g, H1[0, 1] * g
    brows = [[H2[i, j] + H4[i, j] + H5[i, j] for j in range(n)] for i in range(n)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b - entrywise(s, rows, brows, twin)}


@claim("s88h2c-factor-small", kind="id", section="8", sizes=FIX)
def factor_small(s):
    """As factor, b with 3 terms per entry (2.65M term products, just over the threshold) (TRUE)."""
    return _factor_small(s, False)


@claim("s88h2c-factor-small-twin", kind="id", section="8", sizes=FIX)
def factor_small_twin(s):
    """FALSE twin: (0, 0) off by 1."""
    return _factor_small(s, True)


def _cancel(s, k, m, twin=False):
    """a: row 0 = [g x, g y, O z, O w] (g = D_1⋯D_k, O = F_1⋯F_k, coprime), the other rows 0; b: column j =
    [y c_j, −x c_j, w d_j, −z d_j] with c_j, d_j sums of m generic scalars: every entry of ab is
    g x y c_j − g y x c_j + O z w d_j − O w z d_j = 0 (TRUE; the twin flips the sign of b[1, 0]: FALSE)."""
    n = int(s.n)
    g, O = s.q(1), s.q(1)
    for i in range(k):
        g = g * D(s, f"G{i}")
        O = O * D(s, f"F{i}")
    x, y, z, w = (s.scalar(t) for t in "xyzw")
    zero = s.q(0)
    rows = [[g * x, g * y, O * z, O * w]] + [[zero] * 4 for _ in range(3)]
    cols = []
    for j in range(4):
        c, d = s.q(0), s.q(0)
        for t in range(m):
            c = c + s.scalar(f"c{j}_{t}")
            d = d + s.scalar(f"d{j}_{t}")
        sg = 1 if (twin and j == 0) else -1
        cols.append([y * c, sg * x * c, w * d, -(z * d)])
    brows = [[cols[j][i] for j in range(4)] for i in range(4)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b}


@claim("s88h2c-cancel3", kind="id", section="8", sizes=FIX)
def cancel3(s):
    """k = 3 (g: 13,824 terms), m = 10: ab = 0 (TRUE)."""
    return _cancel(s, 3, 10)


@claim("s88h2c-cancel3-twin", kind="id", section="8", sizes=FIX)
def cancel3_twin(s):
    """FALSE twin: b[1, 0] = +x c_0."""
    return _cancel(s, 3, 10, True)


@claim("s88h2c-cancel4", kind="id", section="8", sizes=FIX)
def cancel4(s):
    """k = 4 (g: 331,776 terms), m = 1: ab = 0 (TRUE)."""
    return _cancel(s, 4, 1)


@claim("s88h2c-cancel4-twin", kind="id", section="8", sizes=FIX)
def cancel4_twin(s):
    """FALSE twin."""
    return _cancel(s, 4, 1, True)


def _chain(s, twin=False):
    """As cancel3, with a second nonzero row and partial common factors: row 0 = [g x, g y, O₁z, O₁w],
    row 1 = [O₂x, O₂y, O₂z, O₂w], g = D₁D₂D₃, O₁ = D₁D₂F₃, O₂ = D₁F₂F₃ (the content shrinks g twice, factoring it
    each time, and ends with D₁): ab = 0 (TRUE)."""
    D1, D2, D3, F2, F3 = D(s, "G1"), D(s, "G2"), D(s, "G3"), D(s, "F2"), D(s, "F3")
    g, O1, O2 = D1 * D2 * D3, D1 * D2 * F3, D1 * F2 * F3
    x, y, z, w = (s.scalar(t) for t in "xyzw")
    zero = s.q(0)
    rows = [[g * x, g * y, O1 * z, O1 * w], [O2 * x, O2 * y, O2 * z, O2 * w]] + [[zero] * 4 for _ in range(2)]
    cols = []
    for j in range(4):
        c, d = s.q(0), s.q(0)
        for t in range(10):
            c = c + s.scalar(f"c{j}_{t}")
            d = d + s.scalar(f"d{j}_{t}")
        sg = 1 if (twin and j == 0) else -1
        cols.append([y * c, sg * x * c, w * d, -(z * d)])
    brows = [[cols[j][i] for j in range(4)] for i in range(4)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b}


@claim("s88h2c-chain", kind="id", section="8", sizes=FIX)
def chain(s):
    """Partial common factors shrinking twice: ab = 0 (TRUE)."""
    return _chain(s)


@claim("s88h2c-chain-twin", kind="id", section="8", sizes=FIX)
def chain_twin(s):
    """FALSE twin."""
    return _chain(s, True)


def _cancel_x(s, m, twin=False, small=1):
    """As cancel3 with g = D₁D₂D₃·d₁⋯d_small, O = F₁F₂F₃·e₁⋯e_small (d_i, e_i determinants of 3×3 corners of generic
    matrices, 6 terms): ab = 0 (TRUE)."""
    g = D(s, "G1") * D(s, "G2") * D(s, "G3")
    O = D(s, "F1") * D(s, "F2") * D(s, "F3")
    for i in range(small):
        g = g * det(s, s.generic(f"g{i}", "n", "n")[0:3, 0:3])
        O = O * det(s, s.generic(f"o{i}", "n", "n")[0:3, 0:3])
    x, y, z, w = (s.scalar(t) for t in "xyzw")
    zero = s.q(0)
    rows = [[g * x, g * y, O * z, O * w]] + [[zero] * 4 for _ in range(3)]
    cols = []
    for j in range(4):
        c, d = s.q(0), s.q(0)
        for t in range(m):
            c = c + s.scalar(f"c{j}_{t}")
            d = d + s.scalar(f"d{j}_{t}")
        sg = 1 if (twin and j == 0) else -1
        cols.append([y * c, sg * x * c, w * d, -(z * d)])
    brows = [[cols[j][i] for j in range(4)] for i in range(4)]
    a, b = s.mat(rows, ("n", "n")), s.mat(brows, ("n", "n"))
    return {"ab": a @ b}


@claim("s88h2c-cancel3x", kind="id", section="8", sizes=FIX)
def cancel3x(s):
    """g = D₁D₂D₃d₁ (82,944 terms), m = 2: ab = 0 (TRUE)."""
    return _cancel_x(s, 2)


@claim("s88h2c-cancel3x-twin", kind="id", section="8", sizes=FIX)
def cancel3x_twin(s):
    """FALSE twin."""
    return _cancel_x(s, 2, True)
