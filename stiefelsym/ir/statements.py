"""The statements a claim returns besides residuals: a rank and an integer count.

They hold a traced matrix (and ints) when claim code makes them, and the
evaluated matrix when a method rebuilds them from the graph."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any


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
    looks for a nonzero constant maximal minor)."""

    matrix: Any
    expected: int
    generic: bool = True
    meaning: str = ""

    def __post_init__(self) -> None:
        _as_int(self, "expected", "an expected rank")
        if type(self.expected) is not int or type(self.generic) is not bool:
            raise TypeError("Rank: the expected rank is an int and generic a bool")
        if type(self.meaning) is not str:
            raise TypeError("Rank: the meaning is a string")


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
        if type(self.meaning) is not str:
            raise TypeError("Count: the meaning is a string")
