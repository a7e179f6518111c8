"""The rank over the function field of a matrix of rational functions: flint's fraction-free elimination
after each row is multiplied by the least common multiple of its denominators, against sympy's
DomainMatrix (the route it replaces, 60 times slower on ad_v of gl(3) in the Cayley chart)."""
from __future__ import annotations

import random

import pytest
import symengine as se
import sympy

from stiefelsym.methods.fixed_size import _bareiss_rank, _flint_rows_cleared


def _sympy_rank(rows):
    from sympy.polys.matrices import DomainMatrix
    m = DomainMatrix.from_list_sympy(len(rows), len(rows[0]), [[sympy.sympify(str(x)) for x in r] for r in rows])
    return len(m.rref_den()[2])


def _random_matrix(rng, m, k, rank):
    """An m x k matrix of rational functions in x, y, z of the given rank (a product of an m x rank and a
    rank x k matrix, rows then scaled by rational functions)."""
    x, y, z = se.symbols("x y z")
    atoms = [x, y, z, x + 1, y - z, x * y + 2, se.Integer(3)]

    def f():
        return rng.choice(atoms) * rng.randint(-3, 3) + rng.choice(atoms)

    left = [[f() for _ in range(rank)] for _ in range(m)]
    right = [[f() / (rng.choice(atoms) + 5) for _ in range(k)] for _ in range(rank)]
    rows = [[sum((left[i][t] * right[t][j] for t in range(rank)), se.Integer(0)) for j in range(k)] for i in range(m)]
    out = []
    for row in rows:
        den = rng.choice(atoms) + 7
        out.append([se.expand(x) / den for x in row])
    return out


def _rank_at_a_point(rows, seed):
    """The rank of the matrix at a random rational point (where every denominator is nonzero): at most the
    rank over the function field."""
    rng = random.Random(seed)
    x, y, z = sympy.symbols("x y z")
    at = {x: sympy.Rational(rng.randint(-50, 50), rng.randint(1, 9)), y: sympy.Rational(rng.randint(-50, 50), 7),
          z: sympy.Rational(rng.randint(-50, 50), 11)}
    return sympy.Matrix([[sympy.sympify(str(e)).subs(at) for e in r] for r in rows]).rank()


@pytest.mark.parametrize("seed", range(6))
def test_the_rank_with_cleared_denominators_is_the_generic_rank(seed):
    """The matrix is a product through ``rank`` columns (so its rank is at most that), and its rank at a point
    is at most its rank: where the two meet, the rank is known; elsewhere sympy's DomainMatrix decides."""
    rng = random.Random(seed)
    m, k = rng.randint(2, 5), rng.randint(2, 5)
    rank = rng.randint(1, min(m, k))
    rows = _random_matrix(rng, m, k, rank)
    low = _rank_at_a_point(rows, seed)
    known = rank if low == rank else _sympy_rank(rows)
    assert _bareiss_rank(_flint_rows_cleared(rows)) == known


def test_the_rank_with_cleared_denominators_is_sympys():
    """Against sympy's DomainMatrix itself, on matrices small enough for it (it takes seconds at 4 x 4)."""
    for seed in range(3):
        rng = random.Random(seed)
        rows = _random_matrix(rng, 3, 3, 1 + seed % 3)
        assert _bareiss_rank(_flint_rows_cleared(rows)) == _sympy_rank(rows)


def test_a_matrix_that_is_not_of_rational_functions_is_left_to_sympy():
    x = se.Symbol("x")
    assert _flint_rows_cleared([[se.sqrt(x), x]]) is None
