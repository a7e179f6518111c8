"""Review s63, batch 2: a claim's own names against the free algebra's letters and coefficient symbols.
Every claim is FALSE (a generic parameter of the claim's own is not the engine's object of that name)."""
from stiefelsym import admissible, claim, twisted

SZ = admissible(n_max=3)
S2 = admissible(n_max=3, n_min=2, r_min=2, r_max=2)


def mk(cid, f, sizes=SZ):
    claim(cid, paper="t", kind="id", section="2", sizes=sizes)(f)


mk("b2-n", lambda s: {"r": s.tr(s.In) - s.scalar("n")})
mk("b2-r", lambda s: {"r": s.tr(s.Ir) - s.scalar("r")})
mk("b2-lam", lambda s: {"r": s.lam - s.scalar("lambda")})
mk("b2-lam2", lambda s: {"r": s.lam - s.scalar("lam")})
mk("b2-kappa", lambda s: {"r": s.kappa - s.scalar("kappa")})
mk("b2-eps", lambda s: {"r": s.eps - s.scalar("epsilon")})
mk("b2-eps2", lambda s: {"r": s.eps - s.scalar("eps")})
mk("b2-m", lambda s: {"r": s.resolvent(s.tr(s.P.T @ s.P)) - s.resolvent(s.scalar("m"))})
mk("b2-m0", lambda s: {"r": s.resolvent(s.tr(s.P.T @ s.P)) - s.resolvent(s.scalar("m0"))})
mk("b2-m1", lambda s: {"r": s.resolvent(s.tr(s.P.T @ s.P)) - s.resolvent(s.scalar("m_1"))})
mk("b2-X", lambda s: {"r": s.X - s.generic("X", "n", "r")})
mk("b2-A", lambda s: {"r": s.A - s.generic("A", "n", "n", "sym")})
mk("b2-Sref", lambda s: {"r": twisted.reflection(s) - s.generic("Sref", "n", "n", "sym")})
mk("b2-Kw", lambda s: {"r": twisted.kernel_annihilator(s) - s.generic("Kw", "n", "n", "sym")})
mk("b2-Wk", lambda s: {"r": twisted.kernel_frame(s) - s.generic("Wk", "n", "r")})
mk("b2-Dn", lambda s: {"r": twisted.eigenspace_projector(s) - s.generic("Dn", "n", "n", "sym")})
mk("b2-E1", lambda s: {"r": twisted.basis_vector(s, 0) - s.generic("E1", "r", "?")}, S2)
mk("b2-xi", lambda s: {"r": s.xi - s.generic("xi", "n", "n", "skew")})
mk("b2-AA", lambda s: {"r": s.sym_operator()(s.Phi) - s.sym_operator("AB")(s.Phi)})
mk("b2-AA2", lambda s: {"r": s.sym_operator()(s.Phi) - s.generic("AA", "n", "n", "skew")})
mk("b2-nr", lambda s: {"r": s.tr(s.In) * s.tr(s.Ir) - s.scalar("n") * s.scalar("r")})
mk("b2-rlam", lambda s: {"r": s.resolvent(s.lam) - s.resolvent(s.scalar("lambda"))})
