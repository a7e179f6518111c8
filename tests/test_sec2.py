"""§2 claims: each holds at small sizes, and a corrupted copy of each FAILS (negative controls)."""
import pytest

from stiefelsym import Count, Inverse, Rank, RightInverse, comm
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points

import stiefelsym.proofs.sec2_hamiltonian_flows as sec2

SEED = 0


def _section2(catalog):
    return [c for c in catalog if c.section == "2"]


# -- corrupted copies of the claims ----------------------------------------------------------

def constraints_wrong_dim(s):
    """Corrupted: d(XᵀX) onto Sym(r) with the right inverse a ↦ Xa (dim V off by a factor of the rank)."""
    def dG(t, dX):
        return t.d(lambda u: u.X.T @ u.X, {"X": dX, "P": t.zeros(t.n, t.r, ("n", "r"))})
    return {"dim V": RightInverse(dG, lambda t, a: t.X @ a, on="R^{n×r}", to="Sym(r)")}


def constraints_wrong_rank(s):
    """Corrupted: a map that is not onto Sym(r) × Sym(r) (twice the differential of XᵀX)."""
    def dF(t, dX, dP):
        first = tuple(t.d(sec2.cond_XP, {"X": dX, "P": dP}))[0]
        return first, first
    return {"rank d(F, G)": RightInverse(dF, lambda t, a, b: (t.X @ a / 2, t.X @ b / 2),
                                         on=("R^{n×r}", "R^{n×r}"), to=("Sym(r)", "Sym(r)"))}


def dirac_pi_sign(s):
    """Corrupted: dX/dt = H_P + X Pi."""
    dirac = s.dirac_flow(sec2.H_linear)
    Pi = s.multiplier_flow(sec2.H_linear)["Pi"]
    HX, HP = s.gradient(sec2.H_linear)
    return {"dX/dt": dirac.Xdot - (HP + s.X @ Pi)}


def dirac_lambda_side(s):
    """Corrupted: dP/dt = -H_X + Lambda-term on the wrong side (P Lambda + X Pi)."""
    dirac = s.dirac_flow(sec2.H_linear)
    mult = s.multiplier_flow(sec2.H_linear)
    HX, HP = s.gradient(sec2.H_linear)
    return {"dP/dt": dirac.Pdot - (-HX + s.P @ mult["Lambda"] + s.X @ mult["Pi"])}


def dirac_bracket_matrix_singular(s):
    """Corrupted: {F_i, F_j}_0 of rank r(r+1) - 1."""
    r = s.r
    return {"C0": Rank(s.mat(s.constraint_bracket_matrix()), r * (r + 1) - 1, generic=False)}


def dirac_bracket_inverse_sign(s):
    """Corrupted: the inverse of {F_i, F_j}_0 with the commutator term's sign flipped, S = (Ka − aK − b)/4."""
    def inverse(t, a, b):
        K = t.X.T @ t.P
        return (K @ a - a @ K - b) / 4, a / 4
    return {"C0": Inverse(sec2.constraint_brackets, inverse, on=("Sym(r)", "Sym(r)"))}


def left_equivariance_swapped(s):
    """Corrupted: dPhi = [Phi, xi] along (xi X, xi P)."""
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    return {"equivariance": s.d(lambda t: t.Phi, left) - comm(s.Phi, s.xi)}


def left_flow_sign(s):
    """Corrupted: the flow of Phi_xi is (-xi X, -xi P)."""
    dirac = s.dirac_flow(sec2.Phi_xi)
    return {"dX/dt": dirac.Xdot + s.xi @ s.X, "dP/dt": dirac.Pdot + s.xi @ s.P}


def left_bracket_with_non_invariant(s):
    """Corrupted: {Phi_xi, F}_0 = 0 for F = X^T A X (not SO(n)-invariant)."""
    return {"{Phi_xi, F}_0": s.d(lambda t: t.X.T @ t.A @ t.X, s.canonical_flow(sec2.Phi_xi))}


def right_equivariance_swapped(s):
    """Corrupted: dPsi = [eta, Psi] along (X eta, P eta)."""
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    return {"equivariance": s.d(lambda t: t.Psi, right) - comm(s.eta, s.Psi)}


def right_flow_left_multiplied(s):
    """Corrupted: the flow of Psi_eta has dX/dt = -X eta."""
    dirac = s.dirac_flow(sec2.Psi_eta)
    return {"dX/dt": dirac.Xdot + s.X @ s.eta}


def poisson_psi_plus(s):
    """Corrupted: Psi Poisson for the (+) bracket."""
    return {"(+)": s.bracket(sec2.Psi_eta, sec2.Psi_theta) - s.killing(s.Psi, comm(s.eta, s.theta))}


def poisson_phi_minus(s):
    """Corrupted: Phi Poisson for the (-) bracket."""
    return {"(-)": s.bracket(sec2.Phi_xi, sec2.Phi_zeta) + s.killing(s.Phi, comm(s.xi, s.zeta))}


def poisson_phi_psi_canonical_cross(s):
    """Corrupted: {Phi_xi, Psi_eta} = <Phi, xi>·<Psi, eta>."""
    return {"cross": s.bracket(sec2.Phi_xi, sec2.Psi_eta) - s.killing(s.Phi, s.xi) * s.killing(s.Psi, s.eta)}


def ddim_wrong_sign(s):
    """Corrupted (ddim): dim V - dim SO(n-r) - dim SO(n-2r) for n > 2r."""
    n, r = s.n, s.r
    checks = dict(sec2.differential_dimension_of_invariants(s))
    M = checks["generic orbit dimension"].matrix
    wrong = sec2.dim_V(n, r) - sec2.dim_so(n - r) - sec2.dim_so(n - 2 * r)
    checks["generic orbit dimension"] = Rank(M, sec2.dim_V(n, r) - wrong, generic=True)
    return checks


def invariance_forgets_P(s):
    """Corrupted: the left action moves X only."""
    left = {"X": s.xi @ s.X, "P": s.zeros(s.n, s.r, ("n", "r"))}
    return {"d Psi": s.d(lambda t: t.Psi, left)}


def invariants_wrong_count(s):
    """Corrupted: the n <= 2r case of (ddim) used for every n."""
    checks = dict(sec2.psi_and_gram_give_ddim_functions(s))
    n, r = s.n, s.r
    checks["rank on the fibre"] = Rank(checks["rank on the fibre"].matrix, sec2.dim_V(n, r) - sec2.dim_so(n - r))
    return checks


def orbit_wrong_formula(s):
    """Corrupted Lemma 2l: 2r(n - r) for n > 2r + 1."""
    n, r = s.n, s.r
    expected = sec2.two_l_printed(n, r) if n <= 2 * r + 1 else 2 * r * (n - r)
    return {"rank": Rank(sec2.ad_matrix(s, s.Phi), expected)}


def regularity_wrong_bound(s):
    """Corrupted remark: regular iff n <= 2r."""
    n, r = s.n, s.r
    regular = n * (n - 1) // 2 - n // 2
    return {"regular": Count(int(sec2.two_l_printed(n, r) == regular), int(n <= 2 * r))}


def chain_not_nested(s):
    """Corrupted chain: the smallest level is the upper-left block, not nested in the next one."""
    n, r = s.n, s.r
    xi = s.xi - sec2.lower_block(s, n - r) @ s.xi @ sec2.lower_block(s, n - r)
    m = n - r + 1                      # the smallest level (here m >= 2, m + 1 < n)
    upper = s.In - sec2.lower_block(s, n - m)          # projector on the first m coordinates
    g1 = s.zeros(n, n, ("n", "n"))
    for e in sec2.wedge_basis(s, n):
        g1 = g1 + e * (s.tr(upper @ xi @ upper @ upper @ e @ upper) * 2)
    g2 = sec2.chain_gradient(s, xi, m + 1, 1)
    return {"bracket": -s.killing(xi, comm(g1, g2))}


def chain_invariance_whole_xi(s):
    """Corrupted: the generator of the smallest level with m >= 2 commutes with all of xi."""
    n, r = s.n, s.r
    xi = s.xi - sec2.lower_block(s, n - r) @ s.xi @ sec2.lower_block(s, n - r)
    m = max(2, n - r + 1)
    return {"invariance": comm(sec2.chain_gradient(s, xi, m, 1), xi)}


# (claim id, corrupted function, sizes where the corruption is visible)
RESIDUAL_CORRUPTIONS = [
    ("constraints-independent", constraints_wrong_dim, [(3, 1), (3, 2), (4, 2)]),
    ("constraints-independent", constraints_wrong_rank, [(3, 1), (3, 2), (4, 2)]),
    ("dirac-bracket-multipliers", dirac_pi_sign, [(3, 1), (3, 2), (4, 2)]),
    ("dirac-bracket-multipliers", dirac_lambda_side, [(3, 2), (4, 2)]),
    ("dirac-bracket-multipliers", dirac_bracket_inverse_sign, [(3, 2), (4, 2)]),   # KΠ = ΠK at r = 1
    ("left-momentum-map", left_equivariance_swapped, [(3, 1), (3, 2), (4, 2)]),
    ("left-momentum-map", left_flow_sign, [(3, 1), (3, 2), (4, 2)]),
    ("left-momentum-map", left_bracket_with_non_invariant, [(3, 1), (3, 2)]),
    ("right-momentum-map", right_equivariance_swapped, [(3, 3), (4, 3)]),   # so(2) is abelian
    ("right-momentum-map", right_flow_left_multiplied, [(3, 2), (4, 2)]),
    ("momentum-maps-poisson", poisson_psi_plus, [(3, 3)]),          # so(r) is abelian for r <= 2
    ("momentum-maps-poisson", poisson_phi_minus, [(3, 1), (3, 2), (4, 2)]),
    ("momentum-maps-poisson", poisson_phi_psi_canonical_cross, [(3, 2), (4, 2)]),
    ("invariants-so-n", invariance_forgets_P, [(3, 2), (4, 2)]),               # Psi = 0 for r = 1
    ("chain-algebra-commutative", chain_not_nested, [(4, 3)]),      # needs two non-Casimir levels
    ("chain-algebra-commutative", chain_invariance_whole_xi, [(3, 2), (4, 2)]),
]

RANK_CORRUPTIONS = [
    ("dirac-bracket-multipliers", dirac_bracket_matrix_singular, [(3, 1), (3, 2), (4, 2)]),
    ("invariants-differential-dimension", ddim_wrong_sign, [(4, 1)]),   # needs n - 2r >= 2
    ("invariants-complete", invariants_wrong_count, [(4, 1)]),          # needs n > 2r + 1
    ("adjoint-orbit-dimension", orbit_wrong_formula, [(4, 1)]),         # needs n > 2r + 1
    ("adjoint-orbit-regularity", regularity_wrong_bound, [(3, 1)]),
]


#: corruptions whose exact refutation takes tens of seconds (the Cayley chart at n = 4): with the slow tests
SLOW_CASES = {("adjoint-orbit-dimension", "orbit_wrong_formula", 4, 1)}


def _cases(table):
    return [pytest.param(cid, f, n, r, id=f"{cid}[{f.__name__},n={n},r={r}]",
                         marks=[pytest.mark.slow] if (cid, f.__name__, n, r) in SLOW_CASES else [])
            for cid, f, sizes in table for n, r in sizes]


@pytest.mark.parametrize("cid, func, n, r", _cases(RESIDUAL_CORRUPTIONS))
def test_corrupted_identity_fails(catalog, cid, func, n, r):
    c = catalog.get(cid)
    assert run_exact(c, n, r, SEED, func=func).verdict == "fails"
    res = run_points(c, n, r, "modular", SEED, func=func)
    assert res.verdict == "fails" and res.witness and res.witness["seed"] == SEED
    assert run_free(c, func).verdict != "proved"     # never a proof for all n, r of a false statement


@pytest.mark.parametrize("cid, func, n, r", _cases(RANK_CORRUPTIONS))
def test_corrupted_dimension_is_not_proved(catalog, cid, func, n, r):
    c = catalog.get(cid)
    assert run_exact(c, n, r, SEED, func=func).verdict == "fails"
    assert run_points(c, n, r, "modular", SEED, func=func).verdict not in ("proved", "checked")


def test_every_claim_has_a_negative_control(catalog):
    from test_sec6 import ADDED   # the bracket claims added to §2 with §6 have theirs there
    covered = {cid for cid, _, _ in RESIDUAL_CORRUPTIONS + RANK_CORRUPTIONS + ADDED}
    assert {c.id for c in _section2(catalog)} <= covered


# -- the claims as printed -------------------------------------------------------------------

@pytest.mark.parametrize("n, r", [(3, 1), (3, 2), (4, 2)])
def test_section_2_holds_at_small_sizes(catalog, n, r):
    for c in _section2(catalog):
        if not c.sizes.admits(n, r):
            continue
        assert run_exact(c, n, r, SEED).verdict == "proved", c.id
        sampled = run_points(c, n, r, "modular", SEED)
        if c.id in EVERY_POINT_RANKS:   # random points establish the generic rank only
            assert sampled.verdict == "undecided" and "every point" in sampled.message, c.id
        elif c.id in FULL_SIZE_RANKS:   # a nonzero maximal minor at a point proves a rank of full size
            assert sampled.verdict in ("proved", "checked"), c.id
            assert sampled.verdict == "checked" or "full size" in sampled.certificate, c.id
        else:
            assert sampled.verdict == "checked", c.id


#: claims whose every check is a generic rank equal to its matrix's full size at some sizes
FULL_SIZE_RANKS = ("invariants-differential-dimension", "invariants-complete")


#: claims that assert a rank at every point of T*V (decided by the exact method only); the independence of
#: the constraints is a right inverse of their differential, identities that random points check
EVERY_POINT_RANKS: tuple[str, ...] = ()


def test_regularity_remark_fails_as_printed_for_n_equal_2r_plus_2(catalog):
    """The remark before Lemma 2l: for n = 2r + 2 the generic orbit is regular, not singular."""
    c = catalog.get("adjoint-orbit-regularity")
    res = run_exact(c, 4, 1, SEED)
    assert res.verdict == "fails" and "regular" in res.certificate
    assert run_points(c, 4, 1, "modular", SEED).verdict == "fails"
