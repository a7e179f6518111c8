"""Routes by which a false statement used to pass, closed by types, doors and fresh names.

Each test writes the trick as a user's claim would and runs it under every method: a
false statement is never ``proved``, ``checked`` or ``numeric``; it fails, is refused
with a type error (``error``) or is left ``undecided`` by the dimension-free method.
"""
import random

import numpy as np
import pytest

from stiefelsym.methods.fixed_size import EXACT_CAYLEY_MAX_N
import symengine as se

from stiefelsym import Mat, admissible, block
from stiefelsym.claims import Claim, Size, _mark_reviewed, load_catalog
from stiefelsym.backends.fields import RationalField
from stiefelsym.backends.matrix import NeedsCoordinates
from stiefelsym.run.runner import run_one
from stiefelsym.ir.trace import TraceRefused
from stiefelsym.scene import Scene, param_name

PASSING = ("proved", "checked", "numeric")
FIXED = ("exact", "rational", "modular", "float", "auto")


def _claim(func, cid="trick"):
    return Claim(id=cid, paper=("cond_XP",), kind="id", section="t", func=func, sizes=admissible(4))


def _verdicts(func, sizes, methods=FIXED + ("free",)):
    c = _claim(func)
    out = {}
    for m in methods:
        for n, r in (sizes if m != "free" else [(None, None)]):
            size = None if n is None else Size(n, r)
            res = run_one(c, size, m, 0)
            out[(m, None if size is None else (n, r))] = res
    return out


def _never_passes(func, sizes, methods=FIXED + ("free",)):
    for key, res in _verdicts(func, sizes, methods).items():
        assert res.verdict not in PASSING, (key, res.verdict, res.certificate, res.message)


def _X0(s):
    """The base point (E_1, ..., E_r) written out with constants."""
    return block([[s.identity(s.r, "r")], [s.zeros(s.n - s.r, s.r)]])


# -- route 1: the equivariant chart ---------------------------------------------------

def x_is_the_base_point_block(s):
    """False: X = (I; 0) (built as a block of constant matrices)."""
    return {"X - X0": s.X - _X0(s)}


def x_is_the_base_point_entrywise(s):
    """False: X = (I; 0) (built entrywise)."""
    rows = [[s.q(1 if i == j else 0) for j in range(s.r)] for i in range(s.n)]
    return {"X - X0": s.X - s.mat(rows, ("n", "r"))}


def x_is_the_base_point_untyped(s):
    """False: X = (I; 0) (built entrywise, untyped)."""
    rows = [[s.q(1 if i == j else 0) for j in range(s.r)] for i in range(s.n)]
    return {"X - X0": s.X - s.mat(rows)}


def x_is_the_base_point_constructor(s):
    """False: X = (I; 0) (the Mat constructor from a numpy array)."""
    a = np.empty((s.n, s.r), dtype=object)
    for i in range(s.n):
        for j in range(s.r):
            a[i, j] = s.q(1 if i == j else 0)
    return {"X - X0": s.X - Mat(a, s.X.field, ("n", "r"))}


def x_is_the_base_point_sliced(s):
    """False: X = first r columns of I_n (a slice of the identity)."""
    return {"X - X0": s.X - s.identity(s.n, "n")[:, 0:s.r]}


def first_entry_of_X_is_one(s):
    """False: X_11 = 1 (an entry read)."""
    return {"X_11": s.X[0, 0] - s.q(1)}


@pytest.mark.parametrize("func", [x_is_the_base_point_block, x_is_the_base_point_entrywise,
                                  x_is_the_base_point_untyped, x_is_the_base_point_constructor,
                                  x_is_the_base_point_sliced, first_entry_of_X_is_one],
                         ids=lambda f: f.__name__)
def test_the_base_point_is_never_proved_to_be_every_point(func):
    _never_passes(func, [(3, 1), (3, 2)])


def test_raw_entries_have_no_unrecorded_door():
    s = Scene(3, 2, RationalField(), chart="equivariant", rng=random.Random(0))
    X = s.X
    for attempt in (lambda: list(X), lambda: np.asarray(X, dtype=float), lambda: X.entries(),
                    lambda: X.rows(), lambda: X.a, lambda: bool(X)):
        with pytest.raises((TypeError, AttributeError, ValueError)):
            attempt()
    with pytest.raises((TypeError, AttributeError)):
        X[0, 0] = 1
    with pytest.raises(AttributeError):
        X.tags = ("r", "r")
    assert s.tracker.used == ()
    s.jacobian(lambda t: t.X.T @ t.X)
    assert "a Jacobian in the coordinates of X, P" in s.tracker.used
    with pytest.raises(AttributeError):
        s.tracker.used.clear()


def test_covariant_constructions_read_no_coordinates():
    s = Scene(4, 2, RationalField(), chart="equivariant", rng=random.Random(0))
    M = s.X @ s.X.T - s.In + s.zeros(4, 4, ("n", "n")) + block([[s.X, s.P]]) @ block([[s.X.T], [s.P.T]])
    s.tr(M @ s.A)
    s.Psi[0, 1]                       # entries of r x r matrices are O(n)-invariant functions
    assert s.tracker.used == ()


# -- route 2: index types -------------------------------------------------------------

def phi_equals_psi(s):
    """False: Φ = Ψ (true at X = I when r = n)."""
    return {"Phi - Psi": s.Phi - s.Psi}


def trace_of_x(s):
    """False: tr X = r (true at X = I when r = n)."""
    return {"tr X": s.tr(s.X) - s.tr(s.Ir)}


def x_times_phi(s):
    """Ill-typed: Ψ X (an r×r times an n×r)."""
    return {"Psi X - X": s.Psi @ s.X - s.X}


@pytest.mark.parametrize("func", [phi_equals_psi, trace_of_x, x_times_phi], ids=lambda f: f.__name__)
def test_n_and_r_indexed_objects_never_meet(func):
    res = _verdicts(func, [(2, 2), (3, 3)])
    for key, r in res.items():
        assert r.verdict not in PASSING, key
        if key[0] != "free":
            assert r.verdict == "error" and "do not match" in r.message, (key, r.message)


def test_types_are_checked_against_sizes():
    s = Scene(4, 1, RationalField())
    with pytest.raises(TypeError):
        s.zeros(3, 1, ("n", "r"))
    with pytest.raises(TypeError):
        block([[s.identity(1, "r")], [s.zeros(3, 1, ("n", "r"))]])


# -- route 3: name capture --------------------------------------------------------------

def scalars_named_like_the_chart(s):
    """False: tr A = A_11 + ... + A_nn with scalars of the claim's own named like A's entries."""
    acc = s.q(0)
    for i in range(s.n):
        acc = acc + s.scalar(param_name("A", i, i))
    return {"tr A": s.tr(s.A) - acc}


def raw_symbols_named_like_the_chart(s):
    """False: tr A = A_11 + ... + A_nn with symbols the claim makes itself."""
    acc = s.q(0)
    for i in range(s.n):
        acc = acc + se.Symbol(param_name("A", i, i))
    return {"tr A": s.tr(s.A) - acc}


def scalar_named_lambda(s):
    """False: a scalar of the claim's own named lambda is the spectral parameter."""
    return {"lambda": s.scalar("lambda") - s.lam}


def generic_named_like_xi(s):
    """False: a generic matrix named xi is the so(n) element xi (its upper triangle)."""
    G = s.general_params("xi", s.n, s.n, ("n", "n"))
    return {"xi": s.killing(s.xi, s.xi) - s.killing(G - G.T, G - G.T) / 4}


@pytest.mark.parametrize("func", [scalars_named_like_the_chart, scalar_named_lambda, generic_named_like_xi],
                         ids=lambda f: f.__name__)
def test_a_claims_own_parameters_are_fresh(func):
    _never_passes(func, [(2, 1), (3, 2)])


def test_raw_symbols_are_not_chart_parameters():
    _never_passes(raw_symbols_named_like_the_chart, [(2, 1), (3, 2)], methods=("exact",))


# -- route 4: the dimension-free scene ----------------------------------------------------

def sizes_compared(s):
    """False: Φ = Ψ whenever n = r (a comparison of sizes)."""
    return {"x": s.Phi - s.Phi if s.n != s.r else s.P}


def entry_of_psi(s):
    """False: Ψ_12 = 0 (an entry of an r-indexed matrix)."""
    return {"Psi_12": s.Psi[0, 1]}


def shape_used(s):
    """False: P = 0 when the shape says so."""
    return {"P": s.P if s.X.shape[0] == 0 else s.X - s.X}


def scalar_named_n(s):
    """False: tr I_n equals a free scalar named n."""
    return {"tr I_n - n": s.tr(s.In) - s.scalar("n")}


def size_in_arithmetic(s):
    """False: tr I_n = n - r + r, the sizes as numbers."""
    return {"x": s.tr(s.In) * (s.n - s.r)}


@pytest.mark.parametrize("func", [sizes_compared, entry_of_psi, shape_used, scalar_named_n, size_in_arithmetic],
                         ids=lambda f: f.__name__)
def test_the_dimension_free_scene_refuses_what_depends_on_a_size(func):
    res = run_one(_claim(func), None, "free", 0)
    assert res.verdict == "undecided", (res.verdict, res.certificate)


def test_free_sizes_only_size_blocks():
    from stiefelsym.free import FreeScene
    s = FreeScene()
    assert (s.zeros(2 * s.r, s.r) @ s.Ir).is_zero() is True
    for attempt in (lambda: s.n == s.r, lambda: s.n != s.n, lambda: int(s.n), lambda: s.n - s.r,
                    lambda: range(s.r), lambda: bool(s.r), lambda: s.X.shape, lambda: s.Psi[0, 0]):
        with pytest.raises(NeedsCoordinates):
            attempt()


# -- more doors: tangent vectors, the operator on so(n), the scene's own record ------------

def derivative_along_a_constant_direction(s):
    """False: d(XᵀX) along the constant direction (I; 0) is 2I (true only at X = (I; 0))."""
    V = block([[s.identity(s.r, "r")], [s.zeros(s.n - s.r, s.r)]])
    return {"d(X^T X)": s.d(lambda t: t.X.T @ t.X, {"X": V, "P": s.zeros(s.n, s.r, ("n", "r"))})
            - s.Ir * 2}


def operator_on_a_symmetric_matrix(s):
    """True: 𝔸 acts on the skew part (an equivariant extension), so 𝔸(XXᵀ) = 0 everywhere, not only
    at X = (I; 0) where a reading of the upper triangle would also give 0."""
    AA = s.sym_operator("AA")
    return {"AA(XX^T)": AA(s.X @ s.X.T)}


def test_the_operator_on_so_n_is_equivariant_on_all_matrices():
    for (n, r), res in _verdicts(operator_on_a_symmetric_matrix, [(3, 1), (3, 2)], ("exact", "rational")).items():
        assert res.verdict in ("proved", "checked"), (n, r, res.verdict)


def operator_named_like_a(s):
    """False: an operator named A shares its coefficients with the matrix A."""
    AA = s.sym_operator("A")
    return {"AA(xi) - A xi": AA(s.xi) - (s.xi @ s.A - s.A @ s.xi)}


def tracker_swapped(s):
    """False: X = (I; 0), hiding the entry reads by swapping the record."""
    from stiefelsym.backends.matrix import CoordinateTracker
    residual = s.X[0, 0] - s.q(1)
    s.tracker = CoordinateTracker()
    return {"X_11": residual}


def chart_switched(s):
    """False: X_11 = 1, after switching the chart."""
    s.chart = "cayley"
    return {"X_11": s.X[0, 0] - s.q(1)}


@pytest.mark.parametrize("func", [derivative_along_a_constant_direction, operator_named_like_a, tracker_swapped, chart_switched],
                         ids=lambda f: f.__name__)
def test_no_side_door_around_the_record(func):
    _never_passes(func, [(3, 1), (3, 2)], methods=FIXED)


def test_tangent_vectors_are_typed():
    s = Scene(3, 3, RationalField(), rng=random.Random(0))
    with pytest.raises(TypeError):
        s.d(lambda t: t.X, {"X": s.Psi})       # an r x r direction for an n x r primitive
    with pytest.raises(TraceRefused, match="a tangent vector moves X, P"):
        s.d(lambda t: t.X, {"A": s.A})      # a refusal like every other (stop 90 h1 M3), not a KeyError


def test_free_generic_names_cannot_alias_a_transpose():
    from stiefelsym.free import FreeScene
    s = FreeScene()
    with pytest.raises(ValueError):
        s.generic("U^T", "r", "n")
    with pytest.raises(ValueError):
        s.generic("U", "n", "1")


def test_parameter_names_are_distinct_at_every_size():
    s = Scene(12, 11, RationalField(), rng=random.Random(0))
    s.P
    names = list(s._point_values())     # S (skew 12x12), W (skew 11x11), Z (12x11), each entry its own name
    assert len(names) == 66 + 55 + 132
    assert len({n.rsplit("_", 1)[1] + n[0] for n in names}) == len(names)
    assert param_name("Z", 0, 10) != param_name("Z", 10, 0)


# -- a stated equivariance reason is relied on only for the reviewed catalog -----------------

def x_is_the_base_point_with_a_reason(s):
    """False: X_11 = 1, with a (false) reason why the reduction is valid."""
    return {"X_11": s.X[0, 0] - s.q(1)}


def entry_of_xtx_with_a_reason(s):
    """True: Σᵢ X_i1² = 1, read from the entries of X (coordinates of R^n)."""
    total = s.X[0, 0] * s.X[0, 0]
    for i in range(1, int(s.n)):
        total = total + s.X[i, 0] * s.X[i, 0]
    return {"|X e_1|^2": total - s.q(1)}


def test_a_users_stated_reason_does_not_buy_the_reduction():
    c = Claim(id="trick", paper=("cond_XP",), kind="id", section="t", func=x_is_the_base_point_with_a_reason,
              sizes=admissible(8), equivariance="trust me: X_11 is an invariant")
    assert not c.reviewed
    for n, r in [(2, 1), (3, 2), (4, 2)]:
        res = run_one(c, Size(n, r), "exact", 0)
        assert res.verdict == "fails", (n, r, res.verdict)
    # beyond the symbolic Cayley chart's limit the reason would have bought the equivariant chart; a claims file's
    # claim is evaluated at an exact rational point first, which refutes it there (before stop 73: inconclusive,
    # "the reduction is relied on only for the reviewed catalog")
    res = run_one(c, Size(EXACT_CAYLEY_MAX_N + 1, 2), "exact", 0)
    assert res.verdict == "fails" and res.witness and "limited to n <=" in res.certificate, \
        (res.verdict, res.message, res.certificate)
    # a true claim that reads coordinates with a reason: the point does not refute it, and the reason still buys
    # nothing beyond the Cayley chart's limit
    t = Claim(id="trick-true", paper=("cond_XP",), kind="id", section="t", func=entry_of_xtx_with_a_reason,
              sizes=admissible(8), equivariance="trust me: an entry of XᵀX is an invariant")
    res = run_one(t, Size(EXACT_CAYLEY_MAX_N + 1, 2), "exact", 0)
    assert res.verdict == "inconclusive" and "reviewed catalog" in res.message, (res.verdict, res.message)


def test_a_reviewed_reason_is_not_lent_to_a_mutant_that_reads_other_coordinates(monkeypatch):
    """The catalog's invariants-complete reads R^n-indexed constants with a reviewed reason (the rank is a
    statement about the fibre over X0).  Its graph mutant P^T P -> P P^T, entries still read at i <= j < r,
    reads entries of an n x n matrix and is true (a full rank: r(r-1)/2 + r(r+1)/2 rows, rank r^2 = ddim
    here).  With the printed claim's reason lent to it, the equivariant chart X = X0 made its rank 0 and
    the exact method refuted it; the reason now stays with the claim's own function and its registered
    corrections: the mutant goes to the Cayley chart, where it is proved; in the mutation analysis the exact
    method leaves such a mutant inconclusive (the Cayley charts of these claims' mutants reached 18 GB)."""
    from stiefelsym.methods.fixed_size import run_exact
    from stiefelsym.proofs.sec2_hamiltonian_flows import ddim_printed, vertical_directions
    from stiefelsym import Rank

    printed = load_catalog().get("invariants-complete")
    assert printed.reviewed

    def mutant(s):
        columns = []
        for v in vertical_directions(s):
            dPsi = s.d(lambda t: t.Psi, v)
            dG = s.d(lambda t: t.P @ t.P.T, v)
            columns.append([dPsi[i, j] for i in range(s.r) for j in range(i + 1, s.r)]
                           + [dG[i, j] for i in range(s.r) for j in range(i, s.r)])
        return {"rank": Rank(s.mat([list(row) for row in zip(*columns)]), ddim_printed(s.n, s.r), generic=True)}

    own = run_exact(printed, 4, 1, 0)
    assert own.verdict == "proved" and any("about the fibre" in x for x in own.reductions), own.reductions
    res = run_exact(printed, 4, 1, 0, func=mutant)
    assert res.verdict == "proved", (res.verdict, res.message)       # on the Cayley chart
    assert not any("about the fibre" in x for x in res.reductions), res.reductions
    assert any("rational parametrization" in x for x in res.reductions), res.reductions
    # in the mutation analysis (points lent or not), such a mutant is left inconclusive by the exact method
    from stiefelsym.methods import fixed_size
    monkeypatch.setattr(fixed_size, "_MUTATION_ANALYSIS", True)
    res = run_exact(printed, 4, 1, 0, func=mutant)
    assert res.verdict == "inconclusive", (res.verdict, res.message)
    assert "reviewed reason of equivariance" in res.message and "own function" in res.message, res.message


def eigenvalues_with_a_reason(s):
    """True: tr A = a_1 + ... + a_n, reading the eigenvalues, with a stated reason."""
    acc = s.q(0)
    for x in s.a:
        acc = acc + x
    return {"tr A": s.tr(s.A) - acc}


def test_objects_the_equivariant_chart_lacks_send_the_claim_to_the_cayley_chart():
    c = _mark_reviewed(Claim(id="eig", paper=("cond_XP",), kind="id", section="t", func=eigenvalues_with_a_reason,
                             sizes=admissible(4), equivariance="the trace is invariant"))
    assert run_one(c, Size(3, 2), "exact", 0).verdict == "proved"


# -- numbers of the scene only -----------------------------------------------------------------

class Zero:
    """A claim's own object that says it equals everything."""

    def __eq__(self, other):
        return True

    __hash__ = object.__hash__


def residual_is_an_object_that_equals_zero(s):
    """False: X = 0, hidden in an object whose == always says yes."""
    return {"X": Zero(), "X entries": s.mat([[Zero()]], ("r", "r"))}


def residual_is_a_python_zero(s):
    """Vacuous: a literal 0 says nothing about the scene."""
    return {"nothing": 0}


def count_is_an_object_that_equals_anything(s):
    """False: a count hidden in an object whose == always says yes."""
    from stiefelsym import Count
    return {"count": Count(Zero(), 3)}


@pytest.mark.parametrize("func", [residual_is_an_object_that_equals_zero, residual_is_a_python_zero,
                                  count_is_an_object_that_equals_anything], ids=lambda f: f.__name__)
def test_residuals_are_numbers_of_the_scene(func):
    for key, res in _verdicts(func, [(3, 2)]).items():
        assert res.verdict in ("error", "undecided"), (key, res.verdict)


# -- an adversarial review's tricks, kept ----------------------------------------------------------

def divides_by_an_identically_zero_expression(s):
    """False: X = 0, written X / (1 / (<ξ,ξ> − <ξ,ξ>)) (symbolically an infinity turned into 0)."""
    k = s.killing(s.xi, s.xi)
    return {"X": s.X / (s.q(1) / (k - k))}


def divides_by_zero_among_constants(s):
    """False: Φ · 1/(1 + 1/0) = 0."""
    return {"Phi": s.Phi * (s.q(1) / (s.q(1) + s.q(1) / s.q(0)))}


def gradient_of_a_matrix(s):
    """False: a matrix 'Hamiltonian' read at its first entry (E_11 at X = (I; 0))."""
    E, _ = s.gradient(lambda t: t.X)
    return {"XX^T E - E": s.X @ s.X.T @ E - E}


def flow_of_a_matrix(s):
    """False: the Dirac flow of a matrix-valued function."""
    flow = s.dirac_flow(lambda t: t.P)
    return {"XX^T X' - X'": s.X @ s.X.T @ flow.Xdot - flow.Xdot}


def operator_and_generic_share_a_name(s):
    """False: a generic matrix named like an operator's coefficients equals them."""
    K = s.sym_operator("K")
    G = s.generic("K", "n", "n")
    E = s.xi - s.xi.T
    return {"shared": s.killing(E, K(E)) - s.tr(G)}


def generic_and_params_share_a_name(s):
    """False: two generic matrices of the claim's own with one name have equal first columns."""
    G = s.generic("G", "n", "r")
    H = s.general_params("G", s.n, s.r, ("n", "r"))
    return {"G - H": G - H}


def conj_of_x(s):
    """False: conj(X)ᵀ X = diag(1, −1) (conj of a matrix that is not realified)."""
    C = s.conj(s.X)
    return {"conj": C.T @ s.X - s.Ir}


def a_chart_parameter_by_name(s):
    """False: a parameter fetched by the chart's own name (not part of the API)."""
    return {"a_1": s.param("a_1") - s.A[0, 0]}


@pytest.mark.parametrize("func", [divides_by_an_identically_zero_expression, divides_by_zero_among_constants,
                                  gradient_of_a_matrix, flow_of_a_matrix, operator_and_generic_share_a_name,
                                  generic_and_params_share_a_name, conj_of_x, a_chart_parameter_by_name],
                         ids=lambda f: f.__name__)
def test_reviewed_tricks_never_pass(func):
    _never_passes(func, [(3, 1), (4, 2)])


def free_trace_of_a_scalar_block(s):
    """False: tr I_n = 1, from a 1×1 matrix typed as R^n."""
    return {"tr": s.tr(s.mat([[1]], ("n", "n"))) - s.q(1)}


def free_moves_a(s):
    """False: the resolvent is constant when A moves."""
    return {"dR": s.d(lambda t: t.resolvent(t.lam), {"A": s.In})}


@pytest.mark.parametrize("func", [free_trace_of_a_scalar_block, free_moves_a], ids=lambda f: f.__name__)
def test_the_free_scene_refuses_untyped_blocks_and_moving_a(func):
    assert run_one(_claim(func), None, "free", 0).verdict in ("undecided", "error")


def test_a_registered_claim_cannot_be_rewritten():
    import dataclasses
    c = _claim(x_is_the_base_point_block)
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.reviewed = True
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.expect = "fails"


def test_metadata_code_that_never_returns_is_stopped(monkeypatch):
    import time
    from stiefelsym import claims
    monkeypatch.setattr(claims, "METADATA_SECONDS", 0.2)
    c = Claim(id="hang", paper=("cond_XP",), kind="id", section="t", func=x_is_the_base_point_block,
              sizes=admissible(3), fails_at=lambda n, r: time.sleep(30), erratum="never returns")
    res = run_one(c, Size(3, 1), "rational", 0)
    assert res.verdict == "error" and "did not finish" in res.message


# -- a last pass at the new doors: sizes under the wrong space, a user-built Flow ----------------

def scalar_matrix_labelled_r_at_n_equal_r(s):
    """False: X = I (an n×n identity labelled as R^r, which agrees with X0 when r = n)."""
    return {"X": s.X - s.scalar_matrix(s.q(1), s.n, "r")}


def user_flow_along_a_constant_direction(s):
    """False: d(XᵀX) = 2I along a Flow whose direction is the constant (I; 0)."""
    from stiefelsym import Flow
    V = block([[s.identity(s.r, "r")], [s.zeros(s.n - s.r, s.r)]])
    return {"d": s.d(lambda t: t.X.T @ t.X, Flow(V, s.zeros(s.n, s.r, ("n", "r")))) - s.Ir * 2}


@pytest.mark.parametrize("func", [scalar_matrix_labelled_r_at_n_equal_r, user_flow_along_a_constant_direction],
                         ids=lambda f: f.__name__)
def test_sizes_and_flows_of_a_users_own_making_never_pass(func):
    _never_passes(func, [(3, 3), (3, 1)])


# -- reading the numbers' values -------------------------------------------------------------

def _frozen_entry(s):
    """False: X[0,0] is a constant (the value read off the sampled point)."""
    x = s.X[0, 0]
    return {"r": x - s.q(int(x))}


def _frozen_float(s):
    """The same through a float's value."""
    from fractions import Fraction
    x = s.X[0, 0]
    q = Fraction(x.v)
    return {"r": x - s.q(q.numerator, q.denominator)}


@pytest.mark.parametrize("method, func", [("modular", _frozen_entry), ("rational", _frozen_entry),
                                          ("float", _frozen_float)])
def test_a_claim_that_reads_the_sampled_values_is_refused_by_the_structural_pass(method, func):
    from stiefelsym.run.runner import run_one
    c = Claim(id="frozen", paper=("t",), kind="id", section="t", func=func, sizes=admissible(4))
    res = run_one(c, Size(4, 2), method, 0)
    assert res.verdict == "error", (res.verdict, res.message)


def _frozen_by_type(s):
    """Would hide from the structural pass by branching on the type of the scene's numbers."""
    x = s.X[0, 0]
    if type(x).__name__ == "nmod":
        return {"r": x - s.q(int(x))}
    return {"r": x - x}


def _caught_value_read(s):
    """False where it runs: x − c with c = x's sampled value, the read's refusal caught in the
    structural pass (where it returned the harmless x − x)."""
    x = s.X[0, 0]
    try:
        c = s.q(int(x))
    except Exception:
        return {"r": x - x}
    return {"r": x - c}


def _caught_str_read(s):
    """The same through the printed value."""
    from fractions import Fraction
    x = s.X[0, 0]
    try:
        c = Fraction(str(x))
    except Exception:
        return {"r": x - x}
    return {"r": x - s.q(c.numerator, c.denominator)}


def _caught_truth_value(s):
    """A value read by a comparison, caught."""
    x, y = s.X[0, 0], s.lam
    try:
        if x == y:
            return {"r": x - x}
    except Exception:
        return {"r": x - x}
    return {"r": x - x}


def _branch_on_the_field(s):
    """Branches on the scene's number system (asked of the scene, then of a matrix)."""
    try:
        name = s.field.name
    except Exception:
        name = s.X.field.name
    return {"r": s.X[0, 0] - (s.X[0, 0] if name == "degree" else s.q(1))}


def _branch_on_the_chart(s):
    """Returns a trivial residual in the equivariant chart only."""
    if s.chart == "equivariant":
        return {"r": s.X - s.X}
    return {"r": s.X}


def _reads_the_point(s):
    """Reads the sampled parameters, the random source or a matrix's values."""
    try:
        vals = list(s.params.values())
    except Exception:
        vals = []
    try:
        (s.X - s.X).is_zero()
    except Exception:
        pass
    return {"r": s.X - s.X} if not vals else {"r": s.X}


def _tampers_with_the_record(s):
    """Would stop the record from seeing reads of coordinates (the claim reads one, then returns
    something trivially zero)."""
    for get in (lambda: s.tracker, lambda: s.X.tracker):
        try:
            get()._used.clear()
        except Exception:
            pass
    return {"r": s.X - s.X}


@pytest.mark.parametrize("method", ["modular", "rational", "float"])
def test_a_claim_that_branches_on_the_number_type_sees_one_type(method):
    """Every method hands the claim the same opaque number type, so a branch on it takes the
    same path everywhere (here x − x, a true statement), and the value read it guards is never
    reached."""
    seen = set()

    def probe(s):
        seen.add(type(s.X[0, 0]).__name__)
        seen.add(type(s.lam).__name__)
        seen.add(type(s.tr(s.X.T @ s.X)).__name__)
        return _frozen_by_type(s)
    c = Claim(id="frozen-by-type", paper=("t",), kind="id", section="t", func=probe, sizes=admissible(4))
    res = run_one(c, Size(4, 2), method, 0)
    assert seen == {"Tracer"}, seen
    assert res.verdict in PASSING, (res.verdict, res.message)


@pytest.mark.parametrize("func", [_caught_value_read, _caught_str_read, _caught_truth_value,
                                  _branch_on_the_field, _branch_on_the_chart, _reads_the_point,
                                  _tampers_with_the_record],
                         ids=lambda f: f.__name__)
@pytest.mark.parametrize("method", ["exact", "modular", "rational", "float"])
def test_a_refusal_the_claim_catches_is_still_recorded(method, func):
    """Reading a number's value, the number system, the chart or the sampled point is refused
    on every method and recorded before the refusal is raised: catching it changes nothing."""
    c = Claim(id="caught", paper=("t",), kind="id", section="t", func=func, sizes=admissible(4))
    res = run_one(c, Size(3, 2), method, 0)
    if func is _caught_str_read:
        # no value to read: str() of a traced number is its kind, so it returns
        # x - x on every method, a true residual (a comparison, ==, is refused and recorded)
        assert res.verdict in PASSING, (res.verdict, res.message)
        return
    assert res.verdict == "error", (res.verdict, res.message)
    assert any(w in res.message for w in ("refused", "never reads", "is the engine's")), res.message


def test_the_engine_still_reads_its_own_numbers():
    """Outside a claim's run (engine code, these tests) entries and traces are the field's numbers."""
    s = Scene(3, 2, RationalField(), rng=random.Random(0))
    assert type(s.X[0, 0]).__name__ == "fmpq"
    assert s.field.name == "rational" and s.tr(s.X.T @ s.X) == 2


def _branch_on_the_scene_class(s):
    """False (X = 0): trivially zero where the scene's class is the dimension-free one."""
    if type(s).__name__ != "Scene":
        return {"r": s.X - s.X}
    return {"r": s.X}


def _branch_on_the_size_class(s):
    """False (X = 0): trivially zero where the size is not a plain number."""
    if not isinstance(s.n, int) or type(s.n).__name__ == "FreeSize":
        return {"r": s.X - s.X}
    return {"r": s.X}


def _branch_inside_a_derivative(s):
    """False: the class of the scene a derivative hands to the function decides."""
    seen = []
    s.d(lambda t: seen.append(type(t).__name__) or t.X, {"X": s.X, "P": s.P})
    if seen[0] not in ("TangentScene",):
        return {"r": s.X - s.X}
    return {"r": s.X}


@pytest.mark.parametrize("func", [_branch_on_the_scene_class, _branch_on_the_size_class,
                                  _branch_inside_a_derivative], ids=lambda f: f.__name__)
def test_a_claim_that_branches_on_the_scene_class_is_not_proved_for_all_sizes(func):
    """Every method and every derivative hands the claim one scene class (TraceScene) and one size
    class (Dim): a branch on them takes the same path everywhere, so the dimension-free method and
    a fixed size agree (both prove the trivial branch, or neither passes)."""
    c = Claim(id="class-branch", paper=("t",), kind="id", section="t", func=func, sizes=admissible(4))
    free = run_one(c, None, "free", 0).verdict
    fixed = run_one(c, Size(3, 2), "exact", 0).verdict
    assert (free in PASSING) == (fixed in PASSING), (free, fixed)


def _metric_block_is_diagonal(s):
    """False: XᵀA⁻¹X is diagonal (true at the metric chart's base points, where O(r) made it so)."""
    M = s.X.T @ s.Ainv @ s.X
    return {"offdiag": M[0, 1] * s.q(1)}


def test_the_metric_charts_r_reduction_is_lost_when_r_coordinates_are_read():
    """The equivariant chart of the metric realization also reduces by O(r) (XᵀA⁻¹X diagonal), so
    there reading coordinates of R^r is recorded like those of R^n."""
    c = Claim(id="diag", paper=("cond_XP2",), kind="id", section="t", func=_metric_block_is_diagonal,
              sizes=admissible(4), realization="metric")
    for n, r in [(3, 2), (2, 2)]:
        for m in ("exact", "modular", "auto"):
            res = run_one(c, Size(n, r), m, 0)
            assert res.verdict not in PASSING, (n, r, m, res.verdict, res.reductions)


def _compares_a_trace_form(s):
    """False (X = 0) where tr(I_r) == 1 is False: on the dimension-free scene a structural
    comparison of trace forms used to answer, where at r = 1 it holds."""
    try:
        same = s.tr(s.Ir) == 1
    except Exception:
        same = True
    return {"r": s.X - s.X} if not same else {"r": s.X}


def test_the_dimension_free_scene_hands_out_the_same_opaque_numbers():
    seen = set()

    def probe(s):
        seen.update({type(s.tr(s.X.T @ s.X)).__name__, type(s.lam).__name__, type(s.q(1, 2)).__name__})
        return {"r": s.X - s.X}
    run_one(_claim(probe), None, "free", 0)
    assert seen == {"Tracer"}, seen
    res = run_one(_claim(_compares_a_trace_form), None, "free", 0)
    assert res.verdict == "error" and "comparison" in res.message, (res.verdict, res.message)


def _caught_division_by_zero(s):
    """False (X = 0) where a division by an identically zero number does not raise: the methods
    raise it differently (at a random point, symbolically, not at all), so catching it told them
    apart, and the branch that caught it was `checked` with a trivially zero residual."""
    try:
        s.q(1) / (s.lam - s.lam)
    except Exception:
        return {"r": s.X - s.X}
    return {"r": s.X}


def _caught_singular_inverse(s):
    """The same through the inverse of an identically singular matrix."""
    try:
        (s.X.T @ s.X - s.Ir).inv()
    except Exception:
        return {"r": s.X - s.X}
    return {"r": s.X}


@pytest.mark.parametrize("func", [_caught_division_by_zero, _caught_singular_inverse], ids=lambda f: f.__name__)
def test_a_caught_arithmetic_exception_is_recorded(func):
    """An arithmetic exception claim code meets (a division, an inverse, a scene method) is recorded
    before it reaches the claim: no method passes the branch that caught it."""
    for m in ("exact", "modular", "rational", "float"):
        res = run_one(_claim(func), Size(3, 2), m, 0)
        assert res.verdict not in PASSING, (m, res.verdict, res.message)
    assert run_one(_claim(func), None, "free", 0).verdict not in PASSING


def _branch_on_the_printed_matrix(s):
    """False (X = 0) where the printed matrix names the dimension-free number system (a matrix
    printed its field's name and shape)."""
    text = repr(s.X) + str(s.X)
    try:
        text += repr(s.n)
    except Exception:
        pass
    return {"r": s.X - s.X} if ("free" in text or "degree" in text or "n" == text[-1:]) else {"r": s.X}


def test_what_a_claim_prints_is_the_same_on_every_method():
    res = run_one(_claim(_branch_on_the_printed_matrix), None, "free", 0)
    assert res.verdict not in PASSING, (res.verdict, res.message)
    assert run_one(_claim(_branch_on_the_printed_matrix), Size(3, 2), "exact", 0).verdict == "fails"


def _caught_size_mismatch(s):
    """False (X = 0): on the dimension-free scene a product of an n-column matrix with a 2r-row one
    failed as a plain ValueError (n = 2r is a matter of the sizes), which a claim could catch."""
    try:
        s.X.T @ s.zeros(2 * s.r, s.r)
    except Exception:
        return {"r": s.X - s.X}
    return {"r": s.X}


def _caught_block_mismatch(s):
    """The same through a block matrix whose blocks fit only when n = 2r."""
    try:
        block([[s.X, s.zeros(s.n, s.r)], [s.zeros(2 * s.r, s.r), s.zeros(2 * s.r, s.r)]])
    except Exception:
        return {"r": s.X - s.X}
    return {"r": s.X}


@pytest.mark.parametrize("func", [_caught_size_mismatch, _caught_block_mismatch], ids=lambda f: f.__name__)
def test_sizes_that_fit_only_for_some_n_r_are_refused_on_record(func):
    res = run_one(_claim(func), None, "free", 0)
    assert res.verdict not in PASSING, (res.verdict, res.message)
    # at n = 2r the spaces ℝⁿ and ℝʳ ⊕ ℝʳ still differ: refused there too (the refusal recorded)
    assert run_one(_claim(func), Size(2, 1), "exact", 0).verdict in ("fails", "error")
