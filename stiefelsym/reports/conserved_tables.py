"""The tables of conserved trace polynomials of the paper's flows, and which of them the paper names.

For each flow (the Neumann flows for every κ, κ = 0 and κ = −½, and the Manakov flow with B = A²)
and each size, :func:`stiefelsym.analyses.discover.conserved` gives the exact space D of conserved trace
polynomials of degree ≤ 4 in X, P modulo those constant on T*V, each basis element verified.  The
paper names some integrals of each flow: the Hamiltonian, the invariants of the momentum Ψ, and
the spectral invariants of its Lax matrix (the coefficients of tr 𝓛(λ)ᵏ in λ).  Any function of
integrals is an integral: N is the span of the named integrals and of the products of two of them,
as functions on T*V; the table gives dim D, dim (D ∩ N) (the conserved quantities the paper
names) and a basis of D modulo N (those it does not name, if any).

D ∩ N is computed as functions on T*V: every element of D and every named function is evaluated at
K random points of T*V over GF(p), p = 2⁶¹ − 1, with K larger than the number of functions by 8,
and dim (D ∩ N) = dim D + rank N − rank (D ∪ N), the ranks taken together with the constant
function.  A rank found at random points is never above the rank of the functions, and falls below it
only when a nonzero ρ × ρ minor of the values at the first ρ points vanishes (ρ the rank), which has
probability at most ρd/p (Schwartz–Zippel, d the degree of the functions as polynomials in the parameters
the points are drawn from).  The two ranks err in opposite directions (rank N too low lowers dim (D ∩ N), rank (D ∪ N) too
low raises it), so each count is exact except with probability at most 2ρd/p.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Any, Callable, Sequence

from stiefelsym.claims import Size
from stiefelsym.analyses.discover import PRIME, Discovery, Integral, conserved, evaluate_derived

#: fixed values of λ at which the spectral invariants are taken (their span is that of the
#: coefficients in λ: a polynomial of degree d in λ is fixed by d + 1 values)
LAMBDAS = tuple(range(0, 9))


def _catalog(module: str) -> Any:
    import importlib
    return importlib.import_module(f"stiefelsym.proofs.{module}")


def _trace_power(s: Any, M: Any, k: int) -> Any:
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


def neumann_named(s: Any) -> dict[str, Any]:
    """The integrals the paper names for the Neumann flows: H_neum,0 = ½⟨Φ,Φ⟩ + V (the Hamiltonian
    of (neumann) for κ = 0; for κ ≠ 0 it differs by κ/2⟨Ψ,Ψ⟩), ⟨Ψ,Ψ⟩ (Ψ is conserved,
    (No)), and the spectral invariants tr 𝓛(λ)ᵏ, k ≤ 4, of (LA2)/(perelomov) 𝓛(λ) = λΦ + XXᵀ − λ²A."""
    sec5 = _catalog("sec5_neumann")
    out = {"H_neum,0": sec5.H_neumann_normal(s), "<Psi, Psi>": s.killing(s.Psi, s.Psi)}
    for lam in LAMBDAS:
        L = sec5.L_neum_at(s, s.q(lam))
        for k in range(1, 5):
            out[f"tr L({lam})^{k}"] = _trace_power(s, L, k)
    return out


def manakov_named(s: Any) -> dict[str, Any]:
    """The integrals the paper names for the Manakov flow (dot_XP3*) (B = A²): tr(λA + Φ)ᵏ of (man),
    k ≤ 4, and the SO(n)-invariant functions of Ψ and PᵀP (tr PᵀP, tr (PᵀP)², ⟨Ψ,Ψ⟩)."""
    PtP = s.P.T @ s.P
    out = {"tr P^T P": s.tr(PtP), "tr (P^T P)^2": s.tr(PtP @ PtP), "<Psi, Psi>": s.killing(s.Psi, s.Psi)}
    for lam in LAMBDAS:
        L = s.q(lam) * s.A + s.Phi
        for k in range(1, 5):
            out[f"tr (lambda A + Phi)^{k} at {lam}"] = _trace_power(s, L, k)
    return out


@dataclass
class Family:
    key: str
    title: str
    label: str                  # the paper's label of the flow
    flow: Callable[[Any], Any]
    named: Callable[[Any], dict[str, Any]]
    named_text: str
    max_a: int = 1


#: what the paper names for a Neumann flow of a given κ (H_neum,κ = H_neum,0 + κ/2⟨Ψ,Ψ⟩: with ⟨Ψ,Ψ⟩, the same span)
NEUMANN_NAMED = "H_neum,{k}, ⟨Ψ,Ψ⟩, and the spectral invariants tr 𝓛(λ)ᵏ (k ≤ 4) of (LA2)"
_SPANNED = " (with ⟨Ψ,Ψ⟩ they span H_neum,0, which the table uses)"


def families() -> list[Family]:
    sec4, sec5 = _catalog("sec4_integrability"), _catalog("sec5_neumann")
    return [
        Family("neumann-kappa", "the Neumann flow (No), for every κ", "No", lambda s: sec5.flow_No(s, s.kappa),
               neumann_named, NEUMANN_NAMED.format(k="κ") + _SPANNED, max_a=2),
        Family("neumann-normal", "the Neumann flow of the normal metric (N0_XP2), κ = 0", "N0_XP2", sec5.flow_N0,
               neumann_named, NEUMANN_NAMED.format(k="0"), max_a=2),
        Family("neumann-euclidean", "the Neumann flow of the Euclidean metric (NE_XP), κ = −½", "NE_XP",
               sec5.flow_NE, neumann_named, NEUMANN_NAMED.format(k="−½") + _SPANNED, max_a=2),
        Family("manakov", "the Manakov flow (dot_XP3*), B = A²", "dot_XP3*", sec4.flow_XP3, manakov_named,
               "tr(λA + Φ)ᵏ of (man) (k ≤ 4), tr PᵀP, tr (PᵀP)², ⟨Ψ,Ψ⟩", max_a=2),
    ]


@dataclass
class Row:
    family: Family
    size: Size
    discovery: Discovery
    named_dim: int = 0
    not_named: list[Integral] = field(default_factory=list)
    seconds: float = 0.0


def _rank(rows: list[list[int]]) -> int:
    import flint
    if not rows:
        return 0
    return flint.nmod_mat(rows, PRIME).rank()


def named_part(fam: Family, d: Discovery, seed: int = 0) -> tuple[int, list[Integral]]:
    """dim (D ∩ N) and the elements of the basis of D that, added in turn, leave span(N, 1)."""
    from stiefelsym.backends.fields import ModularField
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.scene import Scene

    integrals = list(d.integrals)

    def probe(s):
        out = {f"I{k}": I.function()(s) for k, I in enumerate(integrals)}
        out.update({f"N:{k}": v for k, v in fam.named(s).items()})
        return out
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS["standard"]
    g = compile_claim(probe, d.size.n, d.size.r, (cons.name, cons.build))
    m = 4 * len(LAMBDAS) + 3                                # the named functions
    K = len(integrals) + m + m * (m + 1) // 2 + 9          # more points than functions, by 9
    rng = random.Random(f"{seed}|named|{fam.key}|{d.size.n}|{d.size.r}")
    cols_I: list[list[int]] = [[] for _ in integrals]
    cols_N: dict[str, list[int]] = {}
    for k in range(K):
        scene = Scene(d.size.n, d.size.r, ModularField(PRIME), chart="cayley", rng=rng,
                      component=k % 2 if d.size.r == d.size.n else 0)
        out = evaluate_derived(g, scene)
        for i in range(len(integrals)):
            cols_I[i].append(int(out[f"I{i}"]))
        for key, v in out.items():
            if key.startswith("N:"):
                cols_N.setdefault(key, []).append(int(v))
    named = list(cols_N.values())
    # the algebra the named integrals generate, to degree 2: every product of two of them
    products = [[x * y % PRIME for x, y in zip(a, b)] for i, a in enumerate(named) for b in named[i:]]
    base = [[1] * K] + named + products
    rank_N = _rank(base)
    rank_all = _rank(base + cols_I)
    named_dim = len(integrals) + rank_N - rank_all
    not_named, acc, r = [], list(base), rank_N
    for I, col in zip(integrals, cols_I):
        r2 = _rank(acc + [col])
        if r2 > r:
            not_named.append(I)
            acc.append(col)
            r = r2
    return named_dim, not_named


def tables(sizes: Sequence[Size] = (Size(4, 2), Size(5, 2)), degree: int = 4, seed: int = 0,
           verify: Sequence[str] = ("auto", "free"), keys: Sequence[str] | None = None) -> list[Row]:
    import time
    rows = []
    for fam in families():
        if keys is not None and fam.key not in keys:
            continue
        for z in sizes:
            t0 = time.perf_counter()
            d = conserved(fam.flow, z, degree, max_a=fam.max_a, seed=seed, name=fam.title, verify=verify)
            dim, extra = named_part(fam, d, seed)
            rows.append(Row(fam, z, d, dim, extra, time.perf_counter() - t0))
    return rows


def markdown(rows: Sequence[Row], neumann2: Sequence[Neumann2] = ()) -> str:
    """The tables (no timings: the file is committed and must not change between identical runs), the paper's
    labels written as the numbers it prints."""
    out = ["# Conserved trace polynomials of the paper's flows", "",
           "Generated by `stiefelsym discover --tables` (`make discover`); do not edit by hand.", "",
           "For each flow and size: the space D of trace polynomials of degree ≤ 4 in X, P (products of at most "
           "two traces, at most two letters A per trace) that the flow conserves, modulo "
           "those constant on T*V; how many of them are in the span N of the integrals the paper names; and a "
           "basis of D modulo N.  Every basis element of D is verified at that size and, where the "
           "dimension-free method applies, for every n and r.  The method is in the last section.", ""]
    for fam_key in dict.fromkeys(r.family.key for r in rows):
        fr = [r for r in rows if r.family.key == fam_key]
        fam = fr[0].family
        out += [f"## {fam.title[0].upper() + fam.title[1:]}", "", f"Named by the paper: {fam.named_text}.", "",
                "| (n, r) | ansatz | dim D | named (D ∩ N) | not named |", "| --- | ---: | ---: | ---: | ---: |"]
        for r in fr:
            out.append(f"| ({r.size.n},{r.size.r}) | {len(r.discovery.ansatz)} | {len(r.discovery.integrals)} | "
                       f"{r.named_dim} | {len(r.discovery.integrals) - r.named_dim} |")
        out.append("")
        for r in fr:
            out += [f"Basis of D at (n, r) = ({r.size.n},{r.size.r}):", ""]
            for k, I in enumerate(r.discovery.integrals, 1):
                v = ", ".join(f"{m} {x}" for m, x in I.verdicts.items())
                tag = "not named by the paper" if I in r.not_named else "in the span of the named integrals"
                out.append(f"{k}. ${I.latex()}$ ({tag}; {v})")
            out.append("")
    if neumann2:
        out += neumann2_markdown(neumann2)
    out += ["## Method", "", __doc__.split("\n\n", 1)[1].strip(), ""]
    from stiefelsym.paperref import readable
    return readable("\n".join(out))        # the paper's numbers for its labels: (4) §5, Theorem 7.1


# -- Theorem NEUMANN2: r(n − r) independent integrals on Ψ = 0 -------------------------------------

@dataclass
class Neumann2:
    size: Size
    chosen: list[tuple[int, int]]         # (k, j): the coefficient of λ^j in tr 𝓛(λ)^k
    rank_all: int                         # the rank of every coefficient's differential at the point


def neumann2_integrals(size: Size, seed: int = 0, on_psi_zero: bool = True) -> Neumann2:
    """At an exact rational point of Ψ⁻¹(0) (P replaced by (I − XXᵀ)P, so XᵀP = 0), the differentials
    of the coefficients c_{k,j} of λʲ in tr 𝓛(λ)ᵏ (perelomov), restricted to the leaf of
    (gl(n), Λ1) through x = Θ(X, P) (multiplied by Λ1(x)); the first r(n − r) independent ones in the
    order (k, j), and the rank of all of them.  A rank at a point bounds the generic rank from below; the
    functions' involution bounds it from above by half the leaf's dimension, r(n − r)."""
    import flint

    from stiefelsym.backends.fields import RationalField
    from stiefelsym.scene import Scene
    sec6 = _catalog("sec6_dimension_lemmas")
    n, r = size.n, size.r
    rng = random.Random(f"{seed}|neumann2|{n}|{r}")
    s = Scene(n, r, RationalField(2**20), chart="cayley", rng=rng)
    X, P = s.X, s.P
    P0 = P - X @ (X.T @ P) if on_psi_zero else P           # XᵀP0 = 0, so Ψ = 0
    x = (P0 @ X.T - X @ P0.T) + X @ X.T                   # Θ = h + v
    rows = sec6.casimir_gradient_rows(s, x, s.A)          # λ = 0..2n−1, then k = 1..n
    L1 = sec6.lambda1(s, x)
    q = lambda v: flint.fmpq(str(v))                       # noqa: E731 - an exact rational of the field
    G = [[q(v) for v in row] for row in rows]
    lam_count = 2 * n
    V = flint.fmpq_mat([[flint.fmpq(lam) ** j for j in range(lam_count)] for lam in range(lam_count)])
    Vinv = V.inv()
    m = len(G[0])
    L1m = flint.fmpq_mat([[q(L1._a[i, j]) for j in range(m)] for i in range(m)])
    coeff_rows: list[tuple[tuple[int, int], Any]] = []
    for k in range(1, n + 1):
        samples = flint.fmpq_mat([G[lam * n + (k - 1)] for lam in range(lam_count)])
        coeffs = Vinv * samples                            # row j: the gradient of the coefficient of λ^j
        restricted = coeffs * L1m
        for j in range(lam_count):
            row = [restricted[j, c] for c in range(m)]
            if any(row):
                coeff_rows.append(((k, j), row))
    chosen, acc, rank = [], [], 0
    for key, row in coeff_rows:
        r2 = flint.fmpq_mat(acc + [row]).rank()
        if r2 > rank:
            chosen.append(key)
            acc.append(row)
            rank = r2
    return Neumann2(size, chosen, rank)


def neumann2_markdown(items: Sequence[Neumann2]) -> list[str]:
    out = ["## Theorem NEUMANN2: the r(n − r) integrals on Ψ = 0", "",
           "On Ψ⁻¹(0)/SO(r) = T*G(n, r) the theorem asserts r(n − r) independent integrals among the functions "
           "(perelomov), c_{k,j} = the coefficient of λʲ in tr 𝓛(λ)ᵏ, 𝓛(λ) = λΦ + XXᵀ − λ²A.  At an exact rational "
           "point of Ψ⁻¹(0) (XᵀP = 0) the differentials of all c_{k,j}, restricted to the symplectic leaf of "
           "(gl(n), Λ1) through Θ(X, P), have rank r(n − r); the table lists the first r(n − r) independent ones "
           "in the order of k, then j.  A rank at an exact point shows that many of them independent there, so "
           "on an open dense part of Ψ = 0 (a rank can only drop on a closed set), which is what the theorem "
           "asserts.  More cannot be: functions in involution ((perelomov); the catalog checks the brackets for "
           "k ≤ 3, claim neumann-spectral-invariants) have differentials spanning an isotropic subspace of the "
           "leaf, of dimension at most r(n − r) on Ψ = 0 (T*G(n, r) has dimension 2r(n − r)).", "",
           "| (n, r) | r(n − r) | rank at the point | the integrals c_{k,j} (k, j) |", "| --- | ---: | ---: | --- |"]
    for it in items:
        n, r = it.size.n, it.size.r
        out.append(f"| ({n},{r}) | {r * (n - r)} | {it.rank_all} | "
                   + ", ".join(f"({k},{j})" for k, j in it.chosen) + " |")
    return out + [""]
