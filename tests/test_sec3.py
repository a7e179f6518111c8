"""§3 claims: each holds at a small size, and a corrupted copy of each fails (negative controls)."""
import pytest

from stiefelsym.proofs import sec3_geodesic_flows as g
from stiefelsym import Rank, admissible, comm
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact, run_points


def corrupted(cid, func, **kw):
    base = load_catalog().get(cid)
    return Claim(id=cid + "-corrupted", paper=base.paper, kind=base.kind, section="3", func=func,
                 sizes=admissible(4), realization=kw.get("realization", base.realization))


def euclidean_flow_sign(s):
    flow = s.dirac_flow(g.H_euclidean)
    return {"dP/dt": flow.Pdot - s.X @ s.P.T @ s.P}


def euclidean_lambda_sign(s):
    flow, mult = s.dirac_flow(g.H_euclidean), s.multiplier_flow(g.H_euclidean)
    return {"Lambda": mult["Lambda"] - flow.Xdot.T @ flow.Xdot}


def euclidean_invariance_wrong_flow(s):
    printed = {"X": s.P, "P": s.X @ s.P.T @ s.P}
    return {"d(X^T P + P^T X)/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, printed)}


def submersion_trace_sign(s):
    AA = s.sym_operator("AA")
    return {"H_AA": g.H_submersion(s) - s.tr(AA(s.Phi) @ s.Phi) / 4}


def submersion_flow_transposed(s):
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(g.H_submersion)
    return {"dX/dt": flow.Xdot - s.X @ AA(s.Phi)[: s.r, : s.r] if s.r == s.n else flow.Xdot + AA(s.Phi) @ s.X}


def right_invariant_euler_sign(s):
    """The Euler–Arnold equation with the sign of a left-invariant metric's (the body frame), Φ̇ = −[𝔸(Φ), Φ]."""
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(g.H_submersion)
    return {"dPhi/dt = [AA(Phi), Phi]": s.d(lambda t: t.Phi, flow) + comm(AA(s.Phi), s.Phi)}


def normal_hamiltonian_half(s):
    XtP = s.X.T @ s.P
    return {"H_0": g.H_normal(s) - (s.tr(s.P.T @ s.P) / 2 + s.tr(XtP @ XtP) / 2)}


def normal_flow_order(s):
    flow = s.dirac_flow(g.H_normal)
    return {"dP/dt": flow.Pdot - (-s.X @ s.P.T @ s.P + s.P @ s.P.T @ s.X)}


def legendre_factor(s):
    Xdot = g._normal_velocity(s)
    return {"P": s.P - (Xdot - s.X @ s.X.T @ Xdot)}


def phi0_factor(s):
    V, X = s.P, s.X
    P_of_V = V - X @ X.T @ V / 2
    Phi0 = V @ X.T - X @ V.T - X @ (X.T @ V - V.T @ X) @ X.T
    return {"Phi_0": Phi0 - (P_of_V @ s.X.T - s.X @ P_of_V.T)}


def lagrangian_legendre_wrong(s):
    V = s.P
    return {"dL/dXdot": s.gradient(g.L_normal)[1] - V}


def jensen_kappa_sign(s):
    XtP = s.X.T @ s.P
    return {"H_kappa": g.H_jensen(s) - (s.tr(s.P.T @ s.P) / 2 - (s.q(1, 2) - s.kappa) * s.tr(XtP @ XtP))}


def jensen_not_invariant(s):
    H = lambda t: g.H_jensen(t) + t.tr(t.X.T @ t.A @ t.X)
    return {"left so(n)": s.d(H, {"X": s.xi @ s.X, "P": s.xi @ s.P})}


def block_jensen_psi_not_conserved(s):
    return {"Psi conserved": s.d(lambda t: t.Psi, s.dirac_flow(g.H_K))}


def metric_legendre_wrong(s):
    P = s.A @ s.P
    return {"cond_XP2": s.X.T @ P + P.T @ s.X}


def metric_flow_lambda_sign(s):
    flow = s.dirac_flow(g.H_metric_A)
    Lam = s.X.T @ flow.Pdot
    M = s.X.T @ s.Ainv @ s.X
    return {"Lambda equation": Lam @ M + M @ Lam - 2 * (s.P.T @ s.Ainv @ s.Ainv @ s.P)}


def invariant_metrics_one_form(s):
    rows, unknowns, N = g._fibre_action_matrix(s)
    M = s.mat([[s.const(c) for c in row] for row in rows], tags=("cond", "coef"))
    return {"invariant forms": Rank(M, unknowns - 1, generic=False)}


CASES = [
    ("euclidean-flow", euclidean_flow_sign, (3, 2)),
    ("euclidean-multipliers", euclidean_lambda_sign, (3, 2)),
    ("euclidean-invariance", euclidean_invariance_wrong_flow, (3, 2)),
    ("submersion-hamiltonian", submersion_trace_sign, (3, 2)),
    ("submersion-flow", submersion_flow_transposed, (3, 2)),
    ("right-invariant-geodesic-flow", right_invariant_euler_sign, (3, 3)),   # so(2) is abelian: n >= 3
    ("normal-hamiltonian", normal_hamiltonian_half, (3, 2)),
    ("normal-flow", normal_flow_order, (3, 2)),
    ("normal-legendre-inverse", legendre_factor, (3, 2)),
    ("normal-momentum-of-velocity", phi0_factor, (3, 2)),
    ("normal-lagrangian", lagrangian_legendre_wrong, (3, 2)),
    ("jensen-hamiltonian", jensen_kappa_sign, (3, 2)),
    ("jensen-invariance", jensen_not_invariant, (3, 2)),
    ("block-jensen-hamiltonian", block_jensen_psi_not_conserved, (4, 4)),   # two blocks so(2) + so(2)
    ("metric-legendre", metric_legendre_wrong, (3, 2)),
    ("metric-flow", metric_flow_lambda_sign, (2, 1)),
    ("invariant-metrics", invariant_metrics_one_form, (3, 2)),
]


def test_every_section3_claim_has_a_negative_control():
    # the claims written in the module of §3 (invariant-metrics, Proposition 4.6, is filed under §4 of the paper)
    assert {c[0] for c in CASES} == {c.id for c in load_catalog() if c.func.__module__.endswith(".sec3_geodesic_flows")}
    assert load_catalog().get("invariant-metrics").section == "4"


@pytest.mark.parametrize("cid,func,size", CASES, ids=[f"{c[0]}-{c[1].__name__}" for c in CASES])
def test_corrupted_claim_fails(cid, func, size):
    c = corrupted(cid, func)
    n, r = size
    assert run_exact(c, n, r, 0).verdict == "fails"
    assert run_points(c, n, r, "modular", 0).verdict in ("fails", "inconclusive")
    assert run_points(c, n, r, "modular", 0).verdict != "checked"
    assert run_free(c, c.func).verdict != "proved"    # never a proof for all n, r of a false statement


@pytest.mark.parametrize("cid", sorted({c[0] for c in CASES}))
def test_claim_holds_as_printed_at_a_small_size(cid):
    c = load_catalog().get(cid)
    # metric-flow: symbolic budget; right-invariant-geodesic-flow: stated at r = n
    n, r = {"metric-flow": (2, 1), "right-invariant-geodesic-flow": (3, 3)}.get(cid, (3, 2))
    assert run_exact(c, n, r, 0).verdict == "proved"
    res = run_points(c, 3, r if cid == "right-invariant-geodesic-flow" else 2, "modular", 0)
    # checks that no parameter enters (counts of integers) are constants, exact over Q: proved
    assert res.verdict == ("proved" if res.certificate.startswith("no parameter enters") else "checked"), res.message
