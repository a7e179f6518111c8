"""Rank(M, k, generic=False) (rank k at EVERY point) is proved by a constant nonzero k x k minor on the chart the
method takes; the equivariant chart X = X0 = (E1..Er) is valid only for O(n)-covariant M.  M = D X with D the
constant projector twisted.eigenspace_projector (diag(I_2, 0) on R^n) or twisted.reflection is NOT covariant.

At n = 4, r = 2: D X has rank 2 at X0 but rank 0 at X = (E3, E4): "rank 2 at every point" is FALSE
(r4-rankall-proj-false); its generic rank is 2 (r4-rankall-proj-generic-true).  S1 X (S1 invertible) has rank r
at every point (r4-rankall-refl-true).  Kernel frame W (generic constant n x r): W^T X at X0 is the top r x r
block of W^T, not constant; [X, W] (n x 2r) at n = 4, r = 2 has rank 4 generically but rank 2 where X = W R
(W's column space): "rank 4 at every point" FALSE (r4-rankall-frame-false)."""
from stiefelsym import Rank, admissible, claim
from stiefelsym.twisted import eigenspace_projector, reflection, kernel_frame
from stiefelsym.backends.matrix import block

SZ = admissible(n_max=4, n_min=4, r_min=2, r_max=2)


@claim("r4-rankall-proj-false", kind="dim", sizes=SZ)
def proj_false(s):
    D = eigenspace_projector(s)
    return {"rank D X = 2 everywhere": Rank(D @ s.X, 2, generic=False)}


@claim("r4-rankall-proj-generic-true", kind="dim", sizes=SZ)
def proj_generic(s):
    D = eigenspace_projector(s)
    return {"generic rank D X = 2": Rank(D @ s.X, 2)}


@claim("r4-rankall-refl-true", kind="dim", sizes=SZ)
def refl_true(s):
    S = reflection(s)
    return {"rank S1 X = 2 everywhere": Rank(S @ s.X, 2, generic=False)}


@claim("r4-rankall-frame-false", kind="dim", sizes=SZ)
def frame_false(s):
    W = kernel_frame(s)
    return {"rank [X W] = 4 everywhere": Rank(block([[s.X, W]]), 4, generic=False)}
