"""s59 review, batch 5: engine state the seal does not watch: the realizations table (stiefelsym.scene.REALIZATIONS)
changed by claim code, its dict and every function in it the engine's own objects."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=3)


@claim("s59r-realization-swap", kind="id", sizes=SIZES)
def realization_swap(s):
    """0 = 0: TRUE.  Its code makes the standard realization's constraints the metric ones."""
    import stiefelsym.scene as sc
    sc.REALIZATIONS["standard"] = sc.Constraints("standard", sc.metric_constraints)
    return {"zero": s.X - s.X}


@claim("s59r-cond-xp", kind="id", sizes=SIZES)
def cond_xp(s):
    """X^T P + P^T X = 0 on T*V (cond_XP): TRUE."""
    return {"res": s.X.T @ s.P + s.P.T @ s.X}


@claim("s59r-cond-xp-metric", kind="id", sizes=SIZES)
def cond_xp_metric(s):
    """X^T A^-1 P + P^T A^-1 X = 0 on the standard T*V: FALSE."""
    return {"res": s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X}


def _h(t):
    return t.tr(t.generic("U", "n", "r").T @ t.X) + t.tr(t.generic("V", "n", "r").T @ t.P)


@claim("s59r-dirac-keeps-xp", kind="id", sizes=SIZES)
def dirac_keeps_xp(s):
    """The Dirac flow of H = tr(U^T X) + tr(V^T P) keeps X^T P + P^T X: d(X^T P + P^T X) = 0: TRUE."""
    flow = s.dirac_flow(_h)
    return {"d": flow.Xdot.T @ s.P + s.X.T @ flow.Pdot + flow.Pdot.T @ s.X + s.P.T @ flow.Xdot}


@claim("s59r-dirac-keeps-metric", kind="id", sizes=SIZES)
def dirac_keeps_metric(s):
    """The Dirac flow keeps X^T A^-1 P + P^T A^-1 X: FALSE on the standard realization."""
    flow = s.dirac_flow(_h)
    Ai = s.Ainv
    return {"d": flow.Xdot.T @ Ai @ s.P + s.X.T @ Ai @ flow.Pdot + flow.Pdot.T @ Ai @ s.X + s.P.T @ Ai @ flow.Xdot}
