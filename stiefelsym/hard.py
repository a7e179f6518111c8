"""Hard numerical cases: parameter choices that stress floating point.

Each case rewrites some chart parameters after they are drawn (so the random
stream, and the seed's meaning, are unchanged).  Exact methods evaluate the
same hard point exactly; the float method must escalate or say inconclusive.
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Callable


@dataclass(frozen=True)
class HardCase:
    name: str
    description: str
    rewrite: Callable[[Any, str, Any], Any]   # (scene, parameter name, drawn value) -> value


def _near_equal_a(s, name, v):
    if name.startswith("a_") and name != "a_1":
        i = int(name[2:])
        return s._param("a_1") + s.field.const(Fraction(i, 10**9)) * (1 + v * v)
    return v


def _near_pole(s, name, v):
    if name == "lambda":
        return s._param("a_1") + s.field.const(Fraction(1, 10**12))
    return v


def _large_momenta(s, name, v):
    if name.startswith(("W_", "Z_")):
        return v * s.field.const(10**6)
    return v


HARD_CASES = {
    "near-equal-a": HardCase("near-equal-a", "a_2..a_n within 1e-9 (1 + t^2) of a_1 (nearly equal eigenvalues)",
                             _near_equal_a),
    "near-pole": HardCase("near-pole", "lambda = a_1 + 1e-12 (spectral parameter next to a pole)", _near_pole),
    "large-momenta": HardCase("large-momenta", "momenta scaled by 1e6", _large_momenta),
}


def hard_case(name: str) -> HardCase:
    try:
        return HARD_CASES[name]
    except KeyError:
        raise ValueError(f"unknown hard case {name!r} (one of {', '.join(HARD_CASES)})") from None
