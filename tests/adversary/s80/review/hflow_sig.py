"""W2 through hamiltonian_flow's H (like={"H": "point"}): a stateful H handed to two hamiltonian_flow calls at
the same point, the second's dict in the order P, X.  H(t, z) = ½tr(PᵀP) + (c/2)·tr(XᵀAX), c = 1 then 2;
constraints (cond_XP) F as in s78/review3/flow_extra_key.py.
Truth (by hand, the Neumann system with c·A): Ẋ = P, Ṗ = −cAX + XΛ_c, Λ_c = c·XᵀAX − PᵀP.  For ONE H both
flows agree; Ṗ(c=1) − Ṗ(c=2) = AX − XXᵀAX ≠ 0 for r < n (generic A), = 0 at r = n (XXᵀ = I).
  s80r-hflow-keyorder-contradiction: Ṗ1 = Ṗ(c=1) and Ṗ2 = Ṗ(c=2)              FALSE at (3,1), (3,2); TRUE at (3,3)
  s80r-hflow-control-true:           two H objects                             TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import hamiltonian_flow, symmetric_entries

PAIRS = [("X", "P")]
SZ = admissible(n_min=3, n_max=3)


def F(t, z):
    X, P = z["X"], z["P"]
    return symmetric_entries(X.T @ X - t.Ir) + symmetric_entries(X.T @ P + P.T @ X)


def _H(mode):
    def H(t, z):
        return t.tr(z["P"].T @ z["P"]) / 2 + t.tr(z["X"].T @ t.A @ z["X"]) * mode[0] / 2
    return H


def _want(s, c):
    X, P, A = s.X, s.P, s.A
    return -(A @ X) * c + X @ (X.T @ A @ X * c - P.T @ P)


@claim("s80r-hflow-keyorder-contradiction", kind="id", sizes=SZ)
def contra(s):
    mode = [1]
    H = _H(mode)
    f1, _ = hamiltonian_flow(s, H, F, {"X": s.X, "P": s.P}, PAIRS)
    mode[0] = 2
    f2, _ = hamiltonian_flow(s, H, F, {"P": s.P, "X": s.X}, PAIRS)
    return {"Xdot 1": f1["X"] - s.P, "Pdot 1": f1["P"] - _want(s, 1),
            "Xdot 2": f2["X"] - s.P, "Pdot 2": f2["P"] - _want(s, 2)}


@claim("s80r-hflow-control-true", kind="id", sizes=SZ)
def control(s):
    f1, _ = hamiltonian_flow(s, _H([1]), F, {"X": s.X, "P": s.P}, PAIRS)
    f2, _ = hamiltonian_flow(s, _H([2]), F, {"P": s.P, "X": s.X}, PAIRS)
    return {"Xdot 1": f1["X"] - s.P, "Pdot 1": f1["P"] - _want(s, 1),
            "Xdot 2": f2["X"] - s.P, "Pdot 2": f2["P"] - _want(s, 2)}
