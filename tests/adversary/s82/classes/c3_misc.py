"""Quick tricks over several classes (truths by hand; sizes (3,2) unless said; r < n).

Rank certificates (class 1/3):
 k-true:      Rank(XXᵀ, r, kernel=I − XXᵀ): XXᵀ(I − XXᵀ) = 0 on V, rank(I − XXᵀ) = n − r, so rank <= r; rank r: TRUE.
 k-false-hi:  Rank(XXᵀ, r + 1, kernel=I − XXᵀ): FALSE (rank r).
 k-dup:       Rank(XXᵀ, r, kernel=[K, K]) (dependent columns): TRUE.
 k-const:     Rank(XXᵀ, r, kernel=e_n) with e_n a constant column typed R^n (XXᵀe_n = 0 only at X₀ = (E₁…E_r)):
              TRUE rank (the kernel is wrong but never refutes), must not fail; k-const-lo: Rank(XXᵀ, r − 1,
              kernel=e_n): FALSE.
 k-pole:      Rank(XXᵀ, r, kernel=(I − XXᵀ)/(tr PᵀP)): TRUE (a kernel with a pole where P = 0).
 k-vanish:    Rank(XXᵀ, r, kernel=(tr XᵀX − tr I_r)(I − XXᵀ)) (identically 0 on V): TRUE, the kernel bounds nothing.
Exceptions (class 3):
 x-det:       try det(s, XᵀX) (needs the size: refused at symbolic sizes) except: 0 residual; else det(XᵀX) − 2
              (det XᵀX = 1: FALSE).  Must not be proved for all n, r, and fails at fixed sizes.
Metadata-chosen budgets (class 1/7):
 m-corank-false: exact_corank={3: 1}, exact_max_n=1, tr(XXᵀ) − tr(I_n) (= r − n ≠ 0): FALSE.
 m-maxr-false:   exact_max_n=2, exact_max_r={3: 2}, XXᵀ − I_n: FALSE at r < n.
 m-freer-false:  free_max_r=2, a loop over r (int(s.r)) summing the diagonal of XᵀX, minus n: Σ (XᵀX)ᵢᵢ = r ≠ n: FALSE.
 m-freer-true:   the same minus r: TRUE.
Declared gradients (class 4):
 g-wrong:     MatrixFunction(½<y, y>, y ↦ 2y): the declared gradient is wrong: error (refused), never a verdict
              on <∇h(x), x> = 4h(x) (FALSE for the real h: it is 2h).
 g-true:      MatrixFunction(½<y, y>, y ↦ y): <∇h(x), x> − 2h(x) = 0: TRUE.
 g-sum-false: (h + h).grad with h = quadratic(): ∇ = 2x; claim <∇(h+h)(x), x> = 2(h+h)(x) TRUE; the twin with
              3(h+h)(x): FALSE (<x,x> = −r/2 ≠ 0).
"""

from stiefelsym import Rank, admissible, claim, det
from stiefelsym.brackets import MatrixFunction, quadratic

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


def _K(s):
    return s.In - s.X @ s.X.T


@claim("k-true", kind="dim", sizes=SZ)
def k_true(s):
    return {"rank": Rank(s.X @ s.X.T, int(s.r), kernel=_K(s))}


@claim("k-false-hi", kind="dim", sizes=SZ)
def k_false_hi(s):
    return {"rank": Rank(s.X @ s.X.T, int(s.r) + 1, kernel=_K(s))}


@claim("k-dup", kind="dim", sizes=SZ)
def k_dup(s):
    from stiefelsym import block
    K = _K(s)
    return {"rank": Rank(s.X @ s.X.T, int(s.r), kernel=block([[K, K]]))}


def _en(s):
    n = int(s.n)
    return s.mat([[0] for _ in range(n - 1)] + [[1]], ("n", "?"))


@claim("k-const", kind="dim", sizes=SZ)
def k_const(s):
    return {"rank": Rank(s.X @ s.X.T, int(s.r), kernel=_en(s))}


@claim("k-const-lo", kind="dim", sizes=SZ)
def k_const_lo(s):
    return {"rank": Rank(s.X @ s.X.T, int(s.r) - 1, kernel=_en(s))}


@claim("k-pole", kind="dim", sizes=SZ)
def k_pole(s):
    return {"rank": Rank(s.X @ s.X.T, int(s.r), kernel=_K(s) / s.tr(s.P.T @ s.P))}


@claim("k-vanish", kind="dim", sizes=SZ)
def k_vanish(s):
    return {"rank": Rank(s.X @ s.X.T, int(s.r), kernel=(s.tr(s.X.T @ s.X) - s.tr(s.Ir)) * _K(s))}


@claim("x-det", kind="id", sizes=SZ)
def x_det(s):
    try:
        d = det(s, s.X.T @ s.X)
    except Exception:       # noqa: BLE001
        return {"det": s.tr(s.X.T @ s.X) - s.tr(s.X.T @ s.X)}
    return {"det": d - 2}


@claim("m-corank-false", kind="id", sizes=SZ, exact_max_n=1, exact_corank={3: 1})
def m_corank_false(s):
    return {"trXXt": s.tr(s.X @ s.X.T) - s.tr(s.In)}


@claim("m-maxr-false", kind="id", sizes=SZ, exact_max_n=2, exact_max_r={3: 2})
def m_maxr_false(s):
    return {"XXt": s.X @ s.X.T - s.In}


def _diag_sum(s):
    M = s.X.T @ s.X
    t = M[0, 0]
    for i in range(1, int(s.r)):
        t = t + M[i, i]
    return t


@claim("m-freer-false", kind="id", sizes=SZ, free_max_r=2)
def m_freer_false(s):
    return {"sum": _diag_sum(s) - s.tr(s.In)}


@claim("m-freer-true", kind="id", sizes=SZ, free_max_r=2)
def m_freer_true(s):
    return {"sum": _diag_sum(s) - s.tr(s.Ir)}


@claim("g-wrong", kind="id", sizes=SZ)
def g_wrong(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y * 2)
    x = s.X @ s.X.T
    return {"euler": s.killing(h.grad(s, x), x) - h(s, x) * 4}


@claim("g-true", kind="id", sizes=SZ)
def g_true(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    x = s.X @ s.X.T
    return {"euler": s.killing(h.grad(s, x), x) - h(s, x) * 2}


@claim("g-sum-true", kind="id", sizes=SZ)
def g_sum_true(s):
    h = quadratic()
    f = h + h
    x = s.X @ s.X.T
    return {"euler": s.killing(f.grad(s, x), x) - f(s, x) * 2}


@claim("g-sum-false", kind="id", sizes=SZ)
def g_sum_false(s):
    h = quadratic()
    f = h + h
    x = s.X @ s.X.T
    return {"euler": s.killing(f.grad(s, x), x) - f(s, x) * 3}
