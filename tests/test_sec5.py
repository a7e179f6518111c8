"""§5 claims: each holds at small sizes, the identities built from matrix products are proved
for every n, r by the dimension-free method, and a corrupted copy of each FAILS (negative
controls; for the Lax pair, the commutator in the other order)."""
import pytest

from stiefelsym import comm
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points

import stiefelsym.proofs.sec5_neumann as sec5

SEED = 0

#: proved for every n, r by rewriting modulo (cond_XP)
FREE_PROVED = ("neumann-hamiltonian", "neumann-flow", "neumann-normal-flow", "neumann-euclidean-flow",
               "neumann-psi-conserved", "prep", "neumann-lax", "neumann-spectral-invariants", "neumann-multipliers")
#: need coordinates: the multipliers Λ, Π and the gradients depend on H off T*V
NEEDS_COORDINATES: tuple[str, ...] = ()


def _section5(catalog):
    return [c for c in catalog if c.section == "5"]


# -- corrupted copies of the claims ----------------------------------------------------------

def hamiltonian_kappa_sign(s):
    """Corrupted: H_neum = H_kappa - V."""
    kinetic = s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2
    return {"H_neum = H_kappa + V": sec5.H_neumann(s) - (kinetic - sec5.potential(s))}


def flow_potential_sign(s):
    """Corrupted (No): +AX in dP/dt."""
    printed = sec5.flow_No(s, s.kappa)
    printed = {"X": printed["X"], "P": printed["P"] + 2 * (s.A @ s.X)}
    return sec5.flow_checks(s, sec5.H_neumann, printed)


def flow_kappa_factor(s):
    """Corrupted (No): (1 + κ) in place of (1 + 2κ)."""
    return sec5.flow_checks(s, sec5.H_neumann, sec5.flow_No(s, s.kappa / 2))


def multipliers_lambda_sign(s):
    """Corrupted: Λ = XᵀAX + PᵀP."""
    mult = s.multiplier_flow(sec5.H_neumann)
    return {"Lambda": mult["Lambda"] - (s.X.T @ s.A @ s.X + s.P.T @ s.P)}


def normal_flow_missing_term(s):
    """Corrupted (N0_XP2): the term PXᵀP dropped."""
    printed = sec5.flow_N0(s)
    printed = {"X": printed["X"], "P": printed["P"] - s.P @ s.X.T @ s.P}
    return sec5.flow_checks(s, sec5.H_neumann_normal, printed)


def euclidean_flow_is_normal(s):
    """Corrupted: the Euclidean Hamiltonian against the normal flow (N0_XP2)."""
    return sec5.flow_checks(s, sec5.H_neumann_euclidean, sec5.flow_N0(s))


def psi_replaced_by_gram(s):
    """Corrupted: PᵀP in place of Ψ (it is not conserved: the potential changes it)."""
    return {"dPsi/dt": s.d(lambda t: t.P.T @ t.P, s.dirac_flow(sec5.H_neumann))}


def prep_commutator_order(s):
    """Corrupted (prep): dΦ/dt = [A, XXᵀ]."""
    flow = s.dirac_flow(sec5.H_neumann)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.A, s.X @ s.X.T)}


def lax_commutator_swapped(s):
    """Corrupted (LA1): d𝓛/dt = [𝓛, 𝓐] (the commutator in the other order)."""
    flow = s.dirac_flow(sec5.H_neumann)
    return {"LA1": s.d(sec5.L_neum, flow) - comm(sec5.L_neum(s), sec5.A_neum(s))}


def lax_wrong_lambda_power(s):
    """Corrupted (LA2): 𝓛 = λΦ + XXᵀ − λA."""
    flow = s.dirac_flow(sec5.H_neumann)
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.A
    return {"LA1": s.d(L, flow) - comm(sec5.A_neum(s), L(s))}


def spectral_invariant_of_the_wrong_matrix(s):
    """Corrupted (perelomov): tr(λΦ + XXᵀ + λ²A)² is not an integral."""
    flow = s.dirac_flow(sec5.H_neumann)
    f = lambda t: sec5.power_trace(t, t.lam * t.Phi + t.X @ t.X.T + t.lam * t.lam * t.A, 2)
    return {"d tr L^2/dt": s.d(f, flow)}


CORRUPTIONS = [
    ("neumann-hamiltonian", hamiltonian_kappa_sign),
    ("neumann-flow", flow_potential_sign),
    ("neumann-flow", flow_kappa_factor),
    ("neumann-multipliers", multipliers_lambda_sign),
    ("neumann-normal-flow", normal_flow_missing_term),
    ("neumann-euclidean-flow", euclidean_flow_is_normal),
    ("neumann-psi-conserved", psi_replaced_by_gram),
    ("prep", prep_commutator_order),
    ("neumann-lax", lax_commutator_swapped),
    ("neumann-lax", lax_wrong_lambda_power),
    ("neumann-spectral-invariants", spectral_invariant_of_the_wrong_matrix),
]


def test_every_section5_claim_has_a_negative_control(catalog):
    assert {cid for cid, _ in CORRUPTIONS} == {c.id for c in _section5(catalog)}


def test_the_free_and_coordinate_lists_cover_section5(catalog):
    assert set(FREE_PROVED) | set(NEEDS_COORDINATES) == {c.id for c in _section5(catalog)}


@pytest.mark.parametrize("cid, func", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f in CORRUPTIONS])
def test_corrupted_claim_fails(catalog, cid, func):
    c = catalog.get(cid)
    assert run_exact(c, 3, 2, SEED, func=func).verdict == "fails"
    res = run_points(c, 3, 2, "modular", SEED, func=func)
    assert res.verdict == "fails" and res.witness and res.witness["seed"] == SEED


@pytest.mark.parametrize("cid, func", [(c, f) for c, f in CORRUPTIONS if c in FREE_PROVED],
                         ids=[f"{c}-{f.__name__}" for c, f in CORRUPTIONS if c in FREE_PROVED])
def test_corrupted_claim_is_not_proved_for_all_sizes(catalog, cid, func):
    assert run_free(catalog.get(cid), func).verdict == "undecided"


# -- the claims as printed -------------------------------------------------------------------

@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (3, 3), (4, 2)])
def test_section_5_holds_as_printed_at_small_sizes(catalog, n, r):
    for c in _section5(catalog):
        assert run_exact(c, n, r, SEED).verdict == "proved", c.id
        assert run_points(c, n, r, "modular", SEED).verdict == "checked", c.id


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_claim_is_proved_for_every_n_and_r(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message


@pytest.mark.parametrize("cid", NEEDS_COORDINATES)
def test_multipliers_need_coordinates(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "undecided" and "needs coordinates" in res.message


def test_normal_and_euclidean_neumann_flows_differ_unless_r_is_1(catalog):
    """The flows (N0_XP2) and (NE_XP) differ by terms in XᵀP, which vanishes when r = 1."""
    c = catalog.get("neumann-normal-flow")
    assert run_exact(c, 3, 2, SEED, func=euclidean_flow_is_normal).verdict == "fails"
    assert run_exact(c, 3, 1, SEED, func=euclidean_flow_is_normal).verdict == "proved"   # XᵀP = 0 when r = 1
