"""Derivatives along flows rewritten into the graph (stiefelsym/ir/derivative.py): closed doors.

* adv-d-nontangent (false): d tr(XᵀX) along Ẋ = X (a flow that is not tangent to V) is 0.  On V,
  tr(XᵀX) = r is constant, but s.d differentiates the function as written, and the rewrite reads the
  flow's components whatever they are: 2 tr(XᵀX) = 2r.  Every method refuses it (free: nf 2r).
* adv-d-nontangent-as-written (true): the same derivative is 2 tr(XᵀX).
* adv-d-inner-flow-moving (false): the second derivative of tr(XᵀAX) along Ẋ = AX, the inner flow built
  from the function's own scene (it moves with the point: an extra term 2 tr(XᵀA³X)), taken for the one
  along the constant flow.  The inner d is left to the scene (a derivative inside a function).
* adv-d-alias (true): a flow whose two components are one matrix (Ẋ = Ṗ = P).
* adv-d-resolvent-sign (false): d tr R(μ) along a flow, μ = tr(XᵀAX) + λ moving, taken as +μ'·tr R².
"""
from stiefelsym import admissible, claim

ALL = admissible(n_max=4, n_min=2)


@claim("adv-d-nontangent", kind="id", sizes=ALL)
def d_nontangent(s):
    """d tr(X^T X) along X' = X, P' = 0 is 0 (false as written: 2 tr(X^T X) = 2r)."""
    return {"v": s.d(lambda u: u.tr(u.X.T @ u.X), {"X": s.X, "P": 0 * s.P})}


@claim("adv-d-nontangent-as-written", kind="id", sizes=ALL)
def d_nontangent_as_written(s):
    """d tr(X^T X) along X' = X, P' = 0 is 2 tr(X^T X) (true)."""
    return {"v": s.d(lambda u: u.tr(u.X.T @ u.X), {"X": s.X, "P": 0 * s.P}) - 2 * s.tr(s.X.T @ s.X)}


@claim("adv-d-inner-flow-moving", kind="id", sizes=ALL)
def d_inner_flow_moving(s):
    """The second derivative with the inner flow moving equals the one with the inner flow constant (false)."""
    fl = {"X": s.A @ s.X, "P": 0 * s.P}
    a = s.d(lambda u: u.d(lambda w: w.tr(w.X.T @ w.A @ w.X), {"X": u.A @ u.X, "P": 0 * u.P}), fl)
    b = s.d(lambda u: u.d(lambda w: w.tr(w.X.T @ w.A @ w.X), fl), fl)
    return {"v": a - b}


@claim("adv-d-alias", kind="id", sizes=ALL)
def d_alias(s):
    """d tr(X^T A P) along X' = P' = P is tr(P^T A P) + tr(X^T A P) (true)."""
    V = s.P
    return {"v": s.d(lambda u: u.tr(u.X.T @ u.A @ u.P), {"X": V, "P": V})
            - s.tr(V.T @ s.A @ s.P) - s.tr(s.X.T @ s.A @ V)}


@claim("adv-d-resolvent-sign", kind="id", sizes=ALL)
def d_resolvent_sign(s):
    """d tr R(mu) = +mu' tr R(mu)^2 for mu = tr(X^T A X) + lam moving (false: the sign is -)."""
    fl = {"X": s.A @ s.X - s.X @ (s.X.T @ s.A @ s.X), "P": 0 * s.P}
    mu = lambda u: u.tr(u.X.T @ u.A @ u.X) + u.lam
    R = s.resolvent(mu(s))
    return {"v": s.d(lambda u: u.tr(u.resolvent(mu(u))), fl) - s.d(mu, fl) * s.tr(R @ R)}
