"""§4 claims: each holds at small sizes (the dual Lax pair after its erratum), the identities
built from matrix products are proved for every n, r by the dimension-free method, and a
corrupted copy of each FAILS (negative controls; for every Lax pair, the commutator in the
other order)."""
import pytest


from stiefelsym import Count, comm, twisted
from stiefelsym.claims import Size
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points
from stiefelsym.run.runner import run_one

import stiefelsym.proofs.sec4_integrability as sec4

SEED = 0

#: proved for every n, r by rewriting modulo (cond_XP)
FREE_PROVED = ("jensen-integrals", "manakov-square", "manakov-square-flow", "manakov-square-lax",
               "manakov-integrals", "noether-normal-metric", "jensen-invariants-conserved", "euler-so-n",
               "manakov-reflections",   # the reflection as a letter S = S^T, S^2 = I, SA = AS
               "gram-commutes-with-psi-if-r-is-1-or-n")   # for every n at r = 1 and at r = n, case by case
#: need coordinates: ranks and counts, the Manakov operator of a general diagonal B
NEEDS_COORDINATES = ("invariant-tori-dimensions", "manakov-operator", "manakov-lax")
#: fail as printed (documented errata with a registered correction)
ERRATA = ("manakov-dual-lax", "gram-not-in-involution-with-psi")


def _section4(catalog):
    """The claims written in the module of §4 (Proposition 4.6, filed under §4, is written and tested with §3)."""
    return [c for c in catalog if c.section == "4" and c.func.__module__.endswith(".sec4_integrability")]


# -- corrupted copies of the claims ----------------------------------------------------------

def jensen_gram_not_conserved(s):
    """Corrupted: PᵀP in place of Ψ (it is not an integral of H_κ for κ ≠ 0)."""
    return {"dPsi/dt": s.d(lambda t: t.P.T @ t.P, s.dirac_flow(sec4.H_jensen))}


def tori_dimension_always_r(s):
    """Corrupted (bols-jov): δ₀ = r for every n."""
    n, r = s.n, s.r
    return {"delta_0": Count(2 * sec4.dim_V(n, r) - sec4.ddim_printed(n, r) - sec4.two_l_printed(n, r), r)}


def manakov_operator_transposed(s):
    """Corrupted (Manakov): (b_i − b_j)/(a_j − a_i)."""
    b = sec4.b_eigenvalues(s)
    AA = sec4.manakov_operator(s, b)
    return {"ad_A AA(xi) = ad_B xi": comm(s.A, AA(s.xi)) + comm(sec4.diagonal(s, b), s.xi)}


def manakov_square_minus(s):
    """Corrupted (Manakov*): 𝔸(ξ) = Aξ − ξA."""
    AA = s.A @ s.xi - s.xi @ s.A
    return {"ad_A AA(xi) = ad_{A^2} xi": comm(s.A, AA) - comm(s.A @ s.A, s.xi)}


def manakov_flow_one_term(s):
    """Corrupted (dot_XP3*): Ẋ = 2AΦX."""
    flow = s.dirac_flow(sec4.H_manakov_square)
    return {"dX/dt": flow.Xdot - 2 * (s.A @ s.Phi @ s.X)}


def manakov_lax_swapped(s):
    """Corrupted: d𝓛/dt = [𝓛, 𝓐] (the commutator in the other order)."""
    b = sec4.b_eigenvalues(s)
    flow = s.dirac_flow(sec4.H_manakov)
    L = s.Phi + s.lam * s.A
    M = sec4.manakov_operator(s, b)(s.Phi) + s.lam * sec4.diagonal(s, b)
    return {"Lax": s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(L, M)}


def manakov_square_lax_swapped(s):
    """Corrupted: d𝓛/dt = [𝓛, 𝓐] for B = A²."""
    flow = s.dirac_flow(sec4.H_manakov_square)
    L = s.Phi + s.lam * s.A
    M = sec4.manakov_square(s, s.Phi) + s.lam * (s.A @ s.A)
    return {"Lax": s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(L, M)}


def manakov_integral_of_the_wrong_pencil(s):
    """Corrupted (man): tr(λA² + Φ)³ is not an integral."""
    flow = s.dirac_flow(sec4.H_manakov_square)
    return {"d tr/dt": s.d(lambda t: sec4.power_trace(t, t.lam * (t.A @ t.A) + t.Phi, 3), flow)}


def dual_lax_corrected_but_swapped(s):
    """Corrupted correction of (MAN-LA): [𝓐*, 𝓛*] with (A + λI)."""
    flow = s.dirac_flow(sec4.H_manakov_square)
    M = sec4.A_man_dual_at(s, s.X, s.P, s.A + s.lam * s.In)
    return {"MAN-LA": s.d(sec4.L_man_dual, flow) - comm(M, sec4.L_man_dual(s))}


def dual_lax_printed_but_swapped(s):
    """The printed (MAN-LA) with the commutator in the other order (it fails too)."""
    flow = s.dirac_flow(sec4.H_manakov_square)
    return {"MAN-LA": s.d(sec4.L_man_dual, flow) - comm(sec4.A_man_dual(s), sec4.L_man_dual(s))}


def gram_commutes_with_phi_squared(s):
    """Corrupted remark: {(p_i, p_j), <Φ, Φ>} (it vanishes: Noether), not <Ψ, Ψ>."""
    gram = lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P)
    return {"{tr(G P^T P), <Phi, Phi>}": s.bracket(gram, lambda t: t.killing(t.Phi, t.Phi))}


def gram_is_plus_psi_squared(s):
    """Corrupted: PᵀP = +Ψ²/4 when r = n."""
    return {"P^T P - Psi^2/4": s.P.T @ s.P - s.Psi @ s.Psi / 4}


def reflections_break_the_resolvent(s):
    """Corrupted: 𝓛* at (S_1 X, P) (only X reflected) is not 𝓛*."""
    S = twisted.reflection(s)   # S_1 at fixed sizes, the letter S of the free algebra
    return {"S_1: L*": sec4.L_man_dual_at(s, S @ s.X, s.P) - sec4.L_man_dual(s)}


CORRUPTIONS = [
    ("jensen-integrals", jensen_gram_not_conserved, (3, 2)),
    ("invariant-tori-dimensions", tori_dimension_always_r, (3, 2)),   # n < 2r
    ("manakov-operator", manakov_operator_transposed, (3, 2)),
    ("manakov-square", manakov_square_minus, (3, 2)),
    ("manakov-square-flow", manakov_flow_one_term, (3, 2)),
    ("manakov-lax", manakov_lax_swapped, None),   # n = 2: both sides vanish; symbolic n = 3 is slow
    ("manakov-square-lax", manakov_square_lax_swapped, (3, 2)),
    ("manakov-integrals", manakov_integral_of_the_wrong_pencil, (3, 2)),
    ("manakov-dual-lax", dual_lax_corrected_but_swapped, (2, 1)),
    ("manakov-dual-lax", dual_lax_printed_but_swapped, (2, 1)),
    ("manakov-reflections", reflections_break_the_resolvent, (2, 1)),
    ("gram-not-in-involution-with-psi", gram_commutes_with_phi_squared, (3, 2)),
    ("gram-commutes-with-psi-if-r-is-1-or-n", gram_is_plus_psi_squared, (3, 3)),
]


def test_every_section4_claim_has_a_negative_control(catalog):
    from test_sec6 import ADDED   # the bracket claims added to §4 with §6 have theirs there
    assert {cid for cid, _, _ in CORRUPTIONS + ADDED} >= {c.id for c in _section4(catalog)}


def test_the_free_coordinate_and_errata_lists_cover_section4(catalog):
    assert set(FREE_PROVED) | set(NEEDS_COORDINATES) | set(ERRATA) == {c.id for c in _section4(catalog)}


@pytest.mark.parametrize("cid, func, size", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f, _ in CORRUPTIONS])
def test_corrupted_claim_fails(catalog, cid, func, size):
    c = catalog.get(cid)
    if size is not None:
        assert run_exact(c, *size, SEED, func=func).verdict == "fails"
    n, r = size or (3, 2)
    for method in ("modular", "rational"):
        res = run_points(c, n, r, method, SEED, func=func)
        assert res.verdict == "fails"
        if c.kind not in ("dim", "not"):    # a wrong count, or a vanishing: no point of T*V to show
            assert res.witness and res.witness["seed"] == SEED


@pytest.mark.parametrize("cid, func", [(c, f) for c, f, _ in CORRUPTIONS if c in FREE_PROVED + ERRATA],
                         ids=[f"{c}-{f.__name__}" for c, f, _ in CORRUPTIONS if c in FREE_PROVED + ERRATA])
def test_corrupted_claim_is_not_proved_for_all_sizes(catalog, cid, func):
    assert run_free(catalog.get(cid), func).verdict == "undecided"


# -- the claims as printed -------------------------------------------------------------------

@pytest.mark.parametrize("n, r", [(2, 1), (2, 2), (3, 2), (4, 2)])
def test_section_4_holds_as_printed_at_small_sizes(catalog, n, r):
    for c in _section4(catalog):
        if c.id in ERRATA or not c.sizes.admits(n, r):
            continue
        res = run_one(c, Size(n, r), "auto", SEED)      # exact within the claim's budget, else modular
        assert res.verdict in ("proved", "checked") and res.expected, res.line()
        # covariant: symbolic in the equivariant chart (not the reflection S_1: it needs A diagonal)
        if c.id not in NEEDS_COORDINATES + ("manakov-reflections",):
            assert res.method == "exact", res.line()
        assert run_points(c, n, r, "modular", SEED).verdict == "checked", c.id


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_claim_is_proved_for_every_n_and_r(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message


@pytest.mark.parametrize("cid", NEEDS_COORDINATES)
def test_coordinate_claims_are_left_to_the_fixed_size_methods(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "undecided" and "needs coordinates" in res.message


# -- the erratum of Theorem man-dual ------------------------------------------------------------

@pytest.mark.parametrize("n, r", [(2, 1), (2, 2), (4, 2)])
def test_manakov_dual_lax_pair_fails_as_printed(catalog, n, r):
    """(LA-MAN3) as printed, with (A + λI)⁻¹: the Lax equation (MAN-LA) fails, with a witness."""
    c = catalog.get("manakov-dual-lax")
    assert c.expects_failure(n, r) and c.erratum
    res = run_one(c, Size(n, r), "auto", SEED)
    assert res.verdict == "fails" and res.expected, res.line()
    assert run_points(c, n, r, "modular", SEED).witness["seed"] == SEED


def test_manakov_dual_lax_pair_holds_trivially_for_n_1(catalog):
    c = catalog.get("manakov-dual-lax")
    assert not c.expects_failure(1, 1)
    assert run_exact(c, 1, 1, SEED).verdict == "proved"


def test_manakov_dual_lax_pair_correction_is_proved(catalog):
    """(A + λI) in place of (A + λI)⁻¹: proved for every n, r, and at fixed sizes."""
    c = catalog.get("manakov-dual-lax")
    (corr,) = c.corrections
    assert run_free(c, corr.func).verdict == "proved"
    assert run_exact(c, 2, 2, SEED, func=corr.func).verdict == "proved"
    assert run_points(c, 4, 2, "modular", SEED, func=corr.func).verdict == "checked"


# -- the erratum of the remark after Theorem ET ---------------------------------------------------

@pytest.mark.parametrize("n, r", [(3, 2), (4, 2), (4, 3)])
def test_gram_does_not_commute_with_psi_squared_for_r_between_2_and_n_minus_1(catalog, n, r):
    c = catalog.get("gram-not-in-involution-with-psi")
    assert run_exact(c, n, r, SEED).verdict == "proved"
    res = run_points(c, n, r, "modular", SEED)
    assert res.verdict == "proved" and res.witness["seed"] == SEED


@pytest.mark.parametrize("n, r", [(2, 1), (3, 1), (2, 2), (3, 3)])
def test_remark_after_ET_fails_as_printed_for_r_1_and_r_n(catalog, n, r):
    """For r = 1 (Ψ = 0) and r = n (PᵀP = −Ψ²/4) the bracket vanishes: the printed remark fails, as documented."""
    c = catalog.get("gram-not-in-involution-with-psi")
    assert c.expects_failure(n, r)
    res = run_one(c, Size(n, r), "auto", SEED)
    assert res.verdict == "fails" and res.expected, res.line()
    assert run_one(catalog.get("gram-commutes-with-psi-if-r-is-1-or-n"), Size(n, r), "auto", SEED).verdict == "proved"
