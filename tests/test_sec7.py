"""§7 claims: the Neumann flows on Ψ = 0, the reduced equation (neum-gras) on e_1∧…∧e_r, the case
r = n − 1 (iden1), (iden2), (neum-gras**), and the quartic Hamiltonian hold at small sizes; those
built from matrix products are proved for every n, r; a corrupted copy of each FAILS (negative
controls)."""
import random
from fractions import Fraction

import pytest

from stiefelsym import Rank
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points

import stiefelsym.proofs.determinants as determinants
import stiefelsym.proofs.sec7_grassmannians as sec7
from stiefelsym.proofs.sec5_neumann import H_neumann_euclidean, H_neumann_normal

SEED = 0

FREE_PROVED = ("neumann-flows-coincide-on-psi-zero", "quartic-psi-zero-invariant", "quartic")
NEEDS_COORDINATES = ("neum-gras", "neum-gras-sphere", "neumann2-kernel", "neumann2-h-size")
#: (exact sizes, modular sizes) of each claim as printed
SIZES = {
    "neumann-flows-coincide-on-psi-zero": ([(2, 1), (3, 2)], [(3, 2), (4, 2), (4, 4)]),
    "quartic-psi-zero-invariant": ([(2, 1), (3, 2)], [(3, 2), (4, 3)]),
    "neum-gras": ([(2, 1), (3, 2), (3, 3)], [(4, 2), (4, 3), (5, 3)]),
    "neum-gras-sphere": ([(2, 1)], [(3, 2), (4, 3)]),
    "quartic": ([(2, 1), (3, 1)], [(4, 1)]),
    "neumann2-kernel": ([(2, 1), (3, 2), (3, 3)], [(4, 2), (4, 3), (5, 2), (5, 3)]),
    "neumann2-h-size": ([(2, 2), (3, 3)], [(4, 4)]),     # the printed h = Ψ(X0, P0) has size n only when r = n
}


def _section7(catalog):
    return [c for c in catalog if c.section == "7"]


# -- corrupted copies of the claims ----------------------------------------------------------

def flows_differ_by_minus_half_psi(s):
    """Corrupted: the κ = 0 and κ = −½ flows differ by −½(XΨ, PΨ)."""
    normal, euclidean = s.dirac_flow(H_neumann_normal), s.dirac_flow(H_neumann_euclidean)
    return {"dX/dt": normal.Xdot - euclidean.Xdot + s.X @ s.Psi / 2}


def flows_coincide_everywhere(s):
    """Corrupted: the printed (N0_XP2) and (NE_XP) coincide at every point (not only on Ψ = 0)."""
    return {"dP/dt": sec7.flow_N0_at(s, s.X, s.P)["P"] - sec7.flow_NE_at(s, s.X, s.P)["P"]}


def neum_gras_without_the_factor_2(s):
    """Corrupted (neum-gras): the second sum with the factor 1 in place of 2 (r >= 2)."""
    flow = s.dirac_flow(H_neumann_euclidean)
    r, n = s.r, s.n
    E = sec7.columns(s.X, r)
    second = s.d(lambda t: sec7.column(t, sec7.first_derivative(t, sec7.columns(t.X, r), sec7.columns(t.P, r))),
                 flow)
    rhs = sec7.neum_gras_rhs(s, s.X, flow.Xdot)
    V = sec7.columns(flow.Xdot, r)
    for i in range(r):
        for j in range(i + 1, r):
            g = sec7.plucker(s, sec7.replaced(E, {i: V[i], j: V[j]}), n)
            rhs = [a - b for a, b in zip(rhs, g)]
    return {"(neum-gras)": second - sec7.column(s, rhs)}


def neum_gras_lambda_sign(s):
    """Corrupted (neum-gras): λ = tr(XᵀAX + ẊᵀẊ)."""
    flow = s.dirac_flow(H_neumann_euclidean)
    r = s.r
    second = s.d(lambda t: sec7.column(t, sec7.first_derivative(t, sec7.columns(t.X, r), sec7.columns(t.P, r))),
                 flow)
    rhs = sec7.neum_gras_rhs(s, s.X, flow.Xdot)
    extra = 2 * s.tr(flow.Xdot.T @ flow.Xdot)
    G = sec7.plucker(s, sec7.columns(s.X, r), s.n)
    return {"(neum-gras)": second - sec7.column(s, [a + extra * g for a, g in zip(rhs, G)])}


def sphere_with_plus_trace(s):
    """Corrupted (neum-gras**): (A + tr A I)e_n + λe_n."""
    r = s.r
    X = s.X
    P0 = sec7.horizontal(s, X, s.P)
    printed = sec7.flow_NE_at(s, X, P0)
    E, Acc = sec7.columns(X, r), sec7.columns(printed["P"], r)
    e = sec7.vector(s, sec7.cross(s, E))
    eddot = sec7.vector(s, sec7.add(*[sec7.cross(s, sec7.replaced(E, {i: Acc[i]})) for i in range(r)]))
    lam = s.tr(X.T @ s.A @ X - printed["X"].T @ printed["X"])
    return {"(neum-gras**)": eddot - (s.A @ e + s.tr(s.A) * e) - lam * e}


def sphere_at_a_point_off_psi_zero(s):
    """Corrupted (neum-gras**): the second term of (neum-gras) vanishes at every point (not only on Ψ = 0)."""
    r = s.r
    E, V = sec7.columns(s.X, r), sec7.columns(s.P, r)
    out = [s.q(0)] * s.n
    for i in range(r):
        for j in range(i + 1, r):
            out = sec7.add(out, sec7.cross(s, sec7.replaced(E, {i: V[i], j: V[j]})))
    return {"second term": sec7.column(s, out)}


def quartic_coefficient(s):
    """Corrupted (quartic): −2(Σ a_i e_i²)²."""
    a, e, p, n = s.a, s.X, s.P, s.n
    pp = sum((p[i, 0] * p[i, 0] for i in range(n)), s.q(0))
    quad = sum((a[i] * a[i] * e[i, 0] * e[i, 0] for i in range(n)), s.q(0))
    mean = sum((a[i] * e[i, 0] * e[i, 0] for i in range(n)), s.q(0))
    return {"(quartic)": sec7.H_quartic(s) - (pp / 2 + quad - 2 * mean * mean)}


def quartic_trace_of_the_square(s):
    """Corrupted (quartic), written with products as the claim is: −2(e, Ae)² in place of −(e, Ae)²."""
    e, p, A = s.X, s.P, s.A
    mean = s.tr(e.T @ A @ e)
    return {"(quartic)": sec7.H_quartic(s) - (s.tr(p.T @ p) / 2 + s.tr(e.T @ A @ A @ e) - 2 * mean * mean)}


def quartic_plus_a_non_invariant_term(s):
    """Corrupted: a Hamiltonian with tr(XᵀAXG), G generic (not SO(r)-invariant), does not keep Ψ."""
    H = lambda t: sec7.H_quartic(t) + t.tr(t.X.T @ t.A @ t.X @ t.generic("G", "r", "r"))
    return {"dPsi/dt": s.d(lambda t: t.Psi, s.dirac_flow(H))}


def neumann2_kernel_off_psi_zero(s):
    """Corrupted (NEUMANN2): the kernel of gl(r) ⊕ gl(n − r) at a generic point of T*V, off Ψ = 0 (there
    Λ1 has the larger rank (dimension) when r >= 3: a certain failure)."""
    n, r = s.n, s.r
    x = sec7.lambda1(s, s.Phi + s.X @ s.X.T)
    return {"rank": Rank(x, n * n - r * r - (n - r) * (n - r))}


def h_block_off_psi_zero(s):
    """Corrupted (NEUMANN2, corrected h = Φ): h_1 = XᵀhX vanishes at a generic point of T*V, not only on Ψ = 0
    (there h_1 = −Ψ)."""
    X = s.X
    return {"h_1": X.T @ (s.P @ X.T - X @ s.P.T) @ X}


#: (claim, corrupted function, (size of the exact check or None, size of the modular check))
CORRUPTIONS = [
    ("neumann-flows-coincide-on-psi-zero", flows_differ_by_minus_half_psi, ((3, 2), (3, 2))),
    ("neumann-flows-coincide-on-psi-zero", flows_coincide_everywhere, ((3, 2), (3, 2))),
    ("neum-gras", neum_gras_without_the_factor_2, ((3, 2), (4, 3))),
    ("neum-gras", neum_gras_lambda_sign, ((3, 2), (4, 2))),
    ("neum-gras-sphere", sphere_with_plus_trace, ((2, 1), (4, 3))),
    ("neum-gras-sphere", sphere_at_a_point_off_psi_zero, (None, (4, 3))),
    ("quartic", quartic_coefficient, ((2, 1), (4, 1))),
    ("quartic", quartic_trace_of_the_square, ((2, 1), (4, 1))),
    ("quartic-psi-zero-invariant", quartic_plus_a_non_invariant_term, ((3, 2), (4, 2))),
    ("neumann2-kernel", neumann2_kernel_off_psi_zero, ((3, 3), (4, 3))),
    ("neumann2-h-size", h_block_off_psi_zero, ((3, 2), (4, 2))),
]


def test_every_section7_claim_has_a_negative_control(catalog):
    assert {cid for cid, _, _ in CORRUPTIONS} == {c.id for c in _section7(catalog)}


def test_the_free_and_coordinate_lists_cover_section7(catalog):
    assert set(FREE_PROVED) | set(NEEDS_COORDINATES) == {c.id for c in _section7(catalog)} == set(SIZES)


@pytest.mark.parametrize("cid, func, size", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f, _ in CORRUPTIONS])
def test_corrupted_claim_fails(catalog, cid, func, size):
    c = catalog.get(cid)
    exact, (n, r) = size
    if exact is not None:
        assert run_exact(c, *exact, SEED, func=func).verdict == "fails"
    res = run_points(c, n, r, "modular", SEED, func=func)
    # a rank has no witness point: the computed and printed numbers are the witness
    assert res.verdict == "fails" and (c.kind == "dim" or res.witness and res.witness["seed"] == SEED)


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_corrupted_claim_is_not_proved_for_all_sizes(catalog, cid):
    for c_id, func, _ in CORRUPTIONS:
        if c_id == cid:
            assert run_free(catalog.get(cid), func).verdict == "undecided"


# -- the claims as printed -------------------------------------------------------------------

@pytest.mark.parametrize("cid", list(SIZES))
def test_section_7_holds_as_printed_at_small_sizes(catalog, cid):
    c = catalog.get(cid)
    exact, modular = SIZES[cid]
    for n, r in exact:
        assert run_exact(c, n, r, SEED).verdict == "proved", (cid, n, r)
    for n, r in modular:
        res = run_points(c, n, r, "modular", SEED)
        # checks that no parameter enters (counts of integers) are constants, exact over Q: proved
        want = "proved" if res.certificate.startswith("no parameter enters") else "checked"
        assert res.verdict == want, (cid, n, r, res.verdict)


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_claim_is_proved_for_every_n_and_r(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message


@pytest.mark.parametrize("cid", NEEDS_COORDINATES)
def test_claim_needs_coordinates(catalog, cid):
    assert run_free(catalog.get(cid)).verdict == "undecided"


def test_the_sphere_vector_is_the_plucker_vector():
    """(iden2) at r = n − 1: the components of e_n are the Plücker coordinates of e_1∧…∧e_{n−1}
    up to the signs (−1)^{n+k} (the cofactors of the last column of (X, e_n))."""
    from stiefelsym.claims import Claim, admissible

    def iden2(s):
        E = sec7.columns(s.X, s.r)
        en = sec7.cross(s, E)
        G = sec7.plucker(s, E, s.n)   # lexicographic: G[j] omits row n − 1 − j
        return {"(iden2)": sec7.column(s, [en[k] - (G[s.n - 1 - k] if (s.n + k + 1) % 2 == 0
                                                     else -G[s.n - 1 - k]) for k in range(s.n)])}
    c = Claim(id="iden2", paper=("iden2",), kind="id", section="7", func=iden2,
              sizes=admissible(4, where=lambda n, r: r == n - 1))
    assert run_exact(c, 3, 2, SEED).verdict == "proved"
    assert run_points(c, 4, 3, "modular", SEED).verdict == "checked"


class _Numbers:
    """A scene's scalar interface over the rationals (s.q), for the determinant helper alone."""
    q = staticmethod(Fraction)


@pytest.mark.parametrize("m", range(1, 13))
def test_det_is_the_determinant_by_either_expansion(m):
    """det(s, rows) (Laplace up to m = 9, Berkowitz's division-free recursion from m = 10 on) is the
    determinant, on matrices with zeros on the diagonal (no pivot is ever divided by); both
    expansions agree at every m, and one changed entry changes the value by its cofactor (a negative
    control: neither expansion ignores an entry)."""
    import sympy
    rng = random.Random(f"det|{m}")
    rows = [[Fraction(rng.randint(-4, 4)) for _ in range(m)] for _ in range(m)]
    for i in range(0, m, 2):
        rows[i][i] = Fraction(0)
    expected = Fraction(int(sympy.Matrix(rows).det()))
    assert sec7.det(_Numbers, rows) == expected
    assert determinants._det_berkowitz(_Numbers, rows) == expected
    assert (2 * determinants._berkowitz_products(m) <= determinants._laplace_products(m)) == (m >= 10)
    k = rng.randrange(m)
    minor = [[rows[i][j] for j in range(m) if j != k] for i in range(1, m)]
    rows[0][k] += 1        # det changes by the cofactor of (0, k)
    cofactor = (-1) ** k * (Fraction(int(sympy.Matrix(minor).det())) if m > 1 else Fraction(1))
    assert sec7.det(_Numbers, rows) == expected + cofactor
    assert determinants._det_berkowitz(_Numbers, rows) == expected + cofactor


def test_the_printed_h_of_the_proof_of_neumann2_is_an_erratum(catalog):
    """The proof of Theorem NEUMANN2 prints h = Ψ(X0, P0), of size r, added to v = X0X0ᵀ of size n: it fails
    as printed for r < n with the printed and computed numbers; the correction h = Φ(X0, P0) has size n and
    its block h_1 = Ψ(X0, P0) vanishes on Ψ⁻¹(0), at every size."""
    c = catalog.get("neumann2-h-size")
    for n, r in [(3, 1), (4, 2), (5, 3)]:
        res = run_exact(c, n, r, SEED)
        assert res.verdict == "fails" and c.expects_failure(n, r) and "paper: " in res.certificate, res
    assert not c.expects_failure(3, 3)
    for n, r in [(3, 1), (4, 2), (4, 4), (5, 3)]:
        assert run_exact(c, n, r, SEED, func=c.corrections[0].func).verdict == "proved"
