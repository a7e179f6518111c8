"""s82 hidden2 (h5): twin of claims3.py: B = diag(−R, I_r) (the cones Σx_i²/(a_i − λ) + Σy_j² = 0, a sign);
true at r = n with n even (det(𝒱ᵀB𝒱) = det(𝒱)² det B there), so stated elsewhere."""
from __future__ import annotations

from stiefelsym import admissible, claim, det

from _common import L_star
from _common3 import VBV

SIZES = admissible(n_max=5, where=lambda n, r: not (r == n and n % 2 == 0), condition="not (r = n, n even)")


@claim("h5x-chasles-cauchy-binet", kind="geo", section="8", sizes=SIZES)
def chasles_cauchy_binet(s):
    """Twin: B = diag(−R, I_r)."""
    return {"det L* - det(V^T B V)": det(s, L_star(s, s.lam)) - det(s, VBV(s, sign=-1))}
