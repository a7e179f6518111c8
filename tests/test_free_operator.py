"""A generic symmetric operator 𝔸 on so(n) as letters of the free algebra: 𝔸(M) is linear in M and
acts on its skew part, tr(𝔸(u)v) = tr(u𝔸(v)) is a normal form of traces, gradients and derivatives
along flows pass through it; the submersion metrics (submersion_metric), (dot_XP2) are then proved for
every n, r, and corrupted copies of them are not."""
import copy

import pytest

from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.free import FreeScene
from stiefelsym.free.mat import entry_of
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.backends.matrix import Mat
from stiefelsym.proofs import sec3_geodesic_flows as g

CATALOG = load_catalog()
BASE = CATALOG.get("submersion-hamiltonian")


def _zero(s, M):
    """M = 0 for every n, r (its normal form is 0)."""
    return s.field.is_zero(entry_of(M) if isinstance(M, Mat) else M)


def _proved(res):
    assert res.verdict == "proved", res.message
    assert check_certificate(res.certificate_data).accepted


# -- the claims of the paper ---------------------------------------------------------------------------
@pytest.mark.parametrize("cid", ["submersion-hamiltonian", "submersion-flow"])
def test_submersion_metrics_are_proved_for_every_n_and_r(cid):
    _proved(run_free(CATALOG.get(cid)))


def test_the_submersion_hamiltonian_is_conserved_by_its_flow():
    """d/dt ½⟨𝔸Φ, Φ⟩ = 0 along its Dirac flow: the derivative passes through 𝔸, and the two
    halves meet by the symmetry of traces."""
    _proved(run_free(BASE, lambda s: {"dH/dt": s.d(g.H_submersion, s.dirac_flow(g.H_submersion))}))


def test_the_derivative_passes_through_the_operator():
    def claim(s):
        flow = s.dirac_flow(g.H_normal)
        return {"dAA(Phi)": s.d(lambda t: t.sym_operator("AA")(t.Phi), flow)
                - s.sym_operator("AA")(s.d(lambda t: t.Phi, flow))}
    _proved(run_free(BASE, claim))


# -- linearity, skewness, typing -------------------------------------------------------------------------
def test_the_operator_is_linear_and_acts_on_the_skew_part():
    s = FreeScene()
    AA = s.sym_operator("AA")
    M, N = s.X @ s.P.T, s.xi @ s.A
    assert _zero(s, AA(M + N) - AA(M) - AA(N))
    assert _zero(s, AA(M * 3) - AA(M) * 3)
    assert _zero(s, AA(s.lam * M) - AA(M) * s.lam)
    assert _zero(s, AA(M.T) + AA(M))                    # 𝔸(Mᵀ) = 𝔸(skew Mᵀ) = −𝔸(M)
    assert _zero(s, AA(s.X @ s.X.T))                    # a symmetric matrix has no skew part
    assert _zero(s, AA(s.In))
    assert _zero(s, AA(s.xi).T + AA(s.xi))              # 𝔸(ξ) ∈ so(n)
    assert not _zero(s, AA(s.xi))
    assert _zero(s, AA(s.Phi) - AA(s.P @ s.X.T) * 2)


def test_the_operator_is_typed():
    """On n×n blocks the operator on so(n), on r×r blocks the operator of that name on so(r) (r×r
    letters), on anything else an error."""
    s = FreeScene()
    AA = s.sym_operator("AA")
    with pytest.raises(TypeError):
        AA(s.X)
    with pytest.raises(TypeError):
        AA(s.X.T @ s.A)
    assert tuple(AA(s.X.T @ s.P).tags) == ("r", "r")
    assert tuple(AA(s.P @ s.X.T).tags) == ("n", "n")
    with pytest.raises(ValueError):
        s.sym_operator("A(")


def test_operators_of_other_names_are_other_operators():
    s = FreeScene()
    AA, BB = s.sym_operator("AA"), s.sym_operator("BB")
    assert not _zero(s, AA(s.xi) - BB(s.xi))
    assert not _zero(s, s.tr(AA(s.xi) @ s.zeta) - s.tr(s.xi @ BB(s.zeta)))


# -- the symmetry ------------------------------------------------------------------------------------------
def test_the_symmetry_is_a_normal_form_of_traces():
    s = FreeScene()
    AA = s.sym_operator("AA")
    X, P, xi, zeta = s.X, s.P, s.xi, s.zeta
    assert _zero(s, s.tr(AA(xi) @ zeta) - s.tr(xi @ AA(zeta)))
    assert _zero(s, s.tr(AA(xi) @ zeta) - s.tr(AA(zeta) @ xi))
    assert _zero(s, s.tr(AA(X @ P.T) @ xi) - s.tr(AA(xi) @ X @ P.T))
    assert _zero(s, s.tr(AA(xi) @ X @ X.T))             # skew against symmetric
    # the rules reduce the word outside the operator, then the pair is ordered
    assert _zero(s, s.tr(AA(xi) @ X @ X.T @ X @ P.T) - s.tr(AA(X @ P.T) @ xi))


def test_the_symmetry_is_not_applied_where_it_does_not_hold():
    s = FreeScene()
    AA = s.sym_operator("AA")
    X, P, A, xi, zeta = s.X, s.P, s.A, s.xi, s.zeta
    assert not _zero(s, AA(xi) @ zeta - xi @ AA(zeta))                       # no trace: no symmetry
    assert not _zero(s, s.tr(AA(xi) @ zeta @ A) - s.tr(xi @ AA(zeta) @ A))   # A is not inside the pairing
    assert not _zero(s, s.tr(AA(xi) @ X @ P.T) - s.tr(AA(xi) @ P @ X.T))    # 𝔸(ξ) pairs with skew(XPᵀ) ≠ 0
    assert not _zero(s, s.tr(AA(xi) @ zeta @ xi) - s.tr(AA(xi) @ xi @ zeta))   # ⟨𝔸ξ, [ζ, ξ]⟩ ≠ 0


# -- negative controls: corrupted claims are not proved ----------------------------------------------------
def hamiltonian_sign(s):
    AA = s.sym_operator("AA")
    return {"H_AA": g.H_submersion(s) - s.tr(AA(s.Phi) @ s.Phi) / 4}


def hamiltonian_transposed(s):
    AA = s.sym_operator("AA")
    return {"H_AA": g.H_submersion(s) - (-(s.tr(AA(s.Phi).T @ s.Phi)) / 4)}


def hamiltonian_other_argument(s):
    AA = s.sym_operator("AA")
    return {"H_AA": g.H_submersion(s) - (-(s.tr(AA(s.X @ s.P.T) @ s.Phi)) / 4)}


def flow_transposed(s):
    AA = s.sym_operator("AA")
    return {"dX/dt": s.dirac_flow(g.H_submersion).Xdot - AA(s.Phi).T @ s.X}


def flow_without_symmetry(s):
    """What differentiating only the second argument of ⟨𝔸Φ, Φ⟩ gives: half the velocity."""
    AA = s.sym_operator("AA")
    return {"dX/dt": s.dirac_flow(g.H_submersion).Xdot - AA(s.Phi) @ s.X / 2}


def flow_momentum_wrong(s):
    AA = s.sym_operator("AA")
    return {"dP/dt": s.dirac_flow(g.H_submersion).Pdot - AA(s.Phi) @ s.X}


def flow_sign(s):
    AA = s.sym_operator("AA")
    return {"dP/dt": s.dirac_flow(g.H_submersion).Pdot + AA(s.Phi) @ s.P}


def pairing_without_the_trace(s):
    AA = s.sym_operator("AA")
    return {"AA(xi) zeta": AA(s.xi) @ s.zeta - s.xi @ AA(s.zeta)}


def pairing_through_a(s):
    AA = s.sym_operator("AA")
    return {"tr": s.tr(AA(s.xi) @ s.zeta @ s.A) - s.tr(s.xi @ AA(s.zeta) @ s.A)}


@pytest.mark.parametrize("func", [hamiltonian_sign, hamiltonian_transposed, hamiltonian_other_argument,
                                  flow_transposed, flow_without_symmetry, flow_momentum_wrong, flow_sign,
                                  pairing_without_the_trace, pairing_through_a])
def test_a_corrupted_claim_is_not_proved(func):
    assert run_free(BASE, func).verdict in ("undecided", "fails")


def test_without_the_symmetry_of_gradients_the_flow_is_not_proved(monkeypatch):
    """Drop the rule d tr(𝔸(u)V) = tr(du 𝔸(V)) (the operator's letters held constant in gradients):
    the printed flow is then not proved."""
    from stiefelsym.free import traces
    monkeypatch.setattr(traces, "_mentions", lambda op, L: False)
    assert run_free(CATALOG.get("submersion-flow")).verdict in ("undecided", "fails")


# -- the independent checker -------------------------------------------------------------------------------
def _words_claim(s):
    AA = s.sym_operator("AA")
    return {"r": AA(s.Phi) @ s.X @ s.X.T @ s.X - AA(s.Phi) @ s.X}


def _trace_claim(s):
    AA = s.sym_operator("AA")
    return {"t": s.tr(AA(s.xi) @ s.X @ s.X.T @ s.X @ s.P.T) - s.tr(AA(s.X @ s.P.T) @ s.xi)}


@pytest.fixture(scope="module")
def words_certificate():
    res = run_free(BASE, _words_claim)
    _proved(res)
    assert res.certificate_data["entries"][0]["terms"]   # the rule XᵀX = I is used next to 𝔸's letter
    return res.certificate_data


@pytest.fixture(scope="module")
def trace_certificate():
    res = run_free(BASE, _trace_claim)
    _proved(res)
    return res.certificate_data


def test_the_checker_rejects_a_flipped_coefficient(words_certificate):
    data = copy.deepcopy(words_certificate)
    data["entries"][0]["terms"][0]["coef"] = "-" + data["entries"][0]["terms"][0]["coef"]
    assert not check_certificate(data).accepted


def test_the_checker_types_operator_letters(words_certificate):
    (name, decl), = words_certificate["letters"].items()
    bad = [{name: dict(decl, argument=["X", "Xt", "X"])},     # the name does not say the argument
           {"AA(X)": {"kind": "operator", "operator": "AA", "argument": ["X"]}},   # not n×n
           {"AA()": {"kind": "operator", "operator": "AA", "argument": []}},
           {name: dict(decl, operator="A*A")},
           {}]                                                   # undeclared
    for letters in bad:
        data = copy.deepcopy(words_certificate)
        data["letters"] = letters
        assert not check_certificate(data).accepted, letters


def test_the_checker_knows_linearity(words_certificate):
    """𝔸(skew wᵀ) = −𝔸(skew w): the letter of the transposed argument with the opposite sign is the
    same residual; with the same sign it is not."""
    for sign, accepted in (("-", True), ("", False)):
        data = copy.deepcopy(words_certificate)
        data["letters"]["AA(X*Pt)"] = {"kind": "operator", "operator": "AA", "argument": ["X", "Pt"]}
        for t in data["entries"][0]["residual"]:
            if t["word"][0] == "AA(P*Xt)":
                t["word"][0] = "AA(X*Pt)"
                t["coef"] = f"{sign}({t['coef']})"
        assert check_certificate(data).accepted is accepted


def test_the_checker_knows_the_symmetry_of_traces(trace_certificate):
    """tr(𝔸(ξ)XPᵀ) = tr(𝔸(XPᵀ)ξ) for one operator; not between two operators."""
    data = copy.deepcopy(trace_certificate)
    data["letters"]["AA(P*Xt)"] = {"kind": "operator", "operator": "AA", "argument": ["P", "Xt"]}
    entry = data["entries"][0]
    entry["residual"] = [t if t["traces"] != [["AA(xi)", "P", "Xt"]] else dict(t, traces=[["AA(P*Xt)", "xi"]])
                         for t in entry["residual"]]
    assert check_certificate(data).accepted
    other = copy.deepcopy(data)
    other["letters"]["BB(P*Xt)"] = {"kind": "operator", "operator": "BB", "argument": ["P", "Xt"]}
    other["entries"][0]["residual"] = [t if t["traces"] != [["AA(P*Xt)", "xi"]] else dict(t, traces=[["BB(P*Xt)", "xi"]])
                                       for t in other["entries"][0]["residual"]]
    assert not check_certificate(other).accepted


# -- the operator of a name on so(r) -----------------------------------------------------------------------
@pytest.mark.parametrize("cid", ["cif-integrals", "com-integrals"])
def test_the_metrics_h_b_on_so_r_are_proved_for_every_n_and_r(cid):
    """(CIF), (COM): the geodesic and Neumann flows of H_𝔹 = ½tr(PᵀP) + ½<Ψ, 𝔹Ψ> for a generic symmetric 𝔹
    on so(r), as the operator's r×r letters."""
    _proved(run_free(CATALOG.get(cid)))


def _so_r_words_claim(s):
    BB = s.sym_operator("BB")
    return {"r": s.X @ BB(s.Psi) @ s.X.T @ s.X - s.X @ BB(s.Psi)}


def bb_with_generic_metric(s):
    """tr(Ψ + μB)³ is not conserved by H_𝔹 for a generic 𝔹 (only for the Manakov one)."""
    from stiefelsym.proofs import sec6_compatible_brackets as sec6
    return {"{BB_3, H_B}": s.bracket(lambda t: sec6.bb(t, t.Psi, t.lam, 3), sec6.H_B_generic)}


def phi_not_conserved_by_the_neumann_metric(s):
    """Φ is not conserved by H_neum,𝔹 (A breaks SO(n))."""
    from stiefelsym.proofs import sec6_compatible_brackets as sec6
    return {"{Phi_xi, H}": s.bracket(sec6.Phi_xi, lambda t: sec6.H_B_generic(t) + sec6.potential(t))}


def symmetry_through_a_third_factor(s):
    BB, G = s.sym_operator("BB"), s.generic("G", "r", "r")
    return {"tr": s.tr(BB(s.eta) @ s.theta @ G) - s.tr(s.eta @ BB(s.theta) @ G)}


def so_r_operator_is_not_the_so_n_one(s):
    BB = s.sym_operator("BB")
    return {"X BB(eta) X^T": s.X @ BB(s.eta) @ s.X.T - BB(s.X @ s.eta @ s.X.T)}


def test_the_symmetry_on_so_r_is_a_normal_form_of_traces():
    s = FreeScene()
    BB = s.sym_operator("BB")
    assert _zero(s, s.tr(BB(s.eta) @ s.theta) - s.tr(s.eta @ BB(s.theta)))
    assert _zero(s, BB(s.Psi) + BB(s.Psi.T))
    assert not _zero(s, s.tr(BB(s.eta) @ s.theta) + s.tr(s.eta @ BB(s.theta)))


@pytest.mark.parametrize("func", [bb_with_generic_metric, phi_not_conserved_by_the_neumann_metric,
                                  symmetry_through_a_third_factor, so_r_operator_is_not_the_so_n_one])
def test_a_corrupted_claim_on_so_r_is_not_proved(func):
    assert run_free(BASE, func).verdict in ("undecided", "fails")


def test_the_corrupted_claims_on_so_r_fail_at_a_fixed_size():
    import random
    from stiefelsym.backends.fields import ModularField
    from stiefelsym.scene import Scene
    s = Scene(4, 3, ModularField(), rng=random.Random("so(r) operator"))
    for func in (bb_with_generic_metric, phi_not_conserved_by_the_neumann_metric, symmetry_through_a_third_factor,
                 so_r_operator_is_not_the_so_n_one):
        (v,) = func(s).values()
        assert not (v.is_zero() if isinstance(v, Mat) else v == 0), func.__name__


def test_the_coordinate_operator_on_so_r_is_symmetric_and_skew():
    import random
    from stiefelsym.backends.fields import ModularField
    from stiefelsym.scene import Scene
    s = Scene(4, 3, ModularField(), rng=random.Random("so(r) operator|coordinates"))
    BB = s.sym_operator("BB")
    eta, theta = s.eta, s.theta
    assert tuple(BB(eta).tags) == ("r", "r")
    assert (BB(eta) + BB(eta).T).is_zero()
    assert s.killing(BB(eta), theta) - s.killing(eta, BB(theta)) == 0
    assert not (BB(eta) - eta).is_zero()


def _renamed(data, old, new):
    if isinstance(data, dict):
        return {(new if k == old else k): _renamed(v, old, new) for k, v in data.items()}
    if isinstance(data, list):
        return [_renamed(x, old, new) for x in data]
    return new if data == old else data


def test_the_checker_types_operator_letters_on_so_r():
    """The letter BB(Ψ-word) is r×r; declared with an n×n argument it no longer fits its words."""
    res = run_free(BASE, _so_r_words_claim)
    _proved(res)
    data = res.certificate_data
    ops = {k: d for k, d in data["letters"].items() if d["kind"] == "operator"}
    assert ops
    for name, decl in ops.items():
        wrong = f"{decl['operator']}(X*Pt)"
        bad = _renamed(copy.deepcopy(data), name, wrong)
        bad["letters"][wrong] = dict(decl, argument=["X", "Pt"])
        assert not check_certificate(bad).accepted
