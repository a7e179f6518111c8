"""Denominators of sparse rational functions: monomials of irreducible factors, as sorted tuples
of (factor, exponent) pairs (the polynomial matrices of :mod:`.polyfield` and the rational-function
matrices of :mod:`.ratmat` share them)."""
from __future__ import annotations

#: the denominator 1
NODEN: tuple = ()


def _merge_max(d1: tuple, d2: tuple) -> tuple:
    if d1 == d2 or not d2:
        return d1
    if not d1:
        return d2
    out = dict(d1)
    for k, e in d2:
        if out.get(k, 0) < e:
            out[k] = e
    return tuple(sorted(out.items()))


def _merge_add(d1: tuple, d2: tuple) -> tuple:
    if not d2:
        return d1
    if not d1:
        return d2
    out = dict(d1)
    for k, e in d2:
        out[k] = out.get(k, 0) + e
    return tuple(sorted(out.items()))


def _minus(d: tuple, sub: tuple) -> tuple:
    """The exponents of d beyond those of sub (d >= sub atom by atom)."""
    s = dict(sub)
    return tuple((k, e - s.get(k, 0)) for k, e in d if e - s.get(k, 0) > 0)
