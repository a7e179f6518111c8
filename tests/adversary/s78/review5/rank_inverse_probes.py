"""Rank at every point and Inverse at every point: declared properties the engine must not take on trust.

(a) Rank([tr PᵀP], 1, generic=False): FALSE (rank 0 at P = 0, a point of T*V).
    Rank([1 + tr PᵀP], 1, generic=False): TRUE (the entry is >= 1).
(b) Inverse on R^{r×r}: op(x) = (I + PᵀP) x, inv(y) = (I + PᵀP)^{-1} y: TRUE (I + PᵀP positive definite), but its
    inverse divides by det(I + PᵀP), a non-constant: the engine may refuse (error), not prove a false twin.
    Inverse op(x) = (PᵀP) x, inv(y) = (PᵀP)^{-1} y: FALSE (op = 0 at P = 0).
    Inverse op(x) = x + (XᵀP) x (XᵀP skew on T*V: I + K invertible for real skew K): TRUE, inv by the Neumann-free
    formula (I + K)^{-1} = (I - K)(I + KᵀK)^{-1}... divides by a non-constant again; not stated.
(c) Inverse op(x) = x + Kx with K = XᵀP nilpotent?  no: a polynomial inverse needs K nilpotent, which it is not.
    Instead: op(x) = x + N x with N = E - E (zero) is trivial.  Polynomial true case:
    op(x, w) = (x, w + x) on R^{r×r} × R^{r×r}, inv(y, v) = (y, v - y): TRUE.
    False twin by a point-dependent scalar that vanishes somewhere: op(x) = tr(PᵀP)·x, inv(y) = y / tr(PᵀP): FALSE."""
from stiefelsym import admissible, claim, Rank, Inverse

SZ = admissible(n_max=3, n_min=2)


@claim("r5-rankall-trpp-false", kind="dim", sizes=SZ)
def rank_trpp(s):
    return {"rank [tr PᵀP] = 1 everywhere": Rank(s.mat([[s.tr(s.P.T @ s.P)]]), 1, generic=False)}


@claim("r5-rankall-1trpp-true", kind="dim", sizes=SZ)
def rank_1trpp(s):
    return {"rank [1 + tr PᵀP] = 1 everywhere": Rank(s.mat([[s.tr(s.P.T @ s.P) + 1]]), 1, generic=False)}


@claim("r5-inv-ipp-true", kind="dim", sizes=SZ)
def inv_ipp(s):
    M = s.Ir + s.P.T @ s.P
    return {"x -> (I + PᵀP)x invertible": Inverse(lambda t, x: M @ x, lambda t, y: M.inv() @ y, "R^{r×r}")}


@claim("r5-inv-pp-false", kind="dim", sizes=SZ)
def inv_pp(s):
    M = s.P.T @ s.P
    return {"x -> (PᵀP)x invertible": Inverse(lambda t, x: M @ x, lambda t, y: M.inv() @ y, "R^{r×r}")}


@claim("r5-inv-shear-true", kind="dim", sizes=SZ)
def inv_shear(s):
    return {"(x, w) -> (x, w + x) invertible": Inverse(lambda t, x, w: (x, w + x), lambda t, y, v: (y, v - y),
                                                      ("R^{r×r}", "R^{r×r}"))}


@claim("r5-inv-scalar-false", kind="dim", sizes=SZ)
def inv_scalar(s):
    c = s.tr(s.P.T @ s.P)
    return {"x -> tr(PᵀP)x invertible": Inverse(lambda t, x: x * c, lambda t, y: y / c, "R^{r×r}")}
