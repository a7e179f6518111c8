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
    return [[se.expand(x) / (rng.choice(atoms) + 7) for x in row] for row in rows]


@pytest.mark.parametrize("seed", range(6))
def test_the_rank_with_cleared_denominators_is_sympys(seed):
    rng = random.Random(seed)
    m, k = rng.randint(2, 5), rng.randint(2, 5)
    rows = _random_matrix(rng, m, k, rng.randint(1, min(m, k)))
    assert _bareiss_rank(_flint_rows_cleared(rows)) == _sympy_rank(rows)


def test_a_matrix_that_is_not_of_rational_functions_is_left_to_sympy():
    x = se.Symbol("x")
    assert _flint_rows_cleared([[se.sqrt(x), x]]) is None
