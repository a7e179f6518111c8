"""s88h2 adversarial claims, part 2 (branches on symbolic comparisons, negative indices, stepped slices).

 s88h2b-eq-branch (FALSE): res = tr 𝓛*² (≠ 0); returns 0 if `res == 0` is truthy, else res.  A proof means a
   Python comparison of a symbolic value steered the statement (wrong verdict for the claim as written,
   whose value is tr 𝓛*² ≠ 0).  Expected: fails or an error (refused comparison).
 s88h2b-ne-branch (FALSE): returns 0 if `not (res != 0)`, else res.
 s88h2b-bool-branch (FALSE): returns 0 if `not res`, else res (bool of a symbolic scalar).
 s88h2b-neg-index (TRUE): 𝓛*[−1, −1] = (PᵀRX)[r−1, r−1].  -twin (FALSE for r ≥ 2): = (PᵀRX)[0, 0].
 s88h2b-step-slice (TRUE): 𝓛*[0:2r:r, 0:2r:r] = [[𝓛*₀₀, 𝓛*₀ᵣ], [𝓛*ᵣ₀, 𝓛*ᵣᵣ]].
   -twin (FALSE): = [[𝓛*₀₀, 𝓛*ᵣ₀], [𝓛*₀ᵣ, 𝓛*ᵣᵣ]] (transposed; 𝓛*₀ᵣ = −(XᵀRX)₀₀ ≠ 𝓛*ᵣ₀ = 1 + (PᵀRP)₀₀).
 s88h2b-max-branch (FALSE): returns 0 if max(res, 0) is res... (an ordering of a symbolic scalar).
"""
from __future__ import annotations

from stiefelsym import admissible, block, claim

ANY = admissible(n_max=4)
R2 = admissible(n_max=4, r_min=2, condition="r >= 2")


def Ldual(s):
    R = s.resolvent(s.lam)
    X, P = s.X, s.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]])


def _res(s):
    L = Ldual(s)
    return s.tr(L @ L)


@claim("s88h2b-eq-branch", kind="id", section="8", sizes=ANY)
def eq_branch(s):
    """FALSE: tr𝓛*², replaced by 0 when `res == 0` is truthy."""
    res = _res(s)
    return {"r": s.q(0) if (res == 0) else res}


@claim("s88h2b-ne-branch", kind="id", section="8", sizes=ANY)
def ne_branch(s):
    """FALSE: tr𝓛*², replaced by 0 when `res != 0` is falsy."""
    res = _res(s)
    return {"r": res if (res != 0) else s.q(0)}


@claim("s88h2b-bool-branch", kind="id", section="8", sizes=ANY)
def bool_branch(s):
    """FALSE: tr𝓛*², replaced by 0 when `not res`."""
    res = _res(s)
    return {"r": s.q(0) if not res else res}


@claim("s88h2b-max-branch", kind="id", section="8", sizes=ANY)
def max_branch(s):
    """FALSE: tr𝓛*², replaced by 0 when `res > 0` (an ordering)."""
    res = _res(s)
    return {"r": s.q(0) if res > 0 else res}


@claim("s88h2b-neg-index", kind="id", section="8", sizes=ANY)
def neg_index(s):
    """TRUE: 𝓛*[−1, −1] = (PᵀRX)[r−1, r−1]."""
    L, R, r = Ldual(s), s.resolvent(s.lam), int(s.r)
    return {"L[-1,-1]": L[-1, -1] - (s.P.T @ R @ s.X)[r - 1, r - 1]}


@claim("s88h2b-neg-index-twin", kind="id", section="8", sizes=R2)
def neg_index_twin(s):
    """FALSE (r ≥ 2): 𝓛*[−1, −1] = (PᵀRX)[0, 0]."""
    L, R = Ldual(s), s.resolvent(s.lam)
    return {"L[-1,-1]": L[-1, -1] - (s.P.T @ R @ s.X)[0, 0]}


def _step(s, twin):
    L, r = Ldual(s), int(s.r)
    sub = L[0:2 * r:r, 0:2 * r:r]
    e = [[L[0, 0], L[0, r]], [L[r, 0], L[r, r]]]
    if twin:
        e = [[e[0][0], e[1][0]], [e[0][1], e[1][1]]]
    return {"step slice": sub - s.mat(e, ("?", "?"))}


@claim("s88h2b-step-slice", kind="id", section="8", sizes=ANY)
def step_slice(s):
    """TRUE: 𝓛*[0:2r:r, 0:2r:r] = [[𝓛*₀₀, 𝓛*₀ᵣ], [𝓛*ᵣ₀, 𝓛*ᵣᵣ]]."""
    return _step(s, False)


@claim("s88h2b-step-slice-twin", kind="id", section="8", sizes=ANY)
def step_slice_twin(s):
    """FALSE: the transposed 2×2."""
    return _step(s, True)
