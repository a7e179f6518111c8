"""The integrated-flows report: Lax spectra along trajectories, work-precision diagrams, long-time
behaviour and the Edelman–Arias–Smith closed forms, written to ``reports/flows/``.

Collect first, render separately: :func:`collect` integrates and returns plain data (JSON-ready);
:func:`write_report` writes the data (``flows.json`` and CSV files), the figures (PNG for Markdown,
PDF for LaTeX) and ``flows.md``.
"""
from __future__ import annotations

import csv
import io
import json
import math
import os
import platform
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence

import numpy as np

from stiefelsym.analyses import integrate as ig
from stiefelsym.results import write_atomic

__all__ = ["collect", "write_report", "algebraic_verdicts", "SPECTRUM_FIXED"]

#: a Lax spectrum whose drift stays below this (relative) along a DOP853 run at tol 1e-12 is "fixed"
SPECTRUM_FIXED = 1e-7
A_DEFAULT = (0.5, 1.3, 2.1, 3.4, 4.6)


def _A(n: int) -> np.ndarray:
    return np.diag(np.asarray(A_DEFAULT[:n], float))


def _start(flow: str, n: int, r: int, seed: int) -> tuple[Any, Any]:
    if flow == "coupled":
        X, P = ig.random_point(n, r, seed=seed)
        Y, Q = ig.random_point(n, r, seed=seed + 100)
        return (X, Y), (P, Q)
    return ig.random_point(n, r, seed=seed)


def _params(flow: str, n: int, kw: dict[str, Any]) -> dict[str, Any]:
    out = dict(kw)
    if flow in ("neumann", "manakov", "magnetic", "coupled"):
        out.setdefault("A", _A(n))
    return out


# --------------------------------------------------------------------------- the cases

def spectra_cases(quick: bool) -> list[dict[str, Any]]:
    """The flows whose Lax spectra are followed: (flow, n, r, parameters, method, tolerance/step, T)."""
    n = 3 if quick else 4
    T = 1.0 if quick else 20.0
    ref = {"method": "dop853", "tol": 1e-12}
    sym = {"method": "rattle4", "step": 0.005, "T": 10.0}
    cases = [
        ("neumann", {"kappa": -0.5}, ref), ("neumann", {"kappa": 0.0}, ref), ("neumann", {"kappa": 0.5}, ref),
        ("jensen", {"kappa": -0.5}, ref), ("jensen", {"kappa": 0.0}, ref),
        ("manakov", {}, ref), ("manakov", {"B": np.diag([0.1, 0.9, 1.2, 2.8, 3.0][:n])}, ref),
        ("magnetic", {"kappa": -0.5, "eps": 0.7}, ref),
        ("magnetic", {"kappa": 0.0, "eps": 0.7}, ref),
        ("magnetic", {"kappa": 0.4, "eps": 0.7}, ref),
        ("magnetic", {"kappa": -0.5, "eps": 0.7, "printed": True}, ref),
        ("magnetic", {"kappa": -0.5, "eps": 0.7, "printed": True}, {"method": "rk4", "step": 0.01}),
        ("coupled", {"kappa": 0.0}, ref), ("coupled", {"kappa": -0.5}, ref),
        ("coupled", {"kappa": -0.5, "perturbed": True}, ref), ("coupled", {"kappa": 0.5, "perturbed": True}, ref),
        # the same spectra along the symplectic, constraint-preserving trajectories
        ("manakov", {}, sym), ("manakov", {"B": np.diag([0.1, 0.9, 1.2, 2.8, 3.0][:n])}, sym),
        ("magnetic", {"kappa": 0.0, "eps": 0.7}, sym), ("coupled", {"kappa": 0.0}, sym),
        ("coupled", {"kappa": 0.5, "perturbed": True}, sym),
    ]
    if quick:
        cases = [cases[i] for i in (1, 5, 8, 12, 16)]
    out = []
    for flow, kw, how in cases:
        r = 2
        out.append({"flow": flow, "n": n, "r": r, "params": kw, "T": min(T, how.get("T", T)),
                    **{k: v for k, v in how.items() if k != "T"}})
    return out


def _run(case: dict[str, Any], seed: int = 1, samples: int = 101) -> ig.Trajectory:
    X0, P0 = _start(case["flow"], case["n"], case["r"], seed)
    kw = _params(case["flow"], case["n"], case["params"])
    return ig.integrate(X0, P0, case["flow"], case["T"], method=case["method"], tol=case.get("tol", 1e-8),
                        step=case.get("step"), samples=samples, **kw)


def _jsonable_params(kw: dict[str, Any]) -> dict[str, Any]:
    out = {}
    for k, v in kw.items():
        if isinstance(v, np.ndarray):
            out[k] = np.diag(v).tolist() if v.ndim == 2 else v.tolist()
        else:
            out[k] = v
    return out


def collect_spectra(quick: bool, log: Callable[[str], None]) -> list[dict[str, Any]]:
    rows = []
    for case in spectra_cases(quick):
        tr = _run(case)
        fl = ig.make_flow(case["flow"], case["n"], case["r"], **_params(case["flow"], case["n"], case["params"]))
        errs = tr.max_errors()
        for lx in fl.lax:
            drift = float(tr.lax_drift[lx.name].max())
            eig_drift = float(tr.lax_eigenvalue_drift[lx.name].max())
            rows.append({
                "flow": fl.label, "flow_name": case["flow"], "paper_flow": list(fl.paper), "n": case["n"], "r": case["r"],
                "params": _jsonable_params(case["params"]), "method": case["method"],
                "tol": case.get("tol"), "step": tr.step, "T": case["T"], "lax": lx.name, "paper": list(lx.paper),
                "printed": lx.printed, "note": lx.note, "lambdas": list(lx.lambdas), "drift": drift,
                "eigenvalue_drift": eig_drift,
                "constraint_error": max(errs["position"], errs["momentum"]),
                "hamiltonian_error": errs.get("hamiltonian"), "seconds": tr.seconds,
                "invariants": {k[len("invariant: "):]: v for k, v in errs.items() if k.startswith("invariant: ")},
            })
        log(f"spectra: {fl.label} {case['method']} ({tr.seconds:.1f}s)")
    return rows


def wp_cases(quick: bool) -> list[dict[str, Any]]:
    """Every flow family with each method: DOP853 at five tolerances, RATTLE (the symplectic step of the
    family), RATTLE4 and RK4 + projection at four or five steps, on V(4, 2) up to T = 50."""
    n, r = (3, 2) if quick else (4, 2)
    T = 2.0 if quick else 50.0
    tols = (1e-6, 1e-9) if quick else (1e-5, 1e-7, 1e-9, 1e-11, 1e-13)
    rk4 = (0.1, 0.05) if quick else (0.2, 0.1, 0.05, 0.025, 0.0125)
    full = {"rattle": (0.1, 0.03) if quick else (0.1, 0.05, 0.02, 0.01, 0.005),
            "rattle4": (0.1,) if quick else (0.2, 0.1, 0.05, 0.025, 0.0125)}
    # the implicit (Manakov) and two-point (coupled) steps cost more: one setting fewer
    costly = {"rattle": (0.1, 0.03) if quick else (0.1, 0.05, 0.025, 0.0125),
              "rattle4": (0.1,) if quick else (0.2, 0.1, 0.05, 0.025)}
    B = np.diag([0.1, 0.9, 1.2, 2.8, 3.0][:n])
    cases = [("neumann", {"kappa": -0.5}, full), ("neumann", {"kappa": 0.0}, full), ("jensen", {"kappa": 0.0}, full),
             ("manakov", {}, costly), ("manakov", {"B": B}, costly), ("magnetic", {"kappa": 0.0, "eps": 0.7}, full),
             ("coupled", {"kappa": 0.0}, costly)]
    if quick:
        cases = [cases[0], cases[3]]
    out = []
    for flow, kw, sym in cases:
        runs = [("dop853", {"tol": t}) for t in tols] + [("rk4", {"step": h}) for h in rk4]
        runs += [("rattle", {"step": h}) for h in sym["rattle"]] + [("rattle4", {"step": h}) for h in sym["rattle4"]]
        out.append({"flow": flow, "n": n, "r": r, "params": kw, "T": T, "runs": runs})
    return out


def _lax_error(tr: ig.Trajectory) -> float:
    """The drift of the printed Lax matrices that hold along the flow (not the so(n, n) matrix, which
    fails as printed, nor its correction)."""
    names = [k for k in tr.lax_drift if "correction" not in k and "so(n,n)" not in k]
    return max((float(tr.lax_drift[k].max()) for k in names), default=float("nan"))


def collect_wp(quick: bool, log: Callable[[str], None]) -> list[dict[str, Any]]:
    rows = []
    for case in wp_cases(quick):
        fl = ig.make_flow(case["flow"], case["n"], case["r"], **_params(case["flow"], case["n"], case["params"]))
        for method, how in case["runs"]:
            c = {**case, "method": method, **how}
            base = {"flow": fl.label, "flow_name": case["flow"], "n": case["n"], "r": case["r"], "T": case["T"],
                    "method": method, "tol": how.get("tol"), "step": how.get("step"),
                    "scheme": ig.symplectic_scheme(fl) if method in ("rattle", "rattle4") else ""}
            try:
                tr = _run(c)
            except RuntimeError as exc:            # a step too large for the implicit/SHAKE iteration
                rows.append({**base, "failed": str(exc), "seconds": float("nan"), "evaluations": 0,
                             "constraint_error": float("nan"), "hamiltonian_error": float("nan"),
                             "lax_error": float("nan")})
                continue
            e = tr.max_errors()
            rows.append({**base, "step": tr.step, "seconds": tr.seconds, "evaluations": tr.evaluations,
                         "constraint_error": max(e["position"], e["momentum"]),
                         "hamiltonian_error": e.get("hamiltonian", float("nan")), "lax_error": _lax_error(tr)})
        log(f"work-precision: {fl.label} ({len(case['runs'])} runs)")
    return rows


def long_cases(quick: bool) -> list[dict[str, Any]]:
    """One long run per family on V(3, 2): every method to t = 1e4 for the Euclidean Neumann flow; for the
    other families the fixed-step methods to t = 1e4 (the coupled flow: RATTLE only) and the costlier
    ones to t = 1e3."""
    T = 20.0 if quick else 1e4
    short = 20.0 if quick else 1e3
    dop = ("dop853", {"tol": 1e-8})
    plan = [("neumann", {"kappa": -0.5}, [(dop, T), (("rattle", {"step": 0.2}), T), (("rk4", {"step": 0.2}), T)]),
            ("jensen", {"kappa": 0.0}, [(dop, short), (("rattle", {"step": 0.25}), T), (("rk4", {"step": 0.25}), T)]),
            ("manakov", {}, [(dop, short), (("rattle", {"step": 0.2}), T), (("rk4", {"step": 0.1}), T)]),
            ("magnetic", {"kappa": 0.0, "eps": 0.7},
             [(dop, short), (("rattle", {"step": 0.2}), T), (("rk4", {"step": 0.2}), T)]),
            ("coupled", {"kappa": 0.0},
             [(dop, short), (("rattle", {"step": 0.125}), T), (("rk4", {"step": 0.125}), short)])]
    if quick:
        plan = [plan[0], plan[2]]
    return [{"flow": f, "n": 3, "r": 2, "params": kw, "runs": runs} for f, kw, runs in plan]


def collect_long(quick: bool, log: Callable[[str], None]) -> list[dict[str, Any]]:
    """The long runs, one per family (see :func:`long_cases`)."""
    out = []
    for case in long_cases(quick):
        fl = ig.make_flow(case["flow"], 3, 2, **_params(case["flow"], 3, case["params"]))
        fam: dict[str, Any] = {"flow": fl.label, "flow_name": case["flow"], "n": 3, "r": 2,
                               "params": _jsonable_params(case["params"]), "T": max(T for _, T in case["runs"]),
                               "runs": []}
        for (method, how), T in case["runs"]:
            c = {"flow": case["flow"], "n": 3, "r": 2, "params": case["params"], "T": T, "method": method, **how}
            tr = _run(c, samples=201)
            e = tr.max_errors()
            names = [k for k in tr.lax_drift if "correction" not in k and "so(n,n)" not in k]
            lax = np.max([tr.lax_drift[k] for k in names], axis=0) if names else np.zeros(len(tr.times))
            fam["runs"].append({
                "method": method, "tol": how.get("tol"), "step": tr.step, "T": T, "seconds": tr.seconds,
                "evaluations": tr.evaluations, "times": tr.times.tolist(),
                "scheme": ig.symplectic_scheme(fl) if method in ("rattle", "rattle4") else "",
                "constraint_error": np.maximum(tr.position_error, tr.momentum_error).tolist(),
                "hamiltonian_error": tr.hamiltonian_error.tolist(), "lax_error": lax.tolist(),
                "max": {"constraint": max(e["position"], e["momentum"]), "hamiltonian": e["hamiltonian"],
                        "lax": float(lax.max())}})
            log(f"long run: {fl.label} {method} to t = {T:g} ({tr.seconds:.1f}s)")
        out.append(fam)
    return out


def collect_closed_forms(quick: bool, log: Callable[[str], None]) -> list[dict[str, Any]]:
    """Integrated Jensen geodesics against the closed forms (EAS Euclidean / canonical, and the rotated
    Euclidean geodesic for any κ)."""
    rows = []
    plan = ({(4, 2): (1.0,)} if quick else {(5, 2): (1.0, 10.0, 100.0), (4, 3): (1.0, 10.0), (3, 3): (1.0, 10.0)})
    kappas = (-0.5, 0.0) if quick else (-0.5, 0.0, 0.5)
    for (n, r), times in plan.items():
        X, P = ig.random_point(n, r, seed=7)
        for kappa in kappas:
            for T in times:
                Xc, Pc = ig.jensen_geodesic(X, P, kappa, T)
                tr = ig.integrate(X, P, "jensen", T, method="dop853", tol=1e-13, samples=2, kappa=kappa)
                Xi, Pi = tr.final()
                row = {"n": n, "r": r, "kappa": kappa, "beta": ig.metric_beta(kappa), "T": T,
                       "dop853_vs_closed_X": float(np.abs(Xi - Xc).max()),
                       "dop853_vs_closed_P": float(np.abs(Pi - Pc).max())}
                if T <= 10:
                    tr2 = ig.integrate(X, P, "jensen", T, method="rattle", step=0.01, samples=2, kappa=kappa)
                    row["rattle_h0.01_vs_closed_X"] = float(np.abs(tr2.final()[0] - Xc).max())
                if kappa == -0.5:
                    row["eas"] = "Euclidean"
                    row["eas_vs_closed_X"] = float(np.abs(ig.euclidean_geodesic(X, P, T) - Xc).max())
                    row["eas_vs_dop853_X"] = float(np.abs(ig.euclidean_geodesic(X, P, T) - Xi).max())
                elif kappa == 0.0:
                    V = P - X @ P.T @ X                      # (dot_X3): the velocity of the normal metric
                    row["eas"] = "canonical"
                    row["eas_vs_closed_X"] = float(np.abs(ig.canonical_geodesic(X, V, T) - Xc).max())
                    row["eas_vs_dop853_X"] = float(np.abs(ig.canonical_geodesic(X, V, T) - Xi).max())
                    row["eas_with_velocity_P_vs_dop853_X"] = float(np.abs(ig.canonical_geodesic(X, P, T) - Xi).max())
                rows.append(row)
        log(f"closed forms: V({n},{r})")
    return rows


def collect_printed_vs_derived(quick: bool, log: Callable[[str], None]) -> list[dict[str, Any]]:
    """The printed equations against the vector fields derived from the Hamiltonians (Dirac flows,
    with the Lorentz force for the twisted form), at seeded random points of T*V."""
    rows = []
    sizes = [(4, 2)] if quick else [(3, 2), (5, 2), (6, 2)]
    for n, r in sizes:
        A = _A(n) if n <= len(A_DEFAULT) else np.diag(np.linspace(0.5, 4.6, n))
        for label, kappa in (("No", 0.3), ("N0_XP2", 0.0), ("NE_XP", -0.5)):
            c = 1 + 2 * kappa
            fl = ig.make_flow("neumann", n, r, kappa=kappa, A=A)
            worst = 0.0
            for seed in range(5):
                X, P = ig.random_point(n, r, seed=seed)
                Xd, Pd = fl.rhs(X[None], P[None])
                Xp = P - c * X @ P.T @ X
                Pp = -A @ X - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A @ X
                worst = max(worst, float(np.abs(Xd[0] - Xp).max()), float(np.abs(Pd[0] - Pp).max()))
            rows.append({"equations": f"({label}), κ = {kappa:g}", "n": n, "r": r, "max_difference": worst})
        for label, kappa in (("mag-euk", -0.5), ("mag-nor", 0.0)):
            d = ig.make_flow("magnetic", n, 2, kappa=kappa, eps=0.7, A=A)
            p = ig.make_flow("magnetic", n, 2, kappa=kappa, eps=0.7, A=A, printed=True)
            worst = 0.0
            for seed in range(5):
                X, P = ig.random_point(n, 2, seed=seed)
                a, b = d.rhs(X[None], P[None]), p.rhs(X[None], P[None])
                worst = max(worst, float(np.abs(a[0] - b[0]).max()), float(np.abs(a[1] - b[1]).max()))
            rows.append({"equations": f"({label}), ε = 0.7", "n": n, "r": 2, "max_difference": worst})
    log("printed equations against the derived vector fields")
    return rows


def collect_dual_every_kappa(quick: bool, log: Callable[[str], None]) -> list[dict[str, Any]]:
    """d𝓛*/dt − [𝓛*, 𝓐*_κ] along the Neumann flow (No) at seeded random points, with
    𝓐*_κ = [[(1+2κ)XᵀP, I], [Λ − λI, −(1+2κ)PᵀX]], Λ = XᵀAX − PᵀP: (LA4) for κ = 0 and κ = −½, and its
    extension to every κ (the κ-flow is the Euclidean one followed by the rotation exp(t(κ+½)Ψ))."""
    rows = []
    sizes = [(4, 2)] if quick else [(4, 2), (5, 3), (5, 5)]
    for n, r in sizes:
        A = _A(n)
        for kappa in (-0.5, 0.0, 0.3, 1.0, -0.8):
            fl = ig.make_flow("neumann", n, r, kappa=kappa, A=A)
            worst, worst_normal = 0.0, 0.0
            for seed in range(5):
                X, P = ig.random_point(n, r, seed=seed)
                Xd, Pd = (v[0] for v in fl.rhs(X[None], P[None]))
                for lam in (0.77, -1.9):
                    R = np.linalg.inv(lam * np.eye(n) - A)
                    L = np.block([[-X.T @ R @ P, -X.T @ R @ X], [np.eye(r) + P.T @ R @ P, P.T @ R @ X]])
                    dL = np.block([[-(Xd.T @ R @ P + X.T @ R @ Pd), -(Xd.T @ R @ X + X.T @ R @ Xd)],
                                   [Pd.T @ R @ P + P.T @ R @ Pd, Pd.T @ R @ X + P.T @ R @ Xd]])
                    Lam = X.T @ A @ X - P.T @ P
                    for c, key in ((1 + 2 * kappa, "k"), (1.0, "normal")):
                        M = np.block([[c * X.T @ P, np.eye(r)], [Lam - lam * np.eye(r), -c * P.T @ X]])
                        res = float(np.abs(dL - (L @ M - M @ L)).max() / max(1.0, np.abs(dL).max()))
                        if key == "k":
                            worst = max(worst, res)
                        else:
                            worst_normal = max(worst_normal, res)
            rows.append({"n": n, "r": r, "kappa": kappa, "residual_A_kappa": worst, "residual_A_normal": worst_normal})
    log("the dual Lax pair for every κ")
    return rows


def collect(quick: bool = False, log: Callable[[str], None] = lambda s: None) -> dict[str, Any]:
    """Every integration of the report, as plain data."""
    started = time.perf_counter()
    data = {
        "schema": 1,
        "meta": {"quick": quick, "created": datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
                 "python": platform.python_version(), "numpy": np.__version__, "machine": platform.machine(),
                 "A": list(A_DEFAULT), "spectrum_fixed_threshold": SPECTRUM_FIXED,
                 "load_average_at_start": list(os.getloadavg()) if hasattr(os, "getloadavg") else None},
        "printed_vs_derived": collect_printed_vs_derived(quick, log),
        "spectra": collect_spectra(quick, log),
        "dual_every_kappa": collect_dual_every_kappa(quick, log),
        "work_precision": collect_wp(quick, log),
        "long_runs": collect_long(quick, log),
        "closed_forms": collect_closed_forms(quick, log),
    }
    data["meta"]["seconds"] = time.perf_counter() - started
    data["meta"]["cpu_seconds"] = time.process_time()
    return data


# --------------------------------------------------------------------------- algebraic verdicts

def _shown(path: Path) -> str:
    """A results file as the report names it: as given when relative (reports/results.json), by its name
    when absolute (no machine's folders in a report)."""
    path = Path(path)
    return path.name if path.is_absolute() else path.as_posix()


def algebraic_verdicts(results_path: Path, labels: Sequence[str] = (), claims: Sequence[str] = (),
                       kinds: Sequence[str] = ("lax", "not")) -> list[dict[str, Any]]:
    """The catalog's verdicts, from a ``results.json``, on the named claims, or else on the claims stated
    for any of the paper labels (``\\label``) with one of ``kinds``: one summary per claim (the printed
    statement, its corrections, the dimension-free verdict)."""
    try:
        doc = json.loads(Path(results_path).read_text())
    except (OSError, ValueError):
        return []
    summary: dict[str, dict[str, Any]] = {}
    for r in doc.get("results", []):
        paper = r.get("paper") or []
        if isinstance(paper, str):
            paper = [paper]
        if claims:
            if r.get("claim") not in claims:
                continue
        elif not set(paper) & set(labels) or r.get("kind") not in kinds:
            continue
        s = summary.setdefault(r["claim"], {"claim": r["claim"], "paper": list(paper), "printed": {}, "corrections": {},
                                            "free": None, "kind": r.get("kind"), "erratum": bool(r.get("erratum"))})
        if r.get("method") == "free" and not r.get("variant"):
            s["free"] = r.get("verdict")
            continue
        bucket = s["corrections"] if r.get("variant") else s["printed"]
        bucket[r.get("verdict")] = bucket.get(r.get("verdict"), 0) + 1
    order = {c: i for i, c in enumerate(claims)}
    return sorted(summary.values(), key=lambda v: order.get(v["claim"], len(order)))


def catalog_claims(row: dict[str, Any]) -> tuple[str, ...]:
    """The catalog's claims about the Lax matrix of a row of the spectra table."""
    flow, kw, lax = row["flow_name"], row["params"], row["lax"]
    kappa, perturbed = kw.get("kappa"), kw.get("perturbed", False)
    if flow in ("neumann", "jensen"):
        if "LA3" in lax:
            return {0.0: ("neumann-dual-lax-normal",), -0.5: ("neumann-dual-lax-euclidean",)}.get(
                kappa, ("neumann-dual-lax-normal", "neumann-dual-lax-euclidean"))
        return ("neumann-lax",)
    if flow == "manakov":
        if "MAN-LA2" in lax:
            return ("manakov-dual-lax",)
        return ("manakov-square-lax", "manakov-lax") if "B" not in kw else ("manakov-lax",)
    if flow == "magnetic":
        return ("magnetic-lax",)
    if flow == "coupled":
        if "so(n,n)" in lax:
            if perturbed:
                return ("coupled-perturbed-big-lax",)
            if kappa == 0.0:
                return ("coupled-big-lax-normal",)
            return ("coupled-big-lax-not-euclidean", "coupled-big-lax-normal")
        return ("coupled-perturbed-dual-lax",) if perturbed else ("coupled-dual-lax",)
    return ()


def _verdict_text(v: dict[str, Any]) -> str:
    def counts(d: dict[str, int]) -> str:
        return ", ".join(f"{k} {c}" for k, c in sorted(d.items()))
    parts = []
    if v["free"] == "proved":
        parts.append("proved for all n, r")
    if v["printed"]:
        parts.append(f"as printed: {counts(v['printed'])} sizes")
    if v["corrections"]:
        parts.append(f"corrected: {counts(v['corrections'])}")
    if v.get("kind") == "not":
        parts.append("(a statement that does *not* hold)")
    return f"`{v['claim']}`: " + "; ".join(parts)


# --------------------------------------------------------------------------- rendering

def _digits(x: float) -> str:
    if x is None or not math.isfinite(x):
        return "–"
    if x <= 0:
        return "1e-16"
    return f"1e{math.ceil(math.log10(x)):d}"


def _e(x: Any) -> str:
    return "–" if x is None or (isinstance(x, float) and not math.isfinite(x)) else f"{x:.1e}"


METHOD_STYLE = {"dop853": ("DOP853 (reference, tol)", "o-"), "rattle": ("RATTLE (step h)", "s-"),
                "rattle4": ("RATTLE4, Yoshida (step h)", "D-"), "rk4": ("RK4 + projection (step h)", "^-")}
#: what ``rattle`` is for each family, in one phrase (the full description: integrate.symplectic_scheme)
SCHEME_SHORT = {"neumann": "RATTLE + exact rotation", "jensen": "RATTLE + exact rotation",
                "manakov": "implicit midpoint (Cayley rotation)", "magnetic": "RATTLE in gauge-shifted momenta",
                "coupled": "RATTLE Strang-split with rotations"}


def _method_label(method: str, flow_name: str) -> str:
    if method == "rattle" and flow_name == "manakov":
        return "symplectic midpoint (step h)"
    if method == "rattle4" and flow_name == "manakov":
        return "midpoint ×3, Yoshida (step h)"
    return METHOD_STYLE[method][0]


def _save(fig: Any, out: Path, name: str) -> None:
    fig.savefig(out / f"{name}.png", dpi=110, metadata={"Software": None})
    fig.savefig(out / f"{name}.pdf", metadata={"CreationDate": None, "Creator": None, "Producer": None})


def long_figure_name(i: int, fam: dict[str, Any]) -> str:
    return "long_time" if i == 0 else f"long_time_{fam['flow_name']}"


def _figures(data: dict[str, Any], out: Path) -> list[str]:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter

    names = []
    wp = data["work_precision"]
    flows = list(dict.fromkeys(r["flow"] for r in wp))
    for i, flow in enumerate(flows):
        rows = [r for r in wp if r["flow"] == flow]
        fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
        for ax, key, title in zip(axes, ("constraint_error", "hamiltonian_error", "lax_error"),
                                  ("constraints ‖XᵀX−I‖, ‖XᵀP+PᵀX‖", "Hamiltonian |ΔH|/|H|", "Lax spectrum drift")):
            for method, (_, style) in METHOD_STYLE.items():
                label = _method_label(method, rows[0]["flow_name"])
                pts = sorted((r["seconds"], max(r[key], 1e-17)) for r in rows if r["method"] == method
                             and r[key] is not None and math.isfinite(r[key]))
                if pts:
                    ax.loglog(*zip(*pts), style, label=label, ms=4)
            ax.set_title(title, fontsize=9)
            ax.xaxis.set_minor_formatter(NullFormatter())
            ax.set_xlabel("wall time (s)")
            ax.grid(True, which="both", alpha=0.3)
        name = f"wp_{i + 1}"
        _finish(fig, axes, "largest error on [0, T]",
                f"work-precision: {flow} on V({rows[0]['n']},{rows[0]['r']}), T = {rows[0]['T']:g}", out, name)
        names.append(name)
    for i, fam in enumerate(data["long_runs"]):
        fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
        for ax, key, title in zip(axes, ("constraint_error", "hamiltonian_error", "lax_error"),
                                  ("constraints", "Hamiltonian |ΔH|/|H|", "Lax spectrum drift")):
            for run in fam["runs"]:
                t = np.asarray(run["times"])[1:]
                y = np.maximum(np.asarray(run[key])[1:], 1e-17)
                what = f"tol {run['tol']:g}" if run["tol"] else f"h = {run['step']:g}"
                ax.loglog(t, y, METHOD_STYLE[run["method"]][1][0] + "-",
                          label=f"{_method_label(run['method'], fam['flow_name']).split(' (')[0]} {what} "
                                f"({run['seconds']:.0f}s)", ms=2, lw=1)
            ax.set_title(title, fontsize=9)
            ax.set_xlabel("t")
            ax.grid(True, which="both", alpha=0.3)
        name = long_figure_name(i, fam)
        _finish(fig, axes, "error at time t",
                f"long run: {fam['flow']} on V({fam['n']},{fam['r']}) to t = {fam['T']:g}", out, name)
        names.append(name)
    return names


def _finish(fig: Any, axes: Any, ylabel: str, title: str, out: Path, name: str) -> None:
    """Label, title and save a row of panels (PNG and PDF), then close it."""
    import matplotlib.pyplot as plt
    axes[0].set_ylabel(ylabel)
    axes[0].legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    _save(fig, out, name)
    plt.close(fig)


def _csv(rows: Iterable[dict[str, Any]], keys: Sequence[str]) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(keys), extrasaction="ignore", lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: (json.dumps(r.get(k), ensure_ascii=False) if isinstance(r.get(k), (dict, list)) else r.get(k))
                    for k in keys})
    return buf.getvalue()


def _setting(row: dict[str, Any]) -> str:
    return f"tol {row['tol']:g}" if row["tol"] else f"h = {row['step']:g}"


#: wall-time budgets (s) and error targets of the trade-off table
BUDGETS = (0.1, 1.0)
TARGETS = (1e-6, 1e-8)


def _error(row: dict[str, Any]) -> float:
    """The error of a work-precision run that the trade-off table ranks by: max(|ΔH|/|H|, Lax drift)."""
    lax = row["lax_error"]
    return max(row["hamiltonian_error"], lax if math.isfinite(lax) else 0.0)


def _time_to(rows: list[dict[str, Any]], target: float) -> float | None:
    """The wall time at which the error of a method first reaches ``target``: log-log interpolation along
    its settings ordered by cost, between the last run above the target and the first one below it;
    None when no setting tried reaches it."""
    pts = sorted((r["seconds"], _error(r)) for r in rows)
    for k, (t, e) in enumerate(pts):
        if e <= target:
            if k == 0:
                return t
            t0, e0 = pts[k - 1]
            if e0 <= target or e0 <= 0 or e <= 0 or e0 == e:
                return t
            w = (math.log(target) - math.log(e0)) / (math.log(e) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t) - math.log(t0)))
    return None


def _observed_order(rows: list[dict[str, Any]]) -> float | None:
    """log(ΔH(h₁)/ΔH(h₂))/log(h₁/h₂) for the two smallest steps whose energy errors are above rounding
    (None for DOP853, or when fewer than two are)."""
    pts = sorted((r["step"], r["hamiltonian_error"]) for r in rows
                 if r["tol"] is None and r["step"] and math.isfinite(r["hamiltonian_error"])
                 and r["hamiltonian_error"] > 1e-12)
    if len(pts) < 2:
        return None
    (h2, e2), (h1, e1) = pts[0], pts[1]
    return math.log(e1 / e2) / math.log(h1 / h2) if h1 != h2 and e2 > 0 else None


def _tradeoffs(wp: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per flow and method: the errors reached within each wall-time budget (the most accurate setting that
    ran within it), and the wall time needed to reach each error target."""
    out = []
    for flow in dict.fromkeys(r["flow"] for r in wp):
        for method in METHOD_STYLE:
            rows = [r for r in wp if r["flow"] == flow and r["method"] == method and math.isfinite(r["seconds"])]
            if not rows:
                continue
            t: dict[str, Any] = {"flow": flow, "flow_name": rows[0]["flow_name"], "method": method,
                                 "T": rows[0]["T"], "n": rows[0]["n"], "r": rows[0]["r"],
                                 "failed": sum(1 for r in wp if r["flow"] == flow and r["method"] == method
                                               and r.get("failed"))}
            for budget in BUDGETS:
                within = [r for r in rows if r["seconds"] <= budget]
                one = min(within, key=_error) if within else None
                t[f"within_{budget:g}s"] = None if one is None else {
                    "setting": _setting(one), "seconds": one["seconds"], "hamiltonian": one["hamiltonian_error"],
                    "lax": one["lax_error"], "constraint": one["constraint_error"]}
            best = min(rows, key=_error)
            t["best"] = {"setting": _setting(best), "seconds": best["seconds"], "error": _error(best),
                         "constraint": best["constraint_error"]}
            for target in TARGETS:
                t[f"seconds_to_{target:g}"] = _time_to(rows, target)
            t["worst_constraint"] = max(r["constraint_error"] for r in rows)
            t["observed_order"] = _observed_order(rows)
            out.append(t)
    return out


def render_markdown(data: dict[str, Any], results_path: Path, figures: Sequence[str]) -> str:
    meta = data["meta"]
    L: list[str] = []
    add = L.append
    add("# Integrated flows: Lax spectra, work-precision and closed-form geodesics")
    add("")
    quick = " in **quick** mode (small sizes, short times)" if meta["quick"] else ""
    add("Generated by `stiefelsym flows` (`make flows`)" + quick
        + f"; {meta['seconds']:.0f} s of compute on {meta['machine']}, numpy {meta['numpy']}, float64. "
        "The API is `stiefelsym.analyses.integrate` (`integrate(X0, P0, flow, t_span, method=..., tol=...)`). "
        f"A = diag({', '.join(f'{a:g}' for a in meta['A'])}) (its first n entries); starting points are seeded random "
        "points of T*V (XᵀX = I, XᵀP + PᵀX = 0, ‖P‖ ≈ √(nr)). Every vector field is the Dirac flow (dot_XP) of the printed "
        "Hamiltonian (the multipliers Π, Λ solved from the constraints; for the magnetic flows with the Lorentz force of "
        "the twisted form), and is compared with the printed equations first. The data are in `flows.json` and the CSV files next to this one.")
    add("")
    add("```python")
    add("from stiefelsym.analyses.integrate import integrate, random_point")
    add("X0, P0 = random_point(4, 2, seed=1)               # a point of T*V(4, 2)")
    add("tr = integrate(X0, P0, \"neumann\", 100.0, method=\"rattle\", step=0.01, kappa=0.0, A=[0.5, 1.3, 2.1, 3.4])")
    add("tr.max_errors()   # constraints, Hamiltonian, Lax spectra (LA2), (LA3), invariants Ψ")
    add("```")
    add("")
    add("Methods: **DOP853** (scipy, explicit, order 8, step control; the reference, which does not keep T*V), "
        "**RATTLE** (`method=\"rattle\"`: a symplectic, time-reversible method of order 2 that keeps XᵀX = I and "
        "XᵀP + PᵀX = 0 to rounding, for every family; `integrate.symplectic_scheme(flow)` names it), **RATTLE4** "
        "(Yoshida's triple jump of the same step: symplectic, symmetric, order 4), **RK4 + projection** (classical RK4 "
        "with a fixed step, then X ↦ polar factor, P ↦ P − X sym(XᵀP); on T*V but not symplectic). What the symplectic "
        "step is, family by family:")
    add("")
    add("* **Neumann (every κ) and Jensen**: RATTLE for H_{−½} = ½tr PᵀP + ½tr XᵀAX (SHAKE for XᵀX = I by a chord-Newton "
        "iteration on the symmetric multiplier, then the exact tangent projection of P), followed by the exact right "
        "rotation exp(t(κ+½)Ψ₀): H_κ = H_{−½} + (κ+½)·½⟨Ψ,Ψ⟩ and the two terms Poisson-commute.")
    add("* **Manakov (B = A² and any diagonal B)**: H = ½⟨𝔸Φ, Φ⟩ depends on (X, P) only through the left momentum "
        "Φ = PXᵀ − XPᵀ, and Ẋ = ΩX, Ṗ = ΩP (Ω = 𝔸Φ) is already the Hamiltonian field of H on the ambient "
        "T*ℝ^{n×r}, with no multipliers. Its implicit midpoint rule is symplectic there and its step is "
        "(X, P) ↦ (QX, QP) with the Cayley rotation Q = (I − hΩ_m/2)⁻¹(I + hΩ_m/2) ∈ SO(n), which keeps XᵀX and XᵀP "
        "exactly: T*V is invariant and the restricted map is symplectic on T*V. Ω_m is solved by a simplified Newton "
        "iteration to rounding.")
    add("* **Magnetic (V(n, 2), every κ)**: ε de₁∧de₂ = d(ε/2 (e₁·de₂ − e₂·de₁)), so in the gauge-shifted momenta "
        "P̃ = P + (ε/2)XJ, J = [[0, 1], [−1, 0]] (p̃₁ = p₁ − (ε/2)e₂, p̃₂ = p₂ + (ε/2)e₁) the twisted form ω_ε is "
        "canonical, T*V is the same set (XᵀJ-terms are skew) and Φ(X, P̃) = Φ_ε, the matrix of the magnetic Lax pair. On "
        "T*V, XᵀP̃ = w̃J and H_κ = ½tr P̃ᵀP̃ + ½tr XᵀAX + f(w̃), f(w) = −εw + 2(κ+½)(w − ε/2)²: the Euclidean Neumann "
        "Hamiltonian in (X, P̃) plus a function of the right momentum, which commutes with it. The step is RATTLE in "
        "(X, P̃) with the exact rotation exp(t f′(w̃)/2 · J); it is symplectic for ω_ε. (So the magnetic Neumann flow on "
        "V(n, 2), for every κ, is the ordinary Euclidean Neumann flow in the shifted momenta followed by a rotation of the "
        "frame (e₁, e₂) at the constant rate f′(w̃)/2; `tests/test_flows_symplectic.py` checks it against DOP853 for "
        "(mag-euk), (mag-nor) and κ = 0.4. This is in line with the paper's remark before (twisted) that the magnetic "
        "T*G_{n,2} arises by reduction at a nonzero value εE₁∧E₂ of the so(2) momentum.)")
    add("* **Coupled (Appendix 2; every κ, perturbed or not)**: on T*V × T*V, H = H_{−½} + F(Ψ_X, Ψ_Y) with "
        "H_{−½} = ½tr PᵀP + ½tr QᵀQ + tr XᵀAY and F = (κ+½)(½⟨Ψ_X,Ψ_X⟩ + ½⟨Ψ_Y,Ψ_Y⟩) + β⟨Ψ_X,Ψ_Y⟩ (β = κ for the "
        "perturbed H_κ, 0 otherwise). They do not commute (only Ψ_X + Ψ_Y is conserved), so the step is Strang's "
        "splitting: the exact flow of F for h/2 (right rotations: X(t) = X(0)e^{t(κ+½−β)Ψ_X(0)}e^{tβS}, "
        "S = Ψ_X + Ψ_Y, likewise Y), RATTLE for H_{−½}, F for h/2. (For the perturbed H_κ, F = ½(½⟨Ψ_X,Ψ_X⟩ + "
        "½⟨Ψ_Y,Ψ_Y⟩) + κ·½⟨S, S⟩, and S is the momentum of the diagonal right rotations, a symmetry of H_0: the "
        "perturbed κ-flow is the κ = 0 coupled flow followed by the rotation (X, Y, P, Q) ↦ (X, Y, P, Q)·exp(tκS₀), which "
        "conjugates the Lax matrices; this is why its Lax pairs hold for every κ. `tests/test_flows_symplectic.py` checks "
        "it on integrated trajectories.)")
    add("")
    add("Every scheme is checked in `tests/test_flows_symplectic.py`: it converges to the DOP853 reference with "
        "order 2 (RATTLE) and 4 (RATTLE4), keeps T*V to 1e-13, keeps the (twisted) symplectic form ω(Du, Dv) = ω(u, v) "
        "on tangent vectors of T*V to 1e-7 where RK4 + projection does not, and its energy error does not drift; "
        "negative controls (a wrong gauge sign, a wrong Manakov operator) are refuted.")
    add("")
    # ---------------------------------------------------------------- printed vs derived
    add("## Printed equations against the derived vector fields")
    add("")
    add("At 5 seeded random points of T*V per size: the largest entry of the difference between the printed right-hand "
        "sides and the Dirac flow derived from the Hamiltonian (for the magnetic flows: with the Lorentz force "
        "ε(ė₂, −ė₁) of the twisted form ω_ε = ω + ε de₁∧de₂ (twisted), from ι_v ω_ε = −dH, the convention that gives "
        "ė = ∂H/∂p, ṗ = −∂H/∂e for ε = 0). Rounding-level differences mean the printed equations are the "
        "flows that are integrated below.")
    add("")
    add("| equations | n, r | max difference |")
    add("| --- | --- | --- |")
    for row in data.get("printed_vs_derived", []):
        add(f"| {row['equations']} | {row['n']}, {row['r']} | {_e(row['max_difference'])} |")
    add("")
    # ---------------------------------------------------------------- spectra
    add("## Lax spectra along integrated trajectories")
    add("")
    add("The spectrum of a Lax matrix L(λ) that satisfies dL/dt = [L, M] for *some* M stays fixed. This checks the "
        "Lax matrix L independently of the algebra; it does "
        "not see the second matrix M of the pair (a wrong printed M with a right L still gives a fixed spectrum). "
        "The spectrum is compared through the power traces tr L(λ)ᵏ, k = 1..dim (the integrals (perelomov)), "
        "scaled by ‖L(λ)‖₂ᵏ at t = 0, at three λ (away from the poles of the resolvents); the drift is the largest change. "
        "The column *eigenvalues* gives the largest move of an eigenvalue (matched to t = 0 by an assignment, relative "
        "to the spectral radius): it says the same, but is of the order of the square root of the error near "
        "colliding eigenvalues. "
        f"\"Fixed to 1e-k\" is the drift rounded up; \"isospectral\" means drift < {SPECTRUM_FIXED:g} while the "
        "constraints and H are kept to about 1e-10.")
    add("")
    add("| flow | n, r | method | Lax matrix | drift (fixed to) | eigenvalues | isospectral | ΔH, constraints "
        f"| algebraic verdict ({_shown(results_path)}) |")
    add("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for row in data["spectra"]:
        wanted = catalog_claims(row)
        verdicts = algebraic_verdicts(results_path, row["paper"], claims=wanted)
        vt = "; ".join(_verdict_text(v) for v in verdicts) if verdicts else \
            f"`{'`, `'.join(wanted)}` not in {results_path.name} yet" if wanted else "–"
        iso = "yes" if row["drift"] < SPECTRUM_FIXED else "**no**"
        how = f"{row['method']} tol {row['tol']:g}" if row["tol"] else f"{row['method']} h = {row['step']:g}"
        name = row["lax"] + ("" if row["printed"] else f" ({row['note']})")
        add(f"| {row['flow']} | {row['n']}, {row['r']} | {how}, T = {row['T']:g} | {name} "
            f"| {_e(row['drift'])} ({_digits(row['drift'])}) | {_e(row.get('eigenvalue_drift'))} | {iso} "
            f"| {_e(row['hamiltonian_error'])}, {_e(row['constraint_error'])} | {vt} |")
    add("")
    add(_spectra_findings(data["spectra"], results_path))
    add("")
    # ---------------------------------------------------------------- dual pair for every kappa
    rows = data.get("dual_every_kappa", [])
    if rows:
        add("### The dual Lax pair (LA3) for every κ")
        add("")
        add("Theorem DUAL gives (LA4) for κ = 0 and κ = −½. Since the κ-flow is the Euclidean flow followed by the "
            "right rotation exp(t(κ+½)Ψ₀), which conjugates 𝓛*(λ) by diag(R, R), the pair extends to every κ with "
            "𝓐*_κ(λ) = [[(1+2κ)XᵀP, I_r], [Λ − λI_r, −(1+2κ)PᵀX]], Λ = XᵀAX − PᵀP (κ = 0 and κ = −½ give the "
            "printed (LA4)). Relative residual max|d𝓛*/dt − [𝓛*, 𝓐*]| along (No) at 5 seeded random points and "
            "λ = 0.77, −1.9 (float64; evidence, not a proof: a candidate claim for the catalog):")
        add("")
        add("| V(n,r) | κ | with 𝓐*_κ | with the normal-metric 𝓐* of (LA4) |")
        add("| --- | --- | --- | --- |")
        for row in rows:
            add(f"| V({row['n']},{row['r']}) | {row['kappa']:g} | {_e(row['residual_A_kappa'])} "
                f"| {_e(row['residual_A_normal'])} |")
        add("")
    # ---------------------------------------------------------------- work precision
    add("## Work-precision diagrams")
    add("")
    add("Largest error on [0, T] against wall time, for every flow family with each method: DOP853 at several "
        "tolerances, RATTLE (the family's symplectic step), RATTLE4 and RK4 + projection at several steps (the errors are "
        "sampled at 101 times). The Lax drift is that of the Lax matrices that hold along the flow.")
    add("")
    for name in figures:
        if name.startswith("wp_"):
            add(f"![{name}]({name}.png)")
            add("")
    failed = [r for r in data["work_precision"] if r.get("failed")]
    for r in failed:
        add(f"* {r['flow']}, {r['method']} {_setting(r)}: no trajectory ({r['failed']}).")
    if failed:
        add("")
    add(_tradeoff_section(data))
    add("")
    add(_wp_findings(data["work_precision"]))
    add("")
    # ---------------------------------------------------------------- long time
    add("## Long runs: t up to 1e4")
    add("")
    add("One long run per family on V(3, 2) (the first-listed one with every method to t = 1e4; for the other families "
        "the fixed-step methods go to t = 1e4 and DOP853 to t = 1e3, where it already shows what it does, and for the "
        "coupled flow RK4 too, to keep `make flows` within a few minutes). The errors are sampled at 201 times.")
    add("")
    for i, fam in enumerate(data["long_runs"]):
        name = long_figure_name(i, fam)
        add(f"### {fam['flow']}")
        add("")
        add(f"![{name}]({name}.png)")
        add("")
        add("| method | setting | t | seconds | right-hand sides / steps | max constraints | max ΔH | max Lax drift "
            "| ΔH growth (last tenth / first tenth) |")
        add("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for run in fam["runs"]:
            what = f"tol {run['tol']:g}" if run["tol"] else f"h = {run['step']:g}"
            add(f"| {_method_label(run['method'], fam['flow_name']).split(' (')[0]} | {what} | {run['T']:g} "
                f"| {run['seconds']:.1f} | {run['evaluations']} | {_e(run['max']['constraint'])} | "
                f"{_e(run['max']['hamiltonian'])} | {_e(run['max']['lax'])} | ×{_growth(run):.1f} |")
        add("")
        add(_long_findings(fam))
        add("")
    # ---------------------------------------------------------------- closed forms
    add("## Closed-form geodesics (Edelman, Arias, Smith 1998)")
    add("")
    add("**Mapping of the metrics.** The Legendre map of H_κ (EM) is Ẋ = P − (1+2κ)XPᵀX (No with A = 0), so "
        "XᵀẊ = 2(1+κ)XᵀP and (I − XXᵀ)Ẋ = (I − XXᵀ)P; the metric ds²_κ is therefore "
        "g_κ(Ẋ, Ẋ) = tr(ẊᵀP) = tr Ẋᵀ(I − βXXᵀ)Ẋ with **β = (1+2κ)/(2+2κ)** (positive definite for κ > −1). "
        "κ = −½ gives β = 0, EAS's Euclidean metric tr ΔᵀΔ (with P = Ẋ, (leg)); κ = 0 gives β = ½, EAS's canonical "
        "metric tr Δᵀ(I − ½YYᵀ)Δ, with the same time parameter and Δ = Ẋ = P − XPᵀX (dot_X3), i.e. the paper's "
        "normalization ⟨ξ, η⟩ = −½tr(ξη) of (killing) is exactly EAS's canonical metric. For every κ the geodesic is "
        "the Euclidean one followed by a right rotation: X_κ(t) = X_E(t)·exp(t(κ+½)Ψ₀), Ψ₀ = X₀ᵀP₀ − P₀ᵀX₀ "
        "(`integrate.jensen_geodesic`). For κ = −½ this is EAS's Euclidean formula itself (hence the zeros in the column "
        "*EAS vs closed form*); the independent checks are the integrations (DOP853, RATTLE) and, for κ = 0, EAS's "
        "canonical formula, which is a different construction (QR of the normal part) of the same curve.")
    add("")
    add("| V(n,r) | κ | β | T | DOP853 (tol 1e-13) vs closed form: X, P | RATTLE h = 0.01 vs closed form | EAS formula "
        "| EAS vs closed form | EAS vs DOP853 |")
    add("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for row in data["closed_forms"]:
        add(f"| V({row['n']},{row['r']}) | {row['kappa']:g} | {row['beta']:g} | {row['T']:g} | "
            f"{_e(row['dop853_vs_closed_X'])}, {_e(row['dop853_vs_closed_P'])} "
            f"| {_e(row.get('rattle_h0.01_vs_closed_X'))} | "
            f"{row.get('eas', '–')} | {_e(row.get('eas_vs_closed_X'))} | {_e(row.get('eas_vs_dop853_X'))} |")
    add("")
    wrong = [r["eas_with_velocity_P_vs_dop853_X"] for r in data["closed_forms"] if "eas_with_velocity_P_vs_dop853_X" in r]
    if wrong:
        add(f"The normalization matters: EAS's canonical geodesic started with Δ = P instead of Δ = P − XPᵀX is off "
            f"by {min(wrong):.1e} to {max(wrong):.1e} (max-norm of X) in the same table's cases.")
        add("")
    return "\n".join(L) + "\n"


def _spectra_findings(rows: list[dict[str, Any]], results_path: Path) -> str:
    out = ["Findings:", ""]
    bad_printed = [r for r in rows if r["printed"] and r["drift"] >= SPECTRUM_FIXED]
    good = [r for r in rows if r["drift"] < SPECTRUM_FIXED]
    if good:
        ref = [r for r in good if r["method"] == "dop853"]
        sym = [r for r in good if r["method"] in ("rattle", "rattle4")]
        out.append(f"* {len(ref)} (flow, Lax matrix) pairs keep their spectrum fixed to ≤ "
                   f"{_digits(max(r['drift'] for r in ref))} along the reference trajectory"
                   + (f"; {len(sym)} along the symplectic, constraint-preserving trajectories of the Manakov, magnetic "
                      f"and coupled flows (RATTLE4, to ≤ {_digits(max(r['drift'] for r in sym))}: the same verdicts "
                      "from an integrator that stays on T*V)" if sym else "") + "." if ref else "")
    mag_k = [r for r in rows if r["flow_name"] == "magnetic" and r["params"].get("kappa") not in (0.0, -0.5)]
    if mag_k and all(r["drift"] < SPECTRUM_FIXED for r in mag_k):
        out.append("* The magnetic Lax matrix λΦ_ε + XXᵀ − λ²A stays isospectral along the magnetic flow for κ = "
                   f"{', '.join(str(r['params']['kappa']) for r in mag_k)} as well (the paper states it for κ = −½ and 0).")
    dual_k = [r for r in rows if r["flow_name"] == "neumann" and "LA3" in r["lax"]
              and r["params"].get("kappa") not in (0.0, -0.5)]
    if dual_k and all(r["drift"] < SPECTRUM_FIXED for r in dual_k):
        out.append("* The dual matrix 𝓛*_neum (LA3) is isospectral along the Neumann flow for κ = "
                   f"{', '.join(str(r['params']['kappa']) for r in dual_k)} too, although Theorem DUAL states it "
                   "for κ = 0 and κ = −½ only: the κ-flow is the Euclidean flow followed by the right rotation "
                   "exp(t(κ+½)Ψ₀), which "
                   "conjugates 𝓛* by diag(R, R).")
    seen: set[tuple[str, str]] = set()
    for r in rows:
        if r["printed"] and r["drift"] < SPECTRUM_FIXED and (r["lax"], r["flow"]) not in seen:
            seen.add((r["lax"], r["flow"]))
            for v in algebraic_verdicts(results_path, claims=catalog_claims(r)):
                if v["kind"] == "lax" and "fails" in v["printed"]:
                    why = ("its registered correction keeps this L and replaces (A + λI)⁻¹ by A + λI in 𝓐*_man (LA-MAN3), "
                           "the other matrix of the pair, which the integration does not see — consistent"
                           if v["claim"] == "manakov-dual-lax" else
                           "the integration tests only L (see the claim's erratum in verification.md)")
                    out.append(f"* {r['lax']} along {r['flow']}: the spectrum is fixed although `{v['claim']}` fails as "
                               f"printed; {why}.")
    sonn = [r for r in bad_printed if r["flow_name"] == "coupled" and "so(n,n)" in r["lax"]]
    if sonn:
        out.append(f"* **(so(n,n)) as printed is not isospectral** along "
                   f"{', '.join(dict.fromkeys(r['flow'] for r in sonn))} (DOP853 and the symplectic step; drift "
                   f"{_e(min(r['drift'] for r in sonn))} to {_e(max(r['drift'] for r in sonn))}). With the ν⁻¹ term of "
                   "opposite sign, L(ν) = ν[[0, A], [A, 0]] + diag(Φ_X, Φ_Y) − ν⁻¹[[0, XYᵀ], [YXᵀ, 0]], the spectrum is "
                   "fixed for κ = 0 and for the perturbed H_κ (rows marked *correction*): dL/dt = [L_+(ν), L(ν)] then "
                   "follows from dΦ_X/dt = XYᵀA − AYXᵀ and d(XYᵀ)/dt = Φ_X XYᵀ − XYᵀΦ_Y (κ = 0), so the printed pair "
                   "(L, L_+) has a sign error. This is the erratum registered in the catalog for "
                   "`coupled-big-lax-normal` and "
                   "`coupled-perturbed-big-lax` (same correction), found here independently of the algebra.")
    for r in bad_printed:
        if r in sonn:
            continue
        if r["flow_name"] == "coupled" and not r["params"].get("perturbed") and r["params"].get("kappa") == -0.5:
            out.append(f"* {r['lax']} drifts ({_e(r['drift'])}) along the unperturbed coupled flow with κ = −½: the "
                       "paper's statement that these Lax pairs hold for κ = 0 and not for the Euclidean metric, "
                       "witnessed numerically.")
        elif r["flow_name"] == "magnetic" and r["method"] == "dop853" and r["params"].get("printed"):
            out.append(f"* {r['flow']} with DOP853: drift {_e(r['drift'])} together with constraint errors "
                       f"{_e(r['constraint_error'])}. The printed (mag-euk) uses XᵀX = I to simplify its multipliers, "
                       "and as an ODE on n × 2 matrices it leaves T*V unstably "
                       "(d/dt(e₁·p₁) ≈ ((e₁, Ae₁) − |p₁|²)(|e₁|² − 1), "
                       "so a rounding error of 1e-12 grows exponentially when |p₁|² > (e₁, Ae₁)). On T*V the printed "
                       "equations are right: they agree with the derived field to rounding (table above), and RK4 + "
                       "projection on them keeps the spectrum and H fixed (next row); the derived field, whose "
                       "multipliers are solved without using XᵀX = I, stays on T*V under DOP853.")
        else:
            out.append(f"* {r['flow']}, {r['lax']}: drift {_e(r['drift'])}.")
    return "\n".join(out)


def _wp_findings(rows: list[dict[str, Any]]) -> str:
    rows = [r for r in rows if not r.get("failed")]
    out = ["Observations:", ""]
    rat = [r for r in rows if r["method"] in ("rattle", "rattle4")]
    if rat:
        out.append(f"* RATTLE and RATTLE4 (every family's symplectic step) keep XᵀX = I and XᵀP + PᵀX = 0 to "
                   f"≤ {max(r['constraint_error'] for r in rat):.0e} at every step size; their energy errors are O(h²) "
                   "and O(h⁴) and bounded in time (symplectic).")
    rk = [r for r in rows if r["method"] == "rk4"]
    if rk:
        out.append(f"* RK4 + projection is on T*V to ≤ {max(r['constraint_error'] for r in rk):.0e} by construction; its "
                   "energy error is O(h⁴) but drifts linearly in time (not symplectic; see the long runs).")
    dop = [r for r in rows if r["method"] == "dop853"]
    if dop:
        lo, hi = min(r["constraint_error"] for r in dop), max(r["constraint_error"] for r in dop)
        trade = _tradeoffs(rows)
        flows = list(dict.fromkeys(t["flow"] for t in trade))
        first = [f for f in flows if min(((t["seconds_to_1e-08"], t["method"]) for t in trade
                                          if t["flow"] == f and t["seconds_to_1e-08"] is not None),
                                         default=(None, ""))[1] == "dop853"]
        out.append(f"* DOP853 (order 8) reaches an invariant error of 1e-8 first in {len(first)} of {len(flows)} families "
                   f"over this short span; its constraint errors follow the tolerance (from {lo:.0e} to {hi:.0e}) since "
                   "nothing projects, and they grow with t (see the long runs).")
    jen = [r for r in rat if r["flow_name"] == "jensen"]
    if jen:
        out.append(f"* For the Jensen flows the symplectic step keeps H and the Lax spectrum to rounding "
                   f"(≤ {max(max(r['hamiltonian_error'], r['lax_error']) for r in jen):.0e}) at every step: RATTLE keeps "
                   "the quadratic momentum Φ of the left SO(n)-symmetry exactly, and with A = 0 the spectrum of "
                   "λΦ + XXᵀ and H_{−½} = ½|P|² are kept with it. Its *trajectory* error is still O(h²) (the RATTLE "
                   "column of the closed-form table), so for these flows the invariant errors of the table above do not "
                   "measure its accuracy.")
    return "\n".join(out)


def _growth(run: dict[str, Any]) -> float:
    h = np.asarray(run["hamiltonian_error"])
    k = len(h)
    early, late = float(h[1:k // 10 + 1].max()), float(h[-k // 10:].max())
    return late / early if early > 0 else float("nan")


def _long_findings(lt: dict[str, Any]) -> str:
    out = []
    for run in lt["runs"]:
        h = np.asarray(run["hamiltonian_error"])
        k = len(h)
        early, late = float(h[1:k // 10 + 1].max()), float(h[-k // 10:].max())
        label = _method_label(run["method"], lt["flow_name"]).split(" (")[0]
        if late < 1e-12:
            kind = "rounding level"
        elif early > 0.1:
            kind = "O(1) from the start: the step is too large for this method"
        elif _growth(run) < 3:
            kind = "bounded, no drift; a linear drift would give about ×10"
        else:
            kind = "drifts; a linear drift gives about ×10"
        out.append(f"* {label}: ΔH at the first tenth of the run ≤ {early:.1e}, at the last tenth ≤ {late:.1e} "
                   f"(growth ×{_growth(run):.1f}: {kind}); constraints ≤ {run['max']['constraint']:.1e}.")
        c = np.asarray(run["constraint_error"])
        off = np.nonzero(c > 1e-2)[0]
        if len(off):
            t_off = run["times"][int(off[0])]
            out.append(f"  Without projection the trajectory drifts off T*V (linearly in t at first) and, once the "
                       f"constraint error passes 1e-2 (t ≈ {t_off:.0f}), the ambient equations leave it for good: the "
                       f"constraint error reaches {c.max():.1e} and the Lax drift {run['max']['lax']:.1e}. Long runs "
                       "need a method that stays on T*V.")
    return "\n".join(out)


def _tradeoff_section(data: dict[str, Any]) -> str:
    meta = data["meta"]
    load = meta.get("load_average_at_start")
    L = ["### Trade-offs: error reached per second of compute, per method", ""]
    L.append("Measured in one run of `stiefelsym flows`, on one machine, every method on the same trajectory (same start, "
             "same T) one after the other in the same process; the wall time is that of the integration only (not of "
             "the error diagnostics), float64, numpy " + meta["numpy"] + ", " + meta["machine"] + ", on a shared machine"
             + (f" (load average {load[0]:.1f} at the start)" if load else "") + ": compare methods within this table, "
             "not across runs. The error is the largest of |ΔH|/|H| and the Lax-spectrum drift on [0, T]. *Within "
             "0.1 s / 1 s*: the most accurate setting tried that ran within that budget (– if none did). *Seconds to "
             "1e-6 / 1e-8*: the wall time at which the error first reaches the target, interpolated (log-log) between "
             "the two settings around it (– if no setting tried reached it). *Constraints*: the largest ‖XᵀX − I‖, "
             "‖XᵀP + PᵀX‖ over the settings. *Observed order*: log(ΔH(h₁)/ΔH(h₂))/log(h₁/h₂) for the two smallest steps "
             "(the design orders are 2 for RATTLE, 4 for RATTLE4 and RK4; – where ΔH is at rounding level).")
    L.append("")
    L.append("| flow (V(n,r), T) | method | within 0.1 s: error | within 1 s: setting | error | constraints | "
             "most accurate: error, seconds | seconds to 1e-6 | seconds to 1e-8 | constraints (worst setting) "
             "| observed order |")
    L.append("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for t in _tradeoffs(data["work_precision"]):
        a, b = t["within_0.1s"], t["within_1s"]
        ea = max(a["hamiltonian"], a["lax"] if math.isfinite(a["lax"]) else 0) if a else None
        eb = max(b["hamiltonian"], b["lax"] if math.isfinite(b["lax"]) else 0) if b else None
        label = _method_label(t["method"], t["flow_name"]).split(" (")[0]
        s6, s8 = t["seconds_to_1e-06"], t["seconds_to_1e-08"]
        L.append(f"| {t['flow']} ({t['n']},{t['r']}, {t['T']:g}) | {label} | {_e(ea)} | {b['setting'] if b else '–'} "
                 f"| {_e(eb)} | {_e(b['constraint']) if b else '–'} | {_e(t['best']['error'])}, "
                 f"{_sec(t['best']['seconds'])} s | {_sec(s6)} | {_sec(s8)} | {_e(t['worst_constraint'])} "
                 f"| {'–' if t.get('observed_order') is None else format(t['observed_order'], '.1f')} |")
    L.append("")
    L.append(_tradeoff_summary(data))
    return "\n".join(L)


def _sec(x: float | None) -> str:
    return "–" if x is None else f"{x:.2g}"


def _tradeoff_summary(data: dict[str, Any]) -> str:
    """One line per family: which method reaches 1e-8 first, and what the symplectic step gives within 1 s."""
    out = ["Per family:", ""]
    rows = _tradeoffs(data["work_precision"])
    for flow in dict.fromkeys(t["flow"] for t in rows):
        ts = [t for t in rows if t["flow"] == flow]
        reach = sorted((t["seconds_to_1e-08"], t["method"]) for t in ts if t["seconds_to_1e-08"] is not None)
        fast = (f"1e-8 is reached first by {reach[0][1]} ({_sec(reach[0][0])} s)"
                + (f", then {', '.join(f'{m} ({_sec(s)} s)' for s, m in reach[1:])}" if len(reach) > 1 else "")
                if reach else "no method reaches 1e-8 in the settings tried")
        sym = [t for t in ts if t["method"] in ("rattle", "rattle4") and t["within_1s"]]
        best_sym = min(sym, key=lambda t: max(t["within_1s"]["hamiltonian"], t["within_1s"]["lax"]
                                            if math.isfinite(t["within_1s"]["lax"]) else 0), default=None)
        dop = next((t for t in ts if t["method"] == "dop853"), None)
        extra = ""
        if best_sym:
            w = best_sym["within_1s"]
            extra = (f"; within 1 s the symplectic {best_sym['method']} ({w['setting']}) reaches "
                     f"{_e(max(w['hamiltonian'], w['lax'] if math.isfinite(w['lax']) else 0))} with the constraints at "
                     f"{_e(w['constraint'])}")
        if dop:
            extra += f", DOP853's constraint error goes up to {_e(dop['worst_constraint'])} at its loosest tolerance"
        out.append(f"* {flow}: {fast}{extra}.")
    return "\n".join(out)


def write_report(data: dict[str, Any], out: Path, results_path: Path) -> list[Path]:
    """Write flows.json, the CSV files, the figures and flows.md into ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    written = []
    figures = _figures(data, out)
    for name in figures:
        written += [out / f"{name}.png", out / f"{name}.pdf"]
    data = {**data, "tradeoffs": _tradeoffs(data["work_precision"])}
    write_atomic(out / "flows.json", json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    write_atomic(out / "spectra.csv", _csv(data["spectra"], [
        "flow", "n", "r", "method", "tol", "step", "T", "lax", "paper", "printed", "drift", "eigenvalue_drift",
        "hamiltonian_error", "constraint_error", "seconds"]))
    write_atomic(out / "work_precision.csv", _csv(data["work_precision"], ["flow", "n", "r", "T", "method", "tol", "step",
                                                                         "seconds", "evaluations", "constraint_error",
                                                                         "hamiltonian_error", "lax_error"]))
    long_rows = [{"flow": fam["flow"], "method": run["method"], "step": run["step"], "tol": run["tol"], "t": t,
                  "constraint_error": c, "hamiltonian_error": h, "lax_error": x}
                 for fam in data["long_runs"] for run in fam["runs"]
                 for t, c, h, x in zip(run["times"], run["constraint_error"], run["hamiltonian_error"], run["lax_error"])]
    write_atomic(out / "long_time.csv", _csv(long_rows, ["flow", "method", "step", "tol", "t", "constraint_error",
                                                          "hamiltonian_error", "lax_error"]))
    write_atomic(out / "tradeoffs.csv", _csv([{**{k: v for k, v in t.items() if not isinstance(v, dict)},
                                                 **{f"{k}_{kk}": vv for k, v in t.items() if isinstance(v, dict)
                                                    for kk, vv in v.items()}}
                                                for t in data["tradeoffs"]],
                                               ["flow", "method", "n", "r", "T", "within_0.1s_setting",
                                                "within_0.1s_hamiltonian", "within_0.1s_lax", "within_0.1s_constraint",
                                                "within_1s_setting", "within_1s_seconds", "within_1s_hamiltonian",
                                                "within_1s_lax", "within_1s_constraint", "best_setting", "best_error",
                                                "best_seconds", "seconds_to_1e-06", "seconds_to_1e-08",
                                                "worst_constraint", "observed_order", "failed"]))
    cf_keys = ["n", "r", "kappa", "beta", "T", "dop853_vs_closed_X", "dop853_vs_closed_P", "rattle_h0.01_vs_closed_X", "eas",
               "eas_vs_closed_X", "eas_vs_dop853_X", "eas_with_velocity_P_vs_dop853_X"]
    write_atomic(out / "closed_forms.csv", _csv(data["closed_forms"], cf_keys))
    write_atomic(out / "flows.md", render_markdown(data, results_path, figures))
    written += [out / n for n in ("flows.json", "spectra.csv", "work_precision.csv", "long_time.csv", "tradeoffs.csv",
                                  "closed_forms.csv",
                                  "flows.md")]
    return written
