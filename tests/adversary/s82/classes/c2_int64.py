"""Class 2 (numbers in disguise): a Fraction whose numerator is a numpy int64 (Fraction(np.int64(2**62)) keeps the
int64: its own arithmetic wraps around, Fraction(np.int64(2**62)) * 4 == 0 in plain Python).

Each claim hands the engine such a constant c = 2^62 and lets the *engine* combine it with another constant; the
truth is that of the exact integers:
 i64-fold-false:   (X·c)·4 = 0: FALSE (2^64·X ≠ 0).
 i64-fold-true:    (X·c)·4 − X·2^64 = 0: TRUE.
 i64-sum-false:    X·c + X·c + X·c + X·c = 0: FALSE.
 i64-sq-false:     (c·tr(XᵀX))·(c·tr(XᵀX)) − 0 = 0 : FALSE (c²r² ≠ 0); its product of two constants is the engine's.
 i64-q-false:      s.q(np.int64(2**62), 1)·X·4 = 0: FALSE (s.q with an int64).
 i64-den-false:    X/c·c − X·2 = 0: FALSE (= −X).
 i64-den-true:     X/c·c − X = 0: TRUE.
"""
from fractions import Fraction

import numpy as np

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)
C = Fraction(np.int64(2 ** 62), 1)


@claim("i64-fold-false", kind="id", sizes=SZ)
def fold_false(s):
    return {"4cX": (s.X * C) * 4}


@claim("i64-fold-true", kind="id", sizes=SZ)
def fold_true(s):
    return {"4cX - 2^64 X": (s.X * C) * 4 - s.X * (2 ** 64)}


@claim("i64-sum-false", kind="id", sizes=SZ)
def sum_false(s):
    return {"4cX": s.X * C + s.X * C + s.X * C + s.X * C}


@claim("i64-sq-false", kind="id", sizes=SZ)
def sq_false(s):
    t = s.tr(s.X.T @ s.X)
    return {"c^2 r^2": (t * C) * (t * C)}


@claim("i64-q-false", kind="id", sizes=SZ)
def q_false(s):
    return {"4cX": s.q(np.int64(2 ** 62), 1) * s.X * 4}


@claim("i64-den-false", kind="id", sizes=SZ)
def den_false(s):
    return {"X/c*c - 2X": s.X / C * C - s.X * 2}


@claim("i64-den-true", kind="id", sizes=SZ)
def den_true(s):
    return {"X/c*c - X": s.X / C * C - s.X}
