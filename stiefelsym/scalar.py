"""The numbers a claim sees: one opaque type for every method, and one recorded door.

A claim computes with the numbers of its scene (λ, κ, the entries of X, traces,
brackets, constants ``s.q(num, den)``); it never looks at them.  Every such number
reaches claim code as a :class:`Scalar`, whatever the method: a symbolic
expression, a rational or a residue at a random point, an error-bounded float, a
degree marker of the structural pass, a dual or reverse number.  A claim therefore
cannot tell the methods (or the structural pass from the sampled one) apart by the
type of its numbers, and every way of reading a value (truth value, comparison,
``int``, ``float``, ``str``, hashing) is refused *and recorded* in the scene's
record before the refusal is raised: a claim that catches the refusal and computes
something else is still an ``error``, since the record outlives the exception
(:func:`stiefelsym.claims.run_claim` checks it when the claim returns).

Engine code receives the raw numbers (:func:`raw`, :func:`claim_code`): the
scene hands a ``Scalar`` only to callers outside the package.
"""
from __future__ import annotations

import sys
from fractions import Fraction
from typing import Any

#: the modules whose code is the engine (everything else is claim code)
ENGINE_PREFIX = "stiefelsym."


#: the matrix class, imported on first use (the matrix module imports this one)
_MAT: list = []

#: how many claims are running (nested: a claim's function may be called inside another's run)
_RUNNING = [0]


def claim_code(depth: int = 2) -> bool:
    """Whether the caller of the function that calls this one is claim code: code outside the
    engine's package, while a claim runs (``depth`` frames up: 2 = the caller of the property or
    method that asks).  Outside a claim's run (the engine's own tests, an interactive session)
    nothing is claim code."""
    if not _RUNNING[0]:
        return False
    return not sys._getframe(depth).f_globals.get("__name__", "").startswith(ENGINE_PREFIX)


class running_claim:
    """Context of a claim's run: inside it, the scene's doors treat outside code as claim code."""

    __slots__ = ()

    def __enter__(self):
        _RUNNING[0] += 1
        return self

    def __exit__(self, *exc):
        _RUNNING[0] -= 1
        return False


class ValueRead(TypeError):
    """A claim tried to read the value of a number of its scene."""


def arithmetic_seen(rec: Any) -> None:
    """Record that claim code met an arithmetic exception (a division by zero, a singular system):
    how a method raises one (at a random point, symbolically, or not at all) tells the methods
    apart, so a claim that catches it and computes something else is not trusted."""
    if rec is not None:
        rec.refuse("an arithmetic exception (a division by zero or a singular system)")


class EngineOnly(AttributeError):
    """A claim asked for something only the engine sees (the number system, the sampled point)."""


def engine_only(rec: Any, what: str):
    """Refuse claim code an engine-only object, recording it first."""
    if rec is not None:
        rec.refuse(what)
    raise EngineOnly(f"{what} is the engine's: a claim computes the same way on every method")


class Scalar:
    """A number of the scene, as claim code sees it (see the module's docstring)."""

    __slots__ = ("_x", "_rec")
    #: the engine's own number types (dual, reverse numbers) defer to an operand of this priority,
    #: so that a claim's number meets them through its reflected operators
    __array_priority__ = 1000

    def __init__(self, x: Any, rec: Any) -> None:
        self._x = x
        self._rec = rec

    def _symengine_(self) -> Any:
        """What symengine sees where a symengine number meets this one (engine numbers a claim got
        from an engine helper): the expression itself."""
        x = self._x
        if type(x).__module__.startswith("symengine"):
            return x
        from ._lazy import symengine_opaque
        return symengine_opaque()

    # -- arithmetic: the raw numbers' own, wrapped again ------------------------------------
    def _other(self, o: Any) -> Any:
        t = type(o)
        if t is Scalar:
            return o._x
        if t is int or t is Fraction:
            return o
        if t is float:
            raise TypeError("use integers or fractions, not floats, as constants in claims")
        if not _MAT:
            from .matrix import Mat
            _MAT.append(Mat)
        return None if isinstance(o, _MAT[0]) else o

    def __add__(self, o):
        y = o._x if type(o) is Scalar else self._other(o)
        return NotImplemented if y is None else Scalar(self._x + y, self._rec)

    def __radd__(self, o):
        y = self._other(o)
        return NotImplemented if y is None else Scalar(y + self._x, self._rec)

    def __sub__(self, o):
        y = o._x if type(o) is Scalar else self._other(o)
        return NotImplemented if y is None else Scalar(self._x - y, self._rec)

    def __rsub__(self, o):
        y = self._other(o)
        return NotImplemented if y is None else Scalar(y - self._x, self._rec)

    def __mul__(self, o):
        y = o._x if type(o) is Scalar else self._other(o)
        return NotImplemented if y is None else Scalar(self._x * y, self._rec)

    def __rmul__(self, o):
        y = self._other(o)
        return NotImplemented if y is None else Scalar(y * self._x, self._rec)

    def _divided(self, a: Any, b: Any) -> "Scalar":
        try:
            return Scalar(a / b, self._rec)
        except ArithmeticError:
            arithmetic_seen(self._rec)
            raise

    def __truediv__(self, o):
        y = o._x if type(o) is Scalar else self._other(o)
        return NotImplemented if y is None else self._divided(self._x, y)

    def __rtruediv__(self, o):
        y = self._other(o)
        return NotImplemented if y is None else self._divided(y, self._x)

    def __pow__(self, k):
        if type(k) is not int:
            raise TypeError("a number of the scene is raised to integer powers only")
        if k < 0:
            return self._divided(1, _power(self._x, -k))
        return Scalar(_power(self._x, k), self._rec)

    def __neg__(self):
        return Scalar(-self._x, self._rec)

    def __pos__(self):
        return self

    # -- every way of looking at the value: refused and recorded ----------------------------
    def _read(self, how: str):
        if self._rec is not None:
            self._rec.refuse(f"the value of a number ({how})")
        raise ValueRead(f"a claim computes with the numbers of its scene and never reads them ({how}); "
                        "return the difference as a residual instead")

    def __repr__(self) -> str:
        return "<a number of the scene>"

    def __reduce__(self):
        self._read("pickling")

    def __iter__(self):
        raise TypeError("a number of the scene is not iterable")


#: the ways of looking at a value, each refused and recorded (see Scalar._read)
_READS = {"__bool__": "its truth value", "__hash__": "a hash", "__int__": "int()", "__float__": "float()",
          "__complex__": "complex()", "__index__": "an index", "__abs__": "abs()", "__round__": "round()",
          "__trunc__": "trunc()", "__floor__": "floor()", "__ceil__": "ceil()", "__str__": "str()",
          "__format__": "format()", **{k: "a comparison" for k in ("__eq__", "__ne__", "__lt__", "__le__",
                                                                  "__gt__", "__ge__")}}


def _door(how: str):
    def read(self, *args):
        self._read(how)
    return read


for _name, _how in _READS.items():
    setattr(Scalar, _name, _door(_how))


def raw(x: Any) -> Any:
    """The engine's number behind a claim's :class:`Scalar` (anything else unchanged)."""
    return x._x if type(x) is Scalar else x


def _power(x: Any, k: int) -> Any:
    """x^k (k >= 0) by squaring and multiplying: every number system multiplies, so every method
    computes the same power the same way (a power some number type lacks would raise there only,
    and a claim catching that could tell the methods apart)."""
    if k == 0:
        return x * 0 + 1
    out = None
    while True:
        if k & 1:
            out = x if out is None else out * x
        k >>= 1
        if not k:
            return out
        x = x * x


def unwrap(v: Any) -> Any:
    """A claim's value with every :class:`Scalar` replaced by its number (dicts, lists, tuples)."""
    t = type(v)
    if t is Scalar:
        return v._x
    if t is dict:
        return {k: unwrap(x) for k, x in v.items()}
    if t is list:
        return [unwrap(x) for x in v]
    if t is tuple:
        return tuple(unwrap(x) for x in v)
    return v


_NUMBER: list = []      # is_scene_number and the reverse number type, bound on first use


def _number_test():
    if not _NUMBER:
        from .matrix import is_scene_number
        from .reverse import Rev
        _NUMBER[:] = [is_scene_number, Rev]
    return _NUMBER


def wrap(x: Any, rec: Any) -> Any:
    """x as claim code sees it: numbers become :class:`Scalar` (lists and tuples of them too);
    matrices, callables and everything else are unchanged."""
    t = type(x)
    if t is Scalar:
        return x
    if t is list:
        return [wrap(y, rec) for y in x]
    if t is tuple:
        return tuple(wrap(y, rec) for y in x)
    if t is dict:
        return {k: wrap(y, rec) for k, y in x.items()}
    is_number, rev = _NUMBER or _number_test()
    if t is rev or is_number(x):
        return Scalar(x, rec)
    return x
