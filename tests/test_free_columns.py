"""The columns E₁, E₂ of ℝʳ as letters of the free algebra, for claims stated at r = 2 only: E_iᵀE_j = δ_ij
as rules, E₁E₁ᵀ + E₂E₂ᵀ = I_r as a canonical form (a hypothesis true at r = 2 alone), 1×1 pieces as
traces; at r = 1 the same with E₁ alone (every r×r matrix a scalar).  The magnetic claims of Appendix 1
are then proved for every n at r = 2, the Poisson sphere's flow at r = 1; corrupted copies of them are
not, a claim stated for other r gets no columns, and the checker rejects forged certificates."""
import copy
import dataclasses

import pytest

from stiefelsym import admissible, comm
from stiefelsym import twisted
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.free import FreeScene
from stiefelsym.free.mat import entry_of
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.backends.matrix import Mat
from stiefelsym.proofs import app1_magnetic_neumann as m
from stiefelsym.proofs.sec5_neumann import H_neumann_euclidean
from free_words import forged

CATALOG = load_catalog()
BASE = CATALOG.get("magnetic-momentum-map")
R2 = "E1E1t+E2E2t"

MAGNETIC = ["magnetic-form-kirillov-kostant", "magnetic-momentum-map", "magnetic-euclidean-flow",
            "magnetic-normal-flow", "magnetic-psi12-conserved", "magnetic-prep", "magnetic-lax",
            "magnetic-grassmannian-momentum", "magnetic-spectral-invariants", "twisted-form-closed"]


def _zero(s, M):
    return s.reduce(entry_of(M) if isinstance(M, Mat) else M).is_zero


def _proved(res):
    assert res.verdict == "proved", res.message
    report = check_certificate(res.certificate_data)
    assert report.accepted, report.message
    return res


def at_sizes(claim, **kw):
    return dataclasses.replace(claim, sizes=admissible(**kw))


# -- the claims of the paper ---------------------------------------------------------------------------
@pytest.mark.parametrize("cid", MAGNETIC)
def test_magnetic_claims_are_proved_for_every_n_at_r_2(cid):
    res = _proved(run_free(CATALOG.get(cid)))
    if R2 in res.certificate_data["summary"]["hypotheses"]:
        assert "r = 2" in res.certificate and "r = 2" in check_certificate(res.certificate_data).message


# -- the letters and their rules ------------------------------------------------------------------------
def test_the_columns_are_orthonormal_and_complete_at_r_2():
    s = FreeScene(columns=2)
    E1, E2 = s.column(0), s.column(1)
    assert _zero(s, s.tr(E1.T @ E1) - 1) and _zero(s, s.tr(E1.T @ E2))
    assert _zero(s, E1 @ E1.T + E2 @ E2.T - s.Ir)
    assert _zero(s, s.X @ s.X.T - s.X @ E1 @ E1.T @ s.X.T - s.X @ E2 @ E2.T @ s.X.T)
    assert _zero(s, s.tr(E1.T @ s.eta @ E1))                       # η skew
    assert not _zero(s, s.tr(E1.T @ s.eta @ E2))
    assert not _zero(s, s.X @ s.X.T - s.X @ E1 @ E1.T @ s.X.T)     # a dropped column
    assert not _zero(s, E1 @ E2.T - E2 @ E1.T)
    assert not _zero(s, s.tr(s.X.T @ s.A @ s.X) - s.tr(E1.T @ s.X.T @ s.A @ s.X @ E1))


def test_without_r_2_there_are_no_columns():
    s = FreeScene()
    with pytest.raises(Exception):
        s.column(0)
    claim = at_sizes(BASE, n_max=5, n_min=3, r_min=2, r_max=3)     # stated at r = 3 too
    res = run_free(claim, lambda t: {"XX^T": t.X @ t.X.T - m.col(t, 0) @ m.col(t, 0).T - m.col(t, 1) @ m.col(t, 1).T})
    assert res.verdict == "undecided", res.message


def test_an_identity_of_r_2_is_proved_at_r_2_only():
    """XXᵀ = e₁e₁ᵀ + e₂e₂ᵀ holds on V(n, 2), not on V(n, 3)."""
    func = lambda t: {"XX^T": t.X @ t.X.T - m.col(t, 0) @ m.col(t, 0).T - m.col(t, 1) @ m.col(t, 1).T}  # noqa: E731
    _proved(run_free(BASE, func))
    assert run_free(at_sizes(BASE, n_max=5, n_min=3, r_min=3, r_max=3), func).verdict != "proved"


# -- negative controls: corrupted claims are not proved -------------------------------------------------
def momentum_map_swapped(s):
    e1, e2, p1, p2 = m.col(s, 0), m.col(s, 1), m.pcol(s, 0), m.pcol(s, 1)
    return {"Phi_eps": m.Phi_eps(s) - (m.wedge(p1, e1) + m.wedge(p2, e2) + s.eps * m.wedge(e2, e1))}


def momentum_map_dropped(s):
    e1, p1 = m.col(s, 0), m.pcol(s, 0)
    return {"Phi_eps": m.Phi_eps(s) - (m.wedge(p1, e1) + s.eps * m.wedge(e1, m.col(s, 1)))}


def euclidean_flow_lorentz_sign(s):
    """(mag-euk) with the Lorentz force −εp₂ in ṗ₁."""
    A, eps = s.A, s.eps
    e1, e2, p1, p2 = m.col(s, 0), m.col(s, 1), m.pcol(s, 0), m.pcol(s, 1)
    d = lambda x, y: m.dot(s, x, y)  # noqa: E731
    p1dot = (-(A @ e1) + (d(e1, A @ e1) - d(p1, p1) - eps * d(e1, p2)) * e1
             + (d(e1, A @ e2) - d(p1, p2)) * e2 - eps * p2)
    return {"dp1/dt": twisted.flow(s, H_neumann_euclidean).Pdot @ m.unit(s, 0) - p1dot}


def euclidean_flow_swapped_columns(s):
    """(mag-euk) with (e₁, Ae₁) in place of (e₂, Ae₂) in ṗ₂."""
    A, eps = s.A, s.eps
    e1, e2, p1, p2 = m.col(s, 0), m.col(s, 1), m.pcol(s, 0), m.pcol(s, 1)
    d = lambda x, y: m.dot(s, x, y)  # noqa: E731
    p2dot = (-(A @ e2) + (d(e1, A @ e2) - d(p1, p2)) * e1
             + (d(e1, A @ e1) - d(p2, p2) + eps * d(e2, p1)) * e2 - eps * p1)
    return {"dp2/dt": twisted.flow(s, H_neumann_euclidean).Pdot @ m.unit(s, 1) - p2dot}


def prep_without_magnetic_term(s):
    flow = twisted.flow(s, H_neumann_euclidean)
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A)}


def lax_with_phi(s):
    flow = twisted.flow(s, H_neumann_euclidean)
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    return {"LA1": s.d(L, flow) - comm(s.Phi - s.lam * s.A, L(s))}


def psi12_not_invariant(s):
    """Ψ₁₂ along the twisted flow of H + (e₁, Ae₁), which is not right SO(2)-invariant."""
    H = lambda t: H_neumann_euclidean(t) + m.dot(t, m.col(t, 0), t.A @ m.col(t, 0))  # noqa: E731
    return {"dPsi/dt": s.d(m.psi12, twisted.flow(s, H))}


def form_sign(s):
    zero = s.zeros(s.n, s.r, ("n", "r"))
    along = lambda a: {"X": a, "P": zero}  # noqa: E731
    return {"omega": twisted.form(s, along(s.xi @ s.X), along(s.zeta @ s.X))
            - s.eps * s.killing(m.e1e2(s), comm(s.xi, s.zeta))}


@pytest.mark.parametrize("func", [momentum_map_swapped, momentum_map_dropped, euclidean_flow_lorentz_sign,
                                  euclidean_flow_swapped_columns, prep_without_magnetic_term, lax_with_phi,
                                  psi12_not_invariant, form_sign])
def test_a_corrupted_magnetic_claim_is_not_proved(func):
    assert run_free(BASE, func).verdict in ("undecided", "fails")


# -- the independent checker ----------------------------------------------------------------------------
def _complete_claim(s):
    return {"XX^T": s.X @ s.X.T - m.col(s, 0) @ m.col(s, 0).T - m.col(s, 1) @ m.col(s, 1).T,
            "(e1, e2) + (e2, p2)": m.dot(s, m.col(s, 0), m.col(s, 1)) + m.dot(s, m.col(s, 1), m.pcol(s, 1))}


@pytest.fixture(scope="module")
def certificate():
    res = _proved(run_free(BASE, _complete_claim))
    hyps = res.certificate_data["summary"]["hypotheses"]
    assert R2 in hyps and "E1tE2" in hyps
    return res.certificate_data


def _terms(data, hyp):
    return [t for e in data["entries"] for t in e["terms"] if t["hyp"] == hyp]


def test_the_checker_says_r_2(certificate):
    assert "r = 2" in check_certificate(certificate).message


def test_the_checker_rejects_a_flipped_coefficient(certificate):
    data = copy.deepcopy(certificate)
    t = _terms(data, R2)[0]
    t["coef"] = f"-({t['coef']})"
    assert not check_certificate(data).accepted


@pytest.mark.parametrize("name, other", [("E1tE2", "E1tE1"), ("E1tE2", "E2tE2"), (R2, "XtX")])
def test_the_checker_rejects_another_hypothesis(certificate, name, other):
    data = copy.deepcopy(certificate)
    for t in _terms(data, name):
        t["hyp"] = other
    assert not check_certificate(data).accepted


def test_the_checker_rejects_swapped_columns_in_the_residual(certificate):
    data = copy.deepcopy(certificate)
    entry = data["entries"][0]
    t = next(t for t in entry["residual"] if "E1" in t["word"])
    t["word"] = ["E2" if x == "E1" else "E2t" if x == "E1t" else x for x in t["word"]]
    assert not check_certificate(data).accepted


def test_the_checker_types_the_columns(certificate):
    data = copy.deepcopy(certificate)
    for t in _terms(data, R2):
        t["left"] = t["left"] + ["E1t"]     # a path through the scalar object that does not close
    assert not check_certificate(data).accepted
    data = copy.deepcopy(certificate)
    data["letters"] = {"E1": {"kind": "generic", "row": "r", "col": "n", "transpose": "E1t"}}
    assert not check_certificate(data).accepted


def test_the_checker_does_not_take_x_xt_for_the_identity(certificate):
    """Without the uses of E₁E₁ᵀ + E₂E₂ᵀ = I_r the certificate does not expand to XXᵀ − e₁e₁ᵀ − e₂e₂ᵀ."""
    data = copy.deepcopy(certificate)
    for e in data["entries"]:
        e["terms"] = [t for t in e["terms"] if t["hyp"] != R2]
    assert not check_certificate(data).accepted


# -- r = 1: every r×r matrix is a scalar ------------------------------------------------------------------
SPHERE = CATALOG.get("poisson-sphere-flow")


def test_the_poisson_sphere_flow_is_proved_for_every_n_at_r_1():
    res = _proved(run_free(SPHERE))
    assert "r = 1" in res.certificate and "r = 1" in check_certificate(res.certificate_data).message


def _commute(t):
    """XᵀAX and XᵀP commute: true at r = 1 (scalars), false at r = 2."""
    M, N = t.X.T @ t.A @ t.X, t.X.T @ t.P
    return {"[X^T A X, X^T P]": M @ N - N @ M}


def test_an_identity_of_r_1_is_proved_at_r_1_only():
    _proved(run_free(SPHERE, _commute))
    assert run_free(at_sizes(SPHERE, n_max=5, r_min=2, r_max=2), _commute).verdict != "proved"
    assert run_free(at_sizes(SPHERE, n_max=3, r_max=2), _commute).verdict != "proved"
    # default sizes at r = 1 only, but the statement is for every r: no columns
    assert run_free(at_sizes(SPHERE, n_max=1), _commute).verdict != "proved"


def sphere_flow_sign(s):
    from stiefelsym.proofs.sec8_dual_lax_pair import H_poisson_sphere
    e, p, Ai = s.X, s.P, s.Ainv
    return {"de/dt": s.dirac_flow(H_poisson_sphere).Xdot - (Ai @ p @ (e.T @ Ai @ e) + Ai @ e @ (e.T @ Ai @ p))}


def sphere_flow_swapped(s):
    from stiefelsym.proofs.sec8_dual_lax_pair import H_poisson_sphere
    e, p, Ai = s.X, s.P, s.Ainv
    return {"dp/dt": s.dirac_flow(H_poisson_sphere).Pdot - (Ai @ e @ (e.T @ Ai @ p) - Ai @ p @ (p.T @ Ai @ p))}


@pytest.mark.parametrize("func", [sphere_flow_sign, sphere_flow_swapped])
def test_a_corrupted_sphere_claim_is_not_proved(func):
    assert run_free(SPHERE, func).verdict in ("undecided", "fails")


def test_the_checker_has_no_second_column_at_r_1():
    """At r = 1, E₂ = E₁E₁ᵀE₂ = 0 would contradict E₂ᵀE₂ = 1: a certificate with both is rejected."""
    data = copy.deepcopy(_proved(run_free(SPHERE, _commute)).certificate_data)
    assert "E1E1t" in data["summary"]["hypotheses"]
    assert check_certificate(data).accepted
    data["entries"][0]["terms"].append({"coef": "0", "traces": [], "left": [], "hyp": "E2tE2", "right": [],
                                        "in_trace": True, "word": []})
    assert not check_certificate(data).accepted


# -- r = n: T*SO(n), X Xᵀ = I_n, and the last column e_n = XE_r ---------------------------------------------
SO_N = ["rigid-body-euler-poisson", "ym-second-derivative", "clebsch-perelomov-hamiltonian"]


@pytest.mark.parametrize("cid", SO_N)
def test_rigid_body_claims_are_proved_for_every_n_at_r_n(cid):
    claim = CATALOG.get(cid)
    assert claim.sizes.r_is_n
    res = _proved(run_free(claim))
    if "XXt" in res.certificate_data["summary"]["hypotheses"]:
        assert "r = n" in res.certificate and "r = n" in check_certificate(res.certificate_data).message


def _orthogonal(t):
    return {"XX^T = I_n": t.X @ t.X.T - t.In, "P X^T + X P^T": t.P @ t.X.T + t.X @ t.P.T}


def test_x_xt_is_the_identity_at_r_n_only():
    so_n = CATALOG.get("rigid-body-euler-poisson")
    _proved(run_free(so_n, _orthogonal))
    assert run_free(at_sizes(so_n, n_max=5, n_min=2), _orthogonal).verdict != "proved"
    # the same sizes r = n, but read from a condition, not declared: not used
    assert run_free(at_sizes(so_n, n_max=5, n_min=2, where=lambda n, r: r == n), _orthogonal).verdict != "proved"


def euler_star_sign(s):
    from stiefelsym.proofs.app1_magnetic_neumann import H_CP, last
    e = last(s)
    return {"(Euler*)": s.d(lambda t: t.Phi, s.dirac_flow(H_CP)) - comm(e @ e.T, s.A)}


def body_velocity_sign(s):
    from stiefelsym.proofs.app1_magnetic_neumann import H_CP
    return {"omega = -m": s.X.T @ s.dirac_flow(H_CP).Xdot + s.X.T @ s.Phi @ s.X}


def last_column_orthogonal_to_p(s):
    """(e_n, p_n) = 0 holds ((XᵀP)_rr = 0), but e_nᵀP = E_rᵀXᵀP is not 0."""
    from stiefelsym.proofs.app1_magnetic_neumann import last
    e = last(s)
    return {"e_n^T P": e.T @ s.P}


@pytest.mark.parametrize("func", [euler_star_sign, body_velocity_sign,
                                  last_column_orthogonal_to_p])
def test_a_corrupted_rigid_body_claim_is_not_proved(func):
    assert run_free(CATALOG.get("rigid-body-euler-poisson"), func).verdict in ("undecided", "fails")


def test_the_last_column_is_a_unit_vector():
    so_n = CATALOG.get("rigid-body-euler-poisson")
    from stiefelsym.proofs.app1_magnetic_neumann import last
    _proved(run_free(so_n, lambda t: {"(e_n, e_n) - 1": m.dot(t, last(t), last(t)) - 1,
                                      "(e_n, p_n)": m.dot(t, last(t), t.P @ twisted.last_basis_vector(t))}))


def test_the_checker_rejects_x_xt_for_xt_x():
    data = copy.deepcopy(_proved(run_free(CATALOG.get("rigid-body-euler-poisson"), _orthogonal)).certificate_data)
    assert "r = n" in check_certificate(data).message
    for e in data["entries"]:
        for t in e["terms"]:
            if t["hyp"] == "XXt":
                t["hyp"] = "XtX"
    assert not check_certificate(data).accepted


def test_the_rules_of_r_n_terminate_in_traces_and_are_confluent_on_words():
    """XPᵀ → −PXᵀ in the order P < X (the other direction loops: tr(XᵀPXᵀP) → −tr(XᵀXPᵀP) → ...), with
    XᵀPXᵀ → −Pᵀ and the completion PᵀPXᵀ → XᵀPPᵀ: every critical pair resolves but tr I_n = tr I_r."""
    from stiefelsym.free.rewriting import critical_pairs
    from stiefelsym.free.scene import P, Pt, X, Xt
    s = FreeScene(square=True)
    s.leading_columns()
    assert s.system.trace_normal_form((Xt, P, Xt, P)) == s.system.trace_normal_form((Pt, P)) * -1
    assert s.system.trace_normal_form((Pt, X, Xt, P)) == s.system.trace_normal_form((Pt, P))
    bad = [p for p in critical_pairs(s.system) if not p.joinable]
    assert {(p.a.name, p.b.name) for p in bad} <= {("XtX", "XXt"), ("XXt", "XtX")}


def _leading(t):
    from stiefelsym.proofs.app1_magnetic_neumann import last
    E, e = twisted.leading_basis_vectors(t), last(t)
    Xp = t.X @ E
    return {"e e^T + X' X'^T = I_n": e @ e.T + Xp @ Xp.T - t.In, "X'^T e = 0": Xp.T @ e,
            "X'^T X' = E^T E": Xp.T @ Xp - E.T @ E}


def leading_dropped(t):
    from stiefelsym.proofs.app1_magnetic_neumann import last
    E, e = twisted.leading_basis_vectors(t), last(t)
    return {"e e^T = X' X'^T": e @ e.T - t.X @ E @ E.T @ t.X.T}


def leading_not_last(t):
    """X'ᵀP = E_{<r}ᵀXᵀP is not 0 (XᵀP is skew, not 0)."""
    E = twisted.leading_basis_vectors(t)
    return {"X'^T P": (t.X @ E).T @ t.P}


def test_the_leading_columns_and_the_last_are_the_identity():
    so_n = CATALOG.get("clebsch-perelomov-hamiltonian")
    res = _proved(run_free(so_n, _leading))
    assert "EleadEleadt+ErErt" in res.certificate_data["summary"]["hypotheses"]
    for func in (leading_dropped, leading_not_last):
        assert run_free(so_n, func).verdict in ("undecided", "fails"), func.__name__
    data, _ = forged(res.certificate_data, {"EleadEleadt+ErErt": "E1E1t+E2E2t"})
    assert not check_certificate(data).accepted


def test_the_report_says_for_which_r_a_proof_holds():
    from stiefelsym.reports.report import free_scope
    assert free_scope(_proved(run_free(CATALOG.get("magnetic-euclidean-flow")))) == "every n at r = 2"
    assert free_scope(_proved(run_free(SPHERE))) == "every n at r = 1"
    assert free_scope(_proved(run_free(CATALOG.get("rigid-body-euler-poisson")))) == "every n at r = n"
    assert free_scope(_proved(run_free(CATALOG.get("magnetic-momentum-map-any-rank")))) == "all n, r"


# -- the problem at another point of T*V (twisted.at_point) --------------------------------------------------
def test_the_magnetic_grassmannian_flow_is_proved_at_the_horizontal_point():
    _proved(run_free(CATALOG.get("magnetic-grassmannian-flow")))


def _horizontal(t):
    return t.X, (t.In - t.X @ t.X.T) @ t.P


def test_values_at_the_point_are_the_base_scene_s():
    """h.P is P_h = (I − XXᵀ)P, h.Psi is Ψ(X, P_h) = 0, the flow at h is the flow at (X, P_h)."""
    def claim(t):
        X, Ph = _horizontal(t)
        h = twisted.at_point(t, X, Ph)
        flow = h.dirac_flow(m.H_neumann_normal)
        return {"h.P": h.P - Ph, "h.Psi": h.Psi, "h.Phi": h.Phi - (Ph @ X.T - X @ Ph.T),
                "flow at h": flow.Xdot - (Ph - X @ Ph.T @ X), "d Psi along it": h.d(lambda u: u.Psi, flow)}
    _proved(run_free(BASE, claim))


def at_point_p_is_p(t):
    h = twisted.at_point(t, *_horizontal(t))
    return {"h.P - P": h.P - t.P}


def at_point_flow_of_the_base(t):
    """The flow at h is not the flow at (X, P)."""
    h = twisted.at_point(t, *_horizontal(t))
    return {"flows": h.dirac_flow(m.H_neumann_normal).Xdot - t.dirac_flow(m.H_neumann_normal).Xdot}


def at_point_not_on_t_star_v(t):
    h = twisted.at_point(t, t.X, t.P + t.X)          # XᵀP + PᵀX + 2I ≠ 0
    return {"Psi": h.Psi - h.Psi}


def at_point_base_tangent(t):
    h = twisted.at_point(t, *_horizontal(t))
    return {"d": h.d(lambda u: u.Psi, {"X": t.xi @ t.X, "P": t.xi @ t.P})}


@pytest.mark.parametrize("func", [at_point_p_is_p, at_point_flow_of_the_base, at_point_not_on_t_star_v,
                                  at_point_base_tangent])
def test_a_corrupted_claim_at_another_point_is_not_proved(func):
    assert run_free(BASE, func).verdict in ("undecided", "fails")


# -- the double Neumann system: a generic point (X, Y, Ẋ, Ẏ) with (D0) as rules ----------------------------------
DOUBLE = CATALOG.get("double-neumann-momentum")


def test_the_double_system_s_momentum_and_corrected_lax_pair_are_proved():
    _proved(run_free(DOUBLE))
    lax = CATALOG.get("double-neumann-dual-lax")
    (corr,) = lax.corrections
    _proved(run_free(lax, corr.func))
    assert run_free(lax).verdict == "undecided"        # as printed it fails at every size


def double_potential_conserved(s):
    from stiefelsym.systems import derivative, double_point
    import stiefelsym.proofs.app2_double_coupled_complex as a
    z = double_point(s)
    return {"d tr(X^T A Y)/dt": derivative(s, lambda t, w: t.tr(w["X"].T @ t.A @ w["Y"]), z, a.flow_double(s, z))}


def double_flow_without_transpose(s):
    """Ẍ = −AX + XΛ (Λᵀ dropped) does not keep ẊᵀY + XᵀẎ = 0: the derivative along it is refused."""
    from stiefelsym.systems import derivative, double_point
    import stiefelsym.proofs.app2_double_coupled_complex as a
    z = double_point(s)
    flow = a.flow_double(s, z)
    flow["Xdot"] = -(s.A @ z["X"]) + z["X"] @ a.Lambda_double(s, z)
    return {"d(X^T Y' - Y^T X')/dt": derivative(s, lambda t, w: w["X"].T @ w["Ydot"] - w["Y"].T @ w["Xdot"], z, flow)}


def double_velocities_product(s):
    """XᵀẎ and YᵀẊ are conserved one by one (so is the printed integral), ẊᵀẎ is not."""
    from stiefelsym.systems import derivative, double_point
    import stiefelsym.proofs.app2_double_coupled_complex as a
    z = double_point(s)
    return {"d(X'^T Y')/dt": derivative(s, lambda t, w: w["Xdot"].T @ w["Ydot"], z, a.flow_double(s, z))}


@pytest.mark.parametrize("func", [double_potential_conserved, double_flow_without_transpose,
                                  double_velocities_product])
def test_a_corrupted_double_claim_is_not_proved(func):
    assert run_free(DOUBLE, func).verdict in ("undecided", "fails")


@pytest.mark.parametrize("cid", ["double-neumann-flow", "double-neumann-diagonal"])
def test_the_euler_lagrange_equations_of_the_double_system_are_solved_in_the_free_algebra(cid):
    _proved(run_free(CATALOG.get(cid)))


def _accelerations(s, z, T=None, U=None, constraints=None):
    import stiefelsym.proofs.app2_double_coupled_complex as a
    from stiefelsym.systems import euler_lagrange, real_coordinates
    acc, _ = euler_lagrange(s, T or a.T_double, U or a.U_double, constraints or a.D0, {"X": z["X"], "Y": z["Y"]},
                            {"X": z["Xdot"], "Y": z["Ydot"]}, real_coordinates(s, ["X", "Y"]))
    return acc


def el_potential_sign(s):
    """(D-eq) against the Euler-Lagrange equations of tr(XᵀAY) + tr(ẊᵀẎ) (the potential's sign flipped)."""
    import stiefelsym.proofs.app2_double_coupled_complex as a
    from stiefelsym.systems import double_point
    z = double_point(s)
    acc = _accelerations(s, z, U=lambda t, q: -a.U_double(t, q))
    return {"X''": acc["X"] - a.flow_double(s, z)["Xdot"]}


def el_other_constraint(s):
    """Constraints YᵀX = I_r written the other way: not the ones the free scene solves, refused."""
    import stiefelsym.proofs.app2_double_coupled_complex as a
    from stiefelsym.systems import double_point
    z = double_point(s)
    acc = _accelerations(s, z, constraints=lambda t, q: [q["Y"].T @ q["X"] - t.Ir])
    return {"X''": acc["X"] - a.flow_double(s, z)["Xdot"]}


def el_transposed_multiplier(s):
    """(D-eq) with Λ in place of Λᵀ in Ẍ."""
    import stiefelsym.proofs.app2_double_coupled_complex as a
    from stiefelsym.systems import double_point
    z = double_point(s)
    acc = _accelerations(s, z)
    return {"X''": acc["X"] - (-(s.A @ z["X"]) + z["X"] @ a.Lambda_double(s, z))}


@pytest.mark.parametrize("func", [el_potential_sign, el_other_constraint, el_transposed_multiplier])
def test_a_corrupted_euler_lagrange_claim_is_not_proved(func):
    assert run_free(DOUBLE, func).verdict in ("undecided", "fails")


def test_the_checker_knows_the_double_point():
    data = copy.deepcopy(_proved(run_free(DOUBLE)).certificate_data)
    assert {"DXtDY", "DXdtDY+DXtDYd"} & set(data["summary"]["hypotheses"])
    for e in data["entries"]:
        for t in e["terms"]:
            if t["hyp"] == "DXdtDY+DXtDYd":
                t["hyp"] = "DYtDXd+DYdtDX"
            elif t["hyp"] == "DXtDY":
                t["hyp"] = "XtX"
    assert not check_certificate(data).accepted


# -- every corrupted claim above that states something false fails at a fixed size ------------------------------
FALSE_CONTROLS = [
    ("magnetic-momentum-map", (3, 2), f) for f in (
        momentum_map_swapped, momentum_map_dropped, euclidean_flow_lorentz_sign, euclidean_flow_swapped_columns,
        prep_without_magnetic_term, lax_with_phi, psi12_not_invariant, form_sign, at_point_p_is_p,
        at_point_flow_of_the_base)] + [
    ("poisson-sphere-flow", (3, 1), f) for f in (sphere_flow_sign, sphere_flow_swapped)] + [
    ("rigid-body-euler-poisson", (3, 3), f) for f in (euler_star_sign, body_velocity_sign, last_column_orthogonal_to_p)] + [
    ("clebsch-perelomov-hamiltonian", (3, 3), f) for f in (leading_dropped, leading_not_last)] + [
    ("double-neumann-momentum", (3, 2), f) for f in (double_potential_conserved, double_velocities_product,
                                                     el_potential_sign, el_transposed_multiplier)]


@pytest.mark.parametrize("cid, size, func", FALSE_CONTROLS, ids=[f"{c}-{f.__name__}" for c, _, f in FALSE_CONTROLS])
def test_the_corrupted_claims_fail_at_a_fixed_size(cid, size, func):
    from stiefelsym.methods.fixed_size import run_exact
    assert run_exact(CATALOG.get(cid), *size, 0, func=func).verdict == "fails"


def test_remembered_canonical_form_is_the_canonical_form(monkeypatch):
    """The canonical form of the columns computed term by term and remembered gives the same terms, in the
    same order, as the one with its certificate, on every call of a free proof at r = 2; and a polynomial
    with one coefficient changed does not get the remembered form of the other (negative control)."""
    from stiefelsym.claims import load_catalog
    from stiefelsym.free import columns
    from stiefelsym.run.runner import run_one
    import stiefelsym.free.scene as scene_module
    seen = []

    def checked(p, r):
        f = columns.canonical_form(p, r)
        q, _ = columns.canonical(p, r)
        assert list(f.terms.items()) == list(q.terms.items())
        if p.terms:
            key, c = next(iter(p.terms.items()))
            other = columns.NCPoly({**p.terms, key: c + 1}, p.row, p.col)
            assert columns.canonical_form(other, r) != f or columns.canonical(other, r)[0] == f
        seen.append(p)
        return f
    monkeypatch.setattr(scene_module, "canonical_form", checked)
    assert run_one(load_catalog().get("magnetic-normal-flow"), None, "free", 0).verdict == "proved"
    assert seen


def test_a_claim_stated_at_one_r_is_proved_at_that_r_whatever_its_hypotheses():
    """A claim stated on V(n, 2) only is traced on the family r = 2; its proof is about every n at r = 2,
    and says so (the report counts it there, not among the claims proved for every n and r), also when the
    proof used no hypothesis of the family (twisted-form: no E_1E_1^T + E_2E_2^T = I_r)."""
    from stiefelsym.claims import load_catalog
    from stiefelsym.reports.report import free_scope
    from stiefelsym.run.runner import run_one

    res = run_one(load_catalog().get("twisted-form"), None, "free", 0)
    assert res.verdict == "proved", res.message
    assert "E_1E_1^T + E_2E_2^T = I_r" not in res.certificate
    assert free_scope(res) == "every n at r = 2", res.certificate


def test_a_mutation_analysis_reduces_entries_until_the_first_open_one_with_the_same_verdicts():
    """In a mutation analysis the dimension-free run stops at the first entry with a nonzero normal form
    (the run is undecided whatever the others give); a corrupted claim is undecided either way, with the
    other entries left unreduced, and the claim as printed, every entry 0, is proved as before."""
    from stiefelsym.methods.fixed_size import mutation_analysis
    corrupted = lambda t: {"XX^T": t.X @ t.X.T + m.col(t, 0) @ m.col(t, 0).T - m.col(t, 1) @ m.col(t, 1).T,  # noqa: E731
                           "Psi": t.Psi + t.Psi}
    printed = lambda t: {"XX^T": t.X @ t.X.T - m.col(t, 0) @ m.col(t, 0).T - m.col(t, 1) @ m.col(t, 1).T}  # noqa: E731
    whole = run_free(BASE, corrupted)
    assert whole.verdict == "undecided" and "residual entries have a nonzero normal form" in whole.message
    with mutation_analysis():
        first = run_free(BASE, corrupted)
        assert first.verdict == "undecided", first.message
        assert "the other entries were not reduced" in first.message
        assert [c.status for c in first.checks] == ["open"]          # Psi + Psi was not reached
        _proved(run_free(BASE, printed))
    assert [c.status for c in whole.checks] == ["open", "open"]
