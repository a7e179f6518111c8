"""The statements a claim returns besides residuals: a rank, an integer count, an inverse and a right
inverse.

They hold a traced matrix (and ints) when claim code makes them, and the
evaluated matrix when a method rebuilds them from the graph."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from stiefelsym.ir.sites import statement_site


def _as_int(obj: Any, name: str, what: str) -> None:
    v = getattr(obj, name)
    conv = getattr(type(v), "_statement_int", None)
    if conv is not None:
        object.__setattr__(obj, name, conv(v, what))


@dataclass(frozen=True)
class Rank:
    """The rank of ``matrix`` equals ``expected``.

    ``generic``: the rank at a generic point of the chart (the paper's
    "generic orbit", "independent functions"); otherwise the rank must be
    ``expected`` at every point of the constraint set (then the exact method
    looks for a nonzero constant maximal minor).

    ``kernel``: a certificate for the upper side of a generic rank, a matrix
    with as many rows as ``matrix`` has columns whose columns are vectors (in the
    point's parameters) with ``matrix @ kernel = 0`` identically on the
    constraint set.  The exact method proves that identity in its chart and the
    rank d of the kernel at an exact point, so the generic rank is at most
    cols − d.  It is only a certificate: a wrong kernel never refutes the rank."""

    matrix: Any
    expected: int
    generic: bool = True
    meaning: str = ""
    kernel: Any = None

    def __post_init__(self) -> None:
        _as_int(self, "expected", "an expected rank")
        if type(self.expected) is not int or type(self.generic) is not bool:
            raise TypeError("Rank: the expected rank is an int and generic a bool")
        if type(self.meaning) is not str:
            raise TypeError("Rank: the meaning is a string")
        if self.kernel is not None and not self.generic:
            raise TypeError("Rank: a kernel certifies a generic rank (generic=True); a rank at every point needs "
                            "a constant minor or a RightInverse")
        statement_site(self)


#: the largest count in bits (about 3,900 decimal digits, below Python's own limit on converting an int to text)
COUNT_BITS = 13_000
COUNT_DIGITS = 3_900


@dataclass(frozen=True)
class Count:
    """An integer computed by the claim (e.g. from ranks) against the printed formula."""

    value: int
    expected: int
    meaning: str = ""

    def __post_init__(self) -> None:
        _as_int(self, "value", "a count")
        _as_int(self, "expected", "a count")
        if type(self.value) is not int or type(self.expected) is not int:
            raise TypeError("Count: the value and the expected count are ints (an object that says it "
                            "equals anything is refused)")
        if max(abs(self.value), abs(self.expected)).bit_length() > COUNT_BITS:
            raise ValueError(f"Count: a count of more than {COUNT_DIGITS:,} digits (a dimension, rank or size "
                             "of the paper is far smaller; each digit would be carried through every record)")
        if type(self.meaning) is not str:
            raise TypeError("Count: the meaning is a string")
        statement_site(self)


#: the spaces an :class:`Inverse` may act on: a generic element of each, as the methods build it
#: (a generic matrix G of its shape, symmetrized or skewed: every symmetric y is G + Gᵀ with G = y/2)
DOMAINS: dict[str, tuple[str, str, str]] = {
    "Sym(r)": ("r", "r", "sym"), "Sym(n)": ("n", "n", "sym"),
    "so(r)": ("r", "r", "skew"), "so(n)": ("n", "n", "skew"),
    "R^{n×r}": ("n", "r", "general"), "R^{r×n}": ("r", "n", "general"),
    "R^{r×r}": ("r", "r", "general"), "R^{n×n}": ("n", "n", "general"),
}


#: the dimension of each space of :data:`DOMAINS`, as a formula in n, r
DIMENSIONS: dict[str, str] = {
    "Sym(r)": "r(r+1)/2", "Sym(n)": "n(n+1)/2", "so(r)": "r(r-1)/2", "so(n)": "n(n-1)/2",
    "R^{n×r}": "nr", "R^{r×n}": "nr", "R^{r×r}": "r²", "R^{n×n}": "n²",
}


@dataclass(frozen=True)
class Inverse:
    """The map ``op`` on the product of the spaces ``on`` is invertible at every point of T*V, with
    inverse ``inv``.

    ``op(s, *x)`` and ``inv(s, *y)`` are functions of the scene and of one matrix per factor of
    ``on`` (names of :data:`DOMAINS`: "Sym(r)", "so(n)", "R^{n×r}", ...), returning one matrix per
    factor (a matrix, or a tuple of them).  The statement is decided as identities in generic
    elements x, y of the product, at every point of T*V: op(inv(y)) = y, inv(op(x)) = x, and
    op(x), inv(y) lie in the product (symmetric, skew) — so op is a bijection of the product onto
    itself at every point, with inverse inv (a proof for every point, where a rank is one point's)."""

    op: Any
    inv: Any
    on: Any
    meaning: str = ""

    def __post_init__(self) -> None:
        on = (self.on,) if type(self.on) is str else self.on
        if type(on) not in (tuple, list) or not on or any(type(d) is not str or d not in DOMAINS for d in on):
            raise TypeError(f"Inverse: on is a space or a tuple of spaces among {', '.join(DOMAINS)}")
        object.__setattr__(self, "on", tuple(on))
        if not callable(self.op) or not callable(self.inv):
            raise TypeError("Inverse: op and inv are functions of the scene and of one matrix per space")
        if type(self.meaning) is not str:
            raise TypeError("Inverse: the meaning is a string")


@dataclass(frozen=True)
class RightInverse:
    """The map ``op`` from the product of the spaces ``on`` to the product of the spaces ``to`` is onto at
    every point of T*V, with right inverse ``inv``.

    ``op(s, *x)`` takes one matrix per factor of ``on`` and returns one per factor of ``to``; ``inv(s, *y)``
    the other way round (names of :data:`DOMAINS`).  The statement is decided as identities in generic
    elements y of ``to`` and x of ``on``, at every point of T*V: op(inv(y)) = y, inv(y) lies in ``on`` and
    op(x) in ``to`` (symmetric, skew).  So op maps the product ``on`` onto the product ``to`` at every
    point; a linear op (a differential) has there the full rank dim(``to``).  Nothing is said of
    inv(op(x)): op need not be injective."""

    op: Any
    inv: Any
    on: Any
    to: Any
    meaning: str = ""

    def __post_init__(self) -> None:
        for name in ("on", "to"):
            spaces = getattr(self, name)
            spaces = (spaces,) if type(spaces) is str else spaces
            if type(spaces) not in (tuple, list) or not spaces or any(
                    type(d) is not str or d not in DOMAINS for d in spaces):
                raise TypeError(f"RightInverse: {name} is a space or a tuple of spaces among {', '.join(DOMAINS)}")
            object.__setattr__(self, name, tuple(spaces))
        if not callable(self.op) or not callable(self.inv):
            raise TypeError("RightInverse: op and inv are functions of the scene and of one matrix per space")
        if type(self.meaning) is not str:
            raise TypeError("RightInverse: the meaning is a string")


class InverseIdentities(list):
    """An :class:`Inverse` statement as a method evaluates it: its residuals (op(inv(y)) − y,
    inv(op(x)) − x and the membership residuals), which must all vanish, with the spaces."""

    def __init__(self, residuals: Any, on: tuple, meaning: str) -> None:
        super().__init__(residuals)
        self.on, self.meaning = tuple(on), meaning

    def describe(self) -> str:
        space = " × ".join(self.on)
        return (f"{self.meaning + ': ' if self.meaning else ''}op(inv(y)) = y and inv(op(x)) = x for generic "
                f"x, y in {space}, at every point (op invertible on {space})")


class RightInverseIdentities(InverseIdentities):
    """A :class:`RightInverse` statement as a method evaluates it: its residuals (op(inv(y)) − y and the
    membership residuals of inv(y) and op(x)), which must all vanish, with the spaces."""

    def __init__(self, residuals: Any, on: tuple, to: tuple, meaning: str) -> None:
        super().__init__(residuals, on, meaning)
        self.to = tuple(to)

    def describe(self) -> str:
        source, target = " × ".join(self.on), " × ".join(self.to)
        dim = " + ".join(DIMENSIONS[d] for d in self.to)
        return (f"{self.meaning + ': ' if self.meaning else ''}op(inv(y)) = y for generic y in {target}, "
                f"at every point (op maps {source} onto {target}; where op is linear, as a differential, it has "
                f"full rank dim({target}) = {dim})")
