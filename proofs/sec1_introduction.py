"""§1 Introduction: the Stiefel varieties of the extreme ranks r = n and r = n − 1."""
from __future__ import annotations

from stiefelsym import admissible, claim

from .determinants import det

ON_O_N = admissible(n_max=5, r_is_n=True, condition="r = n: V(n, n)")
ON_V_NN1 = admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")


def entries(M, m, k):
    return [[M[i, j] for j in range(k)] for i in range(m)]


@claim("stiefel-top-rank", nature="statement", encodes='both V_{n,n} and V_{n,n−1} are diffeomorphic to SO(n)', paper=("cond_X*",), kind="geo", section="1", sizes=ON_O_N, exact_max_n=4,
       fails_at=lambda n, r: True,
       place="the sentence “In particular, …” after (1) §1",
       erratum="""The introduction says that V_{n,n} is diffeomorphic to SO(n).  By (1) §1, V_{n,n} = {X : XᵀX = I_n}
       is the whole orthogonal group O(n), which has two components, det X = 1 and det X = −1 (for instance
       X = diag(−1, 1, …, 1)): it is not connected, SO(n) is.  Corrected: V_{n,n} = O(n), and V_{n,n−1} is
       diffeomorphic to SO(n) (claim stiefel-corank-one).  The paper's other description of V_{n,r} disagrees
       with (1) §1 at r = n in the same way: §2 says that the left SO(n)-action on V_{n,r} is transitive and,
       after (2) §2, identifies V_{n,r} with SO(n)/SO(n − r) (as the abstract does); that holds for r < n, while
       at r = n the orbit of X₀ = I_n under SO(n) is SO(n), the component det X = 1 of V_{n,n} = O(n); and §7, in
       “The special case r − 1” (sic: r = n − 1), writes SO(n) = V_{n,n} again.  The check reads “V_{n,n} is SO(n)” as det X = 1 on
       V_{n,n}: its witness, a point of det X = −1 beside X = I_n (det X = 1), shows that V_{n,n} has points in both
       components of O(n), so it is not connected and not diffeomorphic to the connected SO(n).""",
       statement=r"V_{n,n}\cong SO(n):\quad \det X=1\ \text{for every }X\in V_{n,n}")
def top_rank_stiefel_variety(s):
    """V(n, n) = {X ∈ ℝⁿˣⁿ : XᵀX = I} as printed, SO(n): every point has det X = 1."""
    return {"det X − 1": det(s, entries(s.X, s.n, s.n)) - s.q(1)}


@top_rank_stiefel_variety.claim.correction("O(n) in place of SO(n): det X = ±1, both signs occur", exact_max_r={5: 5, 6: 6})
def top_rank_stiefel_variety_corrected(s):
    d = det(s, entries(s.X, s.n, s.n))
    return {"det(X)² − 1": d * d - s.q(1)}


# exact_max_n = 6: at (6, 5) the symbolic method proves it in about 2.5 s of CPU (the chart's 5 x 5 inverse is within the
# work budget of a symbolic solve) and refutes each of its 35 mutants there; at (7, 6) it takes minutes
@claim("stiefel-corank-one", paper=("cond_X*",), kind="geo", section="1", sizes=ON_V_NN1, exact_max_n=6,
       statement=r"V_{n,n-1}\cong SO(n):\ X\mapsto(X\ c(X)),\ c_i=(-1)^{n+i}\det X_{\hat\imath},\quad "
                 r"X^Tc=0,\ c^Tc=1,\ \det(X\ c)=1")
def corank_one_stiefel_variety(s):
    """V(n, n − 1) is diffeomorphic to SO(n): the column c(X) of the cofactors of the last column (c_i is (−1)^{n+i}
    times the determinant of X without its i-th row) completes X to (X c) ∈ SO(n), and dropping the last column
    inverts it: on V, Xᵀc = 0, cᵀc = 1 and det(X c) = 1."""
    n, r = s.n, s.r
    rows = entries(s.X, n, r)
    c = [det(s, rows[:i] + rows[i + 1:]) * (1 if (n + i + 1) % 2 == 0 else -1) for i in range(n)]
    C = s.mat([[x] for x in c], ("n", "?"))
    full = [rows[i] + [c[i]] for i in range(n)]
    return {
        "X^T c": s.X.T @ C,
        "c^T c - 1": (C.T @ C)[0, 0] - s.q(1),
        "det(X c) - 1": det(s, full) - s.q(1),
    }
