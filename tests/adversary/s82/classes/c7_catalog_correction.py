"""Class 7 (engine privileges): a correction registered by a user's file on a reviewed catalog claim.

The catalog claim pencil-leaves-singular (proofs/sec6_dimension_lemmas.py) carries a reviewed equivariance reason
(relied on for "its own function and registered corrections only") and fails at (2,1) (its erratum), so a run of it
at (2,1) runs its registered corrections.  This file imports the catalog claim and registers a correction of its
own whose function reads a coordinate: X₁₁ − 1 (FALSE on V(2,1): X = (cos t, sin t), X₁₁ = 1 only at t = 0; on the
equivariant chart X = X₀ = E₁ it is identically 0).  A right engine runs no such correction, or runs it on a chart
that sees the read (fails).

c7-cat-own-false: the same residual X₁₁ − 1 as a claim of this file (control: FALSE, must fail).
c7-cat-own-true: X₁₁² + X₂₁² − 1 = 0 (TRUE at r = 1, n = 2: XᵀX = 1) as a claim of this file.
"""
from stiefelsym import admissible, claim
from proofs.sec6_dimension_lemmas import pencil_leaves_singular


@pencil_leaves_singular.claim.correction("the user's own correction: X₁₁ = 1")
def user_correction(s):
    return {"X11 - 1": s.X[0, 0] - 1}


@claim("c7-cat-own-false", kind="id", sizes=admissible(n_max=2, n_min=2, r_max=1))
def own_false(s):
    return {"X11 - 1": s.X[0, 0] - 1}


@claim("c7-cat-own-true", kind="id", sizes=admissible(n_max=2, n_min=2, r_max=1))
def own_true(s):
    return {"|x|^2 - 1": s.X[0, 0] * s.X[0, 0] + s.X[1, 0] * s.X[1, 0] - 1}
