# ruff: noqa
"""s79 hidden round (rank statements, split off for their run time): 2 of the statements of Fedorov & Jovanović (Appendix 1, §5, §7, Introduction) that neither the
catalog nor the earlier rounds state (true; numpy check in indep.py.in).  Run with
    stiefelsym verify --claims tests/adversary/s79/hidden/claims.py --method M --jobs 1 --timeout 120
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym import twisted
from stiefelsym.systems import derivative

from _h79_helpers import (L_reduced, monopole, quartic_potential, F_Omega, H_neum, H_neum_k, col, cross, dim_V, dot, euler_ss_point, euler_ss_tangent,
                          flow_No, jacobian_along, pcol, perelomov_functions, tangent_spanning_set, yang_mills_field)

SPHERE = admissible(n_max=5, n_min=2, r_max=1,
                    condition="r = 1: the scene's X is the unit vector e of S^{n-1}; (Omega, e) a generic point of so(n) x S^{n-1}")
ALL = admissible(n_max=5)
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
N3R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, stated_n_max=3, condition="n = 3, r = 2")
DIM = admissible(n_max=4)

# 6 ------------------------------------------------------------------------------------------------------------
@claim("h79-neumann2-rank-psi0", paper=("NEUMANN2", "perelomov", "grassmannian"), kind="dim", sizes=DIM,
       statement=r"\operatorname{rank}\{d\tr\mathcal L_{neum}(\lambda_j)^k|_{T\Psi^{-1}(0)}\}=r(n-r)=\dim G_{n,r}")
def neumann2_rank_psi0(s):
    """§7, Theorem NEUMANN2: among the functions (perelomov), restricted to Ψ⁻¹(0), exactly r(n − r) = dim G_{n,r}
    are independent (a complete commutative set on T*G_{n,r}).  Computed as the generic rank of the functions
    composed with the retraction (X, P) ↦ (X, (I − XXᵀ)P) of T*V onto Ψ⁻¹(0), along a spanning set of T(T*V);
    functions tr 𝓛(λ)^k, k = 2..n, λ ∈ {1/2, 3/2, 5/2}."""
    n, r = int(s.n), int(s.r)
    F = lambda t: perelomov_functions(t, t.X, (t.In - t.X @ t.X.T) @ t.P)
    M = jacobian_along(s, F, tangent_spanning_set(s))
    return {"rank": Rank(M, r * (n - r))}


# 7 ------------------------------------------------------------------------------------------------------------
@claim("h79-perelomov-rank-r2", paper=("perelomov", "Neumann_LA", "torus"), kind="dim", sizes=R2,
       statement=r"r=2:\ \operatorname{rank}\{d\tr\mathcal L_{neum}(\lambda_j)^k\}=\dim V_{n,2}=2n-3")
def perelomov_rank_r2(s):
    """Introduction (and §5): 'for r > 1 this Lax pair ... does not provide a non-commutative set of integrals,
    necessary for the integrability'.  At r = 2 the (commuting) integrals (perelomov) of the big Lax pair have
    generic rank dim V_{n,2} = 2n − 3 on T*V, half of dim T*V: they are already a complete commutative set
    (numpy: singular values 4.2 vs 0 at (4,2)), so the Introduction's remark does not hold at r = 2 (for r ≥ 3 the
    rank is below dim V).  Functions tr 𝓛(λ)^k, k = 2..n, λ ∈ {1/2, 3/2, 5/2}, along a spanning set of T(T*V)."""
    n, r = int(s.n), int(s.r)
    F = lambda t: perelomov_functions(t, t.X, t.P)
    M = jacobian_along(s, F, tangent_spanning_set(s))
    return {"rank": Rank(M, dim_V(n, r))}
