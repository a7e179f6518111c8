"""Soundness of the dimension-free method: no way around its refusals, no way to tell it apart.

A claim that catches a refusal of the free scene (an entry, a block, a size or a trace form used
as a number, an object that needs coordinates) and returns something that vanishes there, while
every fixed size sees something else, must not be "proved for all n, r": every refusal is
recorded in the run's record before it is raised, and the free method gives no proof when the
record holds one.  And the matrices of the free scene are of the one class ``Mat``.
"""
from __future__ import annotations

import pytest

from stiefelsym.claims import Claim, admissible
from stiefelsym.free import FreeScene
from stiefelsym.free.algebra import NeedsCoordinates, recording, refusals
from stiefelsym.free.mat import entry_of
from stiefelsym.backends.matrix import Mat
from stiefelsym.run.runner import run_one


def _free(func):
    claim = Claim(id="free-trick", paper=("t",), kind="id", section="t", func=func, sizes=admissible(4))
    return run_one(claim, None, "free", 0)


def _tricked(touch):
    """A claim that is false at every size but would vanish on the free scene if the refusal of
    ``touch`` could be caught and forgotten."""
    def func(s):
        try:
            touch(s)
        except Exception:   # noqa: BLE001 - the trick: swallow whatever the free scene raises
            return {"r": s.X - s.X}
        return {"r": s.X}
    return func


TRICKS = {
    "an entry": lambda s: s.X[0, 0],
    "a block": lambda s: s.A[0:1, :],
    "a shape": lambda s: s.X.shape,
    "the size n as a number": lambda s: int(s.n),
    "sizes compared": lambda s: s.n == s.r,
    "a size in arithmetic": lambda s: s.r + 1,
    "a matrix of a numeric size": lambda s: s.zeros(2, 2),
    "the dimension r as a number": lambda s: int(s.tr(s.Ir)),
    "a trace form compared": lambda s: s.tr(s.X.T @ s.P) < 0,
    "an inverse": lambda s: s.A.inv(),
    "the eigenvalues of A": lambda s: s.a,
    "a coordinate-scene method": lambda s: s.jacobian,
    "a gradient of a matrix": lambda s: s.gradient(lambda t: t.P),
    "the multipliers of a matrix": lambda s: s.multiplier_flow(lambda t: t.P.T @ t.P),
    "a flow that moves A": lambda s: s.tangent({"A": s.A}),
    "a value along a flow off T*V": lambda s: s.d(s.Phi, {"X": s.X, "P": s.P}),
    "a Hamiltonian that is no trace form": lambda s: s.dirac_flow(lambda t: t.X),
}


#: refusals raised by Mat itself (stiefelsym/backends/matrix.py: Mat.shape, Mat.__getitem__): closed once Mat
#: records them before raising; until then the route is open (kept as strict xfails)
MATRIX_DOORS = {"an entry", "a block", "a shape"}


def _mat_records_its_refusals() -> bool:
    s = FreeScene(lazy=True)
    try:
        s.X.shape
    except Exception:   # noqa: BLE001
        pass
    return bool(refusals(s.tracker))


MAT_RECORDS = _mat_records_its_refusals()


def _cases():
    return [pytest.param(name, marks=pytest.mark.xfail(
        not MAT_RECORDS, strict=True,
        reason="Mat.shape and Mat.__getitem__ raise NeedsCoordinates without recording it"))
        if name in MATRIX_DOORS else name for name in sorted(TRICKS)]


@pytest.mark.parametrize("name", _cases())
def test_a_caught_refusal_is_never_a_proof(name):
    res = _free(_tricked(TRICKS[name]))
    # the claim is traced: whatever it caught, the verdict is about the graph it built, never a proof
    assert res.verdict in ("undecided", "error"), (name, res.verdict, res.message)


def test_the_untricked_claim_is_still_proved_and_the_false_one_open():
    assert _free(lambda s: {"r": s.X - s.X}).verdict == "proved"
    assert _free(lambda s: {"r": s.X}).verdict == "undecided"


@pytest.mark.parametrize("name", _cases())
def test_a_refusal_is_recorded_before_it_is_raised(name):
    """In the scene's record (or, for the objects every run shares -- the dimension symbols, trace
    forms, the rewriting system -- in the record of the run in progress)."""
    s = FreeScene(lazy=True)
    with recording(s.tracker):
        with pytest.raises(Exception):   # noqa: PT011 - the refusal itself, or the claim-facing guard's
            TRICKS[name](s)
    assert refusals(s.tracker), name


def test_a_refusal_in_the_dual_scene_of_a_flow_is_recorded_too():
    def func(s):
        def F(t):
            try:
                int(t.n)
            except Exception:   # noqa: BLE001
                return t.X - t.X
            return t.X
        return {"r": s.d(F, {"X": s.P, "P": -(s.A @ s.X)})}
    res = _free(func)
    assert res.verdict == "undecided" and "a refusal the claim caught still counts" in res.message, res.message


def test_the_matrices_of_the_free_scene_are_of_the_one_class_Mat():
    s = FreeScene(lazy=True)
    k = 1 + 2 * s.kappa
    values = [s.X, s.P, s.A, s.Phi, s.X @ s.P.T, -(s.A @ s.X), (s.X @ s.P.T @ s.X) * k, s.X / s.lam,
              s.resolvent(s.lam), s.identity(s.n), s.zeros(s.n, s.r), s.scalar_matrix(s.lam, 2 * s.r)]
    t = s.tangent({"X": s.P, "P": -(s.A @ s.X)})
    values += [t.X, t.X @ t.P.T - t.P @ t.X.T]
    flow = s.dirac_flow(lambda u: u.tr(u.P.T @ u.P))
    values += [flow.Xdot, flow.Pdot, s.d(s.Phi, flow)]
    for M in values:
        assert type(M) is Mat, type(M)


#: refusals raised outside the free scene, by library helpers a claim may call with it
#: (stiefelsym/twisted.py: _scene, stiefelsym/systems.py: _coordinate_scene): recorded in the
#: scene's record before they are raised, like the scene's own
HELPER_DOORS = {
    "twisted.magnetic_matrix": lambda s: __import__("stiefelsym.twisted", fromlist=["x"]).magnetic_matrix(s),
    "systems.real_coordinates": lambda s: __import__("stiefelsym.systems", fromlist=["x"]).real_coordinates(s, ["X"]),
}


@pytest.mark.parametrize("name", sorted(HELPER_DOORS))
def test_a_caught_refusal_of_a_library_helper_is_never_a_proof(name):
    res = _free(_tricked(HELPER_DOORS[name]))
    assert res.verdict == "undecided", (name, res.verdict, res.message)


def test_ambient_quantities_need_the_function_as_written():
    """Gradients, canonical flows, multipliers and {,}_0 depend on a function off T*V: a lazy scene
    (the free method's) keeps the trace form as written and offers them; an eager scene, which has
    reduced it modulo the constraints, refuses and records the refusal."""
    H = lambda t: t.tr(t.X.T @ t.X @ t.P.T @ t.P)
    lazy = FreeScene(lazy=True)
    HX, HP = lazy.gradient(H)
    # ∂/∂X tr(XᵀX PᵀP) = 2 X PᵀP, whose normal form is not that of the reduced H = tr(PᵀP) (which is 0)
    assert not lazy.system.is_zero(entry_of(HX))
    assert lazy.system.is_zero(entry_of(HX - 2 * lazy.X @ lazy.P.T @ lazy.P))
    assert lazy.system.is_zero(entry_of(HP - 2 * lazy.P))
    flow = lazy.canonical_flow(H)
    assert lazy.system.is_zero(entry_of(flow.Xdot - HP)) and lazy.system.is_zero(entry_of(flow.Pdot + HX))
    eager = FreeScene()
    for op in (lambda s: s.gradient(H), lambda s: s.canonical_flow(H), lambda s: s.multiplier_flow(H),
               lambda s: s.canonical_bracket(H, H)):
        with recording(eager.tracker):
            with pytest.raises(NeedsCoordinates):
                op(eager)
        assert refusals(eager.tracker)


def test_a_claim_left_to_the_fixed_size_methods_says_what_it_reads():
    """The reason is read from the claim's graph at a fixed size: what it states and reads there."""
    from stiefelsym.claims import load_catalog
    from stiefelsym.methods.dimension_free import run_free
    cat = load_catalog()
    expect = {"pencil-rank-a1": "a rank", "mum-geod": "the eigenvalues a_i of A",
              "neumann-torus-dimension": "a Jacobian", "gen-chasles-momentum-ranges": "a count of dimensions",
              "gen-chasles2": "entries of a matrix on R^n",
              "2r-integrals": "its statement uses a size as a number"}
    for cid, what in expect.items():
        res = run_free(cat.get(cid))
        assert res.verdict == "undecided" and "needs coordinates (fixed n, r)" in res.message, res.message
        assert what in res.message, (cid, res.message)
