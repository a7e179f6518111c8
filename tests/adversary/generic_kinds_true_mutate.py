"""Adversary (generic kinds): true claims with symmetric and skew generic matrices, for the mutation analysis and
the charts (O(n) equivariant chart, diagonal chart, right reduction, Cayley chart when coordinates are read)."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-true-traces", paper="adv", kind="id", sizes=S)
def true_traces(s):
    """True: tr(S K) = 0, tr(S A K) + tr(K A S) = 0, (S X)ᵀ = Xᵀ S, tr(K) = 0 for S sym, K skew (on R^n and R^r)."""
    Sn, Kn = s.generic("S", "n", "n", "sym"), s.generic("K", "n", "n", "skew")
    Sr, Kr = s.generic("Sr", "r", "r", "sym"), s.generic("Kr", "r", "r", "skew")      # one name, one parameter
    return {"tr(SK)": (Sn @ Kn).trace(),
            "tr(SAK)+tr(KAS)": (Sn @ s.A @ Kn).trace() + (Kn @ s.A @ Sn).trace(),
            "(SX)^T - X^T S": (Sn @ s.X).T - s.X.T @ Sn,
            "tr(Kr)": Kr.trace(), "tr(Sr Kr)": (Sr @ Kr).trace(),
            "X Kr X^T skew": s.X @ Kr @ s.X.T + (s.X @ Kr @ s.X.T).T}


@claim("adv-gk-true-gl", paper="adv", kind="id", sizes=S)
def true_gl(s):
    """True: for y = S + K, (y + yᵀ)/2 = S and (y − yᵀ)/2 = K."""
    Sn, Kn = s.generic("S", "n", "n", "sym"), s.generic("K", "n", "n", "skew")
    y = Sn + Kn
    return {"sym part": (y + y.T) * s.q(1, 2) - Sn, "skew part": (y - y.T) * s.q(1, 2) - Kn}
