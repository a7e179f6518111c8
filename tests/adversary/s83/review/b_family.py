"""Stop 83 review (h2): traces that the cost count does reassociate (a family of matrices paired with a point, so
[x, z] or x z is shared).  -t- true, -f- false (one change).  Independent check: b_family.py.in (numpy)."""
from stiefelsym import admissible, claim, comm

S = admissible(n_min=3, n_max=4, r_min=1, r_max=3)


def _fam(s):
    F = s.X @ s.P.T - s.P @ s.X.T
    G = s.A @ F - F @ s.A
    M = s.generic("M", "n", "n")
    N = s.generic("N", "n", "n")
    return [F, G, s.Phi, s.A, N, F @ N], M


def _expand(s, x, terms):
    """tr(x Σ sign a b) computed without the fusion: each tr((x a) b) is a trace of a product whose x a is read
    once more (by an extra 0 * tr(x a)), so it is not reassociated."""
    acc = 0
    for sign, a, b in terms:
        xa = x @ a
        acc = acc + sign * s.tr(xa @ b) + 0 * s.tr(xa.T @ xa)
    return acc


@claim("adv-s83r-t-family-comm", paper="adv", kind="id", sizes=S)
def t_fam(s):
    """True: tr(M [z_i, z_j]) for all pairs of a family of six (fused: [M, z_i] once per i), against the traces of
    (M z_i) z_j − (M z_j) z_i made otherwise."""
    zs, M = _fam(s)
    out = {}
    for i, z in enumerate(zs):
        for j, w in enumerate(zs):
            out[f"{i}{j}"] = s.tr(M @ comm(z, w)) - _expand(s, M, [(1, z, w), (-1, w, z)])
    return out


@claim("adv-s83r-f-family-comm", paper="adv", kind="id", sizes=S)
def f_fam(s):
    """False: one pair (2, 4) of the family with its commutator reversed on the right ([Φ, N] for [N, Φ]):
    tr(M [Φ, N]) ≠ 0 for generic M, N."""
    zs, M = _fam(s)
    out = {}
    for i, z in enumerate(zs):
        for j, w in enumerate(zs):
            sign = -1 if (i, j) == (2, 4) else 1
            out[f"{i}{j}"] = s.tr(M @ comm(z, w)) - sign * _expand(s, M, [(1, z, w), (-1, w, z)])
    return out


@claim("adv-s83r-t-family-two-points", paper="adv", kind="id", sizes=S)
def t_two(s):
    """True: tr(M [z, w]) − tr((M − A)[z, w]) + tr(A [w, z]) = 0 for every pair (the commutator shared by two
    traces, the third written [w, z])."""
    zs, M = _fam(s)
    Y = M - s.A
    return {f"{i}{j}": s.tr(M @ comm(z, w)) - s.tr(Y @ comm(z, w)) + s.tr(s.A @ comm(w, z))
            for i, z in enumerate(zs) for j, w in enumerate(zs)}


@claim("adv-s83r-f-family-two-points", paper="adv", kind="id", sizes=S)
def f_two(s):
    """False: + tr(A [z, w]) for the third (= 2 tr(A[z, w]) ≠ 0 for the pairs where it is not 0)."""
    zs, M = _fam(s)
    Y = M - s.A
    return {f"{i}{j}": s.tr(M @ comm(z, w)) - s.tr(Y @ comm(z, w)) + s.tr(s.A @ comm(z, w))
            for i, z in enumerate(zs) for j, w in enumerate(zs)}


@claim("adv-s83r-t-family-sums", paper="adv", kind="id", sizes=S)
def t_sums(s):
    """True: y a sum of three signed products/commutators of the family, with a cancelling pair, against the
    expansion; and the y on the left, tr(y M)."""
    zs, M = _fam(s)
    out = {}
    for i in range(len(zs)):
        a, b, c = zs[i], zs[(i + 1) % 6], zs[(i + 2) % 6]
        y = comm(a, b) - c @ a + a @ c + b @ b - b @ b - comm(c, b)
        e = _expand(s, M, [(1, a, b), (-1, b, a), (-1, c, a), (1, a, c), (-1, c, b), (1, b, c)])
        out[f"l{i}"] = s.tr(M @ y) - e
        out[f"r{i}"] = s.tr(y @ M) - e
    return out


@claim("adv-s83r-f-family-sums", paper="adv", kind="id", sizes=S)
def f_sums(s):
    """False: the expansion with + c b for − c b... i.e. (1, c, b) in place of (−1, c, b) at i = 3 only."""
    zs, M = _fam(s)
    out = {}
    for i in range(len(zs)):
        a, b, c = zs[i], zs[(i + 1) % 6], zs[(i + 2) % 6]
        y = comm(a, b) - c @ a + a @ c + b @ b - b @ b - comm(c, b)
        sg = 1 if i == 3 else -1
        e = _expand(s, M, [(1, a, b), (-1, b, a), (-1, c, a), (1, a, c), (sg, c, b), (1, b, c)])
        out[f"l{i}"] = s.tr(M @ y) - e
        out[f"r{i}"] = s.tr(y @ M) - e
    return out


@claim("adv-s83r-t-family-rect", paper="adv", kind="id", sizes=S)
def t_rect(s):
    """True: rectangular family: u_i ∈ {X, P, A X, N P} (n × r), v_j = u_jᵀ: tr(M (u_i v_j − u_j v_i))
    against the expansion, and tr(Ψ (u_iᵀ u_j − u_jᵀ u_i)) on ℝʳ with the generic r × r point K."""
    _, M = _fam(s)
    N = s.generic("N", "n", "n")
    K = s.generic("K", "r", "r")
    us = [s.X, s.P, s.A @ s.X, N @ s.P]
    out = {}
    for i, u in enumerate(us):
        for j, w in enumerate(us):
            out[f"n{i}{j}"] = s.tr(M @ (u @ w.T - w @ u.T)) - _expand(s, M, [(1, u, w.T), (-1, w, u.T)])
            out[f"r{i}{j}"] = s.tr(K @ (u.T @ w - w.T @ u)) - _expand(s, K, [(1, u.T, w), (-1, w.T, u)])
    return out


@claim("adv-s83r-f-family-rect", paper="adv", kind="id", sizes=S)
def f_rect(s):
    """False: at (i, j) = (1, 3) the ℝʳ expansion uses u_jᵀ u_i − u_iᵀ u_j (sign flipped) (tr(K(PᵀNP − (NP)ᵀP))
    ≠ 0 for generic K, N)."""
    _, M = _fam(s)
    N = s.generic("N", "n", "n")
    K = s.generic("K", "r", "r")
    us = [s.X, s.P, s.A @ s.X, N @ s.P]
    out = {}
    for i, u in enumerate(us):
        for j, w in enumerate(us):
            sg = -1 if (i, j) == (1, 3) else 1
            out[f"n{i}{j}"] = s.tr(M @ (u @ w.T - w @ u.T)) - _expand(s, M, [(1, u, w.T), (-1, w, u.T)])
            out[f"r{i}{j}"] = s.tr(K @ (u.T @ w - w.T @ u)) - sg * _expand(s, K, [(1, u.T, w), (-1, w.T, u)])
    return out


@claim("adv-s83r-t-family-mixed-kinds", paper="adv", kind="id", sizes=S)
def t_kinds(s):
    """True: a commutator [z, w] shared by tr(M C), <M, C> and tr(C A): tr(M C) + 2<M, C> = 0 and
    tr(C A) = tr(A C), every pair."""
    zs, M = _fam(s)
    out = {}
    for i, z in enumerate(zs):
        for j, w in enumerate(zs):
            C = comm(z, w)
            out[f"{i}{j}"] = s.tr(M @ C) + 2 * s.killing(M, C) + s.tr(C @ s.A) - s.tr(s.A @ comm(z, w))
    return out


@claim("adv-s83r-f-family-mixed-kinds", paper="adv", kind="id", sizes=S)
def f_kinds(s):
    """False: tr(M C) − 2<M, C> (= 2 tr(M C) ≠ 0 for generic M and z ≠ w non-commuting)."""
    zs, M = _fam(s)
    out = {}
    for i, z in enumerate(zs):
        for j, w in enumerate(zs):
            C = comm(z, w)
            out[f"{i}{j}"] = s.tr(M @ C) - 2 * s.killing(M, C) + s.tr(C @ s.A) - s.tr(s.A @ comm(z, w))
    return out
