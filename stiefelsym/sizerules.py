"""Statements about sizes that read right: the rule that separates the sizes where a statement
fails from those where it holds, as a formula in n and r.

Over the computed sizes only: the rule is the simplest condition (one comparison, or two joined
by "and" or by "or") of the forms r ⋛ k, n ⋛ k, n − r ⋛ k and n − 2r ⋛ k (and ≠) that is true at every size in
``fails`` and false at every size in ``holds``.  It says nothing about sizes not computed, and
the report says so.
"""
from __future__ import annotations

import re

from itertools import combinations
from typing import Callable, Iterable, NamedTuple

Size = tuple[int, int]

#: a size as text: "n,r", with spaces, signs and "n=", "r=" allowed (the one reading of --size, of a text in
#: ``verify(sizes=...)`` and of the pytest plugin's --stiefelsym-size)
_SIZE_TEXT = re.compile(r"\s*(?:n\s*=\s*)?([+-]?\d+)\s*,\s*(?:r\s*=\s*)?([+-]?\d+)\s*")


def parse_size(text: str) -> Size:
    """The size (n, r) an "n,r" text names, with 1 <= r <= n; ValueError, in one line naming the text, otherwise."""
    m = _SIZE_TEXT.fullmatch(str(text))
    if not m:
        raise ValueError(f"{text!r} is not a size; write n,r with integers 1 <= r <= n, e.g. 4,2")
    n, r = int(m.group(1)), int(m.group(2))
    if n < 1:
        raise ValueError(f"{text!r}: n = {n}, but the Stiefel variety V(n,r) needs n >= 1")
    if r < 1:
        raise ValueError(f"{text!r}: r = {r}, but the Stiefel variety V(n,r) needs r >= 1")
    if r > n:
        raise ValueError(f"{text!r}: r = {r} > n = {n}, but the Stiefel variety V(n,r) needs r <= n")
    return n, r


class Atom(NamedTuple):
    text: str
    test: Callable[[int, int], bool]


def _linear(name: str, f: Callable[[int, int], int], k: int) -> list[Atom]:
    """f(n, r) = k, ≥ k, ≤ k, written the way a mathematician writes them."""
    def say(op: str) -> str:
        if name == "n - r":
            return {("=", 0): "r = n", (">=", 1): "r < n", ("<=", 0): "r = n"}.get(
                (op, k), f"n − r {op.replace('>=', '≥').replace('<=', '≤')} {k}")
        if name == "n - 2r":
            if op == "=":
                return "n = 2r" + (f" + {k}" if k > 0 else f" − {-k}" if k < 0 else "")
            if op == ">=":
                return "2r ≤ n" if k == 0 else "2r < n" if k == 1 else f"n ≥ 2r + {k}" if k > 0 else f"n ≥ 2r − {-k}"
            return "2r ≥ n" if k == 0 else "2r > n" if k == -1 else f"n ≤ 2r + {k}" if k > 0 else f"n ≤ 2r − {-k}"
        return f"{name} {op.replace('>=', '≥').replace('<=', '≤')} {k}"
    return [Atom(say("="), lambda n, r: f(n, r) == k), Atom(say(">="), lambda n, r: f(n, r) >= k),
            Atom(say("<="), lambda n, r: f(n, r) <= k)]


def _atoms(sizes: list[Size]) -> list[Atom]:
    forms: list[tuple[str, Callable[[int, int], int]]] = [
        ("r", lambda n, r: r), ("n", lambda n, r: n), ("n - r", lambda n, r: n - r),
        ("n - 2r", lambda n, r: n - 2 * r)]
    out, unequal = [], []
    for name, f in forms:
        for k in sorted({f(n, r) for n, r in sizes}):
            out += _linear(name, f, k)
            unequal.append(_unequal(name, f, k))
    # f(n, r) ≠ k after every other comparison: "n ≠ 2r" where the sizes would otherwise read "2r > n or 2r < n"
    return out + unequal


def _unequal(name: str, f: Callable[[int, int], int], k: int) -> Atom:
    """f(n, r) ≠ k, written the way a mathematician writes it."""
    if name == "n - 2r":
        text = "n ≠ 2r" + (f" + {k}" if k > 0 else f" − {-k}" if k < 0 else "")
    elif name == "n - r":
        text = "r < n" if k == 0 else f"n − r ≠ {k}"
    else:
        text = f"{name} ≠ {k}"
    return Atom(text, lambda n, r: f(n, r) != k)


def rule(fails: Iterable[Size], holds: Iterable[Size]) -> str | None:
    """The simplest condition true exactly on ``fails`` among ``fails`` ∪ ``holds``: one comparison,
    else two joined by "and", else two joined by "or"; None if none separates them (or either set
    is empty)."""
    bad, good = sorted(set(fails)), sorted(set(holds))
    if not bad or not good:
        return None
    atoms = [a for a in _atoms(bad + good) if all(a.test(n, r) for n, r in bad)]
    for a in atoms:
        if not any(a.test(n, r) for n, r in good):
            return a.text
    for a, b in combinations(atoms, 2):
        if not any(a.test(n, r) and b.test(n, r) for n, r in good):
            return f"{a.text} and {b.text}"
    clean = [a for a in _atoms(bad + good) if not any(a.test(n, r) for n, r in good)]
    for a, b in combinations(clean, 2):
        if all(a.test(n, r) or b.test(n, r) for n, r in bad):
            return f"{a.text} or {b.text}"
    return None


def sizes_text(sizes: Iterable[Size]) -> str:
    """Every size, listed exactly: "(3,1), (4,2), (5,2)"."""
    return ", ".join(f"({n},{r})" for n, r in sorted(set(sizes), key=lambda s: (s[0], s[1])))


def _some(sizes: list[Size], what: str, limit: int) -> str:
    return f"{what}: {sizes_text(sizes)}" if len(sizes) <= limit else f"{what} ({len(sizes)} sizes)"


def fails_holds_text(fails: Iterable[Size], holds: Iterable[Size], limit: int = 6) -> str:
    """"fails at every computed size with r ≥ 2 (15 sizes); holds as printed at (1,1), (2,1)",
    or both lists in full where no rule separates them."""
    bad, good = sorted(set(fails)), sorted(set(holds))
    if not good:
        return (f"fails at every computed size: {sizes_text(bad)}" if len(bad) <= limit
                else f"fails at all {len(bad)} computed sizes")
    cond = rule(bad, good)
    if cond is None:
        return f"fails at {sizes_text(bad)}; holds as printed at {sizes_text(good)}"
    held = _range(rule(good, bad))
    other = (f"holds as printed at {sizes_text(good)}" if len(good) <= limit
             else f"holds as printed at the other {len(good)} computed sizes" + (f", those with {held}" if held else ""))
    return f"{_some(bad, f'fails at every computed size with {cond}', limit)}; {other}"


def _range(cond: str | None) -> str:
    """A condition of :func:`rule` that bounds r on both sides, "r ≥ 2 and r < n", as one range, "2 ≤ r ≤ n − 1";
    "" for any other (the sizes where a statement holds are named by a range alone)."""
    m = re.fullmatch(r"r ≥ (\d+) and r < n|r < n and r ≥ (\d+)", cond or "")
    return f"{m.group(1) or m.group(2)} ≤ r ≤ n − 1" if m else ""
