"""The integrators of stiefelsym.analyses.integrate: orders, constraints, closed forms, Lax spectra, bad input,
and the ``stiefelsym flows`` command (quick mode)."""
from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from stiefelsym.analyses import integrate as ig

A4 = np.diag([0.5, 1.3, 2.1, 3.4])


def point(n=4, r=2, seed=1):
    return ig.random_point(n, r, seed=seed)


# --------------------------------------------------------------------------- flows as printed

@pytest.mark.parametrize("kappa", [-0.5, 0.0, 0.3])
def test_neumann_vector_field_is_No_as_printed(kappa):
    """The Dirac flow of H_neum,κ (neumann) is (No) on T*V."""
    X, P = point(4, 2, seed=3)
    Xd, Pd = ig.make_flow("neumann", 4, 2, kappa=kappa, A=A4).rhs(X[None], P[None])
    c = 1 + 2 * kappa
    assert np.allclose(Xd[0], P - c * X @ P.T @ X, atol=1e-14)
    assert np.allclose(Pd[0], -A4 @ X - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A4 @ X, atol=1e-13)


def test_manakov_square_is_dot_XP3_as_printed():
    X, P = point(4, 3, seed=2)
    Xd, Pd = ig.make_flow("manakov", 4, 3, A=A4).rhs(X[None], P[None])
    Phi = P @ X.T - X @ P.T
    assert np.allclose(Xd[0], A4 @ Phi @ X + Phi @ A4 @ X, atol=1e-13)
    assert np.allclose(Pd[0], A4 @ Phi @ P + Phi @ A4 @ P, atol=1e-13)


# --------------------------------------------------------------------------- orders and constraints

def test_rk4_energy_error_is_fourth_order():
    X, P = point()
    e = [ig.integrate(X, P, "neumann", 2.0, method="rk4", step=h, A=A4, samples=5).max_errors()["hamiltonian"]
         for h in (0.1, 0.05)]
    assert 10 < e[0] / e[1] < 24           # 2⁴ = 16
    assert e[1] < 1e-5


@pytest.mark.parametrize("kappa", [-0.5, 0.0])
def test_rattle_energy_error_is_second_order_and_XtX_exact(kappa):
    X, P = point()
    runs = [ig.integrate(X, P, "neumann", 2.0, method="rattle", step=h, A=A4, kappa=kappa, samples=5) for h in (0.04, 0.02)]
    e = [t.max_errors()["hamiltonian"] for t in runs]
    assert 3 < e[0] / e[1] < 5.5           # 2² = 4
    for t in runs:
        assert t.position_error.max() < 1e-14
        assert t.momentum_error.max() < 1e-14


def test_rattle4_is_fourth_order_and_on_T_star_V():
    X, P = point()
    runs = [ig.integrate(X, P, "neumann", 2.0, method="rattle4", step=h, A=A4, kappa=0.0, samples=5) for h in (0.1, 0.05)]
    e = [t.max_errors()["hamiltonian"] for t in runs]
    assert 12 < e[0] / e[1] < 20           # 2⁴ = 16
    assert max(t.position_error.max() for t in runs) < 1e-14


def test_rattle_stays_on_T_star_V_at_a_large_step_and_keeps_psi():
    X, P = point(5, 3, seed=4)
    t = ig.integrate(X, P, "neumann", 20.0, method="rattle", step=0.2, kappa=0.0, samples=11)
    errs = t.max_errors()
    assert errs["position"] < 1e-14 and errs["momentum"] < 1e-14
    assert errs["invariant: Ψ (right momentum)"] < 1e-12
    assert errs["hamiltonian"] < 0.1       # bounded, not exact


def test_rk4_projection_and_dop853_constraints():
    X, P = point()
    t = ig.integrate(X, P, "manakov", 5.0, method="rk4", step=0.05, A=A4, samples=6)
    assert max(t.position_error.max(), t.momentum_error.max()) < 1e-14
    loose, tight = (ig.integrate(X, P, "neumann", 5.0, method="dop853", tol=tol, A=A4, samples=6).max_errors()
                    for tol in (1e-6, 1e-11))
    assert tight["position"] < 1e-9 < loose["position"] or tight["position"] < loose["position"] / 100
    assert tight["hamiltonian"] < 1e-9


def test_coupled_flow_rattle_for_the_euclidean_metric():
    X, P = point(4, 2, seed=1)
    Y, Q = point(4, 2, seed=2)
    runs = [ig.integrate((X, Y), (P, Q), "coupled", 3.0, method="rattle", step=h, kappa=-0.5, A=A4, samples=4)
            for h in (0.02, 0.01)]
    e = [t.max_errors() for t in runs]
    assert 3.5 < e[0]["hamiltonian"] / e[1]["hamiltonian"] < 4.5      # order 2
    for errs in e:
        assert errs["position"] < 1e-14 and errs["momentum"] < 1e-14
        assert errs["invariant: XᵀP − PᵀX + YᵀQ − QᵀY"] < 1e-11


# --------------------------------------------------------------------------- closed forms

@pytest.mark.parametrize("kappa", [-0.5, 0.0, 0.4])
def test_closed_form_geodesics_agree_with_integration(kappa):
    X, P = point(5, 2, seed=7)
    t = ig.integrate(X, P, "jensen", 3.0, method="dop853", tol=1e-13, kappa=kappa, samples=2)
    Xc, Pc = ig.jensen_geodesic(X, P, kappa, 3.0)
    Xi, Pi = t.final()
    assert np.abs(Xi - Xc).max() < 1e-10 and np.abs(Pi - Pc).max() < 1e-10


def test_edelman_arias_smith_euclidean_and_canonical_match_kappa():
    """κ = −½ is EAS's Euclidean metric with Δ = P; κ = 0 is their canonical metric with Δ = Ẋ = P − XPᵀX."""
    X, P = point(5, 3, seed=8)
    for T in (0.5, 4.0):
        assert np.abs(ig.euclidean_geodesic(X, P, T) - ig.jensen_geodesic(X, P, -0.5, T)[0]).max() < 1e-12
        V = P - X @ P.T @ X
        assert np.abs(ig.canonical_geodesic(X, V, T) - ig.jensen_geodesic(X, P, 0.0, T)[0]).max() < 1e-12
    # the other normalization (Δ = P) is a different curve
    assert np.abs(ig.canonical_geodesic(X, P, 4.0) - ig.jensen_geodesic(X, P, 0.0, 4.0)[0]).max() > 1e-2
    assert ig.metric_beta(-0.5) == 0.0 and ig.metric_beta(0.0) == 0.5


def test_metric_beta_is_the_legendre_map():
    """tr(ẊᵀP) = tr Ẋᵀ(I − βXXᵀ)Ẋ for Ẋ = P − (1 + 2κ)XPᵀX."""
    X, P = point(5, 2, seed=9)
    for kappa in (-0.5, 0.0, 0.7):
        V = P - (1 + 2 * kappa) * X @ P.T @ X
        b = ig.metric_beta(kappa)
        assert np.isclose(np.trace(V.T @ P), np.trace(V.T @ (np.eye(5) - b * X @ X.T) @ V))


# --------------------------------------------------------------------------- Lax spectra

@pytest.mark.parametrize("flow,kw", [("neumann", {"kappa": 0.0, "A": A4}), ("neumann", {"kappa": -0.5, "A": A4}),
                                     ("manakov", {"A": A4}), ("magnetic", {"kappa": 0.0, "eps": 0.7, "A": A4}),
                                     ("jensen", {"kappa": 0.3})])
def test_lax_spectra_stay_fixed_for_correct_pairs(flow, kw):
    X, P = point()
    t = ig.integrate(X, P, flow, 3.0, method="dop853", tol=1e-12, samples=7, **kw)
    assert t.lax_drift
    for name, d in t.lax_drift.items():
        assert d.max() < 1e-8, name


def test_lax_spectrum_of_a_corrupted_matrix_drifts():
    """Negative control: λΦ + 2XXᵀ − λ²A is not a Lax matrix of (No); every method sees its spectrum move."""
    X, P = point()
    fl = ig.make_flow("neumann", 4, 2, kappa=0.0, A=A4)
    bad = ig.LaxMatrix("corrupted", (), lambda X, P, lam: lam * (P[0] @ X[0].T - X[0] @ P[0].T)
                       + 2 * X[0] @ X[0].T - lam ** 2 * A4, (0.7, -1.3))
    fl = dataclasses.replace(fl, lax=fl.lax + (bad,))
    for method, how in (("dop853", {"tol": 1e-10}), ("rk4", {"step": 0.02}), ("rattle", {"step": 0.01})):
        t = ig.integrate(X, P, fl, 3.0, method=method, samples=7, **how)
        assert t.lax_drift["corrupted"].max() > 1e-3, method
        assert t.lax_drift["L_neum (LA2)"].max() < 1e-4, method


def test_coupled_so_nn_lax_as_printed_drifts_and_the_sign_correction_does_not():
    X, P = point(4, 2, seed=1)
    Y, Q = point(4, 2, seed=2)
    t = ig.integrate((X, Y), (P, Q), "coupled", 2.0, method="dop853", tol=1e-12, kappa=0.0, A=A4, samples=5)
    drift = {k: v.max() for k, v in t.lax_drift.items()}
    assert drift["L(ν) in so(n,n) (so(n,n))"] > 1e-2
    assert drift["L(ν) in so(n,n) with −ν⁻¹ (correction)"] < 1e-8
    assert drift["4r x 4r L(λ) (LA3*C)"] < 1e-8
    t = ig.integrate((X, Y), (P, Q), "coupled", 2.0, method="dop853", tol=1e-12, kappa=-0.5, A=A4, samples=5)
    assert t.lax_drift["4r x 4r L(λ) (LA3*C)"].max() > 1e-2      # not for the Euclidean metric, as the paper says


def test_spectral_drift_is_zero_under_conjugation():
    rng = np.random.default_rng(0)
    L = rng.standard_normal((6, 6))
    S = rng.standard_normal((6, 6)) + 3 * np.eye(6)
    assert ig.spectral_drift(L, np.linalg.solve(S, L @ S)) < 1e-10
    assert ig.spectral_drift(L, L + 0.1 * np.eye(6)) > 1e-3


# --------------------------------------------------------------------------- user flows and bad input

def test_custom_flow_with_invariants():
    X, P = point(3, 1, seed=5)
    H = lambda X, P: 0.5 * float(np.sum(P * P))            # noqa: E731  the geodesic flow of the sphere

    def rhs(X, P):
        return P, -X * float(np.sum(P * P))

    t = ig.integrate(X, P, rhs, 5.0, method="rk4", step=0.01, hamiltonian=H,
                     invariants={"angular momentum": lambda X, P: X @ P.T - P @ X.T}, samples=5)
    errs = t.max_errors()
    assert errs["hamiltonian"] < 1e-9 and errs["invariant: angular momentum"] < 1e-9


@pytest.mark.parametrize("call,message", [
    (lambda X, P: ig.integrate(X[:, :1], P, "neumann", 1.0), "n x r"),
    (lambda X, P: ig.integrate(X.T, P.T, "neumann", 1.0), "r <= n"),
    (lambda X, P: ig.integrate(X, P, "neumann", 1.0, tol=-1e-8), "tolerance"),
    (lambda X, P: ig.integrate(X, P, "neumann", 1.0, method="euler"), "unknown method"),
    (lambda X, P: ig.integrate(X, P, "kepler", 1.0), "unknown flow"),
    (lambda X, P: ig.integrate(X, P, "manakov", 1.0, A=[1.0, 2.0, 2.0, 3.0]), "distinct"),
    (lambda X, P: ig.integrate(X, P, "magnetic", 1.0, method="rattle", eps=0.7, printed=True), "RATTLE covers"),
    (lambda X, P: ig.integrate(X, P, lambda X, P: (0 * X, 0 * P), 1.0, method="rattle"), "RATTLE covers"),
    (lambda X, P: ig.integrate(X, P, "neumann", 1.0, kappa=-1.0), "kappa"),
    (lambda X, P: ig.integrate(X, P, "neumann", (1.0, 0.0)), "t0 < t1"),
    (lambda X, P: ig.integrate(X, P, "neumann", 1.0, A=np.ones((3, 3))), "A must be"),
    (lambda X, P: ig.integrate(X, P, "magnetic", 1.0, kappa=0.3, printed=True), "printed for kappa"),
    (lambda X, P: ig.integrate(2 * X, P, "neumann", 1.0), "not on T*V"),
    (lambda X, P: ig.integrate(X, P + X, "neumann", 1.0), "not on T*V"),
    (lambda X, P: ig.integrate(X, P, "neumann", 1.0, step=0.0, method="rk4"), "step"),
    (lambda X, P: ig.integrate(X, P, "neumann", 1.0, eps=0.5), "takes the parameters"),
    (lambda X, P: ig.integrate(X, P, lambda X, P: (P, -X), 1.0, kappa=0.5), "user flow"),
])
def test_bad_input_is_a_clear_value_error(call, message):
    X, P = point()
    with pytest.raises(ValueError, match=message.replace("*", r"\*")):
        call(X, P)


def test_off_shell_point_is_projected_on_request():
    X, P = point()
    t = ig.integrate(1.01 * X, P + 0.1 * X, "neumann", 0.5, method="dop853", project=True, samples=3)
    assert t.position_error[0] < 1e-14 and t.momentum_error[0] < 1e-14


@pytest.mark.parametrize("kappa", [-0.5, 0.0])
def test_magnetic_flows_as_printed_are_the_twisted_dirac_flows(kappa):
    """(mag-euk), (mag-nor) as printed agree on T*V with the Dirac flow of H_neum,κ plus the Lorentz force."""
    X, P = point(5, 2, seed=4)
    A = np.diag([0.5, 1.3, 2.1, 3.4, 4.6])
    a = ig.make_flow("magnetic", 5, 2, kappa=kappa, eps=0.7, A=A).rhs(X[None], P[None])
    b = ig.make_flow("magnetic", 5, 2, kappa=kappa, eps=0.7, A=A, printed=True).rhs(X[None], P[None])
    assert np.abs(a[0] - b[0]).max() < 1e-13 and np.abs(a[1] - b[1]).max() < 1e-13


def test_magnetic_flow_needs_r_2():
    X, P = point(4, 3)
    with pytest.raises(ValueError, match="V\\(n, 2\\)"):
        ig.integrate(X, P, "magnetic", 1.0, eps=0.5)


# --------------------------------------------------------------------------- the command

@pytest.mark.slow   # the whole flows command (12 s): run by `make verify-all`
def test_flows_command_writes_its_files(run, tmp_path):
    pytest.importorskip("matplotlib")
    res = run("flows", "--quick", "--report-dir", "out")
    assert res.exit_code == 0, res.output
    out = tmp_path / "out"
    for name in ("flows.md", "flows.json", "spectra.csv", "work_precision.csv", "long_time.csv", "closed_forms.csv",
                 "wp_1.png", "wp_1.pdf", "long_time.png", "long_time.pdf"):
        assert (out / name).is_file() and (out / name).stat().st_size > 0, name
    data = json.loads((out / "flows.json").read_text())
    assert data["meta"]["quick"] is True and data["spectra"] and data["closed_forms"]
    md = (out / "flows.md").read_text()
    assert "Edelman" in md and "β = (1+2κ)/(2+2κ)" in md and "![wp_1](wp_1.png)" in md


def test_flows_command_refuses_an_unwritable_report_dir(run, tmp_path):
    (tmp_path / "f").write_text("")
    res = run("flows", "--quick", "--report-dir", "f/sub")
    assert res.exit_code == 2
    assert "cannot write" in res.output


def test_custom_potential_flow_gets_the_dirac_field_and_rattle():
    """A user's H = ½tr PᵀP + V(X): the Dirac flow is derived; with V the Neumann potential it is (NE_XP),
    and RATTLE applies; a user Lax matrix is followed."""
    X, P = point()
    grad = lambda X: A4 @ X                                  # noqa: E731
    V = lambda X: 0.5 * float(np.trace(X.T @ A4 @ X))        # noqa: E731
    L = lambda X, P, lam: lam * (P @ X.T - X @ P.T) + X @ X.T - lam ** 2 * A4   # noqa: E731
    fl = ig.custom_flow(n=4, r=2, potential=V, potential_gradient=grad, lax={"LA2": L})
    ref = ig.make_flow("neumann", 4, 2, kappa=-0.5, A=A4)
    assert np.allclose(fl.rhs(X[None], P[None])[1], ref.rhs(X[None], P[None])[1], atol=1e-13)
    t = ig.integrate(X, P, fl, 2.0, method="rattle", step=0.01, samples=5)
    errs = t.max_errors()
    assert errs["position"] < 1e-14 and errs["hamiltonian"] < 1e-3 and errs["lax: LA2"] < 1e-3
    assert t.lax_eigenvalue_drift["LA2"].max() < 1e-2


def test_default_tolerance_and_step():
    X, P = point()
    t = ig.integrate(X, P, "neumann", 1.0, samples=3)
    assert t.method == "dop853" and t.tol == 1e-10 and t.max_errors()["hamiltonian"] < 1e-9
    t = ig.integrate(X, P, "neumann", 1.0, method="rattle", samples=3)
    assert t.step == pytest.approx(0.01)
    t = ig.integrate(X, P, "neumann", 1.0, method="rk4", tol=1e-8, samples=3)
    assert t.step == pytest.approx(0.01)


def test_dual_lax_pair_extends_to_every_kappa():
    """(LA3) with 𝓐*_κ = [[(1+2κ)XᵀP, I], [Λ − λI, −(1+2κ)PᵀX]] along (No) for every κ; the normal-metric 𝓐*
    of (LA4) fails off κ = 0 (negative control)."""
    from stiefelsym.reports.flows_report import collect_dual_every_kappa
    for row in collect_dual_every_kappa(True, lambda s: None):
        assert row["residual_A_kappa"] < 1e-12
        if row["kappa"] != 0.0:
            assert row["residual_A_normal"] > 1e-2


def test_every_lax_matrix_of_the_report_names_claims_of_the_catalog(catalog):
    """The spectra table looks the algebraic verdicts up by claim id: every id must exist, with a paper
    label in common with the Lax matrix or its flow."""
    from stiefelsym.reports.flows_report import _params, catalog_claims, spectra_cases
    ids = {c.id for c in catalog}
    for quick in (False,):
        for case in spectra_cases(quick):
            fl = ig.make_flow(case["flow"], case["n"], case["r"], **_params(case["flow"], case["n"], case["params"]))
            for lx in fl.lax:
                row = {"flow_name": case["flow"], "params": case["params"], "lax": lx.name}
                wanted = catalog_claims(row)
                assert wanted, (fl.label, lx.name)
                for cid in wanted:
                    assert cid in ids, cid
                    labels = set(catalog.get(cid).paper)
                    assert labels & (set(lx.paper) | set(fl.paper) | {"LA2", "LA3"}), (cid, lx.paper)


def test_algebraic_verdicts_are_read_from_results_json(tmp_path):
    from stiefelsym.reports.flows_report import algebraic_verdicts
    doc = {"results": [
        {"claim": "neumann-lax", "paper": ["Neumann_LA", "LA1", "LA2"], "kind": "lax", "method": "free", "verdict": "proved"},
        {"claim": "neumann-lax", "paper": ["Neumann_LA", "LA1", "LA2"], "kind": "lax", "method": "exact", "verdict": "proved"},
        {"claim": "manakov-dual-lax", "paper": ["MAN-LA2"], "kind": "lax", "method": "modular", "verdict": "fails"},
        {"claim": "manakov-dual-lax", "paper": ["MAN-LA2"], "kind": "lax", "method": "modular", "verdict": "checked",
         "variant": "(LA-MAN3): ..."}]}
    path = tmp_path / "results.json"
    path.write_text(json.dumps(doc))
    v = {x["claim"]: x for x in algebraic_verdicts(path, claims=("neumann-lax", "manakov-dual-lax"))}
    assert v["neumann-lax"]["free"] == "proved" and v["neumann-lax"]["printed"] == {"proved": 1}
    assert v["manakov-dual-lax"]["printed"] == {"fails": 1} and v["manakov-dual-lax"]["corrections"] == {"checked": 1}
    assert algebraic_verdicts(tmp_path / "missing.json", claims=("neumann-lax",)) == []
