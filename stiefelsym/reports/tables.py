"""Appendix tables: the paper's dimension formulas against exact computations, and the verdict
matrix of a results file.

(a) For every size 1 <= r <= n <= n_max, each dimension the paper prints (dim V, ddim, 2l, δ₀,
δ, the torus dimension (dim_fol), N, the leaf dimension (dimension) of Lemma LEMA1, the ranks of
(A1), (A2) and (KER) in Lemma LEMA2, the count of NEUMANN2, the invariant quadratic forms of the
proposition after Theorem ET) is computed from the matrix it is the rank of, with a two-sided
certificate (:mod:`stiefelsym.methods.dimensions`), and set next to the printed formula.  Where the paper
says "complete" or "independent" and that is a rank statement, the rank is computed too.

Every computation is done at X₀ = (E₁..E_r) with P = (P₁; P₂) (P₁ skew) and, where A enters, A a
generic symmetric matrix: the quantities are ranks of O(n)-covariant constructions, invariant
under (X, P, A) ↦ (gX, gP, gAgᵀ), and O(n) moves X₀ to every point of V, so the generic rank over
T*V × {diagonal A} is the generic rank over this slice.  The variables (entries of P₁, P₂, A) are
drawn as integers; every matrix below is polynomial in them, with the degree bound stated.

(b) The verdict matrix claim × size × method of a ``results.json``.
"""
from __future__ import annotations

import hashlib
import json
import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Iterable

import flint

from stiefelsym.methods.dimensions import Certificate, Side, exact, generic_rank, rank_at_point, verified_kernel

Z = flint.fmpz_mat


# -- the paper's formulas ---------------------------------------------------------------------------

def dim_so(m: int) -> int:
    return m * (m - 1) // 2 if m > 1 else 0


def dim_V(n: int, r: int) -> int:
    """§2: dim V(n, r) = rn - r(r+1)/2."""
    return r * n - r * (r + 1) // 2


def ddim_printed(n: int, r: int) -> int:
    """(ddim)."""
    if n <= 2 * r:
        return dim_V(n, r) - dim_so(n - r)
    return dim_V(n, r) - dim_so(n - r) + dim_so(n - 2 * r)


def two_l_printed(n: int, r: int) -> int:
    """Lemma 2l."""
    if n <= 2 * r + 1:
        return n * (n - 1) // 2 - n // 2
    return 2 * r * (n - r - 1)


def delta0_printed(n: int, r: int) -> int:
    """The closed form of δ₀ after Theorem bols-jov."""
    if n >= 2 * r:
        return r
    return dim_V(n, r) + dim_so(n - r) - dim_so(n) + n // 2


def delta0_definition(n: int, r: int) -> int:
    """δ₀ = 2 dim V − ddim − 2l with the printed ddim and 2l."""
    return 2 * dim_V(n, r) - ddim_printed(n, r) - two_l_printed(n, r)


def delta_printed(n: int, r: int) -> int | None:
    """§4: δ = r(n − r) for n >= 2r (the paper gives no closed form for n < 2r)."""
    return r * (n - r) if n >= 2 * r else None


def delta_definition(n: int, r: int) -> Fraction:
    """δ = 2 dim V − ddim − l with the printed ddim and 2l (l may be a half-integer if 2l is odd)."""
    return Fraction(2 * dim_V(n, r) - ddim_printed(n, r)) - Fraction(two_l_printed(n, r), 2)


def leaf_printed(n: int, r: int) -> int:
    """(dimension): 2l = 2r(n−r) + r(r−1)/2 − [r/2], the generic leaf in Θ(T*V)."""
    return 2 * r * (n - r) + r * (r - 1) // 2 - r // 2


def torus_printed(n: int, r: int) -> Fraction:
    """(dim_fol): ½(2r(n−r) + r(r−1)/2 − [r/2]) + [r/2]."""
    return Fraction(leaf_printed(n, r), 2) + r // 2


def N_printed(n: int, r: int) -> int:
    """§8: N = (n−1) + … + (n−r) = r(n−r) + r(r−1)/2."""
    return r * (n - r) + r * (r - 1) // 2


def ker_printed(n: int, r: int) -> int:
    """(KER): dim so(r)_{h1} ⊕ Sym(r) ⊕ gl(n−r) = [r/2] + r(r+1)/2 + (n−r)²."""
    return r // 2 + r * (r + 1) // 2 + (n - r) ** 2


def chain_complete_printed(n: int, r: int) -> Fraction:
    """§2: 𝔄 complete iff ddim 𝔄 = dim V − l, with the printed 2l."""
    return Fraction(dim_V(n, r)) - Fraction(two_l_printed(n, r), 2)


# -- integer matrices at a point of the slice X = X0 ------------------------------------------------

def zeros(m: int, k: int) -> Z:
    return Z(m, k, [0] * (m * k))


def unit(m: int, k: int, a: int, b: int) -> Z:
    M = zeros(m, k)
    M[a, b] = 1
    return M


def skew_basis(m: int) -> list[Z]:
    out = []
    for i in range(m):
        for j in range(i + 1, m):
            E = zeros(m, m)
            E[i, j], E[j, i] = 1, -1
            out.append(E)
    return out


def sym_basis(m: int) -> list[Z]:
    out = []
    for i in range(m):
        for j in range(i, m):
            E = zeros(m, m)
            E[i, j] = 1
            E[j, i] = 1
            out.append(E)
    return out


def gl_basis(n: int) -> tuple[list[Z], int]:
    """so(n) ⊕ Sym(n): the skew basis first; returns the basis and the number of skew elements."""
    so = skew_basis(n)
    return so + sym_basis(n), len(so)


def upper_entries(M: Z, strict: bool) -> list:
    m = M.nrows()
    return [M[i, j] for i in range(m) for j in range(i + (1 if strict else 0), m)]


def vec(M: Z) -> list:
    return list(M.entries())


def trace_pairing_row(M: Z) -> list:
    """The row a with a · vec(B) = tr(M B)."""
    n = M.nrows()
    return [M[j, i] for i in range(n) for j in range(M.ncols())]


def trace(M: Z):
    return sum((M[i, i] for i in range(M.nrows())), flint.fmpz(0))


@dataclass
class Point:
    """(X0, P, A) with P = (P1; P2), P1 skew, A symmetric, from a list of integers."""

    n: int
    r: int
    X: Z
    P: Z
    A: Z

    @property
    def Phi(self) -> Z:
        return self.P * self.X.transpose() - self.X * self.P.transpose()

    @property
    def Psi(self) -> Z:
        return self.X.transpose() * self.P - self.P.transpose() * self.X

    @property
    def v(self) -> Z:
        return self.X * self.X.transpose()


def X0(n: int, r: int) -> Z:
    X = zeros(n, r)
    for i in range(r):
        X[i, i] = 1
    return X


def nvars(n: int, r: int, *, with_A: bool = True, P1: bool = True, P2: bool = True) -> int:
    return (dim_so(r) if P1 else 0) + ((n - r) * r if P2 else 0) + (n * (n + 1) // 2 if with_A else 0)


def make_point(n: int, r: int, x: list[int], *, with_A: bool = True, P1: bool = True, P2: bool = True,
               diagonal_A: bool = False) -> Point:
    it = iter(x)
    P = zeros(n, r)
    if P1:
        for i in range(r):
            for j in range(i + 1, r):
                c = next(it)
                P[i, j], P[j, i] = c, -c
    if P2:
        for i in range(r, n):
            for j in range(r):
                P[i, j] = next(it)
    A = zeros(n, n)
    if with_A:
        for i in range(n):
            for j in range(i, n):
                c = next(it)
                if diagonal_A and i != j:
                    continue
                A[i, j] = c
                A[j, i] = c
    return Point(n, r, X0(n, r), P, A)


# -- the tangent space of T*V at (X0, P) and the symplectic form ---------------------------------------

def tangent_basis(pt: Point) -> tuple[list[tuple[Z, Z]], list[tuple[Z, Z]]]:
    """A basis of T_{(X0,P)}T*V: the horizontal directions (2δX, −X0(δXᵀP + PᵀδX)) with
    δX = (ω; 0), (0; E_ab), and the vertical ones (0, X0 ω), (0, (0; E_ab)); dim V of each."""
    n, r, X, P = pt.n, pt.r, pt.X, pt.P
    dXs = [_stack(w, zeros(n - r, r)) for w in skew_basis(r)]
    dXs += [_stack(zeros(r, r), unit(n - r, r, a, b)) for a in range(n - r) for b in range(r)]
    horizontal = [(2 * dX, -(X * (dX.transpose() * P + P.transpose() * dX))) for dX in dXs]
    vertical = [(zeros(n, r), dX) for dX in dXs]
    return horizontal, vertical


def _stack(top: Z, bottom: Z) -> Z:
    m1, m2, k = top.nrows(), bottom.nrows(), top.ncols()
    out = zeros(m1 + m2, k)
    for i in range(m1):
        for j in range(k):
            out[i, j] = top[i, j]
    for i in range(m2):
        for j in range(k):
            out[m1 + i, j] = bottom[i, j]
    return out


def omega(a: tuple[Z, Z], b: tuple[Z, Z]):
    """ω₀(a, b) = tr(δP_aᵀ δX_b) − tr(δP_bᵀ δX_a)."""
    return trace(a[1].transpose() * b[0]) - trace(b[1].transpose() * a[0])


def poisson_inverse(pt: Point, basis: list[tuple[Z, Z]]) -> Z:
    """A nonzero integer multiple of Ω⁻¹, Ω = (ω₀(t_i, t_j)) in the basis horizontal + vertical.

    Ω = [[C, K], [−Kᵀ, 0]] with K = ω₀(horizontal, vertical) constant diagonal (entries 4 and 2),
    so Ω⁻¹ = [[0, −K⁻ᵀ], [K⁻¹, K⁻¹CK⁻ᵀ]], exactly."""
    m = len(basis) // 2
    Om = Z([[omega(a, b) for b in basis] for a in basis])
    Kd = [Om[i, m + i] for i in range(m)]
    for i in range(m):
        for j in range(m):
            if i != j and Om[i, m + j] != 0:
                raise ArithmeticError("the pairing of horizontal and vertical directions is not diagonal")
    scale = 1
    for k in Kd:
        scale = scale * int(k) // math.gcd(scale, int(k))
    scale = scale * scale
    inv = zeros(2 * m, 2 * m)
    for i in range(m):
        inv[i, m + i] = -scale // int(Kd[i])
        inv[m + i, i] = scale // int(Kd[i])
        for j in range(m):
            inv[m + i, m + j] = Om[i, j] * scale // (int(Kd[i]) * int(Kd[j]))
    check = Om * inv
    for i in range(2 * m):
        for j in range(2 * m):
            if check[i, j] != (scale if i == j else 0):
                raise ArithmeticError("Ω·Ω⁻¹ is not the identity")
    return inv


# -- differentials of the paper's functions along the tangent basis ----------------------------------

def d_Phi(pt: Point, t: tuple[Z, Z]) -> Z:
    dX, dP = t
    X, P = pt.X, pt.P
    return dP * X.transpose() + P * dX.transpose() - dX * P.transpose() - X * dP.transpose()


def d_Psi(pt: Point, t: tuple[Z, Z]) -> Z:
    dX, dP = t
    X, P = pt.X, pt.P
    return dX.transpose() * P + X.transpose() * dP - dP.transpose() * X - P.transpose() * dX


def d_gram(pt: Point, t: tuple[Z, Z]) -> Z:
    dP = t[1]
    return dP.transpose() * pt.P + pt.P.transpose() * dP


def d_v(pt: Point, t: tuple[Z, Z]) -> Z:
    dX = t[0]
    return dX * pt.X.transpose() + pt.X * dX.transpose()


def rows_of(component_lists: list[list]) -> list[list]:
    """Columns (one list of components per tangent vector) -> rows (one per component)."""
    return [list(row) for row in zip(*component_lists)]


def trace_power_differentials(M: Z, dM: list[Z], kmax: int) -> list[list]:
    """Rows k·tr(M^{k−1} δM_t), k = 1..kmax, over the tangent vectors t (δM_t given)."""
    n = M.nrows()
    DM = Z([vec(d) for d in dM]).transpose() if dM else zeros(n * n, 0)   # n² x T
    W_rows, power = [], Z([[1 if i == j else 0 for j in range(n)] for i in range(n)])
    for k in range(1, kmax + 1):
        W_rows.append([k * e for e in trace_pairing_row(power)])
        power = power * M
    return (Z(W_rows) * DM).tolist()


def casimir_rows(pt: Point, tangent: list[tuple[Z, Z]]) -> list[list]:
    """The differentials of 𝓕 ∘ Θ = {tr(λΦ + XXᵀ − λ²A)^k}: k = 1..n and 2n values of λ (the
    row is a polynomial of degree <= 2k − 1 in λ, so these values span every λ)."""
    n = pt.n
    Phi, v, A = pt.Phi, pt.v, pt.A
    dPhi = [d_Phi(pt, t) for t in tangent]
    dv = [d_v(pt, t) for t in tangent]
    rows = []
    for lam in range(2 * n):
        M = lam * Phi + v - lam * lam * A
        rows += trace_power_differentials(M, [lam * a + b for a, b in zip(dPhi, dv)], n)
    return rows


def manakov_rows(pt: Point, tangent: list[tuple[Z, Z]]) -> list[list]:
    """The differentials of (man) tr(Φ + λA)^k, k = 1..n, at n values of λ (degree k − 1 in λ)."""
    n = pt.n
    dPhi = [d_Phi(pt, t) for t in tangent]
    rows = []
    for lam in range(n):
        rows += trace_power_differentials(pt.Phi + lam * pt.A, dPhi, n)
    return rows


def psi_rows(pt: Point, tangent) -> list[list]:
    return rows_of([upper_entries(d_Psi(pt, t), True) for t in tangent])


def gram_rows(pt: Point, tangent) -> list[list]:
    return rows_of([upper_entries(d_gram(pt, t), False) for t in tangent])


def phi_rows(pt: Point, tangent) -> list[list]:
    return rows_of([upper_entries(d_Phi(pt, t), True) for t in tangent])


def stack_rows(*blocks: list[list], ncols: int) -> Z:
    rows = [row for block in blocks for row in block]
    return Z(rows) if rows else zeros(0, ncols)


# -- the brackets Λ1, Λ2 on gl(n) ---------------------------------------------------------------------

def lie_poisson(x: Z, basis: list[Z]) -> Z:
    """(tr(x[u_i, u_j])): −2 times the Lie–Poisson tensor <x, [u_i, u_j]> of gl(n) in the basis."""
    U = Z([vec(u) for u in basis]).transpose()          # n² x n²: columns vec(u_j)
    rows = [trace_pairing_row(x * u - u * x) for u in basis]   # tr([x, u_i] u_j) = tr(x [u_i, u_j])
    return Z(rows) * U


def lambda1(x: Z, basis: list[Z], nskew: int) -> Z:
    """Λ1 at x (up to the factor −2): the Lie–Poisson tensor with the Sym × Sym block removed."""
    L = lie_poisson(x, basis)
    m = len(basis)
    for i in range(nskew, m):
        for j in range(nskew, m):
            L[i, j] = 0
    return L


def lambda2(x: Z, A: Z, basis: list[Z]) -> Z:
    """Λ2 at x: <x − A, [u_i, u_j]> (up to −2)."""
    return lie_poisson(x - A, basis)


def gram_inverse(basis: list[Z], nskew: int) -> Z:
    """A multiple of the inverse Gram matrix of <a, b> = −½tr(ab) in the basis (diagonal: 1 on
    E_i∧E_j, −1 on E_ij + E_ji, −2 on E_ii): turns the rows df(u_j) into coordinates of ∇f."""
    m = len(basis)
    G = zeros(m, m)
    for k, u in enumerate(basis):
        G[k, k] = 1 if k < nskew else (-2 if sum(1 for e in u.entries() if e != 0) == 1 else -1)
    return G


def casimir_gradients(x: Z, A: Z, basis: list[Z], nskew: int) -> Z:
    """Rows df(u_j) of f = tr(λh + v − λ²A)^k, x = h + v: k·tr(M^{k−1}(λu)) on so(n), k·tr(M^{k−1}u)
    on Sym(n); k = 1..n, 2n values of λ."""
    n = x.nrows()
    # x = h + v with h = (x − xᵀ)/2, v = (x + xᵀ)/2: work with 2x to stay in ℤ (scales every row)
    h2 = x - x.transpose()
    v2 = x + x.transpose()
    U = Z([vec(u) for u in basis]).transpose()
    rows = []
    for lam in range(2 * n):
        M = lam * h2 + v2 - 2 * lam * lam * A       # 2(λh + v − λ²A)
        power = Z([[1 if i == j else 0 for j in range(n)] for i in range(n)])
        for k in range(1, n + 1):
            row = (Z([trace_pairing_row(power)]) * U).tolist()[0]
            rows.append([k * (lam * c if j < nskew else c) for j, c in enumerate(row)])
            power = power * M
    return Z(rows)


# -- invariant quadratic forms on the fibre (the proposition after Theorem ET) --------------------------

def invariant_forms_matrix(n: int, r: int) -> tuple[Z, int, Z]:
    """The linear conditions on the coefficients of a quadratic form on T*_{X0}V (coordinates: P1
    above the diagonal, then P2) to be invariant under P1 ↦ QᵀP1Q, P2 ↦ BP2Q (Q ∈ SO(r),
    B ∈ SO(n−r)); and the coefficient vectors of tr(PᵀP), tr((XᵀP)²) as columns."""
    coords = [("P1", i, j) for i, j in _pairs(r)] + [("P2", a, b) for a in range(n - r) for b in range(r)]
    index = {c: k for k, c in enumerate(coords)}
    N = len(coords)

    def action(eta: Z | None, beta: Z | None) -> list[list[int]]:
        """The matrix of the infinitesimal action: P1 ↦ [P1, η], P2 ↦ βP2 + P2η."""
        T = [[0] * N for _ in range(N)]
        for k, c in enumerate(coords):
            P1, P2 = zeros(r, r), zeros(n - r, r)
            if c[0] == "P1":
                P1[c[1], c[2]], P1[c[2], c[1]] = 1, -1
            else:
                P2[c[1], c[2]] = 1
            img1 = P1 * eta - eta * P1 if eta is not None else zeros(r, r)
            img2 = zeros(n - r, r)
            if eta is not None:
                img2 += P2 * eta
            if beta is not None:
                img2 += beta * P2
            for (i, j) in _pairs(r):
                T[index[("P1", i, j)]][k] += int(img1[i, j])
            for a in range(n - r):
                for b in range(r):
                    T[index[("P2", a, b)]][k] += int(img2[a, b])
        return T

    gens = [action(E, None) for E in skew_basis(r)] + [action(None, B) for B in skew_basis(n - r)]
    unknowns = [(i, j) for i in range(N) for j in range(i, N)]
    rows = []
    for T in gens:
        for k in range(N):
            for l in range(k, N):
                row = []
                for (i, j) in unknowns:
                    c = 0   # (TᵀG + GT)_{kl} as a linear form in G_ij = G_ji
                    for (a, b) in {(i, j), (j, i)}:
                        c += T[a][k] * (1 if b == l else 0) + (1 if a == k else 0) * T[b][l]
                    row.append(c)
                rows.append(row)
    # the paper's forms: tr(PᵀP) = 2 Σ P1_ij² + Σ P2_ab², tr((XᵀP)²) = tr(P1²) = −2 Σ P1_ij²
    def form(weights: dict) -> list[int]:
        return [weights.get(coords[i][0], 0) if i == j else 0 for (i, j) in unknowns]
    paper = Z([form({"P1": 2, "P2": 1}), form({"P1": -2})]).transpose() if unknowns else zeros(0, 2)
    M = Z(rows) if rows else zeros(0, len(unknowns))
    return M, len(unknowns), paper


def _pairs(m: int):
    return [(i, j) for i in range(m) for j in range(i + 1, m)]


# -- one size -------------------------------------------------------------------------------------------

@dataclass
class Row:
    """One quantity at one size: the printed formula, the computed certificate, agreement."""

    key: str
    label: str
    printed: Any
    cert: Certificate
    agree: bool | None = None   # None: nothing printed at this size

    def as_dict(self) -> dict:
        printed = self.printed
        if isinstance(printed, Fraction):
            printed = str(printed) if printed.denominator != 1 else int(printed)
        return {"key": self.key, "label": self.label, "printed": printed, "agree": self.agree,
                **self.cert.as_dict()}


#: the table's quantities: key -> (paper label, meaning)
QUANTITIES = {
    "dimV": ("cond_XP", "dim V = nr − rank d(XᵀX) at X₀"),
    "ddim": ("ddim", "dim V − generic rank of b ↦ bP₂ on so(n−r)"),
    "ddim_inv": ("SO(n)-inv", "generic rank of d(Ψ_ij, (PᵀP)_ij) on the fibre (= ddim: they define the generic orbits)"),
    "2l": ("2l", "generic rank of ad_Φ on so(n)"),
    "regular": ("2l", "the generic orbit in Φ(T*V) is regular (1) or not (0); printed: n ≤ 2r + 1"),
    "chain": ("com", "generic rank of d𝔄 on the fibre; printed: dim V − l (𝔄 complete)"),
    "delta0": ("bols-jov", "2 dim V − rank d(Φ, Ψ, PᵀP)"),
    "delta0_complete": ("bols-jov", "rank d(Φ,Ψ,PᵀP) − rank{ , } (isotropic kernel); = δ₀ iff complete"),
    "delta": ("man", "2 dim V − rank d(Ψ, PᵀP, tr(Φ+λA)^k); printed r(n−r) for n ≥ 2r"),
    "delta_complete": ("man", "rank d(F) − rank{F, F} for the Manakov integrals; = δ iff complete"),
    "leaf": ("dimension", "generic rank of Λ1 at Θ(X,P) (Lemma LEMA1; (L1), (L2))"),
    "leaf_singular": ("dimension", "2l < n² − n (the leaves in Θ(T*V) are singular): 1 if the computed 2l is below n² − n"),
    "L5L6": ("L6", "dim of the solutions of (L5), (L6) as printed in so(r)_{h1} ⊕ Sym(r); printed: r"),
    "L5L6_corrected": ("L6", "the same with (L6) read as [A1, η1] ⟂ so(r)_{h1}; printed: r"),
    "leaf_pushforward": ("dimension", "generic rank of dΘ·ω⁻¹·dΘᵀ (Θ is Poisson: the same leaf)"),
    "complete_F": ("LEMA2", "generic rank of (d𝓕)·Λ1 (independent Casimirs on the leaf); printed: l"),
    "A1": ("LEMA2", "generic rank of Λ_{1,−1} at Θ(X,P); printed: n² − n (the condition (A1); (LAMBDA), (L3), (L4))"),
    "A1_t": ("LEMA2", "generic rank of Λ_{1,t} (t a variable) and of Λ2; printed: n² − n"),
    "KER": ("KER", "dim ker Λ1 at h = diag(h₁, 0), with the printed kernel checked inside"),
    "A2": ("A2", "dim of ker Λ_{1,−1} restricted to ker Λ1 at h = diag(h₁, 0), A diagonal (the condition (A2); (L5)–(L8))"),
    "torus": ("dim_fol", "2 dim V − rank d(Θ*𝓕, Ψ) (NEUMANN)"),
    "torus_complete": ("NEUMANN", "rank d(Θ*𝓕, Ψ) − rank{ , }; = torus iff complete"),
    "NEUMANN2": ("NEUMANN2", "generic rank of (d𝓕)·Λ1 at Ψ = 0; printed r(n−r) = dim G(n,r)"),
    "N": ("2r-integrals", "Σ_l (deg I_2l) = Σ_{l=1}^r (n − l) = dim V"),
    "N_rank": ("2r-integrals", "rank of d tr(a(λ)𝓛*(λ))^k (k ≤ 2r, enough λ) on T*V: the independent integrals of the "
               "dual Lax matrix 𝓛*_neum(λ) (the display (2) §8) among the N (nothing printed: the paper says some are dependent)"),
    "N_dependent": ("2r-integrals", "some of the N integrals are dependent (1) or not (0): the computed rank below N"),
    "N_vs_l": ("2r-integrals", "N > l (half the leaf (dimension)): some of the N integrals are dependent"),
    "invariant_forms": ("SO(n-r)-action", "dim of SO(r)×SO(n−r)-invariant quadratic forms on the fibre; printed: dim span{tr PᵀP, tr (XᵀP)²}"),
}


#: the invariant quadratic forms are computed when dim V is at most this (the linear system has
#: dim V (dim V + 1)/2 unknowns and (dim so(r) + dim so(n − r)) times as many equations)
INVARIANT_FORMS_MAX_DIM = 30

#: the quantities computed beyond the full range (n_max < n <= extended n_max): every dimension of
#: the table without the completeness checks (Poisson matrices of the integrals), which grow fastest
EXTENDED = ("dimV", "ddim", "ddim_inv", "2l", "regular", "chain", "delta0", "delta", "leaf", "leaf_singular",
            "L5L6", "L5L6_corrected", "A1", "A1_t", "KER", "A2", "torus", "N", "N_rank", "N_dependent", "N_vs_l")


def _cmp(printed, cert: Certificate) -> bool | None:
    if printed is None:
        return None
    v = cert.value
    if v is None:   # the bounds do not meet: a disagreement only if the printed value is outside them
        return False if not cert.lower.bound <= printed <= cert.upper.bound else None
    return Fraction(printed) == v


def compute_size(n: int, r: int, *, seed: int = 0, include: Iterable[str] | None = None) -> list[Row]:
    """Every quantity of the table at (n, r)."""
    want = set(include) if include is not None else set(QUANTITIES)
    rows: list[Row] = []
    s = f"{seed}|{n}|{r}"

    def add(key, printed, cert):
        if key in want:
            rows.append(Row(key, QUANTITIES[key][0], printed, cert, _cmp(printed, cert)))

    dV = dim_V(n, r)
    # dim V: the differential of XᵀX at X0 on M_{n,r}, constant; V is homogeneous
    cols = []
    for a in range(n):
        for b in range(r):
            dX = unit(n, r, a, b)
            cols.append(upper_entries(dX.transpose() * X0(n, r) + X0(n, r).transpose() * dX, False))
    rk = rank_at_point(rows_of(cols), "rank d(XᵀX)", seed=seed, where="at X0 (V is homogeneous)")
    dimV_cert = (n * r - rk).renamed("dim V")
    add("dimV", dV, dimV_cert)

    # ddim: the orbit map b -> b P2 on so(n-r), variables P2, degree 1
    nP2 = (n - r) * r

    def orbit(x):
        pt = make_point(n, r, x, with_A=False, P1=False)
        P2 = Z([[pt.P[r + a, b] for b in range(r)] for a in range(n - r)]) if n > r else zeros(0, r)
        return [vec(B * P2) for B in skew_basis(n - r)] or [[0] * max(nP2, 1)]
    if "ddim" in want:
        if n - r >= 2 and r >= 1:
            orb = generic_rank(orbit, nP2, 1, "rank of b ↦ bP₂", seed=seed)
        else:
            orb = exact("rank of b ↦ bP₂", 0, "so(n−r) = 0")
        add("ddim", ddim_printed(n, r), (dV - orb).renamed("ddim"))

    nv_fibre = nvars(n, r, with_A=False)

    def invariants(x):
        pt = make_point(n, r, x, with_A=False)
        _, vertical = tangent_basis(pt)
        return stack_rows(psi_rows(pt, vertical), gram_rows(pt, vertical), ncols=len(vertical))
    if "ddim_inv" in want:
        add("ddim_inv", ddim_printed(n, r), _safe_generic(invariants, nv_fibre, 1, "rank d(Ψ, PᵀP) on the fibre", seed, dV))

    # 2l: ad_Phi on so(n)
    def ad_phi(x):
        pt = make_point(n, r, x, with_A=False)
        Phi = pt.Phi
        return [upper_entries(Phi * e - e * Phi, True) for e in skew_basis(n)] or [[0]]
    two_l = _safe_generic(ad_phi, nv_fibre, 1, "rank ad_Φ", seed, dim_so(n)) if want & {"2l", "regular"} else None
    if two_l is not None and two_l.lower.bound == dim_so(n) - n // 2 and not two_l.upper.proved:
        two_l = _odd_powers_bound(two_l, n, r, seed)
    if two_l is not None:
        add("2l", two_l_printed(n, r), two_l)
    regular_value = n * (n - 1) // 2 - n // 2
    if two_l is not None and two_l.value is not None:
        add("regular", int(n <= 2 * r + 1), exact("regular", int(two_l.value == regular_value),
                                                  f"2l = {two_l.value} against n(n−1)/2 − [n/2] = {regular_value}"))

    # the chain algebra: generators tr ξ_(m)^{2k}, n − r < m <= n, on the fibre
    def chain(x):
        pt = make_point(n, r, x, with_A=False)
        _, vertical = tangent_basis(pt)
        Phi = pt.Phi
        out = []
        for m in range(n - r + 1, n + 1):
            lo = n - m
            block = Z([[Phi[lo + i, lo + j] for j in range(m)] for i in range(m)])
            dblocks = [Z([[d[lo + i, lo + j] for j in range(m)] for i in range(m)])
                       for d in (d_Phi(pt, t) for t in vertical)]
            out += [row for k, row in enumerate(trace_power_differentials(block, dblocks, m)) if k % 2 == 1]
        return stack_rows(out, ncols=len(vertical))
    if "chain" in want:
        add("chain", chain_complete_printed(n, r), _safe_generic(chain, nv_fibre, n, "rank d𝔄 on the fibre", seed, dV))

    # tori of the geodesic flows: all of Φ with the SO(n)-invariants
    def full_T(x, with_A=False):
        pt = make_point(n, r, x, with_A=with_A)
        hor, ver = tangent_basis(pt)
        return pt, hor + ver

    def bols_jov(x):
        pt, T = full_T(x)
        return stack_rows(phi_rows(pt, T), psi_rows(pt, T), gram_rows(pt, T), ncols=len(T))

    def bols_jov_bracket(x):
        pt, T = full_T(x)
        D = bols_jov(x)
        return D * poisson_inverse(pt, T) * D.transpose()
    if want & {"delta0", "delta0_complete"}:
        rank_D = _safe_generic(bols_jov, nv_fibre, 2, "rank d(Φ, Ψ, PᵀP)", seed, 2 * dV)
        add("delta0", delta0_printed(n, r), (2 * dV - rank_D).renamed("δ₀"))
    if "delta0_complete" in want:
        rank_B = _safe_generic(bols_jov_bracket, nv_fibre, 5, "rank {Φ,Ψ,PᵀP}", seed, 2 * dV)
        add("delta0_complete", delta0_printed(n, r), (rank_D - rank_B).renamed("rank dF − rank{F,F}"))

    nv_all = nvars(n, r)

    def manakov(x):
        pt, T = full_T(x, True)
        return stack_rows(psi_rows(pt, T), gram_rows(pt, T), manakov_rows(pt, T), ncols=len(T))

    def manakov_bracket(x):
        pt, T = full_T(x, True)
        D = manakov(x)
        return D * poisson_inverse(pt, T) * D.transpose()
    d_def = delta_definition(n, r)
    if want & {"delta", "delta_complete"}:
        rank_M = _safe_generic(manakov, nv_all, max(n, 2), "rank d(Ψ, PᵀP, man)", seed, 2 * dV)
        add("delta", delta_printed(n, r) if delta_printed(n, r) is not None else d_def,
            (2 * dV - rank_M).renamed("δ"))
    if "delta_complete" in want:
        rank_MB = _safe_generic(manakov_bracket, nv_all, 2 * max(n, 2) + 1, "rank {man, man}", seed, 2 * dV)
        add("delta_complete", delta_printed(n, r) if delta_printed(n, r) is not None else d_def,
            (rank_M - rank_MB).renamed("rank dF − rank{F,F}"))

    # Λ1, Λ2 on gl(n) at x = Θ(X0, P) = Φ + X0X0ᵀ
    basis, nskew = gl_basis(n)

    def theta_point(x, **kw):
        pt = make_point(n, r, x, **kw)
        return pt, pt.Phi + pt.v

    leaf = _safe_generic(lambda x: lambda1(theta_point(x, with_A=False)[1], basis, nskew), nv_fibre, 1,
                         "rank Λ1(Θ)", seed, n * n) if want & {"leaf", "leaf_singular", "N_vs_l"} else None
    if leaf is not None and not leaf.upper.proved and r <= LEAF_PROOF_MAX_R:
        leaf = _leaf_kernel_bound(leaf, n, r, seed)
    if leaf is not None:
        add("leaf", leaf_printed(n, r), leaf)
    if leaf is not None and leaf.value is not None:
        add("leaf_singular", 1, exact("2l < n² − n", int(leaf.value < n * n - n),
                                      f"2l = {leaf.value} against n² − n = {n * n - n}"))
    if want & {"L5L6", "L5L6_corrected"}:
        for key, printed_l6 in (("L5L6", True), ("L5L6_corrected", False)):
            M, unknowns = l5_l6_matrix(r, printed_l6, seed=f"{s}|L5L6")
            add(key, r, (unknowns - rank_at_point(M, "rank", seed=seed, where="at h1, A1 (random integers)")).renamed(
                "dim of the solutions of (L5), (L6)"))

    def pushforward(x):
        pt, T = full_T(x)
        D = Z([vec(d_Phi(pt, t) + d_v(pt, t)) for t in T]).transpose()   # n² x 2dim V
        return D * poisson_inverse(pt, T) * D.transpose()
    if "leaf_pushforward" in want:
        add("leaf_pushforward", leaf_printed(n, r), _safe_generic(pushforward, nv_fibre, 3, "rank dΘ ω⁻¹ dΘᵀ", seed, n * n))

    def casimirs_on_leaf(x, **kw):
        pt, th = theta_point(x, **kw)
        return casimir_gradients(th, pt.A, basis, nskew) * gram_inverse(basis, nskew) * lambda1(th, basis, nskew)
    if "complete_F" in want:
        add("complete_F", Fraction(leaf_printed(n, r), 2),
            _safe_generic(casimirs_on_leaf, nv_all, n, "rank d𝓕·Λ1", seed, n * n))

    def lam_1m1(x):
        pt, th = theta_point(x)
        return lambda1(th, basis, nskew) - lambda2(th, pt.A, basis)
    if "A1" in want:
        add("A1", n * n - n, _safe_generic(lam_1m1, nv_all, 1, "rank Λ_{1,−1}", seed, n * n))

    def lam_t(x):
        pt, th = theta_point(x[1:])
        t = x[0]
        return lambda1(th, basis, nskew) + t * lambda2(th, pt.A, basis)
    if "A1_t" in want:
        add("A1_t", n * n - n, _safe_generic(lam_t, nv_all + 1, 2, "rank Λ_{1,t}", seed, n * n))

    # KER and (A2) at h = diag(h1, 0) (P2 = 0), A diagonal: exact at one point
    if "KER" in want or "A2" in want:
        import random as _random
        rng = _random.Random(f"{s}|KER")
        x = [rng.randint(-2 ** 20, 2 ** 20) for _ in range(nvars(n, r, P2=False))]
        pt = make_point(n, r, x, P2=False, diagonal_A=True)
        # distinct diagonal entries (the lemma assumes them)
        while len({int(pt.A[i, i]) for i in range(n)}) < n:
            x = [rng.randint(-2 ** 20, 2 ** 20) for _ in range(len(x))]
            pt = make_point(n, r, x, P2=False, diagonal_A=True)
        th = pt.Phi + pt.v
        L1 = lambda1(th, basis, nskew)
        ker_cert = (n * n - rank_at_point(L1, "rank Λ1", seed=seed, where="at h = diag(h1, 0)")).renamed("dim ker Λ1")
        printed_kernel = _printed_ker_basis(pt, basis)
        k_in = verified_kernel(L1, printed_kernel)
        ker_cert = Certificate(ker_cert.quantity, ker_cert.lower, ker_cert.upper,
                               (f"the printed space so(r)_h1 ⊕ Sym(r) ⊕ gl(n−r) lies in the kernel: "
                                f"{k_in} independent vectors checked exactly",))
        add("KER", ker_printed(n, r), ker_cert)
        if "A2" in want and k_in == printed_kernel.ncols():
            L = L1 - lambda2(th, pt.A, basis)
            restricted = printed_kernel.transpose() * L * printed_kernel
            a2 = (k_in - rank_at_point(restricted, "rank", seed=seed, where="at h = diag(h1, 0)")).renamed(
                "dim ker Λ_{1,−1}|ker Λ1")
            if ker_cert.value == k_in:
                add("A2", n, a2)

    def torus(x):
        pt, T = full_T(x, True)
        return stack_rows(casimir_rows(pt, T), psi_rows(pt, T), ncols=len(T))

    def torus_bracket(x):
        pt, T = full_T(x, True)
        D = torus(x)
        return D * poisson_inverse(pt, T) * D.transpose()
    if want & {"torus", "torus_complete"}:
        rank_T = _safe_generic(torus, nv_all, n, "rank d(Θ*𝓕, Ψ)", seed, 2 * dV)
        add("torus", torus_printed(n, r), (2 * dV - rank_T).renamed("torus dimension"))
    if "torus_complete" in want:
        rank_TB = _safe_generic(torus_bracket, nv_all, 2 * n + 1, "rank {Θ*𝓕, Ψ}", seed, 2 * dV)
        add("torus_complete", torus_printed(n, r), (rank_T - rank_TB).renamed("rank dF − rank{F,F}"))

    # NEUMANN2: Ψ = 0 (P1 = 0)
    if "NEUMANN2" in want:
        nv2 = nvars(n, r, P1=False)
        neu2 = _safe_generic(lambda x: casimirs_on_leaf(x, P1=False), nv2, n, "rank d𝓕·Λ1 at Ψ = 0", seed, n * n)
        add("NEUMANN2", r * (n - r), neu2)

    # the integrals of the dual Lax matrix: how many of the N are independent
    if want & {"N_rank", "N_dependent"} and n * r <= N_RANK_MAX_NR:
        def dual(x):
            pt, T = full_T(x, True)
            return stack_rows(dual_lax_rows(pt, T), ncols=len(T))
        # entries of a(λ)𝓛*(λ) and of their derivatives have degree <= n + 1 in (P, A)
        N_rank = _safe_generic(dual, nv_all, 2 * r * (n + 1), "rank d tr(a𝓛*)^k", seed, 2 * dV)
        add("N_rank", None, N_rank)
        if N_rank.value is not None:
            add("N_dependent", 1, exact("some dependent", int(N_rank.value < N_printed(n, r)),
                                        f"rank {N_rank.value} against N = {N_printed(n, r)}"))

    # N: a count; and the remark that N exceeds half the leaf dimension
    N_comp = exact("N", sum(n - l for l in range(1, r + 1)), "Σ_{l=1}^r deg I_2l, deg I_2l = n − l")
    add("N", N_printed(n, r), N_comp)
    if leaf is not None and leaf.value is not None:
        add("N_vs_l", 1, exact("N > l", int(2 * N_printed(n, r) > leaf.value),
                               f"N = {N_printed(n, r)} against l = {Fraction(leaf.value, 2)}"))

    if "invariant_forms" in want and dV <= INVARIANT_FORMS_MAX_DIM:
        M, unknowns, paper = invariant_forms_matrix(n, r)
        inv = (unknowns - rank_at_point(M, "rank", seed=seed, where="(constant matrix)")).renamed(
            "invariant quadratic forms") if M.nrows() else exact("invariant quadratic forms", unknowns, "no condition")
        paper_span = rank_at_point(paper, "span", seed=seed, where="(constant)") if paper.nrows() else exact("span", 0, "")
        k_in = verified_kernel(M, paper) if M.nrows() else paper.rank()
        if paper_span.value is not None:
            inv = Certificate(inv.quantity, inv.lower, inv.upper,
                              (f"tr(PᵀP), tr((XᵀP)²) are invariant: {k_in} independent, checked exactly",))
            add("invariant_forms", paper_span.value, inv)
    return rows


#: the rank of the dual Lax integrals is computed while n·r is at most this (2rn + 1 values of λ, powers
#: up to 2r of a 2r x 2r matrix)
N_RANK_MAX_NR = 20


def adjugate(M: Z) -> Z:
    """adj(M) = det(M) M⁻¹, exactly (M invertible)."""
    d = M.det()
    inv = flint.fmpq_mat(M).inv() * flint.fmpq(int(d))
    num, den = inv.numer_denom()
    if den != 1:
        raise ArithmeticError("the adjugate is not integral")
    return num


def dual_lax_rows(pt: Point, tangent: list[tuple[Z, Z]]) -> list[list]:
    """The differentials of tr(a(λ)𝓛*(λ))^k, k = 1..2r, 𝓛* of the display (2) §8, a(λ) = det(λI − A), at 2rn + 1
    integer values of λ (each row is a polynomial of degree <= 2rn in λ)."""
    n, r = pt.n, pt.r
    X, P, A = pt.X, pt.P, pt.A
    I_r = Z([[1 if i == j else 0 for j in range(r)] for i in range(r)])
    rows = []
    lam = 0
    used = 0
    while used < 2 * r * n + 1:
        lam += 1
        Lm = Z([[lam if i == j else 0 for j in range(n)] for i in range(n)]) - A
        a = Lm.det()
        if a == 0:
            continue
        used += 1
        R = adjugate(Lm)          # a(λ)(λI − A)⁻¹

        def L(X, P, dX=None, dP=None):
            if dX is None:
                return _block(-(X.transpose() * R * P), -(X.transpose() * R * X),
                              int(a) * I_r + P.transpose() * R * P, P.transpose() * R * X)
            return _block(-(dX.transpose() * R * P + X.transpose() * R * dP),
                          -(dX.transpose() * R * X + X.transpose() * R * dX),
                          dP.transpose() * R * P + P.transpose() * R * dP,
                          dP.transpose() * R * X + P.transpose() * R * dX)
        M = L(X, P)
        rows += trace_power_differentials(M, [L(X, P, dX, dP) for dX, dP in tangent], 2 * r)
    return rows


def _block(a: Z, b: Z, c: Z, d: Z) -> Z:
    m, k = a.nrows(), a.ncols()
    out = zeros(2 * m, 2 * k)
    for i in range(m):
        for j in range(k):
            out[i, j], out[i, k + j], out[m + i, j], out[m + i, k + j] = a[i, j], b[i, j], c[i, j], d[i, j]
    return out


def l5_l6_matrix(r: int, printed: bool, seed: str) -> tuple[Z, int]:
    """(L5), (L6) on ξ1 ∈ so(r)_{h1} (odd powers of h1), η1 ∈ Sym(r), at random integer h1 ∈ so(r) and
    A1 = diag (distinct): (L6) as printed ([A1, η1] ∈ so(r)^⊥ = Sym(r), i.e. [A1, η1] = 0) or corrected
    ([A1, η1] ⟂ so(r)_{h1})."""
    import random as _random
    rng = _random.Random(seed)
    h1, A1 = zeros(r, r), zeros(r, r)
    for i, j in _pairs(r):
        c = rng.randint(-2 ** 20, 2 ** 20)
        h1[i, j], h1[j, i] = c, -c
    for i, a in enumerate(rng.sample(range(-2 ** 20, 2 ** 20), r)):
        A1[i, i] = a
    cartan, power = [], h1
    for _ in range(r // 2):
        cartan.append(power)
        power = power * h1 * h1
    unknowns = [(c, zeros(r, r)) for c in cartan] + [(zeros(r, r), S) for S in sym_basis(r)]
    cols = []
    for xi1, eta1 in unknowns:
        L5 = (A1 * xi1 - xi1 * A1) - (h1 * eta1 - eta1 * h1)
        C6 = A1 * eta1 - eta1 * A1
        col = list(L5.entries())
        col += list(C6.entries()) if printed else [trace(C6 * c) for c in cartan]
        cols.append(col)
    return Z(rows_of(cols)), len(unknowns)


#: the polynomial kernel of Λ1 is multiplied out over ℤ[P] while r is at most this (it contains the odd
#: powers of h1 up to h1^(2[r/2]−1), whose expansion grows fast with r)
LEAF_PROOF_MAX_R = 6


def _leaf_kernel_bound(cert: Certificate, n: int, r: int, seed: int) -> Certificate:
    """The proved upper side of rank Λ1(Θ(X0, P)): the solutions of (L1), (L2) written as polynomials
    in P — ξ1 = h1^{2j+1} with η3 = ξ1h2; ξ2 ∈ so(n−r) with η3 = −h2ξ2; η1 ∈ Sym(r); η2 ∈ Sym(n−r)
    (h = [[h1, h2], [−h2ᵀ, 0]]) — are checked to lie in ker Λ1 identically, by multiplying out
    over ℤ[P] (fmpz_mpoly), and their rank at an integer point is a lower bound on their generic rank."""
    import random as _random
    nv = nvars(n, r, with_A=False)
    if nv == 0:
        return cert
    ctx = flint.fmpz_mpoly_ctx.get(("p", nv), "lex")
    gens = list(ctx.gens())
    zero = ctx.constant(0)
    # the symbolic point: P1 skew, P2 from the generators, in the order of make_point
    it = iter(gens)
    P = [[zero] * r for _ in range(n)]
    for i in range(r):
        for j in range(i + 1, r):
            g = next(it)
            P[i][j], P[j][i] = g, -g
    for i in range(r, n):
        for j in range(r):
            P[i][j] = next(it)
    # x = Φ + X0X0ᵀ, Φ = PX0ᵀ − X0Pᵀ
    x = [[zero] * n for _ in range(n)]
    for a in range(n):
        for b in range(n):
            v = (P[a][b] if b < r else zero) - (P[b][a] if a < r else zero)
            x[a][b] = v + (1 if a == b and a < r else 0)
    basis, nskew = gl_basis(n)
    units = [[(i, j, int(u[i, j])) for i in range(n) for j in range(n) if u[i, j] != 0] for u in basis]
    kinds = []
    for i in range(n):
        for j in range(i + 1, n):
            kinds.append(("so", i, j))
    for i in range(n):
        for j in range(i, n):
            kinds.append(("sym", i, j))

    def commutator_with(u):
        C = {}
        for (c, b, val) in u:            # (x u)_{ab} = x_{ac} u_{cb}
            for a in range(n):
                C[(a, b)] = C.get((a, b), zero) + x[a][c] * val
        for (a, c, val) in u:            # (u x)_{ab} = u_{ac} x_{cb}
            for b in range(n):
                C[(a, b)] = C.get((a, b), zero) - x[c][b] * val
        return C

    def pair(C, kind):
        what, i, j = kind
        get = lambda a, b: C.get((a, b), zero)
        if what == "so":
            return get(j, i) - get(i, j)
        return get(j, i) + get(i, j) if i != j else get(i, i)

    L = []
    for a, u in enumerate(units):
        C = commutator_with(u)
        L.append([zero if a >= nskew and b >= nskew else pair(C, kinds[b]) for b in range(len(basis))])
    # the kernel vectors as (ξ, η) n x n matrices of polynomials
    h1 = [[x[i][j] - (1 if i == j else 0) for j in range(r)] for i in range(r)]     # h = x − v
    h2 = [[x[i][r + j] for j in range(n - r)] for i in range(r)]

    def mul(A, B):
        return [[sum((A[i][k] * B[k][j] for k in range(len(B))), zero) for j in range(len(B[0]))] for i in range(len(A))]

    def element(xi1=None, xi2=None, eta1=None, eta2=None, eta3=None):
        xi = [[zero] * n for _ in range(n)]
        eta = [[zero] * n for _ in range(n)]
        for blk, off in ((xi1, 0), (xi2, r)):
            if blk is not None:
                for i in range(len(blk)):
                    for j in range(len(blk)):
                        xi[off + i][off + j] = blk[i][j]
        for blk, off in ((eta1, 0), (eta2, r)):
            if blk is not None:
                for i in range(len(blk)):
                    for j in range(len(blk)):
                        eta[off + i][off + j] = blk[i][j]
        if eta3 is not None:
            for i in range(r):
                for j in range(n - r):
                    eta[i][r + j] = eta3[i][j]
                    eta[r + j][i] = eta3[i][j]
        coords = [xi[i][j] for (w, i, j) in kinds if w == "so"] + [eta[i][j] for (w, i, j) in kinds if w == "sym"]
        return coords

    def const(M):
        return [[ctx.constant(int(M[i, j])) for j in range(M.ncols())] for i in range(M.nrows())]
    K = []
    power = h1
    for _ in range(r // 2):
        K.append(element(xi1=power, eta3=mul(power, h2) if n > r else None))
        power = mul(mul(power, h1), h1)
    for B in skew_basis(n - r):
        Bm = const(B)
        K.append(element(xi2=Bm, eta3=[[-e for e in row] for row in mul(h2, Bm)]))
    K += [element(eta1=const(S)) for S in sym_basis(r)]
    K += [element(eta2=const(S)) for S in sym_basis(n - r)]
    for k in K:
        for row in L:
            if not sum((a * b for a, b in zip(row, k)), zero).is_zero():
                return cert   # not a kernel vector: keep the randomized bound
    # their rank at an integer point
    rng = _random.Random(f"{seed}|{n}|{r}|leaf kernel")
    point = [rng.randint(-2 ** 20, 2 ** 20) for _ in range(nv)]
    values = [[int(e(*point)) if not isinstance(e, int) else e for e in k] for k in K]
    k_rank = rank_at_point(values, "kernel vectors", seed=seed).lower.bound if K else 0
    upper = Side(n * n - k_rank, f"{k_rank} polynomial solutions of (L1), (L2) in ker Λ1 identically (over ℤ[P]), "
                                 f"independent at an integer point")
    return Certificate(cert.quantity, cert.lower, upper, cert.notes)


def _odd_powers_bound(cert: Certificate, n: int, r: int, seed: int) -> Certificate:
    """The proved upper side of rank ad_Φ <= dim so(n) − [n/2]: the odd powers Φ, Φ³, …, Φ^{2[n/2]−1}
    are skew and commute with Φ identically (powers of one matrix commute), so they lie in ker ad_Φ
    at every point; at the point below they are [n/2] independent vectors (rank modulo a prime, a
    lower bound), hence dim ker ad_Φ >= [n/2] everywhere on a dense open set, and at the generic point."""
    import random as _random
    rng = _random.Random(f"{seed}|{n}|{r}|odd powers")
    pt = make_point(n, r, [rng.randint(-2 ** 20, 2 ** 20) for _ in range(nvars(n, r, with_A=False))], with_A=False)
    Phi, powers, power = pt.Phi, [], pt.Phi
    for _ in range(n // 2):
        powers.append(upper_entries(power, True))
        power = power * Phi * Phi
    k = rank_at_point(powers, "odd powers", seed=seed).lower.bound if powers else 0
    if k != n // 2:
        return cert
    upper = Side(dim_so(n) - k, f"the {k} odd powers Φ^(2j+1) commute with Φ identically and are independent "
                              f"at an integer point")
    return Certificate(cert.quantity, cert.lower, upper, cert.notes)


def _safe_generic(evaluate, nv: int, degree: int, quantity: str, seed: int, full: int) -> Certificate:
    if nv == 0:
        M = evaluate([])
        return rank_at_point(M, quantity, seed=seed, where="(constant)")
    return generic_rank(evaluate, nv, degree, quantity, seed=seed)


def _printed_ker_basis(pt: Point, basis: list[Z]) -> Z:
    """Columns (coordinates in ``basis``) of so(r)_{h1} ⊕ Sym(r) ⊕ gl(n−r): the odd powers of h1,
    Sym(r) and gl(n − r) = so(n−r) ⊕ Sym(n−r) in the lower block."""
    n, r = pt.n, pt.r
    h = pt.Phi
    h1 = Z([[h[i, j] for j in range(r)] for i in range(r)])
    elems = []
    power = h1
    for _ in range(r // 2):
        elems.append(_embed(power, n, 0))
        power = power * h1 * h1
    elems += [_embed(S, n, 0) for S in sym_basis(r)]
    elems += [_embed(B, n, r) for B in skew_basis(n - r) + sym_basis(n - r)]
    # coordinates: basis is E_ij − E_ji (i<j) then E_ij + E_ji (i<=j): read them off the entries
    cols = []
    for E in elems:
        col = []
        for i in range(n):
            for j in range(i + 1, n):
                col.append(Fraction(int(E[i, j] - E[j, i]), 2))
        for i in range(n):
            for j in range(i, n):
                col.append(Fraction(int(E[i, j] + E[j, i]), 2) if i != j else Fraction(int(E[i, i])))
        cols.append(col)
    Q = flint.fmpq_mat([[flint.fmpq(c.numerator, c.denominator) for c in row] for row in zip(*cols)])
    return Q.numer_denom()[0]


def _embed(B: Z, n: int, offset: int) -> Z:
    out = zeros(n, n)
    m = B.nrows()
    for i in range(m):
        for j in range(m):
            out[offset + i, offset + j] = B[i, j]
    return out


# -- disagreements as formulas in n and r ------------------------------------------------------------

#: the sets where a printed formula disagrees with the computation, stated in closed form; each is
#: checked against every computed size (a size in the set that agrees, or outside it that
#: disagrees, is itself reported)
KNOWN_DISAGREEMENTS: dict[str, tuple[str, Callable[[int, int], bool]]] = {
    "regular": ("n = 2r + 2", lambda n, r: n == 2 * r + 2),
    "N_vs_l": ("r = 1 (then N = l = n − 1)", lambda n, r: r == 1),
    "N_dependent": ("r ≤ 2 (the N integrals are independent: N = l + [r/2])", lambda n, r: r <= 2),
    "leaf_singular": ("r = 1 and n ≤ 2 (2l = n² − n)", lambda n, r: r == 1 and n <= 2),
    "L5L6": ("r ≥ 3 (the solutions are 2-dimensional)", lambda n, r: r >= 3),
    "invariant_forms": ("r = 4, or n − r = r = 2, or (n − r, r) = (1, 3)",
                        lambda n, r: r == 4 or (n - r == 2 and r == 2) or (n - r == 1 and r == 3)),
}


@dataclass
class Tables:
    n_max: int
    seed: int
    extended_n_max: int | None = None
    rows: dict[tuple[int, int], list[Row]] = field(default_factory=dict)
    seconds: dict[tuple[int, int], float] = field(default_factory=dict)

    def disagreements(self) -> dict[str, list[tuple[int, int]]]:
        out: dict[str, list[tuple[int, int]]] = {}
        for (n, r), rows in sorted(self.rows.items()):
            for row in rows:
                if row.agree is False:
                    out.setdefault(row.key, []).append((n, r))
        return out

    def undecided(self) -> dict[str, list[tuple[int, int]]]:
        out: dict[str, list[tuple[int, int]]] = {}
        for (n, r), rows in sorted(self.rows.items()):
            for row in rows:
                if row.printed is not None and row.cert.value is None:
                    out.setdefault(row.key, []).append((n, r))
        return out

    def formula_check(self) -> dict[str, dict]:
        """For each quantity with a disagreement: the closed-form set, and whether it matches the
        computed sizes exactly."""
        found = self.disagreements()
        out = {}
        for key in sorted(set(found) | set(KNOWN_DISAGREEMENTS)):
            sizes = set(found.get(key, []))
            text, pred = KNOWN_DISAGREEMENTS.get(key, ("(no closed form)", lambda n, r: False))
            computed = [(n, r) for (n, r), rows in self.rows.items() if any(x.key == key and x.agree is not None for x in rows)]
            mismatch = sorted((n, r) for (n, r) in computed if pred(n, r) != ((n, r) in sizes))
            out[key] = {"set": text, "sizes": sorted(sizes), "checked_sizes": len(computed),
                        "matches_formula": not mismatch, "mismatch": mismatch}
        return out


def compute_tables(n_max: int = 9, *, seed: int = 0, progress: Callable[[int, int, float], None] | None = None,
                   include: Iterable[str] | None = None) -> Tables:
    import time
    T = Tables(n_max, seed)
    for n in range(1, n_max + 1):
        for r in range(1, n + 1):
            t0 = time.perf_counter()
            T.rows[(n, r)] = compute_size(n, r, seed=seed, include=include)
            T.seconds[(n, r)] = time.perf_counter() - t0
            if progress:
                progress(n, r, T.seconds[(n, r)])
    return T


# -- rendering -----------------------------------------------------------------------------------------

#: the three tables of part (a): (title, quantity keys)
GROUPS = (
    ("§2–§4: the variety, SO(n)-invariants, orbits and the tori of the geodesic flows",
     ("dimV", "ddim", "ddim_inv", "2l", "regular", "chain", "delta0", "delta0_complete", "delta", "delta_complete")),
    ("§6: the pencil Λ1, Λ2 of Lemmas LEMA1, LEMA2, and the tori of the Neumann systems",
     ("leaf", "leaf_singular", "leaf_pushforward", "complete_F", "A1", "A1_t", "KER", "A2", "L5L6", "L5L6_corrected",
      "torus", "torus_complete")),
    ("§4, §7, §8: invariant metrics, Grassmannians, the count N",
     ("invariant_forms", "NEUMANN2", "N", "N_rank", "N_dependent", "N_vs_l")),
)

#: short column headings (Markdown, LaTeX)
HEADINGS = {
    "dimV": ("dim V", r"$\dim V$"), "ddim": ("ddim", r"ddim"), "ddim_inv": ("ddim (Ψ,PᵀP)", r"ddim$(\Psi,P^TP)$"),
    "2l": ("2l", r"$2l$"), "regular": ("regular", r"reg."), "chain": ("ddim 𝔄", r"ddim$\,\mathfrak A$"),
    "delta0": ("δ₀", r"$\delta_0$"), "delta0_complete": ("δ₀ (compl.)", r"$\delta_0$ c."),
    "delta": ("δ", r"$\delta$"), "delta_complete": ("δ (compl.)", r"$\delta$ c."),
    "leaf": ("2l by (dimension)", r"$2l$ (dimension)"), "leaf_singular": ("2l < n²−n", r"$2l<n^2-n$"),
    "L5L6": ("(L5), (L6)", r"(L5), (L6)"), "L5L6_corrected": ("(L5), (L6) corr.", r"(L5), (L6) c."),
    "leaf_pushforward": ("2l via Θ", r"$2l$ via $\Theta$"),
    "complete_F": ("l by Lemma LEMA2", r"$l$ (LEMA2)"), "A1": ("(A1) t=−1", r"(A1) $t{=}{-1}$"),
    "A1_t": ("(A1) any t", r"(A1) $t$"), "KER": ("(KER)", r"(KER)"), "A2": ("(A2)", r"(A2)"),
    "torus": ("torus", r"torus"), "torus_complete": ("torus (compl.)", r"torus c."),
    "NEUMANN2": ("Theorem NEUMANN2", r"(NEUMANN2)"), "N": ("N", r"$N$"), "N_rank": ("N indep.", r"$N$ indep."),
    "N_dependent": ("some dependent", r"dep."), "N_vs_l": ("N > l", r"$N>l$"),
    "invariant_forms": ("inv. forms", r"inv.\ forms"),
}


def _fmt(x) -> str:
    if isinstance(x, Fraction):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    return str(x)


def _cell(row: Row | None, latex: bool = False) -> str:
    if row is None:
        return "" if not latex else ""
    v = row.cert.value
    val = _fmt(v) if v is not None else f"[{row.cert.lower.bound},{row.cert.upper.bound}]"
    mark = "" if row.cert.kind == "proved" else ("*" if not latex else r"$^*$")
    if row.agree is False:
        return (f"**{_fmt(row.printed)} ≠ {val}**{mark}" if not latex
                else rf"\textbf{{{_fmt(row.printed)}}}$\ne$\textbf{{{val}}}{mark}")
    if row.agree is None and row.printed is None:
        return f"({val}){mark}"
    return f"{val}{mark}"


def _power_of_ten(p: float) -> str:
    """A probability as the reports write one: m·10⁻ᵏ (Unicode), "0" for none."""
    from stiefelsym.reports.report import format_bound
    return format_bound(p)


def _sizes_text(sizes: list[tuple[int, int]]) -> str:
    return ", ".join(f"({n},{r})" for n, r in sizes)


def tables_json(T: Tables, verdicts: dict[str, Any]) -> dict:
    return {
        "schema": "stiefelsym-tables/1", "n_max": T.n_max, "extended_n_max": T.extended_n_max, "seed": T.seed,
        "extended_quantities": list(EXTENDED),
        "quantities": {k: {"label": v[0], "meaning": v[1]} for k, v in QUANTITIES.items()},
        # no timings: the file is committed, and the same command on the same commit writes the same bytes
        "sizes": [{"n": n, "r": r, "rows": [row.as_dict() for row in rows]} for (n, r), rows in sorted(T.rows.items())],
        "disagreements": T.formula_check(),
        "undecided": {k: v for k, v in T.undecided().items()},
        "max_false_probability": max((row.cert.false_probability for rows in T.rows.values() for row in rows), default=0.0),
        "verdicts": verdicts,
    }


#: two equations of one section in a row: "(16) §6, (17) §6" is printed "(16), (17) §6"
_SAME_SECTION = re.compile(r"\((\d+)\) §(\d+)(, |–)\((\d+)\) §\2(?!\d)")


def _readable(text: str) -> str:
    """The prose of the tables with the paper's printed numbers for its label keys ("Lemma LEMA2" is "Lemma 6.3",
    "(L5)" is "(16) §6", "(dim_fol)" is "(1) §6"), the conditions (A1), (A2) of the proof of Lemma 6.3 kept as the
    paper names them (:data:`stiefelsym.paperref.CONDITION_NAMES`); equations of one section in a row share their
    "§": "(16), (17) §6", "(16)–(19) §6"."""
    from stiefelsym.paperref import CONDITION_NAMES, readable
    out = readable(text, keep=CONDITION_NAMES)
    while True:
        new = _SAME_SECTION.sub(r"(\1)\3(\4) §\2", out)
        if new == out:
            return out
        out = new


def _tex_readable(text: str) -> str:
    """:func:`_readable` for LaTeX that is already set: "§" as ``\\S``."""
    return _readable(text).replace("§", r"\ensuremath{\S}")


def _tex_heading(key: str) -> str:
    """A column's heading in the PDF: the paper's numbers for its label keys, without their section (the table's
    caption names it): "(16), (17)", "(Theorem 7.1)"."""
    return re.sub(r" §\d+", "", _readable(HEADINGS[key][1]))


def _row_lookup(T: Tables) -> dict[tuple[int, int], dict[str, Row]]:
    return {size: {row.key: row for row in rows} for size, rows in T.rows.items()}


def render_markdown(T: Tables, verdicts: dict[str, Any]) -> str:
    look = _row_lookup(T)
    sizes = sorted(T.rows)
    maxp = max((row.cert.false_probability for rows in T.rows.values() for row in rows), default=0.0)
    ext = T.extended_n_max if T.extended_n_max and T.extended_n_max > T.n_max else None
    title_n = f"n ≤ {T.n_max}" + (f"; n ≤ {ext} without the completeness checks" if ext else "")
    out = [f"# Appendix tables: the paper's dimensions against exact computations ({title_n})", "",
           "Each cell is the computed value at (n, r); where it differs from the paper's formula the cell reads "
           "**printed ≠ computed**.  A value without a mark is *proved* on both sides: a rank modulo a prime at an "
           "integer point from below, and from above exact kernel vectors (checked over ℤ at the point for the "
           "statements at one point: (KER), (A2), (L5)–(L6), invariant forms; checked identically over ℤ[P] for the "
           "generic leaf dimension (dimension) when r ≤ 6: the polynomial solutions of (L1), (L2); the odd powers "
           "of Φ for a regular 2l), or a count.  A value marked * is *checked*: the lower side is "
           "proved (an exact rank at an integer point), the upper side holds unless random points hit the zero set "
           "of a nonzero minor (Schwartz–Zippel) — the false-pass probability of every checked value in these "
           f"tables is at most {_power_of_ten(maxp)}.  A value in parentheses has no printed counterpart at that size.  "
           f"Computed with seed {T.seed} (`stiefelsym tables --seed {T.seed}` reproduces every number).  "
           + (f"For {T.n_max} < n ≤ {ext} the columns of completeness checks (Poisson matrices of the integrals) "
              "are left empty." if ext else ""), ""]
    for title, keys in GROUPS:
        out += [f"## {title}", "", "| (n, r) | " + " | ".join(HEADINGS[k][0] for k in keys) + " |",
                "|---" * (len(keys) + 1) + "|"]
        for size in sizes:
            cells = [_cell(look[size].get(k)) for k in keys]
            out.append(f"| ({size[0]},{size[1]}) | " + " | ".join(cells) + " |")
        out += ["", "What each column computes:", ""]
        out += [f"- **{_readable(HEADINGS[k][0])}** ({QUANTITIES[k][0]}): {QUANTITIES[k][1]}" for k in keys]
        out.append("")
    out += ["## Disagreements between the printed formulas and the computation", ""]
    checks = T.formula_check()
    if not any(c["sizes"] for c in checks.values()):
        out += ["None at any computed size.", ""]
    for key, c in checks.items():
        if not c["sizes"] and c["matches_formula"]:
            continue
        verdict = ("the closed form matches the computed sizes exactly" if c["matches_formula"] else
                   f"the closed form does NOT match at {_sizes_text(c['mismatch'])}")
        out += [f"- **{_readable(HEADINGS[key][0])}** ({QUANTITIES[key][0]}): disagrees exactly when {c['set']}; "
                f"{verdict} (checked at all {c['checked_sizes']} computed sizes). "
                f"Sizes: {_sizes_text(c['sizes']) or 'none'}."]
    out += ["", *_notes_markdown(), ""]
    und = T.undecided()
    if und:
        out += ["Undecided (the bounds did not meet): " + "; ".join(f"{k} at {_sizes_text(v)}" for k, v in und.items()), ""]
    # the prose (not the rows of numbers) with the paper's printed numbers for its label keys
    out = [line if re.match(r"\| \(\d", line) else _readable(line) for line in out]
    out += verdict_markdown(verdicts)
    return "\n".join(out) + "\n"


def _notes_markdown() -> list[str]:
    return [
        "Notes on the disagreements:", "",
        "- *regular*: the remark before Lemma 2l (the generic orbit in Φ(T*V) is regular iff n ≤ 2r + 1); at "
        "n = 2r + 2 the second case of Lemma 2l, 2r(n − r − 1), equals the regular dimension, so the orbit is regular there (the Lemma's "
        "formula itself agrees everywhere).",
        "- *inv. forms*: Proposition 4.6 (the SO(n)×SO(r)-invariant quadratic forms on T*_{X₀}V "
        "are spanned by tr(PᵀP), tr((XᵀP)²)); at r = 4 the Pfaffian of P₁ is a further invariant form for every "
        "n ≥ 4, at n − r = r = 2 det P₂, at (n, r) = (4, 3) the pairing of the axial vector of P₁ with P₂.",
        "- *N > l*: §8 says N = r(n−r) + r(r−1)/2 exceeds half the dimension (dimension) of a generic leaf, so "
        "some of the N integrals are dependent.  For r = 1, N = l = n − 1: the premise fails (and the Neumann "
        "integrals on the sphere are independent); for r ≥ 2, N − l = r(r−1)/4 + [r/2]/2 > 0.",
        "- *some dependent*: the conclusion of that remark, computed as the rank of the differentials of the "
        "coefficients of the dual spectral curve (column *N indep.*).  Commuting integrals on T*V/SO(r) number at "
        "most l + [r/2] (the leaf and its [r/2] Casimirs), and N − (l + [r/2]) = r(r−1)/4 − [r/2]/2, which is 0 "
        "for r ≤ 2: there all N integrals are independent (computed), and some are dependent exactly for r ≥ 3.  "
        "Wherever computed, the rank equals the torus dimension (dim_fol) = l + [r/2].",
        "- *2l < n²−n*: (dimension) states the strict inequality; at (1,1) and (2,1) 2l = n² − n (0 and 2).",
        "- *(L5), (L6)*: the proof of Lemma LEMA2 says the solutions of (L5), (L6) form an r-dimensional space.  "
        "With (L6) as printed, [A₁, η₁] ∈ so(r,ℂ)^⊥ = Sym(r) forces the skew matrix [A₁, η₁] to vanish, and the "
        "solutions are 2-dimensional for every r ≥ 3.  Pairing with the Cartan subalgebra so(r)_{h₁} (the part of "
        "ker Λ1 it is paired with) gives [A₁, η₁] ⟂ so(r,ℂ)_{h₁}: then the dimension is r at every size (column "
        "*(L5), (L6) corr.*), and (A2) holds (column *(A2)*, computed without (L5)–(L8)).",
    ]


def verdict_matrix(results: list[dict], meta: dict | None = None) -> dict[str, Any]:
    """claim (with its correction as a separate row) × size × method -> verdict (and expected); and the run
    the records come from (``meta``, the results file's: its commit and command), with its number of claims
    and a digest of its catalog (the claims' statements as printed), which tell one run's catalog from
    another's."""
    matrix: dict[str, dict[str, dict[str, list]]] = {}
    sizes, methods = set(), []
    for r in results:
        claim = r["claim"] + (" [corrected]" if r.get("variant") else "")
        size = "all" if r.get("n") is None else f"{r['n']},{r['r']}"
        sizes.add(size)
        if r["method"] not in methods:
            methods.append(r["method"])
        matrix.setdefault(claim, {}).setdefault(size, {})[r["method"]] = [r["verdict"], bool(r.get("expected"))]
    order = ["exact", "auto", "rational", "modular", "float", "ball", "free"]
    methods.sort(key=lambda m: order.index(m) if m in order else len(order))

    def size_key(s):
        return (0, 0) if s == "all" else tuple(int(x) for x in s.split(","))
    statements = sorted({(r["claim"], str(r.get("statement") or "")) for r in results if not r.get("variant")})
    run = {"commit": (meta or {}).get("commit"), "command": (meta or {}).get("command"),
           "claims": len({r["claim"] for r in results}), "records": len(results),
           "catalog": hashlib.sha256(json.dumps(statements, ensure_ascii=False).encode("utf-8")).hexdigest()[:12]}
    return {"methods": methods, "sizes": sorted(sizes, key=size_key), "claims": matrix, "run": run}


def _claims(k: int) -> str:
    return f"{k:,} claim" + ("" if k == 1 else "s")


def run_words(name: str, vm: dict[str, Any], first: tuple[str, dict[str, Any]] | None) -> list[str]:
    """The sentences above a verdict matrix: the run it comes from (commit, command, claims, records), and,
    when its commit or catalog is not that of ``first`` (the first matrix, the main results file), that it is
    another run and which matrix the report is rendered from."""
    run = vm.get("run")
    if not run:
        return ["The results file does not say which run it is."]
    command = f" (`{run['command']}`)" if run.get("command") else ""
    out = [f"From the run of commit {run.get('commit') or 'unknown'}{command}: {_claims(run['claims'])}, "
           f"{run['records']:,} record{'' if run['records'] == 1 else 's'}."]
    if first is None or first[1].get("run") is None or first[0] == name:
        return out
    ref_name, ref = first[0], first[1]["run"]
    other_commit = run.get("commit") != ref.get("commit")
    other_catalog = run.get("catalog") != ref.get("catalog")
    if not (other_commit or other_catalog):
        return out
    ids, ref_ids = ({c.removesuffix(" [corrected]") for c in m["claims"]} for m in (vm, first[1]))
    parts = []
    if other_commit:
        parts.append(f"of commit {run.get('commit') or 'unknown'}, not {ref.get('commit') or 'unknown'}")
    if other_catalog:
        missing, extra = len(ref_ids - ids), len(ids - ref_ids)
        diff = ([f"{_claims(missing)} of {ref_name} {'is' if missing == 1 else 'are'} not in it"] if missing else []) \
            + ([f"{extra} of its claims {'is' if extra == 1 else 'are'} not in {ref_name}"] if extra else [])
        parts.append(f"of another catalog ({_claims(run['claims'])} against {ref['claims']}"
                     + (f"; {', '.join(diff)}" if diff else "; the same claims with other statements") + ")")
    return out + [f"**This is another run than that of {ref_name}**: it is {', and '.join(parts)}.  Its verdicts are "
                  f"those of that commit's engine and catalog; where the two matrices differ, the report "
                  f"(verification.md) is rendered from {ref_name}."]


VERDICT_LETTERS = {"proved": "P", "checked": "C", "numeric": "N", "fails": "F", "inconclusive": "I",
                   "undecided": "u", "error": "E"}


def _verdict_cell(cell: dict[str, list] | None, methods: list[str]) -> str:
    if not cell:
        return ""
    out = ""
    for m in methods:
        if m in cell:
            verdict, expected = cell[m]
            out += VERDICT_LETTERS.get(verdict, "?") + ("" if expected else "!")
        else:
            out += "·"
    return out


def verdict_markdown(verdicts: dict[str, Any]) -> list[str]:
    out = ["# Verdict matrix: claim × size × method", ""]
    if not verdicts:
        return out + ["No results file was found.", ""]
    out += ["Letters: P proved, C checked, N numeric, F fails, I inconclusive, u undecided, E error; "
            "`!` marks a verdict the catalog does not expect; `·` a method not run there.  Size `all` is the "
            "dimension-free method (every n, r).", ""]
    first = next(iter(verdicts.items()))
    for name, vm in verdicts.items():
        methods, sizes = vm["methods"], vm["sizes"]
        out += [f"## {name}", "", " ".join(run_words(name, vm, first)), "",
                f"Each cell lists the methods in the order {', '.join(methods)}.", "",
                "| claim | " + " | ".join(sizes) + " |", "|---" * (len(sizes) + 1) + "|"]
        for claim in sorted(vm["claims"]):
            row = vm["claims"][claim]
            out.append(f"| `{claim}` | " + " | ".join(_verdict_cell(row.get(s), methods) for s in sizes) + " |")
        out.append("")
    return out


def _tex(text: str) -> str:
    repl = {"\\": r"\textbackslash{}", "_": r"\_", "&": r"\&", "%": r"\%", "#": r"\#", "$": r"\$",
            "{": r"\{", "}": r"\}", "^": r"\^{}", "~": r"\~{}"}
    repl.update({"−": "-", "–": "--", "≤": r"$\le$", "≥": r"$\ge$", "≠": r"$\ne$",
                 # in the default (OT1) text font < and > would print as ¡ and ¿; ² is a bitmap (TS1) glyph
                 "<": "$<$", ">": "$>$", "|": "$|$", "²": "$^2$", "³": "$^3$", "·": r"$\cdot$"})
    return "".join(repl.get(c, c) for c in text.replace("<=", "≤").replace(">=", "≥"))


def render_latex(T: Tables, verdicts: dict[str, Any]) -> str:
    """booktabs tables, to be \\input into a document with booktabs and longtable."""
    look = _row_lookup(T)
    sizes = sorted(T.rows)
    maxp = max((row.cert.false_probability for rows in T.rows.values() for row in rows), default=0.0)
    maxp_tex = f"{maxp:.1e}".replace("e-", r"\cdot 10^{-") + "}" if maxp else "0"
    # the range as the Markdown states it: the extended sizes have no completeness checks
    ext = T.extended_n_max if T.extended_n_max and T.extended_n_max > T.n_max else None
    title_n = f"$n\\le {T.n_max}$" + (f"; $n\\le {ext}$ without the completeness checks" if ext else "")
    out = ["% Generated by `stiefelsym tables`; needs \\usepackage{booktabs,longtable}.",
           rf"\paragraph{{Dimensions, printed against computed ({title_n}).}}",
           r"A value is proved on both sides unless marked $^*$ (lower side proved, upper side by "
           rf"Schwartz--Zippel, false-pass probability at most ${maxp_tex}$); a bold pair reads "
           r"printed${}\ne{}$computed; a value in parentheses has no printed counterpart."
           + (rf"  For ${T.n_max} < n\le {ext}$ the columns of completeness checks (Poisson matrices of the "
              "integrals) are left empty." if ext else ""), ""]
    for title, keys in GROUPS:
        cols = "l" + "r" * len(keys)
        out += [r"{\footnotesize\setlength{\tabcolsep}{3pt}", r"\begin{longtable}{" + cols + "}",
                r"\caption{" + _tex_title(_readable(title)) + r"}\\", r"\toprule",
                "$(n,r)$ & " + " & ".join(_tex_heading(k) for k in keys) + r" \\", r"\midrule", r"\endhead"]
        for size in sizes:
            out.append(f"$({size[0]},{size[1]})$ & " + " & ".join(_cell(look[size].get(k), True) for k in keys) + r" \\")
        out += [r"\bottomrule", r"\end{longtable}}", ""]
    checks = T.formula_check()
    out += [r"\paragraph{Disagreements.}", r"\begin{itemize}"]
    any_item = False
    for key, c in checks.items():
        if not c["sizes"] and c["matches_formula"]:
            continue
        any_item = True
        verdict = ("the closed form matches every computed size" if c["matches_formula"] else
                   "the closed form does not match at " + _tex(_sizes_text(c["mismatch"])))
        ref = _tex(_readable(f"({QUANTITIES[key][0]})")).replace("§", r"\ensuremath{\S}")
        out.append(rf"\item {_tex_readable(HEADINGS[key][1])} {ref}: "
                   rf"exactly when {_tex(c['set'])}; "
                   rf"{verdict} ({c['checked_sizes']} sizes).")
    if not any_item:
        out.append(r"\item None.")
    out += [r"\end{itemize}", ""]
    if verdicts:
        out += [r"\paragraph{Verdict matrix.} P proved, C checked, N numeric, F fails, I inconclusive, "
                r"u undecided, E error; ! unexpected; $\cdot$ not run.", ""]
        first = next(iter(verdicts.items()))
        for name, vm in verdicts.items():
            methods, vsizes = vm["methods"], vm["sizes"]
            words = " ".join(run_words(name, vm, first))
            # (sloppy: a command in typewriter type breaks only at its spaces)
            out += [r"{\sloppy\noindent\texttt{" + _tex(name) + "}: "
                    + re.sub(r"\*\*(.+?)\*\*", r"\\textbf{\1}", re.sub(r"`([^`]*)`", r"\\texttt{\1}", _tex(words)))
                    + r"\par}", "",
                    r"{\scriptsize\setlength{\tabcolsep}{2pt}", r"\begin{longtable}{l" + "c" * len(vsizes) + "}",
                    r"\caption{" + _tex(name) + " (methods: " + _tex(", ".join(methods)) + r")}\\", r"\toprule",
                    "claim & " + " & ".join(_tex(s) for s in vsizes) + r" \\", r"\midrule", r"\endhead"]
            for claim in sorted(vm["claims"]):
                row = vm["claims"][claim]
                cells = [_verdict_cell(row.get(s), methods).replace("·", r"$\cdot$") for s in vsizes]
                out.append(r"\texttt{" + _tex(claim) + "} & " + " & ".join(cells) + r" \\")
            out += [r"\bottomrule", r"\end{longtable}}", ""]
    return "\n".join(out) + "\n"


def _tex_title(title: str) -> str:
    return (title.replace("§", r"\ensuremath{\S}").replace("Λ1", r"$\Lambda_1$").replace("Λ2", r"$\Lambda_2$")
            .replace("SO(n)", r"$SO(n)$").replace("–", "--"))


STANDALONE = r"""% Compile with: pdflatex tables-standalone.tex  (in the directory of tables.tex)
\documentclass[10pt]{article}
\usepackage[landscape,margin=1.5cm]{geometry}
\usepackage{booktabs,longtable,amssymb}
% the default bullet comes from a TS1 font that Debian's texlive-latex-base has only as bitmaps
\renewcommand{\labelitemi}{$\bullet$}
\begin{document}
\input{tables}
\end{document}
"""
