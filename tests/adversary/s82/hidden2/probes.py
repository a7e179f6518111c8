"""s82 hidden2 (h5): natural rewritings of true statements of claims*.py, to look for false refusals."""
from __future__ import annotations

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym.bases import matrix_of, so_basis
from stiefelsym.brackets import casimir_residual, lambda1, trace_power

from _common import L_star

R1 = admissible(n_max=4, r_max=1, condition="r = 1")
ALL = admissible(n_max=4)
N2 = admissible(n_max=4, n_min=2)


@claim("h5p-chasles-r1-matrices", kind="geo", section="8", sizes=R1)
def chasles_r1_matrices(s):
    """h5-chasles-r1-discriminant with 1×1 matrices and [0, 0] (how a reader writes ⟨e, Ce⟩)."""
    C = (s.A - s.lam * s.In).inv()
    e, p = s.X, s.P
    ee, pp, ep = (e.T @ C @ e)[0, 0], (p.T @ C @ p)[0, 0], (e.T @ C @ p)[0, 0]
    return {"disc - e2(L*)": ee * (pp - 1) - ep * ep - elementary(s, L_star(s, s.lam), 2)[2]}


@claim("h5p-lambda1-casimir-int-scale", kind="pb", section="6", sizes=ALL)
def lambda1_casimir_int_scale(s):
    """h5-lambda1-casimirs-v with so_scale=lambda t: 0 (a Python 0)."""
    x, b = s.fresh("n", "n"), s.fresh("n", "n")
    return {"Lambda1(grad tr v^2, b)": casimir_residual(s, lambda1(), trace_power(2, so_scale=lambda t: 0), x, b)}


@claim("h5p-l1-rank-no-kind", kind="dim", section="6", sizes=N2)
def l1_rank_no_kind(s):
    """h5-l1-rank without kernel and with matrix_of's default kind ("general")."""
    n, r = int(s.n), int(s.r)
    v = s.X @ s.X.T
    return {"rank": Rank(matrix_of(s, lambda xi: comm(xi, v), so_basis(s, "n")), r * (n - r))}


@claim("h5p-l1-rank-everywhere-at-X0", kind="dim", section="6", sizes=N2)
def l1_rank_everywhere_X0(s):
    """The rank of ξ ↦ [ξ, XXᵀ] everywhere, written with ξ ↦ [ξ, XXᵀ]X and ξ ↦ Xᵀ[ξ, XXᵀ]... (the map
    ξ ↦ (I − XXᵀ)ξX, whose rank is r(n − r) too: [ξ, v] = (I−v)ξv − vξ(I−v) on v = XXᵀ), via matrix_of."""
    n, r = int(s.n), int(s.r)
    Q = s.In - s.X @ s.X.T
    return {"rank": Rank(matrix_of(s, lambda xi: Q @ xi @ s.X, so_basis(s, "n")), r * (n - r), generic=False)}


@claim("h5p-theta-jacobian-mat", kind="dim", section="6", sizes=ALL)
def theta_jacobian_mat(s):
    """h5-theta-rank with s.jacobian of a function returning a Mat (not a list) and of the scene's own
    constraints written by hand, without symmetric=."""
    n, r = int(s.n), int(s.r)
    rows = (s.jacobian(lambda t: t.Phi + t.X @ t.X.T)
            + s.jacobian(lambda t: [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]))
    return {"rank": Rank(s.mat(rows), 2 * n * r - r * (r - 1) // 2)}
