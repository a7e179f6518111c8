"""Bases of the matrix spaces a claim works in, and the matrix of a linear map in them.

A dimension statement of the paper is often the rank of a linear map between matrix spaces:
ξ ↦ ξX on so(n) (the infinitesimal action, (hat)), ad_μ on so(n), the differential of a map
along the directions of a fibre.  Its matrix in bases of the two spaces is what ``Rank`` takes:

    from stiefelsym import Rank, admissible, claim
    from stiefelsym.bases import matrix_of, so_basis

    @claim("my-action-rank", kind="dim", sizes=admissible(n_max=5, n_min=2, condition="n >= 2"))
    def action_rank(s):
        n, r = int(s.n), int(s.r)
        M = matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n"))
        return {"rank of xi -> xi X": Rank(M, n * r - r * (r + 1) // 2)}

Every function here builds the basis from the scene's own constants (``s.q``), so a basis
matrix is an exact constant of the claim's graph, typed on the index spaces it is given
('n' or 'r').  The number of basis elements depends on the size, so a claim that uses them
reads n (or r) as a number: it is stated at fixed sizes only, and the dimension-free method
refuses it (as it refuses any claim that reads a size as a number).

The coordinates of a matrix in the image (the rows of :func:`matrix_of`) are its entries row by
row, or, for a skew ("skew") or symmetric ("sym") image, its independent entries first and then
the combinations that vanish on such an image (see :func:`coordinates`): the rank of the map is
the same for any basis of its domain, and these coordinates determine the matrix whatever it is.
"""
from __future__ import annotations

from typing import Any, Callable, Sequence

from stiefelsym.backends.matrix import Mat

__all__ = ["matrix_units", "so_basis", "sym_basis", "coordinates", "matrix_of"]

_SPACES = ("n", "r")


def _size(s: Any, space: str, what: str) -> int:
    if space not in _SPACES:
        raise ValueError(f"{what}: the index spaces are 'n' or 'r', not {space!r}")
    return int(s.n if space == "n" else s.r)


def _unit(s: Any, m: int, k: int, cells: dict, spaces: tuple) -> Mat:
    """The m×k constant matrix with the given nonzero cells {(i, j): ±1} (every other entry 0)."""
    one, zero, minus = s.q(1), s.q(0), s.q(-1)
    value = {1: one, -1: minus}
    return s.mat([[value[cells[(i, j)]] if (i, j) in cells else zero for j in range(k)] for i in range(m)],
                 spaces)


def matrix_units(s: Any, rows: str, cols: str) -> list[Mat]:
    """The matrix units E_ab of the space of (rows)×(cols) matrices (rows, cols in {'n', 'r'}), a
    basis orthonormal for tr(aᵀb), in row-major order (a, b from 0): the coordinates of a matrix in
    it are its entries row by row."""
    m, k = _size(s, rows, "matrix_units"), _size(s, cols, "matrix_units")
    return [_unit(s, m, k, {(a, b): 1}, (rows, cols)) for a in range(m) for b in range(k)]


def so_basis(s: Any, space: str) -> list[Mat]:
    """The basis E_i ∧ E_j = E_ij − E_ji (i < j, in row-major order) of so(m), m = n or r: orthonormal for
    the paper's ⟨a, b⟩ = −½ tr(ab) (``s.killing``).  so(1) has the empty basis."""
    m = _size(s, space, "so_basis")
    return [_unit(s, m, m, {(i, j): 1, (j, i): -1}, (space, space)) for i in range(m) for j in range(i + 1, m)]


def sym_basis(s: Any, space: str) -> list[Mat]:
    """The basis E_ii (i in order), then E_ij + E_ji (i < j, row-major) of Sym(m), m = n or r."""
    m = _size(s, space, "sym_basis")
    diagonal = [_unit(s, m, m, {(i, i): 1}, (space, space)) for i in range(m)]
    return diagonal + [_unit(s, m, m, {(i, j): 1, (j, i): 1}, (space, space))
                       for i in range(m) for j in range(i + 1, m)]


def coordinates(M: Mat, kind: str = "general") -> list[Any]:
    """The coordinates of a matrix as a list of scalars: every entry row by row ("general"); for a square M, the
    entries on and above the diagonal followed by M_ij − M_ji (i < j) ("sym"), or the entries above the diagonal
    followed by the diagonal and M_ij + M_ji (i < j) ("skew").  The second part vanishes identically where M is
    symmetric (skew), so it costs a rank nothing there; and since the coordinates determine M in every case, a
    matrix of such columns has the rank of the map whatever its image is (a non-symmetric image written in "sym"
    coordinates is not taken for its upper triangle)."""
    m, k = M.shape
    m, k = int(m), int(k)
    if kind == "general":
        return [M[i, j] for i in range(m) for j in range(k)]
    if kind not in ("skew", "sym"):
        raise ValueError(f"coordinates: kind is 'general', 'skew' or 'sym', not {kind!r}")
    if m != k:
        raise ValueError(f"coordinates of a {kind} matrix: it is square, this one is {m}×{k}")
    pairs = [(i, j) for i in range(m) for j in range(i + 1, m)]
    if kind == "sym":
        return ([M[i, j] for i in range(m) for j in range(i, m)]
                + [M[i, j] - M[j, i] for i, j in pairs])
    return [M[i, j] for i, j in pairs] + [M[i, i] for i in range(m)] + [M[i, j] + M[j, i] for i, j in pairs]


def matrix_of(s: Any, f: Callable[[Mat], Mat], basis: Sequence[Mat], kind: str = "general") -> Mat:
    """The matrix of the linear map f in the given basis of its domain: column j holds the
    :func:`coordinates` (``kind``) of f(basis[j]), which determine f(basis[j]) whatever ``kind`` is.  Its rank is the rank of f; a ``Rank(...,
    kernel=K)`` certificate is written in the coordinates of the same basis (K has len(basis) rows).
    Nothing checks that f is linear: a map that is not gives the rank of the vectors f(basis[j])."""
    if not basis:
        raise ValueError("matrix_of: the basis is empty (so(1) has dimension 0): there is no matrix to take a "
                         "rank of")
    columns = [coordinates(f(b), kind) for b in basis]
    if not columns[0]:
        raise ValueError("matrix_of: the image has no coordinates")
    return s.mat([list(row) for row in zip(*columns)])
