"""Numerical integration of the paper's flows on T*V(n, r), with their constraint and invariant errors.

This module is numerical and independent of the symbolic engine (numpy/scipy, float64).  A user
gives a point (X0, P0) of T*V(n, r) (XᵀX = I, XᵀP + PᵀX = 0), a flow, a time span, a tolerance and a
method, and gets a :class:`Trajectory`: times, states, the constraint errors ‖XᵀX − I‖ and
‖XᵀP + PᵀX‖, the relative error of the Hamiltonian, the drift of matrix invariants (Φ, Ψ, …) and the
drift of the spectra of the Lax matrices L(λ) at a few λ (the power traces tr L(λ)ᵏ against t = 0).

Flows (:func:`make_flow`), as in the paper:

* ``"neumann"`` (kappa, A): H = ½tr PᵀP − (½ + κ)tr (XᵀP)² + ½tr XᵀAX, equations (No);
  Lax matrices (LA2) 𝓛 = λΦ + XXᵀ − λ²A and the dual (LA3) 𝓛*(λ).
* ``"jensen"`` (kappa): the geodesic flow of ds²_κ, Hamiltonian (EM) (the Neumann flow with A = 0).
* ``"manakov"`` (A, B, default B = A²): (dot_XP2) with 𝔸 = ad_A⁻¹ad_B; 𝓛 = Φ + λA, and for B = A²
  the dual (MAN-LA2).
* ``"magnetic"`` (eps, A, kappa; printed): the magnetic Neumann flows on V(n, 2) for the twisted
  form (twisted), or (mag-euk), (mag-nor) as printed; 𝓛 = λΦ_ε + XXᵀ − λ²A with Φ_ε = Φ + ε e₁∧e₂.
* ``"coupled"`` (kappa, A, perturbed): the r-coupled Neumann system (C-neumann) on T*V × T*V, or the
  perturbed H_κ with −2κ tr(XᵀP YᵀQ); the so(n, n) Lax matrix (so(n,n)) and the 4r × 4r (LA3*C).

Every vector field of a Hamiltonian is the Dirac flow (dot_XP): Ẋ = ∂H/∂P − XΠ,
Ṗ = −∂H/∂X + XΛ + PΠ with the symmetric multipliers solved from the time derivatives of the
constraints, so the flow is derived from the printed Hamiltonian, never typed in (the magnetic
flows add the Lorentz force of the twisted form; their printed equations are available too).

Methods (:func:`integrate`):

* ``"dop853"``: scipy's explicit Runge–Kutta of order 8 with step control (rtol = tol), the reference;
* ``"rattle"``: the symplectic, time-reversible, constraint-preserving method of order 2 (on T*V to
  rounding); :func:`symplectic_scheme` says what it is for a flow.  RATTLE (SHAKE for XᵀX = I by
  Newton on the symmetric multiplier, exact tangent projection of P) for ½tr PᵀP + V(X); for the
  Jensen and Neumann flows of every κ, H_κ = H_{−½} + (κ + ½)·½⟨Ψ, Ψ⟩, the two terms Poisson-commute
  (H_{−½} is right SO(r)-invariant and ⟨Ψ, Ψ⟩ is a function of the right momentum map) and the flow
  of ½⟨Ψ, Ψ⟩ is the right rotation (X, P) ↦ (X, P)·exp(tΨ), so the κ-flow is the Euclidean flow
  followed by the exact rotation exp(t(κ + ½)Ψ₀).  The coupled flows (every κ, perturbed or not):
  RATTLE for ½tr PᵀP + ½tr QᵀQ + tr XᵀAY Strang-split with the exact flow (right rotations) of the
  rest, a function of Ψ_X and Ψ_Y.  The magnetic flows on V(n, 2): the same in the gauge-shifted momenta
  P̃ = P + (ε/2)XJ, in which the twisted form is canonical (the rest is then a function of the right
  momentum, and commutes).  The Manakov flows (every diagonal B): the implicit midpoint rule of the
  collective field Ẋ = ΩX, Ṗ = ΩP, Ω = 𝔸Φ, a Hamiltonian field of the ambient space whose midpoint step
  is the Cayley rotation (X, P) ↦ (QX, QP), so T*V is kept exactly;
* ``"rattle4"``: Yoshida's triple jump of that step (steps w₁h, w₀h, w₁h with w₁ = 1/(2 − 2^{1/3}),
  w₀ = 1 − 2w₁), symplectic, symmetric, of order 4, on T*V to rounding; it covers the same flows;
* ``"rk4"``: the classical explicit Runge–Kutta of order 4 with a fixed step, followed after every
  step by the projection onto T*V (polar factor of X, then P ↦ P − X sym(XᵀP)).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from functools import partial
from typing import Any, Callable, Mapping, Sequence

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm

__all__ = ["Flow", "LaxMatrix", "Trajectory", "make_flow", "custom_flow", "integrate", "FLOWS", "METHODS",
           "project_to_tangent_bundle", "constraint_errors", "expm_skew", "euclidean_geodesic", "canonical_geodesic",
           "jensen_geodesic", "metric_beta", "random_point", "spectral_drift", "eigenvalue_drift", "dirac_vector_field",
           "symplectic_scheme"]

FLOWS = ("neumann", "jensen", "manakov", "magnetic", "coupled")
#: the parameters each named flow takes
FLOW_PARAMETERS = {"neumann": ("kappa", "A"), "jensen": ("kappa",), "manakov": ("A", "B"),
                   "magnetic": ("kappa", "eps", "A", "printed"), "coupled": ("kappa", "A", "perturbed")}
METHODS = ("dop853", "rattle", "rattle4", "rk4")
#: Yoshida's triple jump: the symmetric composition of three RATTLE steps of order 4
_YOSHIDA = (1 / (2 - 2 ** (1 / 3)), -2 ** (1 / 3) / (2 - 2 ** (1 / 3)), 1 / (2 - 2 ** (1 / 3)))
#: the largest constraint violation accepted as "on T*V" without projection
ON_SHELL = 1e-10
#: DOP853's relative tolerance and the fixed-step methods' step when neither tol nor step is given
DEFAULT_TOL, DEFAULT_STEP = 1e-10, 0.01

Array = np.ndarray
Vector = Callable[[Array, Array], tuple[Array, Array]]


# --------------------------------------------------------------------------- small algebra

def _sym(M: Array) -> Array:
    return (M + np.swapaxes(M, -1, -2)) / 2


def _T(M: Array) -> Array:
    return np.swapaxes(M, -1, -2)


def constraint_errors(X: Array, P: Array) -> tuple[float, float]:
    """(max ‖XᵀX − I‖, max ‖XᵀP + PᵀX‖) in the Frobenius norm, over the points of a state (m, n, r)."""
    X, P = np.asarray(X, float), np.asarray(P, float)
    if X.ndim == 2:
        X, P = X[None], P[None]
    r = X.shape[-1]
    XtX = _T(X) @ X
    XtP = _T(X) @ P
    e1 = np.linalg.norm(XtX - np.eye(r), axis=(-2, -1)).max()
    e2 = np.linalg.norm(XtP + _T(XtP), axis=(-2, -1)).max()
    return float(e1), float(e2)


def project_to_tangent_bundle(X: Array, P: Array) -> tuple[Array, Array]:
    """The projection onto T*V: X ↦ its polar factor UVᵀ (X = UΣVᵀ), then P ↦ P − X sym(XᵀP)."""
    U, _, Vt = np.linalg.svd(X, full_matrices=False)
    Xp = U @ Vt
    Pp = P - Xp @ _sym(_T(Xp) @ P)
    return Xp, Pp


def random_point(n: int, r: int, seed: int = 0, scale: float = 1.0) -> tuple[Array, Array]:
    """A seeded random point of T*V(n, r): X with orthonormal columns, P tangent, ‖P‖ ≈ scale·√(nr)."""
    _check_size(n, r)
    rng = np.random.default_rng(seed)
    Q, R = np.linalg.qr(rng.standard_normal((n, r)))
    X = Q * np.sign(np.diag(R))
    P = scale * rng.standard_normal((n, r))
    return X, P - X @ _sym(X.T @ P)


def _check_size(n: int, r: int) -> None:
    if not (isinstance(n, (int, np.integer)) and isinstance(r, (int, np.integer))):
        raise ValueError(f"n and r must be integers, got n={n!r}, r={r!r}")
    if not 1 <= r <= n:
        raise ValueError(f"the Stiefel variety V(n, r) needs 1 <= r <= n, got n={n}, r={r}")


def _killing(a: Array, b: Array) -> float:
    """⟨a, b⟩ = −½ tr(ab) (killing)."""
    return float(-0.5 * np.trace(a @ b))


# --------------------------------------------------------------------------- flows

@dataclass(frozen=True)
class LaxMatrix:
    """A Lax matrix L(X, P, λ) of a flow (state arrays (m, n, r)), with the paper labels of its pair."""

    name: str
    paper: tuple[str, ...]
    matrix: Callable[[Array, Array, float], Array]
    lambdas: tuple[float, ...]
    #: False for a correction of a printed matrix (then ``note`` says which)
    printed: bool = True
    note: str = ""


@dataclass(frozen=True)
class Flow:
    """A flow on T*V(n, r) (or on the product of ``points`` copies of it).

    ``rhs(X, P)`` takes and returns arrays of shape (points, n, r).  ``potential_gradient`` (X ↦ ∂V/∂X)
    is set when H = ½tr PᵀP + V(X) up to the exact right rotation of rate ``rotation`` (κ + ½):
    that is what RATTLE needs."""

    name: str
    n: int
    r: int
    rhs: Vector
    points: int = 1
    hamiltonian: Callable[[Array, Array], float] | None = None
    lax: tuple[LaxMatrix, ...] = ()
    invariants: Mapping[str, Callable[[Array, Array], Array]] = field(default_factory=dict)
    potential_gradient: Callable[[Array], Array] | None = None
    rotation: float = 0.0
    params: Mapping[str, Any] = field(default_factory=dict)
    paper: tuple[str, ...] = ()
    constraint: Callable[[Array, Array], float] | None = None
    #: a symmetric, symplectic step (X, P, h) -> (X, P) of order 2 on T*V, when the flow is not covered
    #: by plain RATTLE (``potential_gradient`` with the rotation); ``symplectic_scheme`` says what it is
    symplectic: Callable[[Array, Array, float], tuple[Array, Array]] | None = None
    symplectic_scheme: str = ""

    @property
    def label(self) -> str:
        extra = ", ".join(f"{k}={_fmt(v)}" for k, v in self.params.items() if k != "A")
        return f"{self.name}({extra})" if extra else self.name


def _fmt(v: Any) -> str:
    if isinstance(v, float):
        return f"{v:g}"
    return str(v)


def dirac_vector_field(gradient: Callable[[Array, Array], tuple[Array, Array]],
                       force: Callable[[Array, Array], Array] | None = None) -> Vector:
    """The Dirac flow (dot_XP) of a Hamiltonian given by its gradient (X, P) ↦ (∂H/∂X, ∂H/∂P), each
    point of the state constrained to its own T*V: Π = sym(Xᵀ∂H/∂P), and Λ from
    d/dt(XᵀP + PᵀX) = 0 (with XᵀX = I).  ``force(X, dX/dt)`` is an extra term of dP/dt (a magnetic
    force from a twisted symplectic form), included before Λ is solved."""

    def rhs(X: Array, P: Array) -> tuple[Array, Array]:
        HX, HP = gradient(X, P)
        Pi = _sym(_T(X) @ HP)
        Xd = HP - X @ Pi
        P0 = -HX + P @ Pi
        if force is not None:
            P0 = P0 + force(X, Xd)
        Lam = -_sym(_T(Xd) @ P + _T(X) @ P0)
        return Xd, P0 + X @ Lam

    return rhs


MANAKOV_SCHEME = ("the implicit midpoint rule of the collective field Ẋ = ΩX, Ṗ = ΩP, Ω = 𝔸Φ (the Hamiltonian field of "
                  "½⟨𝔸Φ, Φ⟩ on T*R^{n×r}); its step is the Cayley rotation (X, P) ↦ (QX, QP), Q ∈ SO(n)")
COUPLED_SCHEME = ("RATTLE for ½tr PᵀP + ½tr QᵀQ + tr XᵀAY, Strang-split with the exact flow of the Ψ-part "
                  "(κ + ½)(½⟨Ψ_X, Ψ_X⟩ + ½⟨Ψ_Y, Ψ_Y⟩) + β⟨Ψ_X, Ψ_Y⟩ (right rotations)")


def _as_matrix_A(A: Any, n: int, *, name: str = "A") -> Array:
    if A is None:
        return np.diag(np.arange(1, n + 1, dtype=float))
    A = np.asarray(A, dtype=float)
    if A.ndim == 1:
        if A.shape != (n,):
            raise ValueError(f"{name} must have n = {n} eigenvalues, got {A.shape[0]}")
        A = np.diag(A)
    if A.shape != (n, n):
        raise ValueError(f"{name} must be an n x n = {n} x {n} matrix, got shape {A.shape}")
    if not np.all(np.isfinite(A)):
        raise ValueError(f"{name} has entries that are not finite")
    if not np.allclose(A, A.T, atol=1e-12 * max(1.0, np.abs(A).max())):
        raise ValueError(f"{name} must be symmetric")
    return (A + A.T) / 2


def _distinct_diagonal(A: Array, name: str = "A") -> Array:
    if not np.allclose(A, np.diag(np.diag(A))):
        raise ValueError(f"{name} must be diagonal for this flow (its eigenvalues a_i in the coordinates of (Manakov))")
    a = np.diag(A)
    gaps = np.abs(a[:, None] - a[None, :])[~np.eye(len(a), dtype=bool)]
    if len(a) > 1 and gaps.min() <= 1e-12 * max(1.0, np.abs(a).max()):
        raise ValueError(f"the eigenvalues of {name} must be distinct, got {a.tolist()}")
    return a


def _kappa(kappa: Any) -> float:
    try:
        k = float(kappa)
    except (TypeError, ValueError):
        raise ValueError(f"kappa must be a real number, got {kappa!r}") from None
    if not math.isfinite(k) or k <= -1:
        raise ValueError(f"kappa must be finite and > -1 (the metric ds²_κ is positive definite only then), got {kappa!r}")
    return k


def _lambdas(a: Array, count: int = 3) -> tuple[float, ...]:
    """A few spectral parameters away from the eigenvalues of A (the poles of the resolvents)."""
    candidates = (-0.731, 1.618, 2.718, -1.414, 0.577, 3.3, -2.2, 4.4)
    spread = max(1.0, float(np.ptp(a)) if len(a) else 1.0)
    out = [lam for lam in candidates if np.min(np.abs(a - lam), initial=np.inf) > 0.05 * spread]
    return tuple(out[:count])


def _phi(X: Array, P: Array) -> Array:
    """Φ = Σ_points (PXᵀ − XPᵀ) of the first point (n x n)."""
    return P[0] @ X[0].T - X[0] @ P[0].T


def _psi(X: Array, P: Array) -> Array:
    return X[0].T @ P[0] - P[0].T @ X[0]


def _neumann_lax(A: Array, lambdas: tuple[float, ...], eps: float = 0.0,
                 paper: tuple[str, ...] = ("Neumann_LA", "LA1", "LA2")) -> LaxMatrix:
    def L(X: Array, P: Array, lam: float) -> Array:
        Phi = _phi(X, P)
        if eps:
            Phi = Phi + eps * (np.outer(X[0][:, 0], X[0][:, 1]) - np.outer(X[0][:, 1], X[0][:, 0]))
        return lam * Phi + X[0] @ X[0].T - lam ** 2 * A
    return LaxMatrix("L_neum (LA2)" if not eps else "L_neum with Φ_ε (LA2)", paper, L, lambdas)


def _dual_lax(A: Array, lambdas: tuple[float, ...], identity: bool, name: str, paper: tuple[str, ...]) -> LaxMatrix:
    n = A.shape[0]

    def L(X: Array, P: Array, lam: float) -> Array:
        X0, P0 = X[0], P[0]
        r = X0.shape[1]
        R = np.linalg.inv(lam * np.eye(n) - A)
        lower_left = P0.T @ R @ P0 + (np.eye(r) if identity else 0)
        return np.block([[-X0.T @ R @ P0, -X0.T @ R @ X0], [lower_left, P0.T @ R @ X0]])
    return LaxMatrix(name, paper, L, lambdas)


def _jensen_gradient(kappa: float, A: Array | None) -> Callable[[Array, Array], tuple[Array, Array]]:
    c = 0.5 + kappa

    def gradient(X: Array, P: Array) -> tuple[Array, Array]:
        W = _T(X) @ P
        HX = -2 * c * P @ W + (A @ X if A is not None else 0)
        HP = P - 2 * c * X @ _T(W)
        return HX, HP
    return gradient


def _jensen_hamiltonian(kappa: float, A: Array | None) -> Callable[[Array, Array], float]:
    c = 0.5 + kappa

    def H(X: Array, P: Array) -> float:
        X0, P0 = X[0], P[0]
        W = X0.T @ P0
        h = 0.5 * np.sum(P0 * P0) - c * np.trace(W @ W)
        if A is not None:
            h += 0.5 * np.trace(X0.T @ A @ X0)
        return float(h)
    return H


def make_flow(name: str, n: int, r: int, *, kappa: float | None = None, A: Any = None, B: Any = None,
              eps: float | None = None, perturbed: bool = False, printed: bool = False) -> Flow:
    """One of the paper's flows by name (see the module docstring) at the size (n, r).

    ``A`` is an n x n symmetric matrix or the vector of its eigenvalues (default diag(1, …, n));
    ``B`` (Manakov only) a diagonal matrix or vector (default A²).  The magnetic flow is the Dirac flow
    of H_neum,κ for the twisted form (twisted), for every κ: the Lorentz force ε(ė₂, −ė₁) is added to
    dP/dt before the multipliers are solved (ι_v(ω + ε de₁∧de₂) = −dH gives ṗ₁ = −∂H/∂e₁ + εė₂,
    ṗ₂ = −∂H/∂e₂ − εė₁); ``printed=True`` integrates (mag-euk), (mag-nor) as printed (κ = −½, 0),
    which agree with it on T*V but, as ODEs on n × 2 matrices, leave T*V unstably."""
    _check_size(n, r)
    if name not in FLOWS:
        raise ValueError(f"unknown flow {name!r}; the flows are {', '.join(FLOWS)} (or give a callable (X, P) -> (dX, dP))")
    if name in ("neumann", "jensen"):
        k = _kappa(-0.5 if kappa is None else kappa)
        Am = _as_matrix_A(A, n) if name == "neumann" else None
        grad = _jensen_gradient(k, Am)
        pot = (lambda X: Am @ X) if Am is not None else (lambda X: np.zeros_like(X))
        inv: dict[str, Callable[[Array, Array], Array]] = {"Ψ (right momentum)": _psi}
        if name == "jensen":
            inv["Φ (left momentum)"] = _phi
            Az = np.zeros((n, n))
            lams = (0.7, -1.3, 2.1)
            lax = (LaxMatrix("L = λΦ + XXᵀ (LA2 with A = 0)", ("Neumann_LA", "LA2"),
                             _neumann_lax(Az, lams).matrix, lams),)
            paper = ("EM",)
            params = {"kappa": k}
        else:
            a = np.linalg.eigvalsh(Am)
            lams = _lambdas(a)
            lax = (_neumann_lax(Am, lams),
                   _dual_lax(Am, lams, True, "L*_neum (LA3)", ("DUAL", "LA3", "LA4")))
            paper = ("neumann", "No")
            params = {"kappa": k, "A": Am}
        return Flow(name, n, r, dirac_vector_field(grad), 1, _jensen_hamiltonian(k, Am), lax, inv, pot, 0.5 + k,
                    params, paper)
    if name == "manakov":
        Am = _as_matrix_A(A, n)
        a = _distinct_diagonal(Am)
        if B is None:
            b = a ** 2
        else:
            Bm = _as_matrix_A(B, n, name="B")
            if not np.allclose(Bm, np.diag(np.diag(Bm))):
                raise ValueError("B must be diagonal (it commutes with the diagonal A)")
            b = np.diag(Bm)
        den = a[:, None] - a[None, :]
        np.fill_diagonal(den, 1.0)
        coef = (b[:, None] - b[None, :]) / den
        np.fill_diagonal(coef, 0.0)

        def op(xi: Array) -> Array:
            return coef * xi

        def rhs(X: Array, P: Array) -> tuple[Array, Array]:
            Om = op(_phi(X, P))
            return (Om @ X[0])[None], (Om @ P[0])[None]

        def H(X: Array, P: Array) -> float:
            Phi = _phi(X, P)
            return 0.5 * _killing(op(Phi), Phi)

        lams = (0.7, -1.3, 2.1)
        lax: tuple[LaxMatrix, ...] = (LaxMatrix("L_man = Φ + λA", ("Manakov", "dot_XP2", "man"),
                                                lambda X, P, lam: _phi(X, P) + lam * Am, lams),)
        if B is None:
            dl = _lambdas(a)
            lax += (_dual_lax(Am, dl, False, "L*_man (MAN-LA2)", ("man-dual", "MAN-LA", "MAN-LA2", "LA-MAN3")),)
        bname = "A²" if B is None else "diag(" + ", ".join(f"{x:g}" for x in b) + ")"
        return Flow(name, n, r, rhs, 1, H, lax, {"Ψ (right momentum)": _psi}, None, 0.0, {"A": Am, "B": bname},
                    ("Manakov", "dot_XP2", "dot_XP3*") if B is None else ("Manakov", "dot_XP2"),
                    symplectic=_collective_midpoint(coef), symplectic_scheme=MANAKOV_SCHEME)
    if name == "magnetic":
        if r != 2:
            raise ValueError(f"the magnetic Neumann flows live on V(n, 2); got r = {r}")
        k = _kappa(-0.5 if kappa is None else kappa)
        if printed and k not in (-0.5, 0.0):
            raise ValueError(f"the magnetic flows are printed for kappa = -1/2 (mag-euk) and kappa = 0 (mag-nor), got {k}")
        e = 0.0 if eps is None else float(eps)
        if not math.isfinite(e):
            raise ValueError(f"eps must be finite, got {eps!r}")
        Am = _as_matrix_A(A, n)
        if printed:
            rhs = _magnetic_rhs(Am, e, k)
        else:
            J = np.array([[0.0, -1.0], [1.0, 0.0]])
            rhs = dirac_vector_field(_jensen_gradient(k, Am), lambda X, Xd: e * Xd @ J)
        a = np.linalg.eigvalsh(Am)
        params: dict[str, Any] = {"kappa": k, "eps": e, "A": Am}
        if printed:
            params["printed"] = True
        return Flow(name, n, r, rhs, 1, _jensen_hamiltonian(k, Am),
                    (_neumann_lax(Am, _lambdas(a), e, ("mag-mom-stief", "mag-euk", "mag-nor")),),
                    {"Ψ_12 = (e₁,p₂) − (e₂,p₁)":
                         lambda X, P: np.array([[X[0][:, 0] @ P[0][:, 1] - X[0][:, 1] @ P[0][:, 0]]])},
                    None, 0.0, params, (("mag-euk",) if k == -0.5 else ("mag-nor",) if k == 0 else ("twisted",)),
                    symplectic=None if printed else _magnetic_step(Am, e, k),
                    symplectic_scheme="" if printed else MAGNETIC_SCHEME)
    # coupled
    k = _kappa(0.0 if kappa is None else kappa)
    Am = _as_matrix_A(A, n)
    return _coupled_flow(n, r, k, Am, perturbed)


#: the sign σ of the gauge P̃ = P + σ(ε/2)XJ, J = [[0, 1], [−1, 0]], that makes ω_ε canonical
_GAUGE_SIGN = 1.0
MAGNETIC_SCHEME = ("RATTLE in the gauge-shifted momenta P̃ = P + (ε/2)XJ, J = [[0, 1], [−1, 0]] (ω_ε is canonical in (X, P̃), "
                   "T*V is the same set), Strang-split with the exact right rotation generated by the Ψ-part of H")


def _magnetic_step(A: Array, eps: float, kappa: float) -> Callable[[Array, Array, float], tuple[Array, Array]]:
    """The symplectic step of the magnetic flow on V(n, 2) for the twisted form ω_ε = ω + ε de₁∧de₂.

    ε de₁∧de₂ = d(ε/2 (e₁·de₂ − e₂·de₁)), so in the momenta P̃ = P + (ε/2)XJ, J = [[0, 1], [−1, 0]]
    (p̃₁ = p₁ − (ε/2)e₂, p̃₂ = p₂ + (ε/2)e₁) the form is canonical, sym(XᵀP̃) = sym(XᵀP) (T*V is the same
    set) and Φ(X, P̃) = Φ_ε.  On T*V, XᵀP̃ = w̃J and H_κ(X, P) = ½tr P̃ᵀP̃ + ½tr XᵀAX + f(w̃),
    f(w) = −εw + 2(κ + ½)(w − ε/2)² + const: the Euclidean Neumann Hamiltonian in (X, P̃) plus a function
    of the right momentum w̃, which commutes with it; the flow of f is (X, P̃) ↦ (X, P̃)·exp(t f′(w̃)/2 · J).
    So the magnetic flow is RATTLE for the Neumann potential in (X, P̃) with that exact rotation."""
    c = 0.5 + kappa
    J = np.array([[0.0, 1.0], [-1.0, 0.0]])
    sg = _GAUGE_SIGN

    def gauge(X: Array) -> Array:
        return sg * eps / 2 * X @ J

    def psi_flow(X: Array, Pt: Array, s: float) -> tuple[Array, Array]:
        W = _T(X[0]) @ Pt[0]
        w = (W[0, 1] - W[1, 0]) / 2
        rate = (-sg * eps + 4 * c * (w - sg * eps / 2)) / 2
        R = expm_skew(s * rate * J)
        return X @ R, Pt @ R

    return _split(lambda X: A @ X, psi_flow, gauge)


def _magnetic_rhs(A: Array, eps: float, kappa: float) -> Vector:
    """(mag-euk) for κ = −½ and (mag-nor) for κ = 0, as printed."""

    def rhs(X: Array, P: Array) -> tuple[Array, Array]:
        e1, e2 = X[0][:, 0], X[0][:, 1]
        p1, p2 = P[0][:, 0], P[0][:, 1]
        if kappa == -0.5:
            de1, de2 = p1, p2
            dp1 = (-A @ e1 + (e1 @ A @ e1 - p1 @ p1 - eps * (e1 @ p2)) * e1
                   + (e1 @ A @ e2 - p1 @ p2) * e2 + eps * p2)
            dp2 = (-A @ e2 + (e1 @ A @ e2 - p1 @ p2) * e1
                   + (e2 @ A @ e2 - p2 @ p2 + eps * (e2 @ p1)) * e2 - eps * p1)
        else:
            Phi0 = np.outer(p1, e1) - np.outer(e1, p1) + np.outer(p2, e2) - np.outer(e2, p2)
            de1, de2 = Phi0 @ e1, Phi0 @ e2
            dp1 = (Phi0 @ p1 - A @ e1 + (e1 @ A @ e1 - eps * (e1 @ Phi0 @ e2)) * e1
                   + (e1 @ A @ e2) * e2 + eps * Phi0 @ e2)
            dp2 = (Phi0 @ p2 - A @ e2 + (e2 @ A @ e1) * e1
                   + (e2 @ A @ e2 + eps * (e2 @ Phi0 @ e1)) * e2 - eps * Phi0 @ e1)
        return np.stack([de1, de2], axis=1)[None], np.stack([dp1, dp2], axis=1)[None]

    return rhs


def _coupled_flow(n: int, r: int, kappa: float, A: Array, perturbed: bool) -> Flow:
    """(C-neumann): H = T_κ + tr(XᵀAY) on T*V × T*V (points X, Y with momenta P, Q), or the perturbed
    H_κ = T_κ + tr(XᵀAY) − 2κ tr(XᵀP YᵀQ)."""
    c = 0.5 + kappa
    g = -2 * kappa if perturbed else 0.0

    def gradient(Z: Array, M: Array) -> tuple[Array, Array]:
        X, Y, P, Q = Z[0], Z[1], M[0], M[1]
        WX, WY = X.T @ P, Y.T @ Q
        HX = -2 * c * P @ WX + A @ Y + g * P @ WY
        HY = -2 * c * Q @ WY + A @ X + g * Q @ WX
        HP = P - 2 * c * X @ WX.T + g * X @ WY.T
        HQ = Q - 2 * c * Y @ WY.T + g * Y @ WX.T
        return np.stack([HX, HY]), np.stack([HP, HQ])

    def H(Z: Array, M: Array) -> float:
        X, Y, P, Q = Z[0], Z[1], M[0], M[1]
        WX, WY = X.T @ P, Y.T @ Q
        T = 0.5 * np.sum(P * P) - c * np.trace(WX @ WX) + 0.5 * np.sum(Q * Q) - c * np.trace(WY @ WY)
        return float(T + np.trace(X.T @ A @ Y) + g * np.trace(WX @ WY))

    a = np.linalg.eigvalsh(A)

    def big(Z: Array, M: Array, nu: float) -> Array:
        X, Y, P, Q = Z[0], Z[1], M[0], M[1]
        O = np.zeros((n, n))
        return (np.block([[O, A], [A, O]]) * nu
                + np.block([[P @ X.T - X @ P.T, O], [O, Q @ Y.T - Y @ Q.T]])
                + np.block([[O, X @ Y.T], [Y @ X.T, O]]) / nu)

    def small(Z: Array, M: Array, lam: float) -> Array:
        X, Y, P, Q = Z[0], Z[1], M[0], M[1]
        Rr = np.linalg.inv(A @ A - lam ** 2 * np.eye(n))
        F = lambda U, V: U.T @ Rr @ V  # noqa: E731  F_λ(U, V) = Uᵀ(A² − λ²)⁻¹V
        I = np.eye(r)
        return np.block([
            [lam * F(P, X), lam * F(P, P), F(A @ P, Y), -I + F(A @ P, Q)],
            [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
            [F(A @ Q, X), -I + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
            [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])

    nus = (0.7, -1.3, 2.1)
    lams = tuple(lam for lam in (0.37, 1.618, 2.718, -0.731, 4.4) if np.min(np.abs(np.abs(a) - abs(lam))) > 0.05)[:3]
    def big_corrected(Z: Array, M: Array, nu: float) -> Array:
        return big(Z, M, nu) - 2 * np.block([[np.zeros((n, n)), Z[0] @ Z[1].T], [Z[1] @ Z[0].T, np.zeros((n, n))]]) / nu

    lax = (LaxMatrix("L(ν) in so(n,n) (so(n,n))", ("so(n,n)",), big, nus),
           LaxMatrix("L(ν) in so(n,n) with −ν⁻¹ (correction)", ("so(n,n)",), big_corrected, nus, printed=False,
                     note="the ν⁻¹ term [[0, XYᵀ], [YXᵀ, 0]] with the opposite sign; then dL/dt = [L_+(ν), L(ν)]"),
           LaxMatrix("4r x 4r L(λ) (LA3*C)", ("dual-DC", "LA3*C", "LA4*C"), small, lams))
    inv = {"XᵀP − PᵀX + YᵀQ − QᵀY": lambda Z, M: Z[0].T @ M[0] - M[0].T @ Z[0] + Z[1].T @ M[1] - M[1].T @ Z[1]}
    pot = lambda Z: np.stack([A @ Z[1], A @ Z[0]])  # noqa: E731
    return Flow("coupled", n, r, dirac_vector_field(gradient), 2, H, lax, inv, pot if kappa == -0.5 and not perturbed else None,
                0.0, {"kappa": kappa, "perturbed": perturbed, "A": A}, ("C-neumann", "C-eq"),
                symplectic=_split(pot, _coupled_psi_flow(kappa + 0.5, kappa if perturbed else 0.0)),
                symplectic_scheme=COUPLED_SCHEME)


def _coupled_psi_flow(a: float, beta: float) -> Callable[[Array, Array, float], tuple[Array, Array]] | None:
    """The exact flow on T*V × T*V of F = a(½⟨Ψ_X, Ψ_X⟩ + ½⟨Ψ_Y, Ψ_Y⟩) + β⟨Ψ_X, Ψ_Y⟩, the part of the
    coupled H_κ that is not ½tr PᵀP + ½tr QᵀQ + tr XᵀAY (on T*V, XᵀP = Ψ_X/2: −(κ+½)tr(XᵀP)² =
    (κ+½)·½⟨Ψ_X, Ψ_X⟩ and −2κ tr(XᵀP YᵀQ) = κ⟨Ψ_X, Ψ_Y⟩).  The X-point turns with the generator
    ∂F/∂Ψ_X = aΨ_X + βΨ_Y; S = Ψ_X + Ψ_Y is constant, Ψ_X(t) = e^{−tβS}Ψ_X(0)e^{tβS}, and
    X(t) = X(0)e^{t(a−β)Ψ_X(0)}e^{tβS} (likewise P, and Y, Q with Ψ_Y)."""
    if a == 0 and beta == 0:
        return None

    def flow(Z: Array, M: Array, s: float) -> tuple[Array, Array]:
        Psi = [_T(Z[i]) @ M[i] - _T(M[i]) @ Z[i] for i in range(2)]
        E = expm_skew(s * beta * (Psi[0] + Psi[1])) if beta else None
        Rs = [expm_skew(s * (a - beta) * Psi[i]) for i in range(2)]
        if E is not None:
            Rs = [R @ E for R in Rs]
        return np.stack([Z[i] @ Rs[i] for i in range(2)]), np.stack([M[i] @ Rs[i] for i in range(2)])

    return flow


def custom_flow(rhs: Callable[[Array, Array], tuple[Array, Array]] | None = None, *, n: int, r: int,
                hamiltonian: Callable[[Array, Array], float] | None = None,
                invariants: Mapping[str, Callable[[Array, Array], Any]] | None = None,
                constraint: Callable[[Array, Array], float] | None = None,
                lax: Mapping[str, Callable[[Array, Array, float], Any]] | None = None,
                lambdas: Sequence[float] = (0.7, -1.3, 2.1),
                potential: Callable[[Array], float] | None = None,
                potential_gradient: Callable[[Array], Array] | None = None, name: str = "custom") -> Flow:
    """A user's flow on T*V(n, r), on n x r matrices.

    Either ``rhs(X, P) -> (dX/dt, dP/dt)``, or ``potential_gradient`` (X ↦ ∂V/∂X, optionally with
    ``potential`` X ↦ V) for H = ½tr PᵀP + V(X): its Dirac flow is derived, and RATTLE applies.
    Optional: a Hamiltonian, named invariants (X, P) -> array, an extra constraint (X, P) -> residual
    norm, and Lax matrices {name: (X, P, λ) -> square matrix} whose spectra are followed at ``lambdas``."""
    _check_size(n, r)
    if rhs is None and potential_gradient is None:
        raise ValueError("give the flow as a callable (X, P) -> (dX, dP), or the potential gradient X -> dV/dX")
    if rhs is not None and not callable(rhs):
        raise ValueError(f"a flow is a name ({', '.join(FLOWS)}) or a callable (X, P) -> (dX, dP), got {rhs!r}")
    if potential_gradient is not None and not callable(potential_gradient):
        raise ValueError(f"potential_gradient must be a callable X -> dV/dX, got {potential_gradient!r}")

    def checked(what: str, M: Any) -> Array:
        M = np.asarray(M, float)
        if M.shape != (n, r):
            raise ValueError(f"{what} returned shape {M.shape}; expected ({n}, {r})")
        return M

    grad = None
    if potential_gradient is not None:
        user_grad = potential_gradient

        def grad(X: Array) -> Array:
            return np.stack([checked("potential_gradient", user_grad(X[i])) for i in range(X.shape[0])])

    if rhs is not None:
        def wrapped(X: Array, P: Array) -> tuple[Array, Array]:
            out = rhs(X[0], P[0])
            try:
                Xd, Pd = out
            except (TypeError, ValueError):
                raise ValueError("the flow callable must return a pair (dX/dt, dP/dt)") from None
            return checked("the flow callable", Xd)[None], checked("the flow callable", Pd)[None]
    else:
        assert grad is not None
        g = grad
        wrapped = dirac_vector_field(lambda X, P: (g(X), P))

    if hamiltonian is not None:
        H = lambda X, P: float(hamiltonian(X[0], P[0]))  # noqa: E731
    elif rhs is None:
        V = potential
        H = (lambda X, P: 0.5 * float(np.sum(P[0] * P[0])) + float(V(X[0]))) if V is not None else None  # noqa: E731
    else:
        H = None
    inv = {k: (lambda f: (lambda X, P: np.atleast_2d(np.asarray(f(X[0], P[0]), float))))(f)
           for k, f in (invariants or {}).items()}
    con = (lambda X, P: float(constraint(X[0], P[0]))) if constraint else None
    laxes = tuple(LaxMatrix(k, (), (lambda f: (lambda X, P, lam: np.asarray(f(X[0], P[0], lam), float)))(f),
                            tuple(float(x) for x in lambdas)) for k, f in (lax or {}).items())
    return Flow(name, n, r, wrapped, 1, H, laxes, inv, grad, 0.0, {}, (), con)


# --------------------------------------------------------------------------- steppers

def _rk4_step(f: Vector, X: Array, P: Array, h: float) -> tuple[Array, Array]:
    k1 = f(X, P)
    k2 = f(X + h / 2 * k1[0], P + h / 2 * k1[1])
    k3 = f(X + h / 2 * k2[0], P + h / 2 * k2[1])
    k4 = f(X + h * k3[0], P + h * k3[1])
    return (X + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
            P + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))


def _kron(a: Array, b: Array) -> Array:
    return (a[:, None, :, None] * b[None, :, None, :]).reshape(a.shape[0] * b.shape[0], a.shape[1] * b.shape[1])


def _shake(Xn: Array, Y: Array, max_iter: int = 50) -> Array:
    """X = Y − Xn·M with M symmetric and XᵀX = I (one point), by the chord (simplified Newton) method on
    M: CᵀM + MC = F(M) + M², C = XnᵀY, F(M) = YᵀY − I (the Jacobian of the Newton method at M = 0;
    M = O(h²), so each iteration gains a factor O(h²))."""
    r = Xn.shape[1]
    I = np.eye(r)
    K = Y.T @ Xn                       # Cᵀ, C = XnᵀY
    Linv = np.linalg.inv(_kron(I, K) + _kron(K, I))    # (Cᵀδ + δC) in column-major vec, inverted once
    F0 = (Y.T @ Y - I).ravel(order="F")
    M = np.zeros((r, r))
    X = Y
    for _ in range(max_iter):
        X = Y - Xn @ M
        err = np.abs(X.T @ X - I).max()
        if err <= 4e-16:
            break
        M = (Linv @ (F0 + (M @ M).ravel(order="F"))).reshape(r, r, order="F")
        M = (M + M.T) / 2
    else:
        if not err <= 1e-12:
            raise RuntimeError(f"SHAKE did not converge (‖XᵀX − I‖ = {err:.1e}): the step is too large for this flow")
    return X


def _rattle_step(flow: Flow, X: Array, P: Array, h: float) -> tuple[Array, Array]:
    grad = flow.potential_gradient
    assert grad is not None
    return _rattle(grad, X, P, h)


def _rattle(grad: Callable[[Array], Array], X: Array, P: Array, h: float) -> tuple[Array, Array]:
    """One RATTLE step of H = ½tr PᵀP + V(X) on T*V (each point of the state on its own T*V)."""
    Ph = P - h / 2 * grad(X)
    Y = X + h * Ph
    Xn = _shake(X[0], Y[0])[None] if X.shape[0] == 1 else np.stack([_shake(X[i], Y[i]) for i in range(X.shape[0])])
    Ph = (Xn - X) / h                          # the half-step momentum with the constraint force
    Pt = Ph - h / 2 * grad(Xn)
    Pn = Pt - Xn @ _sym(_T(Xn) @ Pt)           # RATTLE's second multiplier: the exact tangent projection
    return Xn, Pn


def _cayley(S: Array, h: float) -> Array:
    """(I − hS/2)⁻¹(I + hS/2): orthogonal for S skew-symmetric."""
    I = np.eye(S.shape[0])
    return np.linalg.solve(I - h / 2 * S, I + h / 2 * S)


def _collective_midpoint(coefficients: Array, max_iter: int = 60
                         ) -> Callable[[Array, Array, float], tuple[Array, Array]]:
    """The implicit midpoint rule for Ẋ = ΩX, Ṗ = ΩP, Ω = 𝔸Φ (entrywise Ω_ij = c_ij Φ_ij), Φ = PXᵀ − XPᵀ.

    This vector field is the Hamiltonian field, in the ambient T*R^{n×r} with tr dPᵀ∧dX, of the
    collective Hamiltonian H = ½⟨𝔸Φ, Φ⟩ (∂H/∂P = ΩX, ∂H/∂X = −ΩP, no multipliers), so the midpoint
    rule is symplectic there; its step is (X, P) ↦ (QX, QP) with the Cayley transform
    Q = cay(hΩ_m) ∈ SO(n) of the midpoint value Ω_m, which keeps XᵀX and XᵀP exactly: T*V (a symplectic
    submanifold) is invariant, and the restricted map is symplectic on T*V.  Symmetric, order 2.
    Ω_m solves Ω = 𝔸(M⁻¹ΦM⁻ᵀ), M = I − hΩ/2 (X_m = M⁻¹X); it is found by a simplified Newton method
    whose Jacobian δΩ ↦ δΩ − (h/2)𝔸[δΩ, Φ] is set up once per step."""
    n = coefficients.shape[0]
    iu = np.triu_indices(n, 1)
    d = len(iu[0])
    E = np.zeros((d, n, n))
    E[np.arange(d), iu[0], iu[1]] = 1.0
    E[np.arange(d), iu[1], iu[0]] = -1.0

    def gen(Phi: Array) -> Array:
        return coefficients * Phi

    def step(X: Array, P: Array, h: float) -> tuple[Array, Array]:
        X0, P0 = X[0], P[0]
        I = np.eye(n)
        Phi = P0 @ X0.T - X0 @ P0.T
        Om = gen(Phi)
        if d:
            Om = gen(Phi + h / 2 * (Om @ Phi - Phi @ Om))    # the predictor Φ(t + h/2) ≈ Φ + (h/2)[Ω, Φ]
            Mi = np.linalg.inv(I - h / 2 * Om)
            Phm = Mi @ Phi @ Mi.T
            # the Jacobian of Ω ↦ Ω − 𝔸(M⁻¹ΦM⁻ᵀ) at the predictor, on the basis E_k of so(n)
            comm = gen(Mi @ E @ Phm - Phm @ E @ Mi.T)
            Jac = np.eye(d) - h / 2 * comm[:, iu[0], iu[1]].T
            Jinv = np.linalg.inv(Jac)
            scale = max(1.0, float(np.abs(Om).max()))
            last = math.inf
            for _ in range(max_iter):
                Mi = np.linalg.inv(I - h / 2 * Om)
                G = (Om - gen(Mi @ Phi @ Mi.T))[iu]
                delta = Jinv @ G
                change = float(np.abs(delta).max())
                D = np.zeros((n, n))
                D[iu] = delta
                Om = Om - (D - D.T)
                # converged: at rounding level, or no longer decreasing once below 1e-13 (rounding noise)
                if change <= 4e-16 * scale or (change >= last and change <= 1e-13 * scale):
                    break
                last = change
            else:
                raise RuntimeError(f"the implicit midpoint iteration did not converge at step h = {h:g}; "
                                   "take a smaller step")
        Q = _cayley(Om, h)
        return (Q @ X0)[None], (Q @ P0)[None]

    return step


def _split(grad: Callable[[Array], Array], psi_flow: Callable[[Array, Array, float], tuple[Array, Array]] | None,
           gauge: Callable[[Array], Array] | None = None) -> Callable[[Array, Array, float], tuple[Array, Array]]:
    """Strang splitting: the exact flow of a function of the right momenta Ψ for h/2 (right rotations),
    a RATTLE step of ½tr PᵀP + V(X), the Ψ-flow for h/2; symplectic, symmetric, order 2, on T*V to
    rounding.  With ``gauge`` (X ↦ a(X)), the step is taken in the momenta P̃ = P + a(X) (where the form
    is canonical) and mapped back."""

    def step(X: Array, P: Array, h: float) -> tuple[Array, Array]:
        if gauge is not None:
            P = P + gauge(X)
        if psi_flow is not None:
            X, P = psi_flow(X, P, h / 2)
        X, P = _rattle(grad, X, P, h)
        if psi_flow is not None:
            X, P = psi_flow(X, P, h / 2)
        if gauge is not None:
            P = P - gauge(X)
        return X, P

    return step


def symplectic_scheme(flow: Flow) -> str:
    """What ``method="rattle"`` does for this flow (``""`` if it does not apply); ``"rattle4"`` is
    Yoshida's triple jump of the same step."""
    if flow.potential_gradient is not None:
        if flow.rotation:
            return ("RATTLE for ½tr PᵀP + V(X), followed by the exact right rotation exp(t(κ + ½)Ψ₀) "
                    "(H_κ = H_{−½} + (κ + ½)·½⟨Ψ, Ψ⟩, the two terms Poisson-commute)")
        return "RATTLE for ½tr PᵀP + V(X)"
    return flow.symplectic_scheme


def expm_skew(S: Array) -> Array:
    """exp(S) for a real skew-symmetric S, orthogonal to rounding whatever ‖S‖ (through the Hermitian
    eigendecomposition of iS, unlike the scaling and squaring of expm)."""
    if S.shape == (2, 2):                      # exp(θJ), J = [[0, 1], [−1, 0]]: the rotation by −θ
        th = (S[0, 1] - S[1, 0]) / 2
        c, s = math.cos(th), math.sin(th)
        return np.array([[c, s], [-s, c]])
    w, U = np.linalg.eigh(1j * (S - S.T) / 2)
    return ((U * np.exp(-1j * w)) @ U.conj().T).real


def _rotate(X: Array, P: Array, Psi0: Array, s: float) -> tuple[Array, Array]:
    R = expm_skew(s * Psi0)
    return X @ R, P @ R


# --------------------------------------------------------------------------- trajectories

@dataclass
class Trajectory:
    """An integrated trajectory with its errors at the sampled times.

    ``X``, ``P`` have shape (k, points, n, r); errors are arrays of length k: ``position_error``
    ‖XᵀX − I‖, ``momentum_error`` ‖XᵀP + PᵀX‖, ``hamiltonian_error`` |H − H(0)|/max(1, |H(0)|),
    ``lax_drift[name]`` the largest change of a power trace tr L(λ)ᵏ over the λ's (see
    :func:`spectral_drift`), ``lax_eigenvalue_drift[name]`` the largest change of a matched eigenvalue
    (see :func:`eigenvalue_drift`), ``invariant_drift[name]`` ‖I(t) − I(0)‖/max(1, ‖I(0)‖)."""

    flow: str
    method: str
    tol: float | None
    step: float | None
    times: Array
    X: Array
    P: Array
    position_error: Array
    momentum_error: Array
    hamiltonian_error: Array | None
    lax_drift: dict[str, Array]
    invariant_drift: dict[str, Array]
    constraint_error: Array | None
    seconds: float
    evaluations: int
    lax_eigenvalue_drift: dict[str, Array] = field(default_factory=dict)

    def max_errors(self) -> dict[str, float]:
        """The largest error of each kind along the trajectory."""
        out = {"position": float(self.position_error.max()), "momentum": float(self.momentum_error.max())}
        if self.hamiltonian_error is not None:
            out["hamiltonian"] = float(self.hamiltonian_error.max())
        for k, v in self.lax_drift.items():
            out[f"lax: {k}"] = float(v.max())
        for k, v in self.invariant_drift.items():
            out[f"invariant: {k}"] = float(v.max())
        if self.constraint_error is not None:
            out["constraint"] = float(self.constraint_error.max())
        return out

    def final(self) -> tuple[Array, Array]:
        """(X, P) at the last time, shaped like the input."""
        X, P = self.X[-1], self.P[-1]
        return (X[0], P[0]) if X.shape[0] == 1 else (X, P)


def spectral_drift(L0: Array, L1: Array) -> float:
    """How far the spectrum of L1 is from that of L0 (m x m): the largest difference of the power traces
    tr Lᵏ, k = 1..m (the coefficients of the characteristic polynomial up to Newton's identities), each
    relative to max(1, ‖L0‖₂)ᵏ.  Unlike matched eigenvalues, this is smooth where eigenvalues collide."""
    m = L0.shape[0]
    s = max(1.0, float(np.linalg.norm(L0, 2)))
    A0, A1 = L0 / s, L1 / s
    P0, P1 = np.eye(m), np.eye(m)
    worst = 0.0
    for _ in range(m):
        P0, P1 = P0 @ A0, P1 @ A1
        worst = max(worst, abs(np.trace(P1) - np.trace(P0)))
    return float(worst)


def eigenvalue_drift(L0: Array, L1: Array) -> float:
    """The largest distance between the eigenvalues of L1 and those of L0, matched optimally (an
    assignment problem; sorting complex eigenvalues is not stable), relative to max(1, spectral radius
    of L0).  Near a multiple eigenvalue this is of the order of the square root of the error."""
    from scipy.optimize import linear_sum_assignment
    e0, e1 = np.linalg.eigvals(L0), np.linalg.eigvals(L1)
    cost = np.abs(e0[:, None] - e1[None, :])
    i, j = linear_sum_assignment(cost)
    return float(cost[i, j].max() / max(1.0, np.abs(e0).max()))


def _diagnostics(flow: Flow, X: Array, P: Array) -> dict[str, Any]:
    e1 = np.empty(len(X))
    e2 = np.empty(len(X))
    for k in range(len(X)):
        e1[k], e2[k] = constraint_errors(X[k], P[k])
    out: dict[str, Any] = {"position": e1, "momentum": e2}
    if flow.hamiltonian is not None:
        H = np.array([flow.hamiltonian(X[k], P[k]) for k in range(len(X))])
        out["hamiltonian"] = np.abs(H - H[0]) / max(1.0, abs(H[0]))
    lax, eig = {}, {}
    for lx in flow.lax:
        L0 = [lx.matrix(X[0], P[0], lam) for lam in lx.lambdas]
        d = np.zeros(len(X))
        e = np.zeros(len(X))
        for k in range(1, len(X)):
            Lk = [lx.matrix(X[k], P[k], lam) for lam in lx.lambdas]
            d[k] = max(spectral_drift(a, b) for a, b in zip(L0, Lk))
            e[k] = max(eigenvalue_drift(a, b) for a, b in zip(L0, Lk))
        lax[lx.name] = d
        eig[lx.name] = e
    out["lax"] = lax
    out["eig"] = eig
    inv = {}
    for name, f in flow.invariants.items():
        I0 = np.asarray(f(X[0], P[0]), float)
        scale = max(1.0, float(np.linalg.norm(I0)))
        inv[name] = np.array([np.linalg.norm(np.asarray(f(X[k], P[k]), float) - I0) / scale for k in range(len(X))])
    out["invariants"] = inv
    if flow.constraint is not None:
        out["constraint"] = np.array([flow.constraint(X[k], P[k]) for k in range(len(X))])
    return out


def _prepare_state(X0: Any, P0: Any, flow: Flow, project: bool) -> tuple[Array, Array]:
    def arr(v: Any, what: str) -> Array:
        try:
            a = np.asarray(v, dtype=float)
        except (TypeError, ValueError):
            raise ValueError(f"{what} must be a real matrix (numpy array), got {type(v).__name__}") from None
        return a

    if flow.points > 1:
        if not (isinstance(X0, (tuple, list)) and isinstance(P0, (tuple, list))
                and len(X0) == flow.points and len(P0) == flow.points):
            raise ValueError(f"the {flow.name} flow has {flow.points} points: give X0 = (X, Y) and P0 = (P, Q)")
        X = np.stack([arr(x, "X0") for x in X0])
        P = np.stack([arr(p, "P0") for p in P0])
    else:
        X, P = arr(X0, "X0")[None], arr(P0, "P0")[None]
    n, r = flow.n, flow.r
    for name, M in (("X0", X), ("P0", P)):
        if M.shape[1:] != (n, r):
            raise ValueError(f"{name} must be an n x r = {n} x {r} matrix for this flow, got shape {M.shape[1:]}")
        if not np.all(np.isfinite(M)):
            raise ValueError(f"{name} has entries that are not finite")
    e1, e2 = constraint_errors(X, P)
    if e1 > ON_SHELL or e2 > ON_SHELL:
        if not project:
            raise ValueError(
                f"(X0, P0) is not on T*V(n, r): ||XᵀX − I|| = {e1:.2e}, ||XᵀP + PᵀX|| = {e2:.2e} "
                f"(tolerance {ON_SHELL:g}); pass project=True to project it (polar factor of X, tangent part of P)")
        if np.linalg.matrix_rank(X[0]) < r or (flow.points > 1 and any(np.linalg.matrix_rank(x) < r for x in X)):
            raise ValueError("X0 has rank < r: it cannot be projected onto the Stiefel variety")
        pts = [project_to_tangent_bundle(X[i], P[i]) for i in range(flow.points)]
        X = np.stack([p[0] for p in pts])
        P = np.stack([p[1] for p in pts])
    return X, P


def _resolve_flow(flow: Any, n: int, r: int, params: dict[str, Any]) -> Flow:
    if isinstance(flow, Flow):
        if params:
            raise ValueError(f"flow parameters {sorted(params)} given together with a ready Flow object")
        return flow
    if isinstance(flow, str):
        allowed = FLOW_PARAMETERS.get(flow)
        if allowed is not None:
            extra = sorted(set(params) - set(allowed))
            if extra:
                raise ValueError(f"the {flow} flow takes the parameters {', '.join(allowed)}; got {', '.join(extra)}")
        return make_flow(flow, n, r, **params)
    if callable(flow):
        try:
            return custom_flow(flow, n=n, r=r, **params)
        except TypeError as exc:
            raise ValueError(f"bad parameters for a user flow: {exc}") from None
    raise ValueError(f"a flow is a name ({', '.join(FLOWS)}), a Flow, or a callable (X, P) -> (dX, dP); got {flow!r}")


def integrate(X0: Any, P0: Any, flow: Any, t_span: Sequence[float] | float, *, method: str = "dop853",
              tol: float | None = None, step: float | None = None, samples: int = 101, project: bool = False,
              **flow_params: Any) -> Trajectory:
    """Integrate ``flow`` from (X0, P0) over ``t_span`` = (t0, t1) (or t1) with ``method``.

    ``tol`` is the relative tolerance of DOP853 (absolute tolerance tol·1e-2; default 1e-10); the
    fixed-step methods use ``step``, or, when it is None, h = tol^(1/2) (RATTLE, order 2) and
    h = tol^(1/4) (RATTLE4, RK4) if ``tol`` is given, else h = 0.01; at most (t1 − t0)/10.  ``samples`` states are kept, evenly spaced in time, and the errors are
    evaluated there.  A point that is off T*V by more than 1e-10 is refused unless ``project``.
    The remaining keywords are the flow's parameters (kappa, A, B, eps, perturbed for a named flow;
    hamiltonian, invariants, constraint, name for a callable)."""
    if isinstance(t_span, (int, float, np.integer, np.floating)):
        t_span = (0.0, float(t_span))
    try:
        t0, t1 = (float(t) for t in t_span)
    except (TypeError, ValueError):
        raise ValueError(f"t_span must be (t0, t1) or t1, got {t_span!r}") from None
    if not (math.isfinite(t0) and math.isfinite(t1)) or t1 <= t0:
        raise ValueError(f"t_span must have finite t0 < t1, got ({t0}, {t1})")
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; the methods are {', '.join(METHODS)}")
    if tol is not None and not (isinstance(tol, (int, float)) and math.isfinite(tol) and tol > 0):
        raise ValueError(f"the tolerance must be a positive number, got {tol!r}")
    if step is not None and not (isinstance(step, (int, float)) and math.isfinite(step) and step > 0):
        raise ValueError(f"the step must be a positive number, got {step!r}")
    if not (isinstance(samples, (int, np.integer)) and samples >= 2):
        raise ValueError(f"samples must be an integer >= 2, got {samples!r}")
    shape = np.shape(X0[0] if isinstance(X0, (tuple, list)) and len(X0) and np.ndim(X0[0]) == 2 else X0)
    if len(shape) != 2:
        raise ValueError(f"X0 must be an n x r matrix, got an array of shape {shape}")
    n, r = int(shape[0]), int(shape[1])
    if r > n:
        raise ValueError(f"X0 is {n} x {r}: the Stiefel variety V(n, r) needs r <= n")
    fl = _resolve_flow(flow, n, r, flow_params)
    X, P = _prepare_state(X0, P0, fl, project)
    if method in ("rattle", "rattle4") and fl.potential_gradient is None and fl.symplectic is None:
        raise ValueError(
            f"RATTLE covers the named flows (Neumann, Jensen, Manakov, magnetic, coupled) and user flows given by a "
            f"potential; {fl.label} is an ODE without that structure (for the magnetic flows: integrate the derived "
            f"flow, printed=False, which agrees with (mag-euk), (mag-nor) on T*V); use dop853 or rk4")
    ts = np.linspace(t0, t1, samples)
    m = fl.points
    started = time.perf_counter()
    if method == "dop853":
        rtol = DEFAULT_TOL if tol is None else tol
        nxr = n * r * m

        def f(t: float, y: Array) -> Array:
            Xd, Pd = fl.rhs(y[:nxr].reshape(m, n, r), y[nxr:].reshape(m, n, r))
            return np.concatenate([np.ravel(Xd), np.ravel(Pd)])

        sol = solve_ivp(f, (t0, t1), np.concatenate([X.ravel(), P.ravel()]), method="DOP853", t_eval=ts,
                        rtol=rtol, atol=rtol * 1e-2)
        if sol.status != 0:
            raise RuntimeError(f"DOP853 failed on {fl.label}: {sol.message}")
        Ys = sol.y.T
        Xs, Ps = Ys[:, :nxr].reshape(-1, m, n, r), Ys[:, nxr:].reshape(-1, m, n, r)
        evals, used_step = int(sol.nfev), None
    else:
        order = 2 if method == "rattle" else 4
        h = step if step is not None else DEFAULT_STEP if tol is None else tol ** (1.0 / order)
        h = min(h, (t1 - t0) / 10)
        per = max(1, int(math.ceil((t1 - t0) / (samples - 1) / h)))
        h = (t1 - t0) / (samples - 1) / per
        Xs, Ps = [X], [P]
        Psi0 = np.stack([_T(X[i]) @ P[i] - _T(P[i]) @ X[i] for i in range(m)])
        evals = 0
        sym_step = fl.symplectic if fl.potential_gradient is None else partial(_rattle_step, fl)
        for k in range(1, samples):
            for _ in range(per):
                if method == "rattle":
                    X, P = sym_step(X, P, h)
                    evals += 1
                elif method == "rattle4":
                    for w in _YOSHIDA:
                        X, P = sym_step(X, P, w * h)
                    evals += 3
                else:
                    X, P = _rk4_step(fl.rhs, X, P, h)
                    pts = [project_to_tangent_bundle(X[i], P[i]) for i in range(m)]
                    X, P = np.stack([q[0] for q in pts]), np.stack([q[1] for q in pts])
                    evals += 4
            if method in ("rattle", "rattle4") and fl.rotation and fl.potential_gradient is not None:
                # the exact right rotation of the κ-part, applied at the sample times only (it commutes)
                Xr, Pr = zip(*[_rotate(X[i], P[i], Psi0[i], fl.rotation * (ts[k] - t0)) for i in range(m)])
                Xs.append(np.stack(Xr))
                Ps.append(np.stack(Pr))
            else:
                Xs.append(X)
                Ps.append(P)
        Xs, Ps, used_step = np.stack(Xs), np.stack(Ps), h
    seconds = time.perf_counter() - started
    diag = _diagnostics(fl, Xs, Ps)
    used_tol = rtol if method == "dop853" else tol if step is None else None
    return Trajectory(fl.label, method, used_tol, used_step, ts, Xs, Ps,
                      diag["position"], diag["momentum"], diag.get("hamiltonian"), diag["lax"], diag["invariants"],
                      diag.get("constraint"), seconds, evals, diag["eig"])


# --------------------------------------------------------------------------- closed forms (Edelman–Arias–Smith)

def metric_beta(kappa: float) -> float:
    """The metric ds²_κ of (EM) is g(Ẋ, Ẋ) = tr Ẋᵀ(I − βXXᵀ)Ẋ with β = (1 + 2κ)/(2 + 2κ).

    The Legendre map of H_κ is Ẋ = P − (1 + 2κ)XPᵀX (No), so XᵀẊ = 2(1 + κ)XᵀP and the normal parts
    agree; the kinetic energy tr(ẊᵀP)/2 is then ½(‖(I − XXᵀ)Ẋ‖² + ‖XᵀẊ‖²/(2 + 2κ)).  κ = −½ gives β = 0,
    the Euclidean metric tr ΔᵀΔ of Edelman–Arias–Smith; κ = 0 gives β = ½, their canonical metric
    tr Δᵀ(I − ½YYᵀ)Δ, with the same time and Δ = Ẋ."""
    k = _kappa(kappa)
    return (1 + 2 * k) / (2 + 2 * k)


def euclidean_geodesic(X0: Array, V0: Array, t: float) -> Array:
    """Edelman–Arias–Smith (1998), §2.2.2: the geodesic of the Euclidean metric from X0 with velocity V0,
    X(t) = [X0, V0] exp(t[[A, −S], [I, A]]) I_{2r,r} exp(−tA), A = X0ᵀV0, S = V0ᵀV0."""
    r = X0.shape[1]
    A = X0.T @ V0
    S = V0.T @ V0
    M = np.block([[A, -S], [np.eye(r), A]])
    E = expm(t * M)[:, :r]
    return np.hstack([X0, V0]) @ E @ expm(-t * A)


def canonical_geodesic(X0: Array, V0: Array, t: float) -> Array:
    """Edelman–Arias–Smith (1998), §2.4.2: the geodesic of the canonical metric from X0 with velocity V0,
    X(t) = X0 M(t) + Q N(t), [M; N] = exp(t[[A, −Rᵀ], [R, 0]]) I_{2r,r}, A = X0ᵀV0, QR = (I − X0X0ᵀ)V0."""
    n, r = X0.shape
    A = X0.T @ V0
    Q, R = np.linalg.qr(V0 - X0 @ A)
    M = np.block([[A, -R.T], [R, np.zeros((r, r))]])
    E = expm(t * M)[:, :r]
    return X0 @ E[:r] + Q @ E[r:]


def jensen_geodesic(X0: Array, P0: Array, kappa: float, t: float) -> tuple[Array, Array]:
    """The closed-form geodesic of ds²_κ from (X0, P0) ∈ T*V: the Euclidean geodesic with velocity P0
    (κ = −½, P = Ẋ), followed by the right rotation exp(t(κ + ½)Ψ0), Ψ0 = X0ᵀP0 − P0ᵀX0 (the flows of
    H_{−½} and ⟨Ψ, Ψ⟩ commute).  Returns (X(t), P(t))."""
    k = _kappa(kappa)
    r = X0.shape[1]
    A = X0.T @ P0
    S = P0.T @ P0
    M = np.block([[A, -S], [np.eye(r), A]])
    E = expm(t * M)
    B = np.hstack([X0, P0])
    XE = B @ E[:, :r] @ expm(-t * A)
    # P = dX/dt along the Euclidean geodesic: d/dt (B e^{tM} I e^{−tA}) = B e^{tM}(M I − I A) e^{−tA}
    PE = B @ (E @ M)[:, :r] @ expm(-t * A) - XE @ A
    R = expm_skew(t * (0.5 + k) * (A - A.T))
    return XE @ R, PE @ R
