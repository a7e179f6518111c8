"""The symplectic, constraint-preserving steps of the Manakov, magnetic and coupled flows
(``method="rattle"`` / ``"rattle4"``): convergence to the DOP853 reference with order 2 and 4, T*V kept
to rounding, no energy drift, the symplectic form kept, and negative controls."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from stiefelsym.analyses import integrate as ig

A4 = np.diag([0.5, 1.3, 2.1, 3.4])
B4 = np.diag([0.1, 0.9, 1.2, 2.8])

FAMILIES = [
    ("manakov", {}),
    ("manakov", {"B": B4}),
    ("magnetic", {"kappa": -0.5, "eps": 0.7}),
    ("magnetic", {"kappa": 0.0, "eps": 0.7}),
    ("magnetic", {"kappa": 0.4, "eps": -1.1}),
    ("coupled", {"kappa": 0.0}),
    ("coupled", {"kappa": 0.5}),
    ("coupled", {"kappa": 0.5, "perturbed": True}),
]


def start(flow, n=4, r=2, seed=1):
    X, P = ig.random_point(n, r, seed=seed)
    if flow == "coupled":
        Y, Q = ig.random_point(n, r, seed=seed + 100)
        return (X, Y), (P, Q)
    return X, P


def final_error(tr, ref):
    return float(np.abs(tr.X[-1] - ref.X[-1]).max() + np.abs(tr.P[-1] - ref.P[-1]).max())


@pytest.mark.parametrize("flow, kw", FAMILIES, ids=[f"{f}-{k}" for f, k in FAMILIES])
def test_symplectic_step_converges_to_the_reference_with_its_order(flow, kw):
    X0, P0 = start(flow)
    kw = dict(kw, A=A4)
    ref = ig.integrate(X0, P0, flow, 2.0, method="dop853", tol=1e-13, samples=3, **kw)
    for method, steps, order in (("rattle", (0.02, 0.01), 2), ("rattle4", (0.05, 0.025), 4)):
        runs = [ig.integrate(X0, P0, flow, 2.0, method=method, step=h, samples=3, **kw) for h in steps]
        e = [final_error(t, ref) for t in runs]
        assert 0.8 * 2 ** order < e[0] / e[1] < 1.25 * 2 ** order, (method, e)
        for t in runs:
            errs = t.max_errors()
            assert errs["position"] < 1e-13 and errs["momentum"] < 1e-13, (method, errs)


@pytest.mark.parametrize("flow, kw", [FAMILIES[0], FAMILIES[3], FAMILIES[7]], ids=["manakov", "magnetic", "coupled"])
def test_long_run_keeps_T_star_V_and_the_energy_error_does_not_drift(flow, kw):
    X0, P0 = start(flow, n=3)
    kw = dict(kw, A=np.diag([0.5, 1.3, 2.1]))
    sym = ig.integrate(X0, P0, flow, 400.0, method="rattle", step=0.1, samples=41, **kw)
    errs = sym.max_errors()
    assert errs["position"] < 1e-12 and errs["momentum"] < 1e-12
    H = sym.hamiltonian_error
    assert H[-10:].max() < 2 * H[:10].max()          # bounded: the last quarter is no worse than the first
    assert H.max() < 1e-2
    for name, d in sym.invariant_drift.items():       # the conserved right momenta
        assert d.max() < 1e-11, name


def tangent_curve(X, P, dX, dP, s):
    return ig.project_to_tangent_bundle(X + s * dX, P + s * dP)


def symplectic_defect(step, X, P, gauge=None, h=0.2, seed=3, d=1e-5):
    """|ω(Du, Dv) − ω(u, v)| for the step map D and two tangent vectors u, v of T*V (central differences),
    ω = tr dP̃ᵀ∧dX with P̃ = P + gauge(X) (the twisted form of the magnetic flows is canonical there)."""
    rng = np.random.default_rng(seed)
    g = gauge or (lambda X: 0 * X)
    tangents = []
    for _ in range(2):
        dX, dP = rng.standard_normal(X.shape), rng.standard_normal(X.shape)
        pts = []
        for s in (-d, d):
            x, p = tangent_curve(X, P, dX, dP, s)
            pts.append((x, p))
        u0 = ((pts[1][0] - pts[0][0]) / (2 * d), (pts[1][1] + g(pts[1][0]) - pts[0][1] - g(pts[0][0])) / (2 * d))
        im = [step(x[None], p[None], h) for x, p in pts]
        u1 = ((im[1][0][0] - im[0][0][0]) / (2 * d),
              (im[1][1][0] + g(im[1][0][0]) - im[0][1][0] - g(im[0][0][0])) / (2 * d))
        tangents.append((u0, u1))

    def omega(a, b):
        return float(np.sum(a[1] * b[0]) - np.sum(b[1] * a[0]))

    (u0, u1), (v0, v1) = tangents
    return abs(omega(u1, v1) - omega(u0, v0)), abs(omega(u0, v0))


@pytest.mark.parametrize("flow, kw", [FAMILIES[1], FAMILIES[4]], ids=["manakov", "magnetic"])
def test_the_step_keeps_the_symplectic_form_and_rk4_does_not(flow, kw):
    X, P = ig.random_point(4, 2, seed=5)
    fl = ig.make_flow(flow, 4, 2, A=A4, **kw)
    gauge = None
    if flow == "magnetic":
        J = np.array([[0.0, 1.0], [-1.0, 0.0]])
        gauge = lambda X: kw["eps"] / 2 * X @ J  # noqa: E731
    defect, size = symplectic_defect(fl.symplectic, X, P, gauge)
    assert size > 0.1 and defect < 1e-7 * size

    def rk4(x, p, h):
        x, p = ig._rk4_step(fl.rhs, x, p, h)
        x0, p0 = ig.project_to_tangent_bundle(x[0], p[0])
        return x0[None], p0[None]
    assert symplectic_defect(rk4, X, P, gauge)[0] > 1e-5 * size


def test_negative_control_a_wrong_gauge_sign_is_refuted(monkeypatch):
    """The magnetic step with P̃ = P − (ε/2)XJ (the wrong sign) does not converge to the reference."""
    X, P = ig.random_point(4, 2, seed=1)
    ref = ig.integrate(X, P, "magnetic", 2.0, method="dop853", tol=1e-13, samples=3, eps=0.7, A=A4)
    good = ig.integrate(X, P, "magnetic", 2.0, method="rattle", step=0.01, samples=3, eps=0.7, A=A4)
    monkeypatch.setattr(ig, "_GAUGE_SIGN", -1.0)
    bad = ig.integrate(X, P, "magnetic", 2.0, method="rattle", step=0.01, samples=3, eps=0.7, A=A4)
    assert final_error(good, ref) < 1e-3 < final_error(bad, ref)


def test_negative_control_a_wrong_manakov_operator_is_refuted():
    """The midpoint step of a corrupted operator (B = A² + I on one entry) leaves the reference trajectory
    and the spectrum of a corrupted Lax matrix moves along the right one."""
    X, P = ig.random_point(4, 2, seed=1)
    ref = ig.integrate(X, P, "manakov", 2.0, method="dop853", tol=1e-13, samples=3, A=A4)
    wrong = np.diag(A4) ** 2
    wrong[0] += 1.0
    bad_flow = ig.make_flow("manakov", 4, 2, A=A4, B=np.diag(wrong))
    fl = ig.make_flow("manakov", 4, 2, A=A4)
    bad = ig.integrate(X, P, dataclasses.replace(fl, symplectic=bad_flow.symplectic), 2.0, method="rattle",
                       step=0.01, samples=3)
    assert final_error(bad, ref) > 1e-2
    corrupted = ig.LaxMatrix("corrupted", (), lambda X, P, lam: (P[0] @ X[0].T - X[0] @ P[0].T) + lam * A4
                             + X[0] @ X[0].T, (0.7, -1.3))
    t = ig.integrate(X, P, dataclasses.replace(fl, lax=fl.lax + (corrupted,)), 3.0, method="rattle", step=0.01,
                     samples=4)
    assert t.lax_drift["corrupted"].max() > 1e-3
    assert t.lax_drift["L_man = Φ + λA"].max() < 1e-4


def test_printed_magnetic_equations_are_not_integrated_by_rattle():
    X, P = ig.random_point(4, 2, seed=1)
    with pytest.raises(ValueError, match="printed=False"):
        ig.integrate(X, P, "magnetic", 1.0, method="rattle", eps=0.7, printed=True)


def test_every_named_flow_has_a_symplectic_scheme():
    for flow, kw in FAMILIES + [("neumann", {"kappa": 0.3}), ("jensen", {"kappa": 0.0})]:
        fl = ig.make_flow(flow, 4, 2, **({"A": A4} if flow != "jensen" else {}), **kw)
        assert fl.potential_gradient is not None or fl.symplectic is not None, fl.label
        assert ig.symplectic_scheme(fl)


def test_the_perturbed_coupled_flow_is_the_kappa_0_flow_rotated_by_the_diagonal_momentum():
    """H_κ (perturbed) = H_0 + κ·½⟨S, S⟩, S = Ψ_X + Ψ_Y: the κ-flow is the κ = 0 flow followed by exp(tκS₀)."""
    (X, Y), (P, Q) = start("coupled")
    S0 = X.T @ P - P.T @ X + Y.T @ Q - Q.T @ Y
    T, kappa = 3.0, 0.7
    a = ig.integrate((X, Y), (P, Q), "coupled", T, method="dop853", tol=1e-13, samples=2, A=A4, kappa=kappa,
                     perturbed=True)
    b = ig.integrate((X, Y), (P, Q), "coupled", T, method="dop853", tol=1e-13, samples=2, A=A4, kappa=0.0,
                     perturbed=True)
    R = ig.expm_skew(T * kappa * S0)
    assert np.abs(a.X[-1] - b.X[-1] @ R).max() < 1e-9
    assert np.abs(a.P[-1] - b.P[-1] @ R).max() < 1e-9
    assert np.abs(a.X[-1] - b.X[-1]).max() > 1e-2          # the rotation is not trivial


@pytest.mark.parametrize("kappa", [-0.5, 0.0, 0.4])
def test_the_magnetic_flow_is_the_euclidean_neumann_flow_in_shifted_momenta_then_a_rotation(kappa):
    """(mag-euk), (mag-nor) and the twisted κ-flows: with P̃ = P + (ε/2)XJ, (X, P̃)(t) is the Euclidean Neumann
    flow from (X0, P̃0) followed by exp(t f′(w̃)/2 · J), f′(w) = −ε + 4(κ + ½)(w − ε/2), w̃ = (X0ᵀP̃0)₁₂."""
    eps, T = 0.7, 3.0
    X, P = ig.random_point(4, 2, seed=2)
    J = np.array([[0.0, 1.0], [-1.0, 0.0]])
    Pt = P + eps / 2 * X @ J
    mag = ig.integrate(X, P, "magnetic", T, method="dop853", tol=1e-13, samples=2, A=A4, kappa=kappa, eps=eps)
    neu = ig.integrate(X, Pt, "neumann", T, method="dop853", tol=1e-13, samples=2, A=A4, kappa=-0.5)
    w = (X.T @ Pt)[0, 1]
    R = ig.expm_skew(T * (-eps + 4 * (kappa + 0.5) * (w - eps / 2)) / 2 * J)
    Xn, Pn = neu.final()
    Xm, Pm = mag.final()
    assert np.abs(Xm - Xn @ R).max() < 1e-9
    assert np.abs(Pm + eps / 2 * Xm @ J - Pn @ R).max() < 1e-9


@pytest.mark.parametrize("kw", [{"kappa": 0.5}, {"kappa": 0.5, "perturbed": True}], ids=["unperturbed", "perturbed"])
def test_the_coupled_step_keeps_the_symplectic_form_of_T_star_V_times_T_star_V(kw):
    (X, Y), (P, Q) = start("coupled", seed=6)
    fl = ig.make_flow("coupled", 4, 2, A=A4, **kw)
    Z, M = np.stack([X, Y]), np.stack([P, Q])
    rng = np.random.default_rng(8)
    d, h = 1e-5, 0.2

    def curve(dZ, dM, s):
        pts = [ig.project_to_tangent_bundle(Z[i] + s * dZ[i], M[i] + s * dM[i]) for i in range(2)]
        return np.stack([p[0] for p in pts]), np.stack([p[1] for p in pts])

    def omega(a, b):
        return float(np.sum(a[1] * b[0]) - np.sum(b[1] * a[0]))

    def defect(step):
        pairs = []
        for _ in range(2):
            dZ, dM = rng.standard_normal(Z.shape), rng.standard_normal(Z.shape)
            (z0, m0), (z1, m1) = curve(dZ, dM, -d), curve(dZ, dM, d)
            (w0, n0), (w1, n1) = step(z0, m0, h), step(z1, m1, h)
            pairs.append((((z1 - z0) / (2 * d), (m1 - m0) / (2 * d)), ((w1 - w0) / (2 * d), (n1 - n0) / (2 * d))))
        (u0, u1), (v0, v1) = pairs
        return abs(omega(u1, v1) - omega(u0, v0)), abs(omega(u0, v0))

    err, size = defect(fl.symplectic)
    assert size > 0.1 and err < 1e-7 * size

    def rk4(z, m, h):
        z, m = ig._rk4_step(fl.rhs, z, m, h)
        pts = [ig.project_to_tangent_bundle(z[i], m[i]) for i in range(2)]
        return np.stack([p[0] for p in pts]), np.stack([p[1] for p in pts])
    assert defect(rk4)[0] > 1e-5 * size
