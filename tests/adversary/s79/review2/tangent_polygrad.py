"""polynomial_gradient on a tangent scene (TangentScene._engine_params lifts its base's symbols): the derivative
along {"X": V} of the gradient of the cubic form c ↦ tr(c³) at M = XXᵀ of the moving scene.
By hand: d/dδ tr((M + δE)³) = 3tr(M²E) = <G, E> = −½tr(GE) for all E ⇒ G = −6(M²)ᵀ = −6M² (M symmetric);
d/dε G = −6(ṀM + MṀ), Ṁ = VXᵀ + XVᵀ.
  s79r2-tangent-polygrad-true:   s.d(G) = −6(ṀM + MṀ)     TRUE
  s79r2-tangent-polygrad-false:  s.d(G) = −6·2ṀM           FALSE at r < n (ṀM ≠ MṀ); TRUE at r = n (M = I)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import polynomial_gradient

SZ = admissible(n_min=3, n_max=3)


def _G(t):
    M = t.X @ t.X.T
    return polynomial_gradient(t, lambda u, c: u.tr(c @ c @ c), M, "gl", "n")


@claim("s79r2-tangent-polygrad-true", kind="id", sizes=SZ)
def t_(s):
    V = s.fresh("n", "r")
    M = s.X @ s.X.T
    Md = V @ s.X.T + s.X @ V.T
    return {"d G": s.d(_G, {"X": V}) + (Md @ M + M @ Md) * 6}


@claim("s79r2-tangent-polygrad-false", kind="id", sizes=SZ)
def f_(s):
    V = s.fresh("n", "r")
    M = s.X @ s.X.T
    Md = V @ s.X.T + s.X @ V.T
    return {"d G": s.d(_G, {"X": V}) + (Md @ M) * 12}
