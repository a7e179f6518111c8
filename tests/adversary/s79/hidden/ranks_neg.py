# ruff: noqa
"""s79 hidden round: the false twins of claims.py, one change each; numpy (indep.py.in) says where each twin is
false.  Run with  stiefelsym verify --claims tests/adversary/s79/hidden/negatives.py --method M --jobs 1 --timeout 120"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym import twisted
from stiefelsym.systems import derivative

from _h79_helpers import (L_reduced, monopole, quartic_potential, F_Omega, H_neum_k, dim_V, dot, euler_ss_point,
                          euler_ss_tangent, flow_No, jacobian_along, perelomov_functions, tangent_spanning_set,
                          yang_mills_field)

SPHERE = admissible(n_max=5, n_min=2, r_max=1, condition="r = 1")
ALL = admissible(n_max=4)
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
N3R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, stated_n_max=3, condition="n = 3, r = 2")

@claim("n79-neumann2-rank-stiefel-count", fails_at=lambda n, r: r >= 2, erratum="false twin (numpy: indep.py.in)", kind="dim", sizes=ALL, paper=("NEUMANN2",))
def t6(s):
    """Twin of h79-neumann2-rank-psi0: rank dim V_{n,r} in place of r(n − r) (false for r ≥ 2)."""
    n, r = int(s.n), int(s.r)
    F = lambda t: perelomov_functions(t, t.X, (t.In - t.X @ t.X.T) @ t.P)
    M = jacobian_along(s, F, tangent_spanning_set(s))
    return {"rank": Rank(M, dim_V(n, r))}


@claim("n79-perelomov-rank-r2-incomplete", fails_at=lambda n, r: True, erratum="false twin (numpy: indep.py.in)", kind="dim", sizes=R2, paper=("perelomov",))
def t7(s):
    """Twin of h79-perelomov-rank-r2: rank dim V − 1 = 2n − 4 at r = 2 (the Introduction's reading: not complete)."""
    n, r = int(s.n), int(s.r)
    F = lambda t: perelomov_functions(t, t.X, t.P)
    M = jacobian_along(s, F, tangent_spanning_set(s))
    return {"rank": Rank(M, dim_V(n, r) - 1)}
