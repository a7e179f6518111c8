"""The float method's error model against balls: the same claim evaluated at the same exact
point in float64 (with its running bound) and in ball arithmetic (arb), entry by entry.

The exact value lies in the ball, so the float64 value's true error is at least its distance to
the ball: a distance above the float64 bound is a certified optimistic bound (a soundness bug)."""
from __future__ import annotations

import random
from dataclasses import dataclass

import flint
import numpy as np

from stiefelsym.backends.ball import BallField, Balls, BallNum, working_precision
from stiefelsym.claims import Count, Rank
from stiefelsym.backends.fields import DegenerateError, ErrNum, FloatField
from stiefelsym.backends.matrix import Mat
from stiefelsym.methods.fixed_size import _entries, _flatten, call_claim
from stiefelsym.backends.native import F64, one_blas_thread, quiet_numpy
from stiefelsym.scene import Scene

#: the balls of the reference evaluation: far tighter than any float64 bound
REFERENCE_BITS = 212


@dataclass
class Violation:
    entry: str
    value: float
    bound: float
    distance: object       # an arb whose lower end bounds |value - exact| from below


def _float_entries(value, name):
    """(position, value, bound) of every entry of a float64 residual (a matrix's normwise bound is
    every entry's)."""
    if isinstance(value, Mat) and isinstance(value._n, F64):
        s = value._n
        cols = s.v.shape[1]
        return [(f"{name}[{i // cols + 1},{i % cols + 1}]", float(v), float(s.e)) for i, v in enumerate(s.v.ravel())]
    out = []
    for pos, x in _entries(value, name):
        if isinstance(x, ErrNum):
            out.append((pos, float(x.v), float(x.e)))
        else:       # an exact constant of the claim: no error
            out.append((pos, float(x), 0.0))
    return out


def _ball_entries(value, name):
    if isinstance(value, Mat) and isinstance(value._n, Balls):
        return value._n.M.entries()
    return [x.b if isinstance(x, BallNum) else flint.arb(x) for _, x in _flatten(value, name)]


def _rng(seed, claim, n, r, comp):
    return random.Random(f"{seed}|{claim.id}|{n}|{r}|float" + (f"|component {comp}" if comp else ""))


def float_model_errors(claim, n: int, r: int, seed: int = 0, func=None, hard: str | None = None) -> list[Violation]:
    """For every finite float64 residual entry at the float method's point(s) of (claim, n, r) (at
    the hard case ``hard``, if named): its value, its float64 bound and a rigorous lower bound of
    its true error (the distance to the ball of the exact value at the same point)."""
    from stiefelsym.methods.hard import hard_case
    func = func or claim.func
    out = []
    for comp in ((0, 1) if r == n else (0,)):
        options = {"hard": hard_case(hard), "hard_hits": []} if hard else None
        with one_blas_thread(), quiet_numpy():
            fs = Scene(n, r, FloatField(), chart="cayley", rng=_rng(seed, claim, n, r, comp), component=comp,
                       realization=claim.realization, options=options)
            try:
                fchecks = call_claim(func, fs)
            except (DegenerateError, OverflowError):
                continue     # float64 gives no value here (the float method goes on to mpmath): nothing to compare
        with working_precision(REFERENCE_BITS), quiet_numpy():      # term scales may overflow: no warning
            bs = Scene(n, r, BallField(REFERENCE_BITS), chart="cayley", rng=_rng(seed, claim, n, r, comp),
                       component=comp, realization=claim.realization)
            if hard:
                # the float scene's point, every coordinate exactly (a hard value is the float64 number
                # the float method took as its exact input): the ball scene draws nothing
                for name, x in fs._point_values().items():
                    bs._params[name] = BallNum(flint.arb(float(x.v)), abs(float(x.v)))
            try:
                bchecks = call_claim(func, bs)
            except DegenerateError:
                continue     # the reference balls are too wide to solve a system (huge-momenta): nothing certified
            for name, fv in fchecks.items():
                if isinstance(fv, (Rank, Count)):
                    continue
                fe = _float_entries(fv, name)
                be = _ball_entries(bchecks[name], name)
                assert len(fe) == len(be)
                for (pos, v, e), b in zip(fe, be):
                    if not (np.isfinite(v) and np.isfinite(e)):
                        continue          # a poisoned number: the float method never decides on it
                    d = abs(flint.arb(v) - b).lower()       # |v - x| >= d for every x in the ball
                    out.append(Violation(pos, v, e, d))
    return out


def optimistic(errors: list[Violation], shrink: float = 1.0) -> list[Violation]:
    """The entries whose float64 bound, times ``shrink``, is certainly below their true error."""
    return [x for x in errors if x.distance > flint.arb(x.bound) * flint.arb(shrink)]
