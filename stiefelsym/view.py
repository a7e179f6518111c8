"""The scene as claim code sees it: one class for every method.

Every method hands a claim a scene: a fixed size over a number system (symbolic,
ℚ, GF(p), float64, degree markers, dual and reverse numbers inside derivatives),
or the dimension-free algebra.  These are different engine classes.  A claim
sees none of them: it gets a :class:`ClaimScene`, the same class on every method
and inside every derivative, gradient and bracket, which offers the documented
API (README, "What a scene s offers") and nothing else:

* numbers come as :class:`~stiefelsym.scalar.Scalar`, sizes ``s.n``, ``s.r`` as
  :class:`Dim` (an ``int`` at a fixed size; on the dimension-free scene every use
  of it as a number is refused and recorded);
* a function the claim hands to the scene (a Hamiltonian, a function to
  differentiate, an operator) is called with a ``ClaimScene`` too;
* anything else public of the engine's scene (its number system, chart, point,
  random source, rewriting system) is refused, and the refusal recorded.

So a claim cannot learn which method runs it from the class of its scene, of its
sizes or of its numbers; the dimension-free method's "proved for all n, r" is
about the same function every fixed-size method evaluates.
"""
from __future__ import annotations

from typing import Any

from .matrix import Mat
from .scalar import Scalar, arithmetic_seen, claim_code, engine_only, unwrap, wrap

#: what a claim may ask of its scene (README: "What a scene s offers" and "More building blocks")
API = frozenset("""
    X P A Ainv Phi Psi In Ir lam kappa eps scalar q const xi zeta eta theta generic sym_operator
    Y Q Zc Zc_dot tr killing resolvent dirac_flow multiplier_flow bracket canonical_bracket
    canonical_flow gradient d mat zeros identity general_params jacobian constraint_bracket_matrix
    scalar_matrix n r a conj realify tangent constraints
""".split())

#: the methods among them that take functions of the scene
_TAKES_FUNCTIONS = frozenset("dirac_flow multiplier_flow bracket canonical_bracket canonical_flow gradient d "
                             "jacobian".split())


def engine_scene(s: Any) -> Any:
    """The engine's scene behind a claim's view (anything else unchanged)."""
    return object.__getattribute__(s, "_s") if type(s) is ClaimScene else s


_SCENE_CLASS: list = []


def _is_scene(x: Any) -> bool:
    if not _SCENE_CLASS:
        from .scene import PaperObjects
        _SCENE_CLASS.append(PaperObjects)
    return isinstance(x, _SCENE_CLASS[0])


def view(s: Any) -> Any:
    """The claim's view of an engine scene (views and other values unchanged)."""
    return ClaimScene(s) if _is_scene(s) else s


class Dim:
    """A size n, r (or a multiple) as a claim sees it, the same class on every method: at a fixed
    size it behaves as its int in every use (``range``, arithmetic, comparisons, formatting, as an
    index); on the dimension-free scene it sizes identity and zero blocks (``2 * s.r``) and every
    other use is refused and recorded.  (Not an ``int`` subclass: ``range`` and ``operator.index``
    read an int subclass's value without asking it.)"""

    __slots__ = ("_v", "_free")

    def __init__(self, value: Any) -> None:
        if type(value) is Dim:
            value = value._engine()
        self._free = None if isinstance(value, int) else value
        self._v = int(value) if self._free is None else None

    def _engine(self) -> Any:
        return self._free if self._free is not None else self._v

    def __mul__(self, c):
        if self._free is not None:
            return Dim(self._free * (c._engine() if type(c) is Dim else c))
        return self._v * (c._v if type(c) is Dim else c)

    def __rmul__(self, c):
        if self._free is not None:
            return Dim(c * self._free)
        return c * self._v

    def __hash__(self) -> int:
        if self._free is not None:
            return self._free._refuse()
        return hash(self._v)

    def __repr__(self) -> str:
        return self._free._refuse() if self._free is not None else repr(self._v)


def _delegating(name: str):
    def op(self, *args):
        if self._free is not None:
            return self._free._refuse()                 # refuses, and records it
        return getattr(self._v, name)(*[a._v if type(a) is Dim and a._free is None else a for a in args])
    op.__name__ = name
    return op


for _name in ("__add__", "__radd__", "__sub__", "__rsub__", "__floordiv__", "__rfloordiv__", "__truediv__",
              "__rtruediv__", "__mod__", "__rmod__", "__pow__", "__neg__", "__pos__", "__abs__", "__int__",
              "__index__", "__float__", "__bool__", "__eq__", "__ne__", "__lt__", "__le__", "__gt__", "__ge__",
              "__str__", "__format__", "__divmod__"):
    setattr(Dim, _name, _delegating(_name))


def _to_engine(x: Any) -> Any:
    """An argument of a claim's call, as the engine takes it."""
    t = type(x)
    if t is Mat or t is int or t is str:
        return x
    if t is ClaimScene:
        return object.__getattribute__(x, "_s")
    if t is Scalar:
        return x._x
    if t is Dim:
        return x._engine()
    if t is list:
        return [_to_engine(y) for y in x]
    if t is tuple:
        return tuple(_to_engine(y) for y in x)
    if t is dict:
        return {k: _to_engine(y) for k, y in x.items()}
    return x


def _viewing(f: Any, scene: Any) -> Any:
    """A claim's function as the engine calls it: scenes it gets are views, what it returns is the
    engine's (memoized per engine scene, so that the engine's caches keyed by the function hit)."""
    if not callable(f) or isinstance(f, (Mat, type)):
        return f
    cache = getattr(scene, "_cache", None)
    key = ("claim function", id(f))
    if cache is not None and key in cache:
        return cache[key][1]

    def g(*args, **kw):
        out = f(*[view(a) for a in args], **{k: view(v) for k, v in kw.items()})
        return unwrap(_to_engine(out))
    g.__name__ = getattr(f, "__name__", "f")
    if cache is not None:
        cache[key] = (f, g)
    return g


def _present(x: Any, rec: Any) -> Any:
    """An engine value as claim code sees it."""
    t = type(x)
    if t is Mat or t is Scalar:
        return x
    if _is_scene(x):
        return ClaimScene(x)
    if callable(x) and not isinstance(x, type):
        return _calling(x, None, rec)
    return wrap(x, rec)


def _calling(method: Any, scene: Any, rec: Any) -> Any:
    """A method (or a function the engine hands out, like an operator) as claim code calls it."""
    takes_functions = scene is not None and getattr(method, "__name__", "") in _TAKES_FUNCTIONS

    def call(*args, **kw):
        args = [_to_engine(a) for a in args]
        kw = {k: _to_engine(v) for k, v in kw.items()}
        if takes_functions:
            args = [_viewing(a, scene) for a in args]
            kw = {k: _viewing(v, scene) for k, v in kw.items()}
        try:
            out = method(*args, **kw)
        except ArithmeticError:
            arithmetic_seen(rec)
            raise
        return _present(out, rec)
    call.__name__ = call.__qualname__ = "scene_method"
    return call


class ClaimScene:
    """The scene as claim code sees it (see the module's docstring)."""

    __slots__ = ("_s", "_m")

    def __init__(self, s: Any) -> None:
        object.__setattr__(self, "_s", engine_scene(s))
        object.__setattr__(self, "_m", {})      # the scene's methods as claim code calls them

    def __getattribute__(self, name: str) -> Any:
        # every attribute comes here (no failed ordinary lookup first, which costs an exception per
        # access); this class's own attributes are private names, found as before, and no public
        # name is an attribute of this class, so that every public name goes the way it did
        if name[:1] == "_":
            try:
                return object.__getattribute__(self, name)
            except AttributeError:
                pass
            return getattr(object.__getattribute__(self, "_s"), name)   # outside the API (README)
        s = object.__getattribute__(self, "_s")
        if not claim_code():
            return getattr(s, name)                  # engine code (helpers a claim called) sees it all
        rec = s._tracker
        if name not in API:
            if hasattr(s, name):
                engine_only(rec, f"the scene's {name!r}")
            raise AttributeError(f"a scene has no {name!r} (see README: what a scene s offers)")
        if name in ("n", "r"):
            return Dim(getattr(s, name))
        methods = object.__getattribute__(self, "_m")
        m = methods.get(name)
        if m is not None:
            return m
        v = getattr(s, name)
        if callable(v) and not isinstance(v, (Mat, type)):
            m = methods[name] = _calling(v, s, rec)
            return m
        return _present(v, rec)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a scene is read-only")

    def __repr__(self) -> str:
        return "<a scene>"

    def __eq__(self, o: Any) -> bool:
        return type(o) is ClaimScene and engine_scene(o) is engine_scene(self)

    def __hash__(self) -> int:
        return id(engine_scene(self))
