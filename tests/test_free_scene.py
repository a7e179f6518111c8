"""The free scene on the paper: Neumann flows, Lax pairs (LA1, LA3/LA4), (prep), Dirac flows.

Each claim is written once against the scene interface; a residual whose
normal form is 0 holds for every n, r and every symmetric A.  Negative
controls (corrupted claims) must not reduce to 0, and their nonzero normal
forms are certified at an exact point of T*V.
"""
from __future__ import annotations

import copy

import random
from fractions import Fraction

import numpy as np
import pytest
import symengine as se

from stiefelsym.backends.fields import Dual, RationalField
from stiefelsym.free.algebra import DIMENSIONS, NCPoly, evaluate
from stiefelsym.free.scene import LAMBDA, FreeScene, NeedsCoordinates
from stiefelsym.backends.matrix import Mat, block, comm
from stiefelsym.scene import Flow, Scene

from test_free_rewriting import exact_point

KAPPAS = {"kappa": None, "normal": 0, "euclidean": Fraction(-1, 2)}


def neumann_flow(s, kappa, flip: str = "") -> Flow:
    """(No): Ẋ = P − (1+2κ)XPᵀX, Ṗ = −AX − XPᵀP + (1+2κ)PXᵀP + XXᵀAX; ``flip`` corrupts a sign."""
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * (s.kappa if kappa is None else kappa)
    sx = -1 if flip == "Xdot" else 1
    sa = -1 if flip == "AX" else 1
    return Flow(P - X @ P.T @ X * (c * sx), -(A @ X) * sa - X @ P.T @ P + P @ X.T @ P * c + X @ X.T @ A @ X)


def neumann_hamiltonian(s):
    """(neumann): ½tr(PᵀP) − (½+κ)tr((XᵀP)²) + ½tr(XᵀAX)."""
    return (s.tr(s.P.T @ s.P) * s.q(1, 2) - s.tr(s.X.T @ s.P @ s.X.T @ s.P) * (s.q(1, 2) + s.kappa)
            + s.tr(s.X.T @ s.A @ s.X) * s.q(1, 2))


def L_neum(s):
    """(LA2): L = λΦ + XXᵀ − λ²A."""
    return s.lam * s.Phi + s.X @ s.X.T - s.lam ** 2 * s.A


def A_neum(s):
    """(LA2): M = Φ − λA."""
    return s.Phi - s.lam * s.A


def L_dual(s):
    """(LA3): the 2r×2r matrix L*(λ) with R = (λI − A)^{-1}."""
    R, X, P = s.resolvent(s.lam), s.X, s.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]])


def A_dual(s, kappa):
    """(LA4): A*(λ) for (N0_XP2) (κ = 0) and for (NE_XP) (κ = −½), Λ = XᵀAX − PᵀP."""
    X, P = s.X, s.P
    Lam = X.T @ s.A @ X - P.T @ P
    lamI = s.scalar_matrix(s.lam, s.r, "r")
    if kappa == 0:
        return block([[X.T @ P, s.Ir], [Lam - lamI, -(P.T @ X)]])
    zero = s.zeros(s.r, s.r, ("r", "r"))
    return block([[zero, s.Ir], [Lam - lamI, zero]])


def la1_residual(s, kappa, flip="", swap=False):
    flow = neumann_flow(s, kappa, flip)
    L, M = L_neum(s), A_neum(s)
    return s.d(L_neum, flow) - (comm(L, M) if swap else comm(M, L))


def la3_residual(s, kappa, flow_kappa=None, swap=False):
    flow = neumann_flow(s, kappa if flow_kappa is None else flow_kappa)
    L, M = L_dual(s), A_dual(s, kappa)
    return s.d(L_dual, flow) - (comm(M, L) if swap else comm(L, M))


def certified_nonzero(s, M: Mat, seed: int = 0) -> bool:
    """Some entry of M's normal form is nonzero at an exact point of T*V_{5,2}."""
    values, scalars = exact_point(5, 2, seed)
    for x in M._a.flat:
        v = evaluate(x, values, scalars)
        if np.any(v != 0) if isinstance(v, np.ndarray) else v != 0:
            return True
    return False


# ---------------------------------------------------------------------------
@pytest.mark.parametrize("kappa", KAPPAS.values(), ids=KAPPAS.keys())
def test_neumann_LA1_holds_for_every_n_and_r(kappa):
    """Theorem Neumann_LA: (No) implies dL/dt = [M, L] for L = λΦ + XXᵀ − λ²A, M = Φ − λA."""
    assert la1_residual(FreeScene(), kappa).is_zero()


@pytest.mark.parametrize("flip", ["Xdot", "AX"])
def test_negative_control_LA1_with_a_sign_flipped_in_the_flow_fails(flip):
    s = FreeScene()
    res = la1_residual(s, None, flip=flip)
    assert not res.is_zero()
    assert certified_nonzero(s, res)


def test_negative_control_LA1_with_the_commutator_swapped_fails():
    s = FreeScene()
    res = la1_residual(s, None, swap=True)
    assert not res.is_zero()
    assert certified_nonzero(s, res)


def test_dirac_flow_of_the_neumann_hamiltonian_is_No():
    """Proposition (No): the Dirac flow of (neumann) is (No); its multipliers are not exposed."""
    s = FreeScene()
    f = s.dirac_flow(neumann_hamiltonian)
    g = neumann_flow(s, None)
    assert (f.Xdot - g.Xdot).is_zero() and (f.Pdot - g.Pdot).is_zero()
    assert not f.multipliers
    assert not (f.Pdot - neumann_flow(s, None, flip="AX").Pdot).is_zero()


def test_dirac_flow_agrees_with_the_coordinate_scene():
    """One Hamiltonian, two backends: the free flow evaluated at a point equals the coordinate flow."""
    sc = Scene(4, 2, RationalField(), chart="cayley", rng=random.Random(7))
    fc = sc.dirac_flow(neumann_hamiltonian)
    frac = lambda M: np.array([[Fraction(int(x.p), int(x.q)) for x in row] for row in M._a], dtype=object)
    values = {"X": frac(sc.X), "P": frac(sc.P), "A": frac(sc.A)}
    scalars = {se.Symbol("kappa"): Fraction(int(sc.kappa.p), int(sc.kappa.q))}
    ff = FreeScene().dirac_flow(neumann_hamiltonian)
    assert (evaluate(ff.Xdot._a[0, 0], values, scalars) == frac(fc.Xdot)).all()
    assert (evaluate(ff.Pdot._a[0, 0], values, scalars) == frac(fc.Pdot)).all()


def test_prep_momentum_and_projector_evolve_by_commutators():
    """(prep): dΦ/dt = [XXᵀ, A] and d(XXᵀ)/dt = [Φ, XXᵀ] along (No), for every κ."""
    s = FreeScene()
    flow = neumann_flow(s, None)
    XX = s.X @ s.X.T
    assert (s.d(lambda t: t.Phi, flow) - comm(XX, s.A)).is_zero()
    assert (s.d(lambda t: t.X @ t.X.T, flow) - comm(s.Phi, XX)).is_zero()
    assert not (s.d(lambda t: t.Phi, flow) - comm(s.A, XX)).is_zero()


def test_psi_is_conserved_and_the_flow_is_tangent():
    s = FreeScene()
    flow = neumann_flow(s, None)
    assert s.d(lambda t: t.Psi, flow).is_zero()
    assert s.d(lambda t: t.X.T @ t.X, flow).is_zero()
    assert s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, flow).is_zero()
    assert not s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, neumann_flow(s, None, flip="Xdot")).is_zero()


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_traces_of_powers_of_L_are_integrals(k):
    """(perelomov): tr L(λ)^k is conserved by (No)."""
    s = FreeScene()

    def power_trace(t):
        M = L_neum(t)
        acc = M
        for _ in range(k - 1):
            acc = acc @ M
        return t.tr(acc)
    assert s.d(power_trace, neumann_flow(s, None)) == 0
    assert not s.system.trace_fallbacks


def test_jensen_hamiltonian_in_terms_of_momenta():
    """(EM): ½<Φ,Φ> + κ/2 <Ψ,Ψ> = ½tr(PᵀP) − (½+κ)tr((XᵀP)²)."""
    s = FreeScene()
    lhs = s.killing(s.Phi, s.Phi) * s.q(1, 2) + s.killing(s.Psi, s.Psi) * s.kappa / 2
    rhs = s.tr(s.P.T @ s.P) * s.q(1, 2) - s.tr(s.X.T @ s.P @ s.X.T @ s.P) * (s.q(1, 2) + s.kappa)
    assert s.field.is_zero(lhs - rhs)
    assert not s.field.is_zero(lhs + rhs)


@pytest.mark.parametrize("kappa", [0, Fraction(-1, 2)], ids=["normal", "euclidean"])
def test_dual_lax_pair_LA3_LA4_as_printed(kappa):
    """Theorem DUAL: dL*/dt = [L*, A*] along (N0_XP2), resp. (NE_XP), with the printed L*, A*."""
    assert la3_residual(FreeScene(), kappa).is_zero()


@pytest.mark.parametrize("kappa", [0, Fraction(-1, 2)], ids=["normal", "euclidean"])
def test_negative_control_LA3_with_the_commutator_swapped_fails(kappa):
    s = FreeScene()
    res = la3_residual(s, kappa, swap=True)
    assert not res.is_zero()
    assert certified_nonzero(s, res)


def test_negative_control_LA4_with_the_other_flow_fails():
    s = FreeScene()
    assert not la3_residual(s, 0, flow_kappa=Fraction(-1, 2)).is_zero()
    assert not la3_residual(s, Fraction(-1, 2), flow_kappa=0).is_zero()


def test_odd_traces_of_the_dual_lax_matrix_vanish():
    """(2r-integrals): tr L* = tr L*³ = 0; tr L*² is conserved."""
    s = FreeScene()
    L = L_dual(s)
    assert s.tr(L) == 0 and s.tr(L @ L @ L) == 0
    assert s.d(lambda t: t.tr(L_dual(t) @ L_dual(t)), neumann_flow(s, 0)) == 0


# ---------------------------------------------------------------------------
def test_scalars_multiply_matrices_and_identities_are_typed():
    s = FreeScene()
    x = s.X._a[0, 0]
    assert (s.lam * s.X)._a[0, 0] == x * s.lam
    assert (2 * s.X - s.X * 2).is_zero()
    assert (s.X / 2 * 2 - s.X).is_zero()
    assert (Fraction(1, 3) * s.X * 3 - s.X).is_zero()
    assert (s.In @ s.X - s.X).is_zero() and (s.X @ s.Ir - s.X).is_zero()
    with pytest.raises(TypeError):
        s.Ir @ s.X
    assert s.tr(s.Ir) == NCPoly.scalar(DIMENSIONS["r"]) and s.tr(s.In) == NCPoly.scalar(DIMENSIONS["n"])
    assert (s.scalar_matrix(s.lam, 2 * s.r) - s.lam * block([[s.Ir, s.zeros(s.r, s.r)],
                                                            [s.zeros(s.r, s.r), s.Ir]])).is_zero()


def test_block_transpose_and_trace():
    s = FreeScene()
    B = block([[s.X.T @ s.P, s.Ir], [s.P.T @ s.P, s.X.T @ s.A @ s.X]])
    assert (B.T.T - B).is_zero()
    assert s.field.is_zero(B.T._a[0, 1] - (s.P.T @ s.P)._a[0, 0])
    assert s.field.is_zero(s.tr(B) - s.tr(s.X.T @ s.A @ s.X))


def test_coordinate_objects_raise_needs_coordinates():
    s = FreeScene()
    with pytest.raises(NeedsCoordinates):
        s.a
    with pytest.raises(NeedsCoordinates):
        s.X.T.__matmul__(s.X).inv()
    with pytest.raises(NeedsCoordinates):
        s.scalar_matrix(s.lam, 3)
    with pytest.raises(NeedsCoordinates):
        range(s.n)
    with pytest.raises(NeedsCoordinates):
        s.r >= 2
    with pytest.raises(NeedsCoordinates):
        FreeScene(realization="metric", square=True)   # (the metric realization at r = n only: not offered)
    with pytest.raises(NeedsCoordinates):
        s.jacobian(lambda t: t.X)
    with pytest.raises(AttributeError):
        s.no_such_thing


def test_multipliers_outside_the_solvable_form_are_reported():
    from stiefelsym.free.scene import FreeSolveError, solve_multipliers
    s = FreeScene()
    Lam = NCPoly.word((LAMBDA,))
    eq = s.X.T._a[0, 0] * s.A._a[0, 0] * s.X._a[0, 0] * Lam + Lam * s.X.T._a[0, 0] * s.A._a[0, 0] * s.X._a[0, 0]
    with pytest.raises(FreeSolveError, match="not of the form"):
        solve_multipliers([s.system.normal_form(eq)], [LAMBDA], s.system)


def test_momentum_map_brackets():
    """(momentum_map): Φ_ξ = <Φ, ξ> generates ξ·(X, P), and {Φ_ξ, Φ_ζ} = Φ_[ξ,ζ] (Dirac = canonical)."""
    s = FreeScene()
    phi = lambda name: (lambda t: t.killing(t.Phi, getattr(t, name)))
    f = s.dirac_flow(phi("xi"))
    assert (f.Xdot - s.xi @ s.X).is_zero() and (f.Pdot - s.xi @ s.P).is_zero()
    target = s.killing(s.Phi, comm(s.xi, s.zeta))
    assert s.field.is_zero(s.bracket(phi("xi"), phi("zeta")) - target)
    with pytest.raises(NeedsCoordinates):     # ambient brackets depend on values off T*V
        s.canonical_bracket(phi("xi"), phi("zeta"))
    assert not s.field.is_zero(s.bracket(phi("xi"), phi("zeta")) + target)


def test_values_are_differentiated_by_the_derivation_along_tangent_flows():
    """s.d(value, flow) (the STYLE sample form) agrees with s.d(function, flow) for tangent flows."""
    s = FreeScene()
    flow = neumann_flow(s, None)
    XX = s.X @ s.X.T
    assert (s.d(s.Phi, flow) - comm(XX, s.A)).is_zero()
    assert (s.d(L_neum(s), flow) - comm(A_neum(s), L_neum(s))).is_zero()
    assert (s.d(L_dual(s), neumann_flow(s, 0)) - comm(L_dual(s), A_dual(s, 0))).is_zero()
    assert s.d(s.tr(L_neum(s) @ L_neum(s)), flow) == 0
    with pytest.raises(ValueError, match="does not preserve"):
        s.d(s.Phi, neumann_flow(s, None, flip="AX"))


# --------------------------------------------------------------------------- the one-block fast path
_GENERIC_FIELDS: dict = {}


def _generic(M):
    """The same matrix over a copy of its field without a whole-matrix backend (the generic,
    entrywise path of every operation of Mat)."""
    f = M._field
    hit = _GENERIC_FIELDS.get(id(f))
    if hit is None or hit[0] is not f:
        g = copy.copy(f)
        g.__dict__["_backend"] = None   # the cached backend of the copy: none
        hit = _GENERIC_FIELDS[id(f)] = (f, g)
    return Mat._wrap(M._view().copy(), hit[1], M.tags, M.tracker)


def _same(a, b) -> bool:
    def eq(x, y):
        assert type(x) is type(y)
        return eq(x.a, y.a) and eq(x.b, y.b) if type(x) is Dual else x == y
    return a.tags == b.tags and a._view().shape == b._view().shape and all(
        eq(x, y) for x, y in zip(a._view().flat, b._view().flat))


def test_one_block_operations_agree_with_the_generic_path():
    s = FreeScene(lazy=True)
    X, P, A = s.X, s.P, s.A
    assert type(X) is Mat   # one class of matrices for every scene: the fast path is the field's backend
    k = 1 + 2 * s.kappa
    cases = [lambda X, P, A: X @ P.T, lambda X, P, A: P @ X.T - X @ P.T, lambda X, P, A: -(A @ X) + X,
             lambda X, P, A: (X @ P.T @ X) * k, lambda X, P, A: s.lam * (A @ X), lambda X, P, A: X / s.lam,
             lambda X, P, A: (X.T @ P) * Fraction(2, 3) - 3 * (P.T @ X)]
    for f in cases:
        fast = f(X, P, A)
        assert type(fast) is Mat
        assert _same(fast, f(_generic(X), _generic(P), _generic(A)))
    # along a flow: entries are dual numbers, the same on both paths
    t = s.tangent({"X": P, "P": -(A @ X)})
    fast = t.X @ t.P.T - t.P @ t.X.T
    assert type(fast) is Mat
    slow = _generic(t.X) @ _generic(t.P).T - _generic(t.P) @ _generic(t.X).T
    assert _same(fast, slow)


def test_one_block_operations_check_index_spaces_like_the_generic_path():
    s = FreeScene(lazy=True)
    for f in (lambda X, P: X + P.T, lambda X, P: X @ P, lambda X, P: X - X.T @ P):
        with pytest.raises(TypeError) as fast:
            f(s.X, s.P)
        with pytest.raises(TypeError) as slow:
            f(_generic(s.X), _generic(s.P))
        assert str(fast.value) == str(slow.value)
    with pytest.raises(TypeError):
        s.X * 0.5
    with pytest.raises(TypeError):
        s.X + 1


def test_a_symengine_scalar_times_a_block_is_the_blocks_reflected_product():
    s = FreeScene(lazy=True)
    for c in (s.lam, 1 + 2 * s.kappa, s.scalar("c")):
        assert _same(c * s.X, s.X * c)
        assert c * s.X._view()[0, 0] == s.X._view()[0, 0] * c
    assert not (s.lam == s.X) and s.lam != s.X
    with pytest.raises(TypeError):
        s.lam ** s.X


def test_the_momentum_maps_of_lazy_scenes_are_built_once_and_are_their_definition():
    for key in ("Phi", "Psi"):
        s, t = FreeScene(lazy=True), FreeScene(lazy=True)
        a, b = getattr(s, key), getattr(t, key)
        assert type(a) is Mat and a.tracker is s.tracker and b.tracker is t.tracker and a._field is s._field
        definition = (t.P @ t.X.T - t.X @ t.P.T) if key == "Phi" else (t.X.T @ t.P - t.P.T @ t.X)
        assert _same(a, definition) and _same(b, definition), key
