"""Derivatives through reads: negative indices, slices with steps and reversals, matrices of given entries,
the trace method, comm and the Killing form.  All TRUE (hand formulas in the docstrings), plus one FALSE twin."""
from stiefelsym import admissible, claim, comm

SZ = admissible(n_max=4, n_min=3, r_min=2, r_max=2)


@claim("s75-dr-negative-index", kind="id", sizes=SZ)
def dr_negative_index(s):
    """d (X[-1, 0] · P[-2, -1]) = V[-1,0]P[-2,-1] + X[-1,0]W[-2,-1]."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.X[-1, 0] * t.P[-2, -1], {"X": V, "P": W})
    return {"w": got - (V[-1, 0] * s.P[-2, -1] + s.X[-1, 0] * W[-2, -1])}


@claim("s75-dr-step-slices", kind="id", sizes=SZ)
def dr_step_slices(s):
    """d tr(X[::2]ᵀ P[::2]) and d of X[::-1][0:2] : V, W read the same way."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.tr(t.X[::2, :].T @ t.P[::2, :]), {"X": V, "P": W})
    got2 = s.d(lambda t: t.X[::-1, :][0:2, :], {"X": V})
    return {"a": got - (s.tr(V[::2, :].T @ s.P[::2, :]) + s.tr(s.X[::2, :].T @ W[::2, :])),
            "b": got2 - V[::-1, :][0:2, :]}


@claim("s75-dr-mat", kind="id", sizes=SZ)
def dr_mat(s):
    """d of the 2 x 2 matrix [[X00·P11, X10], [P01, X00]] (untyped) is [[V00·P11 + X00·W11, V10], [W01, V00]]."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")

    def m(t, X, P):
        return t.mat([[X[0, 0] * P[1, 1], X[1, 0]], [P[0, 1], X[0, 0]]], ("?", "?"))

    got = s.d(lambda t: m(t, t.X, t.P), {"X": V, "P": W})
    want = s.mat([[V[0, 0] * s.P[1, 1] + s.X[0, 0] * W[1, 1], V[1, 0]], [W[0, 1], V[0, 0]]], ("?", "?"))
    return {"w": got - want}


@claim("s75-dr-killing-comm", kind="id", sizes=SZ)
def dr_killing_comm(s):
    """d ⟨Φ, [Φ, A]⟩ = ⟨Φ̇, [Φ, A]⟩ + ⟨Φ, [Φ̇, A]⟩; d (M.trace()) = tr Ṁ for M = XPᵀ."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    Phid = W @ s.X.T + s.P @ V.T - V @ s.P.T - s.X @ W.T
    got = s.d(lambda t: t.killing(t.Phi, comm(t.Phi, t.A)), {"X": V, "P": W})
    got2 = s.d(lambda t: (t.X @ t.P.T).trace(), {"X": V, "P": W})
    return {"k": got - (s.killing(Phid, comm(s.Phi, s.A)) + s.killing(s.Phi, comm(Phid, s.A))),
            "t": got2 - (V @ s.P.T + s.X @ W.T).trace()}


@claim("s75-dr-negative-index-false", kind="id", sizes=SZ)
def dr_negative_index_false(s):
    """FALSE twin: d (X[-1, 0]) = V[0, 0]."""
    V = s.fresh("n", "r")
    return {"w": s.d(lambda t: t.X[-1, 0], {"X": V}) - V[0, 0]}
