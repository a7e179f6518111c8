"""Stop 83 review (h2): a claim for the mutation analysis whose checks are reassociated traces (brief item 6).
True: tr(M [z, w]) = tr(z [w, M]) (cyclic trace) for every pair of the family z, w ∈ {F, G, N, Φ}, and
tr(M (zw + wz − zw)) = tr((M w) z); plus the cancelled commutator tr(M [z, z]) = 0.
Independent check: d_mutate.py.in."""
from stiefelsym import admissible, claim, comm

S = admissible(n_min=3, n_max=3, r_min=2, r_max=2)


@claim("adv-s83r-t-mutate-cyclic", paper="adv", kind="id", sizes=S)
def t_cyclic(s):
    """True (cyclic trace, see the module docstring)."""
    F = s.X @ s.P.T - s.P @ s.X.T
    G = s.A @ F - F @ s.A
    N = s.generic("N", "n", "n")
    M = s.generic("M", "n", "n")
    zs = [F, G, N, s.Phi]
    out = {}
    for i, z in enumerate(zs):
        for j, w in enumerate(zs):
            if i < j:
                out[f"c{i}{j}"] = s.tr(M @ comm(z, w)) - s.tr(z @ comm(w, M))
                out[f"s{i}{j}"] = s.tr(M @ (z @ w + w @ z - z @ w)) - s.tr((M @ w) @ z)
    out["self"] = s.tr(M @ comm(F, F)) + s.tr(M @ comm(G, G))
    return out
