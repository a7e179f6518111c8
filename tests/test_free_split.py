"""The projectors D, C of two orthogonal blocks of ℝʳ (ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂}) as letters of the free algebra:
symmetric, D² = D, C² = C, DC = CD = 0 and nothing else.  The block Jensen Hamiltonian and Corollary nikinorov
are then proved for every n, r and every such pair of blocks (at fixed sizes: r₁ = ⌈r/2⌉), the symmetric
Clebsch–Perelomov–Bogoyavlenski bodies on T*SO(n) for every splitting ℝⁿ = ℝʳ ⊕ ℝⁿ⁻ʳ at once; corrupted copies of
them are not (and fail at a fixed size), D + C = I_r is not assumed, and the checker rejects a forged
certificate."""

import pytest

from stiefelsym import twisted
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.proofs import sec3_geodesic_flows as s3
from stiefelsym.proofs import sec6_compatible_brackets as s6
from free_words import forged

CATALOG = load_catalog()
SPLIT_HYPS = {"DsplitDsplit", "CsplitCsplit", "DsplitCsplit", "CsplitDsplit"}


def _proved(res):
    assert res.verdict == "proved", res.message
    report = check_certificate(res.certificate_data)
    assert report.accepted, report.message
    return res


@pytest.mark.parametrize("cid", ["block-jensen-hamiltonian", "nikinorov-integrals", "cpb-euler", "cpb-right-momentum"])
def test_the_block_claims_are_proved_for_every_splitting(cid):
    res = _proved(run_free(CATALOG.get(cid)))
    if cid.startswith("cpb"):   # T*SO(n): stated at r = n, every splitting of R^n (every r < n of the paper)
        assert "r = n" in res.certificate
    else:
        assert "for every n at r" not in res.certificate      # no hypothesis of one r
    used = {t["hyp"] for e in res.certificate_data["entries"] for t in e["terms"]}
    assert used & SPLIT_HYPS


def nikinorov_chain_against_a_linear_function(s):
    """tr Ψ₁² generates the rotations of the first block: it does not commute with a generic ⟨Ψ, θ⟩."""
    return {"{tr Psi_1^2, <Psi, theta>}": s.bracket(lambda t: s6.power_trace(t, s6.block_parts(t, t.Psi)[0], 2),
                                                    lambda t: t.killing(t.Psi, t.theta))}


def nikinorov_mixed_hamiltonian(s):
    """K with the mixed part ⟨DΨC, θ⟩-like term DΨC paired with the block DθD: not SO(r₁) × SO(r₂)-invariant."""
    H = lambda t: s6.H_K(t) + t.killing(twisted.block_projector(t, 0) @ t.Psi @ twisted.block_projector(t, 1),
                                        t.theta)   # noqa: E731
    return {"{tr Psi_1^2, H_K + <D Psi C, theta>}": s.bracket(
        lambda t: s6.power_trace(t, s6.block_parts(t, t.Psi)[0], 2), H)}


def jensen_full_right_action(s):
    """H_K is not invariant under all of SO(r): the right action of η itself, not of its block part."""
    return {"right so(r)": s.d(s3.H_K, {"X": s.X @ s.eta, "P": s.P @ s.eta})}


def jensen_block_part_not_orthogonal(s):
    """Ψ − Ψ₁ is orthogonal to so(r₁), but Ψ₁ is not orthogonal to it."""
    return {"Psi_1 orthogonal to so(r_1)": s.killing(s3._block_part(s, s.Psi, 0), s3._block_part(s, s.eta, 0))}


def blocks_complete(s):
    """D + C = I_r holds at fixed sizes but is not a rule of the free algebra (a proof holds for every pair of
    orthogonal blocks): not proved there."""
    return {"D + C - I": twisted.block_projector(s, 0) + twisted.block_projector(s, 1) - s.Ir}


CORRUPTED = [("nikinorov-integrals", nikinorov_chain_against_a_linear_function),
             ("nikinorov-integrals", nikinorov_mixed_hamiltonian),
             ("block-jensen-hamiltonian", jensen_full_right_action),
             ("block-jensen-hamiltonian", jensen_block_part_not_orthogonal)]


@pytest.mark.parametrize("cid, func", CORRUPTED, ids=[f.__name__ for _, f in CORRUPTED])
def test_a_corrupted_block_claim_is_not_proved(cid, func):
    assert run_free(CATALOG.get(cid), func).verdict in ("undecided", "fails")


@pytest.mark.parametrize("cid, func", CORRUPTED, ids=[f.__name__ for _, f in CORRUPTED])
def test_the_corrupted_block_claims_fail_at_a_fixed_size(cid, func):
    assert run_exact(CATALOG.get(cid), 4, 3, 0, func=func).verdict == "fails"


def test_the_blocks_are_not_assumed_to_fill_r():
    assert run_free(CATALOG.get("block-jensen-hamiltonian"), blocks_complete).verdict == "undecided"
    assert run_exact(CATALOG.get("block-jensen-hamiltonian"), 4, 3, 0, func=blocks_complete).verdict == "proved"


def test_the_checker_rejects_a_forged_block_hypothesis():
    data, changed = forged(_proved(run_free(CATALOG.get("block-jensen-hamiltonian"))).certificate_data,
                           {"DsplitCsplit": "DsplitDsplit", "CsplitCsplit": "CsplitDsplit"})
    assert changed
    assert not check_certificate(data).accepted


def test_the_fixed_size_blocks_are_the_coordinate_blocks():
    from stiefelsym.backends import fields
    from stiefelsym.scene import Scene
    s = Scene(5, 3, fields.RationalField())
    D, C = (twisted.block_projector(s, i) for i in range(2))
    assert [[int(D[i, j] != 0) for j in range(3)] for i in range(3)] == [[1, 0, 0], [0, 1, 0], [0, 0, 0]]
    assert [[int(C[i, j] != 0) for j in range(3)] for i in range(3)] == [[0, 0, 0], [0, 0, 0], [0, 0, 1]]


# -- an eigenspace of A as an orthogonal projector D of R^n (singular-a-noether) ---------------------------

def test_an_eigenspace_claim_is_proved_for_every_projector_and_not_its_rank():
    c = CATALOG.get("singular-a-noether")
    res = _proved(run_free(c))
    assert "DnDn" in {t["hyp"] for e in res.certificate_data["entries"] for t in e["terms"]}
    rank_two = lambda s: {"tr D - 2": s.tr(twisted.eigenspace_projector(s)) - 2}   # noqa: E731
    assert run_free(c, rank_two).verdict == "undecided"            # true at fixed sizes only (D = diag(I_2, 0))
    assert run_exact(c, 3, 2, 0, func=rank_two).verdict == "proved"
    data, _ = forged(res.certificate_data, {"DnDn": "DsplitDsplit"})
    assert not check_certificate(data).accepted


# -- ker Wᵀ through a symmetric K with KW = 0 (singular-a-noether-covariant) -------------------------------

def test_the_kernel_claim_is_proved_for_every_annihilator_and_the_checker_needs_both_hypotheses():
    c = CATALOG.get("singular-a-noether-covariant")
    res = _proved(run_free(c))
    used = {t["hyp"] for e in res.certificate_data["entries"] for t in e["terms"]}
    assert used <= {"KwWk", "WktKw", "XtX", "XtP+PtX"} and used & {"KwWk", "WktKw"}
    assert {"KwWk", "WktKw"} <= used
    for old, new in (("KwWk", "DnDn"), ("WktKw", "KwWk")):
        data, changed = forged(res.certificate_data, {old: new})
        assert changed
        assert not check_certificate(data).accepted


def kernel_one_sided_block(s):
    """Corrupted: d(KΦ)/dt, one side only, is not zero."""
    K = twisted.kernel_annihilator(s)
    return {"d(K Phi)/dt": K @ s.d(lambda t: t.Phi, s.dirac_flow(s6.H_neum_W))}


def kernel_with_the_generic_a(s):
    """Corrupted: the block KΦK with the Neumann flow of the generic A (not αI + βWWᵀ) is not conserved."""
    K = twisted.kernel_annihilator(s)
    return {"d(K Phi K)/dt": K @ s.d(lambda t: t.Phi, s.dirac_flow(H_neumann_generic)) @ K}


def H_neumann_generic(t):
    """H_neum,κ with the generic A."""
    XtP = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(XtP @ XtP) + t.tr(t.X.T @ t.A @ t.X) / 2


@pytest.mark.parametrize("func", [kernel_one_sided_block, kernel_with_the_generic_a])
def test_a_corrupted_kernel_claim_is_not_proved_and_fails_at_a_fixed_size(func):
    c = CATALOG.get("singular-a-noether-covariant")
    assert run_free(c, func).verdict == "undecided"
    assert run_exact(c, 3, 1, 0, func=func).verdict == "fails"


def test_what_holds_for_the_fixed_annihilator_only_is_not_proved():
    """K² = det(WᵀW)K holds for the annihilator built at fixed sizes, not for every symmetric K with KW = 0."""
    c = CATALOG.get("singular-a-noether-covariant")

    def square(s):
        W, K = twisted.kernel_frame(s), twisted.kernel_annihilator(s)
        G = W.T @ W
        return {"K^2 - det(W^T W) K": K @ K - G[0, 0] * K}
    assert run_free(c, square).verdict == "undecided"
    assert run_exact(c, 3, 1, 0, func=square).verdict == "proved"
