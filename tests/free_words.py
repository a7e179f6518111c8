"""Random well-typed words for the free-algebra tests."""
from __future__ import annotations

import random

from stiefelsym.free.scene import X, Xt


def random_word(rng: random.Random, letters, row: str, col: str, length: int) -> tuple:
    """A random product of ``letters`` from type ``row`` to type ``col`` (closed by X or X^T)."""
    out, t = [], row
    for _ in range(length):
        L = rng.choice([L for L in letters if L.row == t])
        out.append(L)
        t = L.col
    if t != col:
        out.append(X if t == "n" else Xt)
    return tuple(out)
