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


def forged(data: dict, renames: dict[str, str]) -> tuple[dict, bool]:
    """A deep copy of certificate data with the hypotheses of its terms renamed (``renames``: old -> new),
    and whether any term was renamed: a forged certificate the checker must reject."""
    import copy
    out, changed = copy.deepcopy(data), False
    for e in out["entries"]:
        for t in e["terms"]:
            if t["hyp"] in renames:
                t["hyp"], changed = renames[t["hyp"]], True
    return out, changed
