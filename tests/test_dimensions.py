"""Two-sided certificates of dimension statements (stiefelsym.methods.dimensions) on known cases, and the §6
dimension lemmas of the catalog: each holds at small sizes (the errata fail where registered) and a
corrupted copy of each FAILS (negative controls)."""
from fractions import Fraction

import flint
import pytest

from stiefelsym import Rank
from stiefelsym.claims import Size
from stiefelsym.methods.dimensions import (Certificate, Side, exact, generic_rank, rank_at_point, symbolic_kernel_bound,
                                   verified_kernel)
from stiefelsym.methods.fixed_size import run_exact, run_points
from stiefelsym.run.runner import run_one

import stiefelsym.proofs.sec6_dimension_lemmas as sec6

SEED = 0


# -- certificates at a point ---------------------------------------------------------------------

def test_rank_at_a_point_is_proved_on_both_sides():
    M = [[1, 2, 3], [2, 4, 6], [1, 0, 1]]
    c = rank_at_point(M, "rank")
    assert c.value == 2 and c.proved and c.kind == "proved"
    assert "rank mod p" in c.lower.how and "kernel vectors checked exactly" in c.upper.how


def test_rank_at_a_point_with_rational_entries_and_full_rank():
    c = rank_at_point([[Fraction(1, 2), 1], [1, Fraction(1, 3)]], "rank")
    assert c.value == 2 and c.proved and c.upper.how == "full rank"


def test_a_rank_one_below_full_needs_the_kernel():
    # rows independent modulo many primes but one rational relation: the kernel certifies it
    M = [[3, 5, 7, 11], [6, 10, 14, 22], [1, 1, 1, 1]]
    c = rank_at_point(M, "rank")
    assert (c.lower.bound, c.upper.bound) == (2, 2)


def test_verified_kernel_rejects_a_wrong_vector():
    M = flint.fmpz_mat([[1, 2], [2, 4]])
    assert verified_kernel(M, flint.fmpz_mat([[2], [-1]])) == 1
    assert verified_kernel(M, flint.fmpz_mat([[1], [1]])) == 0


def test_certificate_arithmetic_swaps_the_sides():
    c = Certificate("rank", Side(3, "minor"), Side(5, "kernel", 1e-40))
    d = 10 - c
    assert (d.lower.bound, d.upper.bound) == (5, 7)
    assert d.lower.false_probability == 1e-40 and d.upper.false_probability == 0.0
    assert d.value is None and d.kind == "bounds"
    e = exact("k", 4, "count") + exact("m", 3, "count")
    assert e.value == 7 and e.proved


# -- generic ranks -------------------------------------------------------------------------------

def test_generic_rank_of_a_rank_one_polynomial_matrix_is_checked_with_a_bound():
    def M(x):
        a, b = x
        return [[a, b], [2 * a, 2 * b], [a * a, a * b]]
    c = generic_rank(M, 2, 2, "rank", seed=SEED)
    assert c.value == 1 and c.kind == "checked"
    assert c.lower.proved and 0 < c.upper.false_probability <= 1e-30


def test_generic_rank_without_enough_points_gives_only_the_trivial_upper_bound():
    c = generic_rank(lambda x: [[x[0], x[1]], [2 * x[0], 2 * x[1]], [0, 0]], 2, 1, "rank", seed=SEED, max_points=1)
    assert c.value is None and c.kind == "bounds" and (c.lower.bound, c.upper.bound) == (1, 2)


def test_generic_rank_is_proved_when_full():
    c = generic_rank(lambda x: [[x[0], 1], [1, x[1]]], 2, 1, "rank", seed=SEED)
    assert c.value == 2 and c.proved


def test_generic_rank_is_reproducible_from_the_seed():
    def M(x):
        return [[x[0], x[1], x[0] + x[1]]]
    assert generic_rank(M, 2, 1, seed=5).as_dict() == generic_rank(M, 2, 1, seed=5).as_dict()


def test_symbolic_kernel_proves_the_upper_side():
    import sympy
    x, y = sympy.symbols("x y")
    M = sympy.Matrix([[x, y], [2 * x, 2 * y]])
    c = symbolic_kernel_bound(M, sympy.Matrix([[y], [-x]]), {x: 3, y: 5}, "rank")
    assert c.value == 1 and c.proved


def test_symbolic_kernel_rejects_a_vector_outside_the_kernel():
    import sympy
    x, y = sympy.symbols("x y")
    M = sympy.Matrix([[x, y], [2 * x, 2 * y]])
    with pytest.raises(ValueError):
        symbolic_kernel_bound(M, sympy.Matrix([[x], [-y]]), {x: 3, y: 5}, "rank")


# -- the §6 claims ---------------------------------------------------------------------------------

def _section6_dims(catalog):
    return [c for c in catalog if c.source.endswith("sec6_dimension_lemmas")]


ERRATA = ("pencil-l5-l6", "pencil-leaves-singular", "pencil-gl-isomorphism")


# Each corruption claims a rank below the true one: the sampled methods see a larger rank at a point,
# a certain failure (a rank above the true one is refuted by the exact method only).

def leaf_dimension_minus_two(s):
    """Corrupted (dimension): 2l − 2."""
    x = sec6.theta(s)
    return {"rank": Rank(sec6.lambda1(s, x), sec6.leaf_printed(s.n, s.r) - 2)}


def leaves_singular_with_more_casimirs(s):
    """Corrupted: the generic rank of Λ1 on gl(n) taken as n² − n − 2 (one Casimir too many)."""
    y = s.generic("Y", "n", "n")
    return {"rank": Rank(sec6.lambda1(s, y), s.n * s.n - s.n - 2)}


def a1_kernel_too_big(s):
    """Corrupted (A1): ker Λ_{1,−1} of dimension n + 1."""
    x = sec6.theta(s)
    return {"rank": Rank(sec6.lambda1(s, x) - sec6.lambda2(s, x, s.A), s.n * s.n - s.n - 1)}


def ker_with_all_of_so_r(s):
    """Corrupted (KER): all of so(r) in place of its Cartan subalgebra so(r)_{h1}."""
    X0, h, v, h1, A = sec6.paper_point(s)
    extra = s.r * (s.r - 1) // 2 - s.r // 2
    return {"rank": Rank(sec6.lambda1(s, h + v), s.n * s.n - sec6.ker_printed(s.n, s.r) - extra - 1)}


def a2_generic_kernel_too_big(s):
    """Corrupted (A2) at a generic point: the restricted kernel of dimension n + 1."""
    x = sec6.theta(s)
    n = s.n
    return {"(A2)": Rank(sec6.a2_system(s, x, s.A), n * n - n - 1 + sec6.leaf_printed(n, s.r))}


def l5_l6_corrected_off_by_one(s):
    """Corrupted correction of (L6): r + 1 solutions."""
    M, unknowns = sec6.l5_l6_matrix(s, printed=False)
    return {"(L5), (L6)": Rank(M, unknowns - s.r - 1)}


def casimirs_one_short(s):
    """Corrupted (LEMA2): l − 1 independent Casimirs on the leaf."""
    x = sec6.theta(s)
    G = s.mat(sec6.casimir_gradient_rows(s, x, s.A))
    return {"rank": Rank(G @ sec6.lambda1(s, x), sec6.leaf_printed(s.n, s.r) // 2 - 1)}


def torus_one_larger(s):
    """Corrupted (dim_fol): tori of dimension (dim_fol) + 1."""
    rows = sec6.differentials(s, sec6.torus_functions(s)) + s.jacobian(s.constraints.build)
    n, r = s.n, s.r
    return {"rank": Rank(s.mat(rows), 2 * sec6.dim_V(n, r) - sec6.torus_twice_printed(n, r) // 2 - 1 + r * (r + 1))}


def gl_isomorphism_wrong_point(s):
    """Corrupted correction of the pencil's isomorphism: Λ_{1−c,c} taken to vanish at c²A (it vanishes at cA)."""
    c = s.scalar("c")
    x0 = s.A * (c * c)
    return {"vanishes": sec6.lambda1(s, x0) * (s.q(1) - c) + sec6.lambda2(s, x0, s.A) * c}


CORRUPTIONS = [
    ("pencil-leaf-dimension", leaf_dimension_minus_two, (3, 2)),
    ("pencil-leaves-singular", leaves_singular_with_more_casimirs, (3, 2)),
    ("pencil-rank-a1", a1_kernel_too_big, (3, 2)),
    ("pencil-kernel-ker-a2", ker_with_all_of_so_r, (3, 3)),
    ("pencil-a2-generic", a2_generic_kernel_too_big, (3, 2)),
    ("pencil-l5-l6", l5_l6_corrected_off_by_one, (3, 2)),
    ("casimirs-complete-on-leaf", casimirs_one_short, (3, 2)),
    ("neumann-torus-dimension", torus_one_larger, (3, 2)),
    ("pencil-gl-isomorphism", gl_isomorphism_wrong_point, (3, 2)),
]


def test_every_dimension_lemma_has_a_negative_control(catalog):
    assert {cid for cid, _, _ in CORRUPTIONS} == {c.id for c in _section6_dims(catalog)}


@pytest.mark.parametrize("cid, func, size", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f, _ in CORRUPTIONS])
def test_corrupted_dimension_lemma_fails(catalog, cid, func, size):
    c = catalog.get(cid)
    assert run_exact(c, *size, SEED, func=func).verdict == "fails"
    for method in ("modular", "rational"):
        assert run_points(c, *size, method, SEED, func=func).verdict == "fails"


@pytest.mark.parametrize("n, r", [(2, 1), (3, 1), (3, 2), (3, 3)])
def test_dimension_lemmas_hold_at_small_sizes(catalog, n, r):
    for c in _section6_dims(catalog):
        if not c.sizes.admits(n, r):
            continue
        res = run_one(c, Size(n, r), "auto", SEED)
        assert res.expected, res.line()
        if c.id not in ERRATA or not c.expects_failure(n, r):
            assert res.verdict in ("proved", "checked"), res.line()


@pytest.mark.parametrize("n, r", [(3, 2), (4, 4)])
def test_differentials_by_gradients_are_the_jacobian_rows(n, r):
    """The rows df from s.gradient (reverse mode) are the rows of s.jacobian (2nr forward passes)."""
    import random

    from stiefelsym import Scene
    from stiefelsym.backends.fields import ModularField
    s = Scene(n, r, ModularField(2305843009213693951), chart="cayley", rng=random.Random(7))
    funcs = sec6.torus_functions(s)
    by_gradients = sec6.differentials(s, funcs)
    by_jacobian = s.jacobian(lambda t: [f(t) for f in funcs])
    assert len(by_gradients) == len(by_jacobian) == len(funcs)
    assert [[str(x) for x in row] for row in by_gradients] == [[str(x) for x in row] for row in by_jacobian]


def test_l6_as_printed_fails_from_r_3(catalog):
    c = catalog.get("pencil-l5-l6")
    assert c.erratum and c.expects_failure(3, 3) and not c.expects_failure(3, 2)
    assert run_one(c, Size(3, 3), "auto", SEED).verdict == "fails"
    assert run_points(c, 3, 3, "modular", SEED).verdict == "fails"


def test_strict_leaf_inequality_fails_only_at_the_smallest_sizes(catalog):
    c = catalog.get("pencil-leaves-singular")
    assert c.expects_failure(2, 1) and c.expects_failure(1, 1) and not c.expects_failure(2, 2)
    res = run_one(c, Size(2, 1), "auto", SEED)
    assert res.verdict == "fails" and res.expected


# -- the functions of the completeness Jacobians are the printed functions --------------------------

def _modular_scene(n, r, seed=0):
    import random
    from stiefelsym.backends.fields import ModularField
    from stiefelsym.scene import Scene
    return Scene(n, r, ModularField(), rng=random.Random(f"dimensions|{n}|{r}|{seed}"))


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (4, 4)])
def test_torus_values_are_the_torus_functions(n, r):
    """The values of the integrals of Theorem NEUMANN with shared powers are those of the functions one
    by one, in the same order, also along a tangent vector (their derivatives)."""
    s = _modular_scene(n, r)
    funcs = sec6.torus_functions(s)
    assert sec6.torus_values(s) == [f(s) for f in funcs]
    t = s.tangent({"X": s.generic("dX", "n", "r"), "P": s.generic("dP", "n", "r")})
    assert [v.b for v in sec6.torus_values(t)] == [f(t).b for f in funcs]


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (4, 4)])
def test_completeness_functions_are_the_printed_ones(n, r):
    """The scalar functions (perelomov), (FF) and (BB) whose gradients the completeness claims take are the
    printed functions, in the same order."""
    import stiefelsym.proofs.sec6_compatible_brackets as cb
    s = _modular_scene(n, r)
    lams = [s.scalar(f"lam{j}") for j in range(3)]
    assert [f(s) for f in cb._perelomov_functions(3, n)] == [cb.perelomov(s, lam, k) for lam in lams
                                                              for k in range(1, n + 1)]
    assert [f(s) for f in cb._FF_functions(3, n)] == [cb.FF(s, lam, k) for lam in lams for k in range(1, n + 1)]
    assert [f(s) for f in cb._bb_functions(r)] == [cb.bb(s, s.Psi, s.scalar(f"mu{j}"), k) for j in range(r + 1)
                                                   for k in range(1, r + 1)]


def test_com_completeness_with_one_power_wrong_fails():
    """Negative controls of the completeness functions: (perelomov) with its top power tr M^n replaced by
    tr M^(n-1)·tr M (dependent on the others) loses an independent differential, refuted exactly; and
    the printed functions with a count one too small are refuted by every sampled method."""
    import stiefelsym.proofs.sec6_compatible_brackets as cb
    claim = next(c for c in _catalog_claims() if c.id == "com-completeness")

    def corrupted(s):
        n, r = s.n, s.r
        functions = cb._perelomov_functions(2 * n + 1, n)
        for j in range(2 * n + 1):
            functions[j * n + n - 1] = lambda t, a=functions[j * n + n - 2], b=functions[j * n]: a(t) * b(t)
        functions += cb._bb_functions(r)
        return {"ddim": Rank(cb._differentials_on_TV(s, functions), cb._dim_V(n, r) + r * (r + 1), generic=True)}

    def one_short(s):
        n, r = s.n, s.r
        functions = cb._perelomov_functions(2 * n + 1, n) + cb._bb_functions(r)
        return {"ddim": Rank(cb._differentials_on_TV(s, functions), cb._dim_V(n, r) + r * (r + 1) - 1, generic=True)}
    assert run_exact(claim, 2, 1, SEED, func=corrupted).verdict == "fails"
    for method in ("modular", "rational"):
        assert run_points(claim, 3, 2, method, SEED, func=one_short).verdict == "fails"


def _catalog_claims():
    from stiefelsym.claims import load_catalog
    return list(load_catalog())
