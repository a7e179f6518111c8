"""The right-reduced Cayley chart's pass sees R^r read through blocks, slices of R^n matrices and traces of
matrices of given entries (round 10, RA-RC), and keeps the reduction for the catalog's block Lax matrices."""
from __future__ import annotations

import pytest

from stiefelsym import block
from stiefelsym.ir import compile_claim
from stiefelsym.ir.passes import right_action_breaks
from stiefelsym.scene import REALIZATIONS


def _graph(func, n=4, r=2):
    cons = REALIZATIONS["standard"]
    return compile_claim(func, n, r, (cons.name, cons.build))


def _block_column(s):
    e1 = block([[s.identity(1)], [s.zeros(1, 1)]])
    return {"x": (s.X @ e1)[1, 0]}


def _rows_of_in(s):
    X1 = s.In[0:s.r, :] @ s.X
    return {"x": X1 - X1.T}


def _trace_given(s):
    q0, q1 = s.q(0), s.q(1)
    B = s.mat([[q0, q1], [-q1, q0], [q0, q0], [q0, q0]])
    return {"x": s.tr(s.X.T @ B)}


def _killing_given(s):
    q0, q1 = s.q(0), s.q(1)
    B = s.mat([[q0, q1], [-q1, q0], [q0, q0], [q0, q0]])
    return {"x": s.killing(s.X.T, B)}


def _block_sums_disagree(s):
    """[X, X] has columns R^r + R^r; joined to a block of four 1 x 1 pieces it is split into coordinates."""
    one, nil = s.identity(1), s.zeros(1, 1)
    e = block([[one], [nil], [nil], [nil]])
    return {"x": (block([[s.X, s.X]]) @ e)[0, 0]}



@pytest.mark.parametrize("func", [_block_column, _rows_of_in, _trace_given, _killing_given, _block_sums_disagree])
def test_reads_of_r_are_breaks(func):
    assert right_action_breaks(_graph(func))


def test_a_covariant_block_matrix_keeps_the_reduction():
    def lax(s):
        L = block([[s.A, s.X], [s.X.T, s.zeros(s.r, s.r)]])
        M = block([[s.Phi, s.P], [s.P.T, s.eta]])
        return {"x": s.tr(L @ M @ L) + s.A[0, 0]}
    assert right_action_breaks(_graph(lax)) == []


def _two_splittings(s):
    """[X; 0]ᵀ[I_r; 0]: R^n + R^r taken for R^r + R^n reads the top r x r block of X."""
    return {"x": block([[s.X], [s.zeros(s.r, s.r)]]).T @ block([[s.Ir], [s.zeros(s.n, s.r)]]) - s.Ir}


def test_two_splittings_of_one_space_are_a_coordinate_read_of_r_n():
    from stiefelsym.ir.passes import TWO_SPLITTINGS, coordinate_reads
    g = _graph(_two_splittings)
    assert coordinate_reads(g).get(TWO_SPLITTINGS) == frozenset({"n", "r"})
    assert right_action_breaks(g)


def test_alike_splittings_and_a_given_matrix_that_takes_a_splitting_are_not_reads():
    """(R^n + R^r) joined to (R^n + R^r), and a matrix of given entries whose side takes a block's splitting."""
    from stiefelsym.ir.passes import TWO_SPLITTINGS, coordinate_reads

    def lax(s):
        L = block([[s.A, s.X], [s.X.T, s.zeros(s.r, s.r)]])
        M = block([[s.Phi, s.P], [s.P.T, s.eta]])
        return {"x": s.tr(L @ M @ L)}
    assert TWO_SPLITTINGS not in coordinate_reads(_graph(lax))


def _int_identity_on_both(s):
    """At r = n an untyped identity of an int size used on R^r and on R^n: X taken for a matrix on R^n."""
    Xu = s.X @ s.identity(3)
    return {"x": Xu - Xu.T}


def _engine_number_times_pieces(s):
    """A number made by s.d times the pieces of R^r + R^n taken for R^n + R^r: the product has the pieces' sides."""
    c = s.d(lambda t: s.tr(t.X.T @ s.A @ t.X), {"X": s.A @ s.X, "P": s.zeros(s.n, s.r, ("n", "r"))})
    top = block([[c * s.Ir], [c * s.zeros(s.n, s.r)]])
    M = block([[s.X], [s.zeros(s.r, s.r)]]).T @ top
    return {"x": M - M.T}


def test_r_joined_to_n_and_engine_numbers_are_breaks():
    assert right_action_breaks(_graph(_int_identity_on_both, 3, 3))
    assert right_action_breaks(_graph(_engine_number_times_pieces, 3, 2))
    assert right_action_breaks(_graph(_engine_number_times_pieces, 4, 2))


def test_an_engine_number_times_a_covariant_matrix_keeps_the_reduction():
    def f(s):
        c = s.d(lambda t: s.tr(t.X.T @ s.A @ t.X), {"X": s.A @ s.X, "P": s.zeros(s.n, s.r, ("n", "r"))})
        return {"x": c * (s.X.T @ s.X) - c * s.Ir}
    assert right_action_breaks(_graph(f, 3, 2)) == []
    assert right_action_breaks(_graph(f, 3, 3)) == []
