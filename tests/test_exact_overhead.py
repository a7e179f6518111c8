"""The per-run shortcuts of the exact method: Phi from one product, its derivative from the base
scene's, the matrix operations' native fast paths, the exact backend's memo of operations on the
same operands and the deadline's handler swap compute the same values and keep every check and
refusal of the general paths."""
import random
import signal
from fractions import Fraction

import numpy as np
import pytest

from stiefelsym.backends import native
from stiefelsym.claims import ClaimTimeout, Size, deadline
from stiefelsym.backends.fields import ModularField, RationalField
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import comm
from stiefelsym.run.runner import run_one
from stiefelsym.scene import Scene

SIZES = [(2, 1), (3, 1), (3, 2), (4, 2), (3, 3)]


def _printed_phi(s):
    return s.P @ s.X.T - s.X @ s.P.T


def _fields():
    return [lambda: SymbolicField(), lambda: RationalField(), lambda: ModularField()]


@pytest.mark.parametrize("n,r", SIZES)
@pytest.mark.parametrize("chart", ["equivariant", "cayley"])
def test_phi_is_the_printed_momentum_map(n, r, chart):
    for make in _fields():
        f = make()
        if chart == "cayley" and n > 3 and isinstance(f, SymbolicField):
            continue                            # the symbolic Cayley chart stops at n = 3
        s = Scene(n, r, f, chart=chart, rng=random.Random(n + 7 * r))
        assert (s.Phi - _printed_phi(s)).is_zero()
        assert (s.Phi + s.Phi.T).is_zero()
        # a corrupted momentum map is told apart
        assert not (s.Phi - (s.P @ s.X.T + s.X @ s.P.T)).is_zero() or (s.X @ s.P.T).is_zero()


def _flow(s):
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    return {"X": P - k * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}


@pytest.mark.parametrize("n,r", SIZES)
@pytest.mark.parametrize("keys", [("X", "P"), ("X",), ("P",)])
def test_derivative_of_phi_is_the_dual_computation(n, r, keys):
    for make in _fields():
        s = Scene(n, r, make(), chart="equivariant", rng=random.Random(3 * n + r))
        printed = {k: v for k, v in _flow(s).items() if k in keys}
        generic = {"X": s.generic("U", "n", "r"), "P": s.generic("V", "n", "r")}
        for flow in (printed, {k: generic[k] for k in keys}):
            fast = s.d(lambda t: t.Phi, flow)
            assert (fast - s.d(_printed_phi, flow)).is_zero()
        # a wrong derivative (that of the symmetric P X^T + X P^T) is told apart at a generic tangent
        wrong = s.d(lambda t: t.P @ t.X.T + t.X @ t.P.T, flow)
        assert not (fast - wrong).is_zero()


def test_phi_on_the_generic_path_agrees(monkeypatch):
    s1 = Scene(3, 2, ModularField(), chart="equivariant", rng=random.Random(5))
    d1 = s1.d(lambda t: t.Phi, _flow(s1))
    monkeypatch.setattr(native, "ENABLED", False)
    s2 = Scene(3, 2, ModularField(), chart="equivariant", rng=random.Random(5))
    d2 = s2.d(lambda t: t.Phi, _flow(s2))
    assert d1._view().tolist() == d2._view().tolist()


def test_native_fast_paths_keep_their_checks():
    s = Scene(3, 1, SymbolicField(), chart="equivariant")
    X, P, A = s.X, s.P, s.A
    assert (P @ X.T - (X @ P.T).T).is_zero()
    with pytest.raises(ValueError):
        X @ X                                   # 3x1 by 3x1
    with pytest.raises(ValueError):
        A + X
    s3 = Scene(3, 3, SymbolicField(), chart="equivariant")
    with pytest.raises(TypeError):
        s3.X + s3.A                             # 3x3 both, R^r is not R^n
    with pytest.raises(TypeError):
        s3.X - s3.A
    with pytest.raises(TypeError):
        s3.X @ s3.A
    with pytest.raises(TypeError):
        2.0 * A
    assert (True * A - A).is_zero()
    assert (Fraction(1, 2) * A + Fraction(1, 2) * A - A).is_zero()
    assert A.__mul__(A) is NotImplemented
    assert comm(A, A).is_zero()


def test_deadline_restores_the_handler_and_fires():
    before = signal.getsignal(signal.SIGALRM)
    with deadline(100.0, "x"):
        pass
    assert signal.getsignal(signal.SIGALRM) == before
    with pytest.raises(ClaimTimeout):
        with deadline(0.05, "a loop"):
            while True:
                pass
    assert signal.getsignal(signal.SIGALRM) == before


def test_a_deadline_that_expires_in_a_weakref_callback_is_neither_lost_nor_printed(capfd):
    """The garbage collector runs weakref callbacks (WeakSet's) whose exceptions Python ignores, printing
    "Exception ignored in ...": a timeout raised there is raised again in the code the deadline limits."""
    import gc
    import sys
    import time
    import weakref

    class Box:
        pass

    def slow_callback(_):             # a callback still running when the deadline expires
        t_end = time.monotonic() + 0.2
        while time.monotonic() < t_end:
            pass
    hook = sys.unraisablehook
    with pytest.raises(ClaimTimeout):
        with deadline(0.05, "a loop"):
            box = Box()
            ref = weakref.ref(box, slow_callback)
            del box                    # the callback runs now, and the alarm comes inside it
            gc.collect()
            t_end = time.monotonic() + 2.0
            while time.monotonic() < t_end:
                pass
    assert ref() is None
    assert sys.unraisablehook is hook
    assert "Exception ignored" not in capfd.readouterr().err


def test_la1_verdicts_and_a_corrupted_la1(catalog):
    """The exact method proves LA1 at small sizes and rejects it with the commutator's sign flipped."""
    from stiefelsym.claims import Claim, admissible

    def la1(s, sign=1):
        L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
        M = s.Phi - s.lam * s.A
        return {"LA1": s.d(L, _flow(s)) - sign * comm(M, L(s))}

    good = Claim(id="LA1-overhead", paper=("LA1",), kind="lax", section="5", func=la1,
                 sizes=admissible(3), title="LA1")
    bad = Claim(id="LA1-overhead-bad", paper=("LA1",), kind="lax", section="5",
                func=lambda s: la1(s, -1), sizes=admissible(3), title="LA1 corrupted")
    for n, r in [(2, 1), (3, 1), (3, 2)]:
        assert run_one(good, Size(n, r), "exact", seed=0).verdict == "proved"
        assert run_one(bad, Size(n, r), "exact", seed=0).verdict == "fails"


def test_exact_backend_remembers_operations_on_the_same_operands_only():
    f = SymbolicField()
    s = Scene(3, 2, f, chart="equivariant")
    be = native.backend(f)
    A, P = s.A._nat(), s.P._nat()
    AP = be.matmul(A, P)
    assert be.matmul(A, P) is AP                       # the same operands: the stored product
    PT = be.T(P)
    assert be.T(P) is PT
    A2 = native.backend(SymbolicField())                # another field: nothing shared
    assert not A2._memo
    # remembered results are the values: compare with the symbolic products entry by entry
    fresh = np.dot(s.A._view(), s.P._view())
    got = be.to_obj(AP)
    assert all(f.is_zero(x - y) for x, y in zip(got.flat, fresh.flat))
    lam = s._param("lambda")
    assert be.smul(A, lam) is be.smul(A, lam)
    assert be.add(A, A) is be.add(A, A) and be.sub(AP, AP) is be.sub(AP, AP)
    # a different operand with equal entries is computed, not looked up by value
    A_again = be.from_obj(s.A._view())
    assert A_again is not A and be.matmul(A_again, P) is not AP
    # bounded
    for _ in range(300):
        be.matmul(be.from_obj(s.A._view()), P)
    assert len(be.__dict__["_memo"]) <= 128


def test_the_claims_scene_is_a_tracing_scene_with_nothing_of_the_engine():
    from stiefelsym.ir.trace import Trace, TraceScene
    from stiefelsym.scene import REALIZATIONS
    t = Trace(3, 1, (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build))
    v = TraceScene(t, t.g.add("scene", (0,)))
    assert type(v) is TraceScene and not isinstance(v, Scene) and repr(v) == "<a scene>"
    with pytest.raises(AttributeError):
        v.no_such_thing = 1
    with pytest.raises(AttributeError):
        v._tracker                                       # no engine state behind it
    assert repr(v.X) == "<traced nxr matrix>"          # its spaces, never the number of a size


def test_tangent_scene_parameters_are_constants_lifted_once():
    s = Scene(3, 1, SymbolicField(), chart="equivariant")
    flow = _flow(s)
    dl = s.d(lambda t: t.lam * t.kappa * t.X, flow)
    assert (dl - s.lam * s.kappa * flow["X"]).is_zero()
    # a derivative that forgets the product rule is told apart
    assert not (dl - s.lam * s.kappa * s.X).is_zero()


def test_a_deadline_whose_timeout_a_handler_swallows_fires_again():
    """A timeout raised inside an ``except Exception`` that falls back to something else (the engine has
    such fallbacks) does not end the deadline: the alarm repeats until the block is left, so a long
    computation after the fallback is still interrupted."""
    import time
    before = signal.getsignal(signal.SIGALRM)
    swallowed = []
    t0 = time.monotonic()
    with pytest.raises(ClaimTimeout):
        with deadline(0.05, "a fallback and a loop"):
            try:
                while True:         # the first alarm comes here, and is swallowed
                    pass
            except Exception as exc:    # noqa: BLE001 - the trick under test
                swallowed.append(exc)
            while time.monotonic() - t0 < 5:
                pass
    assert swallowed and isinstance(swallowed[0], ClaimTimeout)
    assert time.monotonic() - t0 < 2
    assert signal.getsignal(signal.SIGALRM) == before
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


def test_nested_deadlines_restore_the_outer_one():
    import time
    with pytest.raises(ClaimTimeout, match="outer"):
        with deadline(0.3, "outer"):
            with pytest.raises(ClaimTimeout, match="inner"):
                with deadline(0.05, "inner"):
                    while True:
                        pass
            left, every = signal.getitimer(signal.ITIMER_REAL)
            assert 0 < left < 0.3 and every > 0
            t_end = time.monotonic() + 5
            while time.monotonic() < t_end:
                pass
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


def test_a_deadline_that_expires_in_the_division_probe_leaves_no_memoized_answer(monkeypatch):
    """The division probe's answers are memoized, and it falls back on "" (no division found) for an exception
    that is not a division: a timeout there must stop the run, not become that answer."""
    from stiefelsym import admissible
    from stiefelsym.claims import Claim
    from stiefelsym.methods import fixed_size
    from stiefelsym.methods.fixed_size import ExactTimeout, division_probe

    def divides(s):
        return {"x": s.X.T @ s.X - s.identity(s.r)}
    claim = Claim(id="probe-expiry", paper=(), kind="id", section="t", func=divides, sizes=admissible(4))
    real = fixed_size.call_claim

    def expires(func, scene):
        raise ExactTimeout("the symbolic computation did not finish within 1 s")
    monkeypatch.setattr(fixed_size, "call_claim", expires)
    with pytest.raises(ExactTimeout):
        division_probe(claim, 3, 2)
    monkeypatch.setattr(fixed_size, "call_claim", real)
    assert division_probe(claim, 3, 2) == ""
