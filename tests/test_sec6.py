"""§6 bracket claims (proofs/sec6_compatible_brackets.py): each holds at small sizes under the
exact and the modular methods, the claims built from matrix products are proved for every n, r by
the dimension-free method, a corrupted copy of each FAILS (negative controls), and every label of
§6 in CLAIMS.md that is not a dimension statement has a claim."""
import re
from pathlib import Path

import pytest

from stiefelsym import Rank as B_Rank
from stiefelsym import comm, twisted
from stiefelsym import brackets as B
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points

import stiefelsym.proofs.sec6_compatible_brackets as sec6

SEED = 0
MODULE = "stiefelsym.proofs.sec6_compatible_brackets"

#: proved for every n, r by rewriting modulo (cond_XP)
FREE_PROVED = ("symmetric-pair", "pencil-casimirs", "theta-poisson-map", "theta-factorization", "cpb-hamiltonian",
               "cpb-flow", "ff-integrals", "bb-manakov-so-r", "lambda12-compatible", "cif-integrals", "com-integrals",
               "nikinorov-integrals", "reduced-bracket-casimirs",
               "singular-a-noether",   # an eigenspace of A as an orthogonal projector D of R^n
               "singular-a-noether-covariant")   # ker W^T through a symmetric K with KW = 0

#: the dimension statements of §6 (proofs/sec6_dimension_lemmas.py, another module)
DIMENSION_LABELS = {"dimension", "LEMA1", "L1", "L2", "LEMA2", "A2", "LAMBDA", "L3", "L4", "L5", "L6", "L7", "L8",
                    "KER", "NEUMANN", "dim_fol"}


#: symbolic Dirac flows with the claim's own singular A are slow beyond n = 2 (Cayley chart: the
#: claim reads coordinates); the exact method runs there at n = 2, the sampled methods beyond
EXACT_N_MAX = {"singular-a-noether": 2, "com-completeness": 2}


def _mine(catalog):
    return [c for c in catalog if c.source == MODULE]


# -- corrupted copies of the claims ----------------------------------------------------------

def pair_bracket_skew(s):
    """Corrupted (symmetric-pair): [so(n), Sym(n)] ⊂ so(n)."""
    eta = s.generic("S", "n", "n") + s.generic("S", "n", "n").T
    C = comm(s.xi, eta)
    return {"[xi, eta] skew": C + C.T}


def lambda1_doubled_action(s):
    """Corrupted (LAMBDA12): Λ1 with the module action doubled is not Poisson."""
    def form(t, x, a, b):
        xi, eta, zeta, theta = B.skew(a), B.sym(a), B.skew(b), B.sym(b)
        return t.killing(x, comm(xi, zeta) + (comm(xi, theta) + comm(eta, zeta)) * 2)
    return B.poisson_checks(s, B.PoissonTensor(B.GL_N, form, 1, "doubled"))


def casimir_without_square(s):
    """Corrupted (central): tr(ch + v − cA)² (λ₂/(λ₁+λ₂) in place of its square root on h)."""
    c = lambda t: t.scalar("c")   # noqa: E731
    T = B.pencil(lambda t: t.q(1) - c(t) * c(t), lambda t: c(t) * c(t))
    f = B.trace_power(2, so_scale=c, shift=lambda t: -c(t) * t.A)
    x, b = s.generic("x", "n", "n"), s.generic("b", "n", "n")
    return {"Casimir": B.casimir_residual(s, T, f, x, b)}


def theta_with_minus_phi(s):
    """Corrupted: −Φ + XXᵀ is not Poisson into (gl(n), Λ1)."""
    a, b = (lambda t: t.generic("a", "n", "n")), (lambda t: t.generic("b", "n", "n"))
    return {"Poisson": B.poisson_map_residual(s, B.dirac, lambda t: -t.Phi + t.X @ t.X.T, B.lambda1(), a, b)}


def psi_invariant_under_the_reflection(s):
    """Corrupted (theta-reflection): Ψ(XR, PR) = Ψ (it is RΨR)."""
    r = s.r
    R = s.mat([[(s.q(-1) if i == 0 else s.q(1)) if i == j else s.q(0) for j in range(r)] for i in range(r)], ("r", "r"))
    XR, PR = s.X @ R, s.P @ R
    return {"Psi": XR.T @ PR - PR.T @ XR - s.Psi}


def phi_action_with_plus_sign(s):
    """Corrupted (theta-factorization): {Φ_ξ, tr(UᵀX)} = +tr(UᵀξX)."""
    U = s.generic("U", "n", "r")
    return {"{Phi_xi, tr U^T X}": s.bracket(sec6.Phi_xi, lambda t: t.tr(t.generic("U", "n", "r").T @ t.X))
            - s.tr(U.T @ s.xi @ s.X)}


def J1_rotation_sign(s):
    """Corrupted: the flow of J₁ = tr Ψ² is the right action of +4Ψ."""
    flow = s.dirac_flow(lambda t: sec6.J(t, 1))
    return {"X": flow.Xdot - s.X @ (s.Psi * 4)}


def J3_not_a_casimir(s):
    """Corrupted: J₃ = tr Ψ⁶ commutes with a function that is not SO(r)-invariant, tr(G PᵀP)."""
    return {"{J_3, tr(G P^T P)}": s.bracket(lambda t: sec6.J(t, 3),
                                             lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P))}


def cpb_potential_sign(s):
    """Corrupted: H_neum₀ = ½<h, h> + <A, v> on Θ."""
    Th = sec6.Theta(s)
    return {"H": sec6.H_neum0(s) - (s.killing(B.skew(Th), B.skew(Th)) / 2 + s.killing(s.A, B.sym(Th)))}


def cpb_flow_swapped(s):
    """Corrupted (CPB): ḣ = [A, v]."""
    x = s.generic("x", "n", "n")
    xdot = B.lambda1().sharp(s, x, sec6.H_CPB.grad(s, x))
    return {"CPB": xdot - (comm(s.A, B.sym(x)) + comm(B.skew(x), B.sym(x)))}


def perelomov_not_geodesic_integral(s):
    """Corrupted (FF): with the term −λ²A, tr(λΦ + XXᵀ − λ²A)² is no integral of H_κ."""
    return {"{perelomov, H_kappa}": s.bracket(lambda t: sec6.perelomov(t, t.lam, 2), sec6.H_jensen)}


def euler_so_r_swapped(s):
    """Corrupted (e-so(r)): ξ̇ = [𝔹ξ, ξ]."""
    T = B.lie_poisson(B.SO_R, -1)
    h = B.quadratic(lambda t, x: sec6.manakov_so_r(t, x, sec6.b_diagonal(t)))
    xi = s.eta
    return {"Euler": T.sharp(s, xi, h.grad(s, xi)) - comm(sec6.manakov_so_r(s, xi, sec6.b_diagonal(s)), xi)}


def bb_with_generic_metric(s):
    """Corrupted (CIF): tr(Ψ + μB)³ is not conserved by H_𝔹 for a generic 𝔹 (only for the Manakov one)."""
    return {"{BB_3, H_B}": s.bracket(lambda t: sec6.bb(t, t.Psi, t.lam, 3), sec6.H_B_generic)}


def nikinorov_manakov_not_conserved(s):
    """Corrupted: the Manakov function tr(Ψ + μB)³ is no integral of H_K."""
    return {"{BB_3, H_K}": s.bracket(lambda t: sec6.bb(t, t.Psi, t.lam, 3), sec6.H_K)}


def com_phi_not_conserved(s):
    """Corrupted: Φ is not conserved by the Neumann system H_neum,𝔹 (A breaks SO(n))."""
    return {"{Phi_xi, H}": s.bracket(sec6.Phi_xi, lambda t: sec6.H_B_generic(t) + sec6.potential(t))}


def singular_a_whole_phi(s):
    """Corrupted: the whole Φ is not conserved when A has the eigenspace range D (only DΦD is)."""
    return {"dPhi/dt": s.d(lambda t: t.Phi, s.dirac_flow(sec6.H_neum_eigenspace))}


def singular_a_complement(s):
    """Corrupted: the block (I − D)Φ(I − D) of the complement (not an eigenspace: B is generic) is not conserved."""
    C = lambda t: t.In - twisted.eigenspace_projector(t)   # noqa: E731
    return {"d(C Phi C)/dt": s.d(lambda t: C(t) @ t.Phi @ C(t), s.dirac_flow(sec6.H_neum_eigenspace))}


def covariant_whole_phi(s):
    """Corrupted: the whole Φ is not conserved for A = αI + βWWᵀ."""
    return {"dPhi/dt": s.d(lambda t: t.Phi, s.dirac_flow(sec6.H_neum_W))}


def cif_one_less(s):
    """Corrupted (CIF): ddim(𝔉 + 𝔅) = dim V − l − 1 (the rank found is higher: a certain failure)."""
    n, r = s.n, s.r
    functions = sec6._FF_functions(n + 1, n) + sec6._bb_functions(r)
    return {"ddim": B_Rank(sec6._differentials_on_TV(s, functions),
                           sec6._dim_V(n, r) - sec6._two_l(n, r) // 2 - 1 + r * (r + 1))}


def com_one_less(s):
    """Corrupted (COM): dim V − 1 independent functions (the rank found is higher: a certain failure)."""
    n, r = s.n, s.r
    functions = sec6._perelomov_functions(2 * n + 1, n) + sec6._bb_functions(r)
    return {"ddim": B_Rank(sec6._differentials_on_TV(s, functions), sec6._dim_V(n, r) - 1 + r * (r + 1))}


CORRUPTIONS = [
    ("symmetric-pair", pair_bracket_skew, (3, 1)),
    ("lambda12-compatible", lambda1_doubled_action, (3, 1)),
    ("pencil-casimirs", casimir_without_square, (3, 1)),
    ("theta-poisson-map", theta_with_minus_phi, (3, 2)),
    ("theta-factorization", phi_action_with_plus_sign, (3, 2)),
    ("theta-reflection", psi_invariant_under_the_reflection, (3, 2)),
    ("reduced-bracket-casimirs", J1_rotation_sign, (3, 2)),
    ("reduced-bracket-casimirs", J3_not_a_casimir, (4, 3)),   # (r = n: PᵀP = −Ψ²/4 is a function of Ψ)
    ("cpb-hamiltonian", cpb_potential_sign, (3, 2)),
    ("cpb-flow", cpb_flow_swapped, (3, 1)),
    ("ff-integrals", perelomov_not_geodesic_integral, (3, 2)),
    ("bb-manakov-so-r", euler_so_r_swapped, (3, 3)),
    ("cif-integrals", bb_with_generic_metric, (3, 3)),
    ("nikinorov-integrals", nikinorov_manakov_not_conserved, (4, 3)),
    ("com-integrals", com_phi_not_conserved, (3, 2)),
    ("singular-a-noether", singular_a_whole_phi, (3, 2)),
    ("singular-a-noether", singular_a_complement, (4, 2)),
    ("singular-a-noether-covariant", covariant_whole_phi, (3, 1)),
    ("cif-completeness", cif_one_less, (3, 2)),
    ("com-completeness", com_one_less, (2, 2)),
]


def test_every_claim_has_a_negative_control(catalog):
    assert {cid for cid, _, _ in CORRUPTIONS} == {c.id for c in _mine(catalog)}


@pytest.mark.parametrize("cid, func, size", CORRUPTIONS, ids=[f"{c}-{f.__name__}" for c, f, _ in CORRUPTIONS])
def test_corrupted_claim_fails(catalog, cid, func, size):
    c = catalog.get(cid)
    n, r = size
    if n <= EXACT_N_MAX.get(cid, 3):
        assert run_exact(c, n, r, SEED, func=func).verdict == "fails"
    for method in ("modular", "rational"):
        res = run_points(c, n, r, method, SEED, func=func)
        assert res.verdict == "fails", (method, res.message)
        if c.kind != "dim":     # a wrong count: no point of T*V to show
            assert res.witness and res.witness["seed"] == SEED


@pytest.mark.parametrize("cid, func", [(c, f) for c, f, _ in CORRUPTIONS if c in FREE_PROVED],
                         ids=[f"{c}-{f.__name__}" for c, f, _ in CORRUPTIONS if c in FREE_PROVED])
def test_corrupted_claim_is_not_proved_for_all_sizes(catalog, cid, func):
    assert run_free(catalog.get(cid), func).verdict == "undecided"


# -- the claims as printed -------------------------------------------------------------------

def _small_size(c):
    for n, r in ((3, 2), (2, 1), (2, 2), (3, 1)):
        if n <= EXACT_N_MAX.get(c.id, 3) and c.sizes.admits(n, r):
            return n, r
    raise AssertionError(c.id)


@pytest.mark.parametrize("cid", [cid for cid, _, _ in CORRUPTIONS])
def test_claim_holds_at_a_small_size_exactly_and_modulo_primes(catalog, cid):
    c = catalog.get(cid)
    n, r = _small_size(c)
    assert run_exact(c, n, r, SEED).verdict == "proved", cid
    assert run_points(c, n, r, "modular", SEED).verdict == "checked", cid
    assert run_points(c, 4, 2 if c.sizes.admits(4, 2) else 1, "modular", SEED).verdict == "checked", cid
    if c.kind != "dim":     # ranks of 2nr columns over Q at n = 5 are slow; the catalog checks them
        assert run_points(c, 5, 3 if c.sizes.admits(5, 3) else 1, "rational", SEED).verdict == "checked", cid


@pytest.mark.parametrize("cid", FREE_PROVED)
def test_claim_is_proved_for_every_n_and_r(catalog, cid):
    res = run_free(catalog.get(cid))
    assert res.verdict == "proved", res.message


def test_other_claims_are_left_to_the_fixed_size_methods(catalog):
    for c in _mine(catalog):
        if c.id not in FREE_PROVED:
            res = run_free(c)
            assert res.verdict == "undecided", (c.id, res.message)


# -- coverage of §6 --------------------------------------------------------------------------

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"


@pytest.mark.skipif(not (SHARED / "CLAIMS.md").exists(), reason="CLAIMS.md is not next to the repository")
def test_every_bracket_label_of_section_6_has_a_claim(catalog):
    text = (SHARED / "CLAIMS.md").read_text(encoding="utf-8")
    block = [b for b in re.split(r"^## ", text, flags=re.M) if b.startswith("§6")][0]
    listed = set(re.findall(r"`([^`]+)`", block))
    paper = set(re.findall(r"\\label\{([^}]*)\}",
                           (SHARED / "paper" / "fedorov-jovanovic-stiefel.tex").read_text(encoding="utf-8")))
    used = {lab for c in _mine(catalog) for lab in c.paper}
    missing = sorted(lab for lab in listed - DIMENSION_LABELS if lab in paper and lab not in used)
    assert not missing, missing


# -- the bracket claims added to §2 and §4 ------------------------------------------------------
# (test_sec2.py and test_sec4.py list the claims of their sections; these three are tested here)

import stiefelsym.proofs.sec2_hamiltonian_flows as sec2   # noqa: E402
import stiefelsym.proofs.sec4_integrability as sec4       # noqa: E402


def phi_poisson_with_minus_sign(s):
    """Corrupted: Φ Poisson for the (−) bracket."""
    minus = B.lie_poisson(B.SO_N, -1)
    (n1, h1), (n2, h2) = sec2._so_n_functions()[:2]   # tr μ⁴ is a Casimir: it commutes for either sign
    Phi = lambda t: t.Phi   # noqa: E731
    return {"(-)": s.bracket(h1.pullback(Phi), h2.pullback(Phi)) - minus.bracket(s, h1, h2, s.Phi)}


def gram_with_psi_squared(s):
    """Corrupted Noether statement: (p_i, p_j) commute with <Ψ, Ψ> (the remark after ET: they do not)."""
    return {"{gram, <Psi, Psi>}": s.bracket(sec4._gram, lambda t: t.killing(t.Psi, t.Psi))}


def non_invariant_function_conserved(s):
    """Corrupted: tr(PᵀAP), not SO(n)-invariant, is no integral of H_κ."""
    return {"{tr P^T A P, H_kappa}": s.bracket(lambda t: t.tr(t.P.T @ t.A @ t.P), sec4.H_jensen)}


def euler_so_n_swapped(s):
    """Corrupted (Euler-so(n)): ξ̇ = [ξ, 𝔸ξ]."""
    T = B.lie_poisson(B.SO_N, 1)
    h = B.quadratic(lambda t, x: t.sym_operator("AA")(x))
    return {"Euler": T.sharp(s, s.xi, h.grad(s, s.xi)) - comm(s.xi, s.sym_operator("AA")(s.xi))}


ADDED = [
    ("momentum-maps-poisson-nonlinear", phi_poisson_with_minus_sign, (3, 2)),
    ("noether-normal-metric", gram_with_psi_squared, (3, 2)),
    ("jensen-invariants-conserved", non_invariant_function_conserved, (3, 2)),
    ("euler-so-n", euler_so_n_swapped, (3, 2)),
]


@pytest.mark.parametrize("cid, func, size", ADDED, ids=[c for c, _, _ in ADDED])
def test_added_claims_hold_and_their_corruptions_fail(catalog, cid, func, size):
    c = catalog.get(cid)
    n, r = size
    assert run_exact(c, n, r, SEED).verdict == "proved"
    assert run_points(c, 4, 3, "modular", SEED).verdict == "checked"
    assert run_exact(c, n, r, SEED, func=func).verdict == "fails"
    for method in ("modular", "rational"):
        res = run_points(c, n, r, method, SEED, func=func)
        assert res.verdict == "fails" and res.witness["seed"] == SEED


@pytest.mark.parametrize("cid", ["noether-normal-metric", "jensen-invariants-conserved", "momentum-maps-poisson-nonlinear",
                                 "euler-so-n"])
def test_added_claims_are_proved_for_every_n_and_r(catalog, cid):
    assert run_free(catalog.get(cid)).verdict == "proved"


@pytest.mark.parametrize("cid, func", [(c, f) for c, f, _ in ADDED], ids=[c for c, _, _ in ADDED])
def test_added_corruptions_are_not_proved_for_all_sizes(catalog, cid, func):
    assert run_free(catalog.get(cid), func).verdict == "undecided"
    corrupted = dict((c, f) for c, f, _ in ADDED)[cid]
    assert run_free(catalog.get(cid), corrupted).verdict == "undecided"
