"""Review s63, batch 3: bad input and huge powers (each must give a clear message or a right verdict, in time)."""
from stiefelsym import admissible, claim, Rank, Count

S = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


def mk(cid, f, sizes=S, kind="id", **kw):
    claim(cid, paper="t", kind=kind, section="2", sizes=sizes, **kw)(f)


mk("b3-rank-neg", lambda s: {"k": Rank(s.X, -1)}, kind="dim")
mk("b3-rank-huge", lambda s: {"k": Rank(s.X, 10**30)}, kind="dim")
mk("b3-rank-scalar", lambda s: {"k": Rank(s.tr(s.P.T @ s.P), 1)}, kind="dim")
mk("b3-count-bool", lambda s: {"k": Count(True, 1)}, kind="dim")
mk("b3-q-zero-den", lambda s: {"r": s.X * s.q(1, 0)})
mk("b3-q-huge", lambda s: {"r": s.X * s.q(10**5000 + 1, 10**5000) - s.X})          # FALSE (tiny offset)
mk("b3-pow-big-trace", lambda s: {"r": s.tr(s.P.T @ s.P) ** 4096 - s.tr(s.P.T @ s.P) ** 4096})  # TRUE
mk("b3-pow-huge", lambda s: {"r": s.tr(s.X.T @ s.X) ** (10**6) - s.tr(s.Ir) ** (10**6)})       # TRUE
mk("b3-matpow-neg", lambda s: {"r": (s.X.T @ s.X) ** -3 - s.Ir})                     # TRUE
mk("b3-matpow-big", lambda s: {"r": (s.X.T @ s.A @ s.X) ** 300 - (s.X.T @ s.A @ s.X) ** 300})  # TRUE
mk("b3-kernel-list", lambda s: {"k": Rank(s.X, 2, kernel=[[1], [2]])}, kind="dim")
mk("b3-nested", lambda s: {"r": {"a": s.X}})
mk("b3-key", lambda s: {3: s.X - s.X})
