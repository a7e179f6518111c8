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
    #: the scene's primitive whose parameters the case rewrites, when they are drawn with another's: the case reaches
    #: a claim only once it reads that one ("P": the momenta are drawn with X's; "": as soon as they are drawn)
    through: str = ""


def _near_equal_a(gap: Fraction) -> Callable[[Any, str, Any], Any]:
    def rewrite(s, name, v):
        if name.startswith("a_") and name != "a_1":
            i = int(name[2:])
            return s._param("a_1") + s.field.const(gap * i) * (1 + v * v)
        return v
    return rewrite


def _near_pole(gap: Fraction) -> Callable[[Any, str, Any], Any]:
    def rewrite(s, name, v):
        if name == "lambda":
            return s._param("a_1") + s.field.const(gap)
        return v
    return rewrite


def _large_momenta(s, name, v):
    if name.startswith(("W_", "Z_")):
        return v * s.field.const(10**6)
    return v


def _huge_momenta(s, name, v):
    if name.startswith(("W_", "Z_")):
        return v * s.field.const(10**160)
    return v


def _manakov_0_0(s, name, v):
    """a_i and the claim's own b_i both nearly equal: (b_i - b_j)/(a_i - a_j) is near 0/0."""
    if name.startswith("a_") and name != "a_1":
        return s._param("a_1") + s.field.const(Fraction(int(name[2:]), 10**9)) * (1 + v * v)
    if name.startswith(USER_B) and name != USER_B + "1":
        return s._param(USER_B + "1") + s.field.const(Fraction(int(name[len(USER_B):]), 10**9)) * (2 + v * v)
    return v


def _far_chart(s, name, v):
    """The Cayley parameters S (X = (I - S)(I + S)^-1) of size 1e4: X far from the chart's origin I."""
    if name.startswith("S_"):
        return v * s.field.const(10**4)
    return v


#: the claim's own scalars named b_i (the eigenvalues of B in the Manakov operator)
USER_B = "scalar:b_"


HARD_CASES = {
    "near-equal-a": HardCase("near-equal-a", "a_2..a_n within 1e-9 (1 + t^2) of a_1 (nearly equal eigenvalues)",
                             _near_equal_a(Fraction(1, 10**9))),
    "near-pole": HardCase("near-pole", "lambda = a_1 + 1e-12 (spectral parameter next to a pole)",
                          _near_pole(Fraction(1, 10**12))),
    "large-momenta": HardCase("large-momenta", "momenta scaled by 1e6", _large_momenta, through="P"),
}
for _k in (3, 6, 12):
    HARD_CASES[f"near-equal-a-1e-{_k}"] = HardCase(
        f"near-equal-a-1e-{_k}", f"a_2..a_n within 1e-{_k} i (1 + t^2) of a_1 (eigenvalue gaps 1e-{_k})",
        _near_equal_a(Fraction(1, 10**_k)))
HARD_CASES["near-pole-1e-8"] = HardCase("near-pole-1e-8", "lambda = a_1 + 1e-8 (spectral parameter 1e-8 from a pole)",
                                        _near_pole(Fraction(1, 10**8)))
HARD_CASES["manakov-0/0"] = HardCase(
    "manakov-0/0", "a_2..a_n and the claim's b_2..b_n within 1e-9 of a_1, b_1 ((b_i - b_j)/(a_i - a_j) near 0/0)",
    _manakov_0_0)
HARD_CASES["huge-momenta"] = HardCase("huge-momenta", "momenta scaled by 1e160 (products overflow float64: the "
                                      "float method must escalate)", _huge_momenta, through="P")
HARD_CASES["far-chart"] = HardCase(
    "far-chart", "Cayley parameters S scaled by 1e4 (a point far from the chart's origin)", _far_chart)


def hard_case(name: str) -> HardCase:
    try:
        return HARD_CASES[name]
    except KeyError:
        raise ValueError(f"unknown hard case {name!r} (one of {', '.join(HARD_CASES)})") from None
