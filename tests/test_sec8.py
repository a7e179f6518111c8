"""§8 claims: the dual Lax pairs (LA3), (LA4) for κ = 0 and κ = −½, the symplectic structure of
𝓛*_neum(λ), its spectral invariants, its reflection symmetry and the Poisson-sphere flow
(P_q), (P_p) hold at small sizes, those built from matrix products are proved for every n, r by
the dimension-free method, and a corrupted copy of each FAILS (negative controls; for the Lax pairs,
the commutator in the other order)."""
import pytest

from stiefelsym import block, comm
from stiefelsym.free_method import run_free
from stiefelsym.methods import run_exact, run_points

import proofs.sec8_dual_lax_pair as sec8
from proofs.sec5_neumann import H_neumann_euclidean, H_neumann_normal, power_trace

SEED = 0

#: proved for every n, r by rewriting modulo (cond_XP)
FREE_PROVED = ("neumann-dual-lax-normal", "neumann-dual-lax-euclidean", "dual-lax-symplectic-structure",
               "dual-lax-spectral-invariants")
#: need coordinates: r = 1 (1×1 products commute), the reflections S_i (the size n as a number)
NEEDS_COORDINATES = ("poisson-sphere-flow", "dual-lax-reflections")
#: sizes of the exact check (the spectral invariants: exact only for n <= 2, the claim's symbolic budget)
EXACT_SIZES = {"dual-lax-spectral-invariants": [(2, 1), (2, 2)],
               "poisson-sphere-flow": [(2, 1), (3, 1)], "dual-lax-reflections": [(2, 1), (3, 2)]}
MODULAR_SIZES = {"poisson-sphere-flow": [(2, 1), (3, 1), (4, 1)]}
DEFAULT_EXACT_SIZES = [(2, 1), (3, 2), (3, 3)]


def _section8(catalog):
    return [c for c in catalog if c.section == "8"]


# -- corrupted copies of the claims ----------------------------------------------------------

def normal_commutator_swapped(s):
    """Corrupted (LA3), κ = 0: d𝓛*/dt = [𝓐*, 𝓛*]."""
    flow = s.dirac_flow(H_neumann_normal)
    return {"LA3": s.d(sec8.L_dual, flow) - comm(sec8.A_dual_normal(s), sec8.L_dual(s))}


def euclidean_commutator_swapped(s):
    """Corrupted (LA3), κ = −½: d𝓛*/dt = [𝓐*, 𝓛*]."""
    flow = s.dirac_flow(H_neumann_euclidean)
    return {"LA3": s.d(sec8.L_dual, flow) - comm(sec8.A_dual_euclidean(s), sec8.L_dual(s))}


def normal_flow_with_euclidean_A(s):
    """Corrupted (LA4): the κ = 0 flow with the κ = −½ matrix 𝓐*."""
    return {"LA3": sec8.dual_lax_residual(s, H_neumann_normal, sec8.A_dual_euclidean)}


def euclidean_lambda_sign(s):
    """Corrupted (LA4), κ = −½: Λ + λI_r in place of Λ − λI_r."""
    zero = s.zeros(s.r, s.r, ("r", "r"))
    M = lambda t: block([[zero, t.Ir], [sec8.Lambda(t) + t.scalar_matrix(t.lam, t.r, "r"), zero]])
    return {"LA3": sec8.dual_lax_residual(s, H_neumann_euclidean, M)}


def symplectic_sign_of_a_block(s):
    """Corrupted (LA3): +XᵀRP in the upper left block of 𝓛*."""
    R, X, P = s.resolvent(s.lam), s.X, s.P
    L = block([[X.T @ R @ P, -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]])
    JL = sec8.J(s) @ L
    return {"(J L*)^T - J L*": JL.T - JL}


def spectral_invariant_without_identity(s):
    """Corrupted (LA3): tr 𝓛² for 𝓛* with the I_r of the lower left block dropped is not an integral."""
    def L0(t):
        R, X, P = t.resolvent(t.lam), t.X, t.P
        return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [P.T @ R @ P, P.T @ R @ X]])
    f = lambda t: power_trace(t, L0(t), 2)
    return {"d tr L^2/dt": s.d(f, s.dirac_flow(H_neumann_euclidean))}


def poisson_sphere_sign(s):
    """Corrupted (P_p): +(A⁻¹p, p)A⁻¹e in dp/dt."""
    printed = sec8.flow_poisson_sphere(s)
    e, p, Ai = s.X, s.P, s.Ainv
    printed = {"X": printed["X"], "P": printed["P"] + 2 * (Ai @ e @ (p.T @ Ai @ p))}
    return {"dp/dt": s.dirac_flow(sec8.H_poisson_sphere).Pdot - printed["P"]}


def reflection_of_X_only(s):
    """Corrupted (reflections): X ↦ S_iX with P fixed does not leave 𝓛* invariant."""
    S = sec8.reflection(s, 0)
    return {"S_1: L*": sec8.L_dual_at(s, S @ s.X, s.P) - sec8.L_dual(s)}


CORRUPTIONS = [
    ("poisson-sphere-flow", poisson_sphere_sign),
    ("dual-lax-reflections", reflection_of_X_only),
    ("neumann-dual-lax-normal", normal_commutator_swapped),
    ("neumann-dual-lax-normal", normal_flow_with_euclidean_A),
    ("neumann-dual-lax-euclidean", euclidean_commutator_swapped),
    ("neumann-dual-lax-euclidean", euclidean_lambda_sign),
    ("dual-lax-symplectic-structure", symplectic_sign_of_a_block),
    ("dual-lax-spectral-invariants", spectral_invariant_without_identity),
]


def test_every_section8_claim_has_a_negative_control(catalog):
    assert {cid for cid, _ in CORRUPTIONS} == {c.id for c in _section8(catalog)}


def test_the_free_and_coordinate_lists_cover_section8(catalog):
    assert set(FREE_PROVED) | set(NEEDS_COORDINATES) == {c.id for c in _section8(catalog)}


@pytest.mark.parametrize("cid, func", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f in CORRUPTIONS])
def test_corrupted_claim_fails(catalog, cid, func):
    c = catalog.get(cid)
    n, r = (3, 1) if cid == "poisson-sphere-flow" else (3, 2)
    assert run_exact(c, n, r, SEED, func=func).verdict == "fails"
    res = run_points(c, n, r, "modular", SEED, func=func)
    assert res.verdict == "fails" and res.witness and res.witness["seed"] == SEED


@pytest.mark.parametrize("cid, func", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f in CORRUPTIONS])
def test_corrupted_claim_is_not_proved_for_all_sizes(catalog, cid, func):
    assert run_free(catalog.get(cid), func).verdict == "undecided"


# -- the claims as printed -------------------------------------------------------------------

@pytest.mark.parametrize("cid", FREE_PROVED + NEEDS_COORDINATES)
def test_section_8_holds_as_printed_at_small_sizes(catalog, cid):
    c = catalog.get(cid)
    for n, r in EXACT_SIZES.get(cid, DEFAULT_EXACT_SIZES):
        assert run_exact(c, n, r, SEED).verdict == "proved", (cid, n, r)
    for n, r in MODULAR_SIZES.get(cid, [(2, 1), (3, 2), (4, 2), (4, 3)]):
        assert run_points(c, n, r, "modular", SEED).verdict == "checked", (cid, n, r)


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_claim_is_proved_for_every_n_and_r(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message


@pytest.mark.parametrize("cid", NEEDS_COORDINATES)
def test_claim_needs_coordinates(catalog, cid):
    assert run_free(catalog.get(cid)).verdict == "undecided"


def test_the_two_dual_pairs_agree_when_r_is_1(catalog):
    """For r = 1, XᵀP = 0 on T*V: the two matrices 𝓐* of (LA4) coincide, as do the flows (N0_XP2) and (NE_XP)."""
    c = catalog.get("neumann-dual-lax-normal")
    assert run_exact(c, 3, 1, SEED, func=normal_flow_with_euclidean_A).verdict == "proved"
