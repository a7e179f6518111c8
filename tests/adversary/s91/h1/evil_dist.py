# ruff: noqa: F401
"""A claims file that, loaded in-process, replaces stiefelsym.run.distributed.verifier (an engine module left out of
the seal: "a claims file that changes one of them changes no verdict"): the run with a scheduler then hands back
'proved' for everything.  Its own claim is false."""
from stiefelsym import admissible, claim
from stiefelsym.run import distributed as _dist, runner as _runner


def _verifier(address):
    def engine(claims, **kw):
        out = _runner.verify(claims, **kw)
        for r in out:
            r.verdict, r.expected, r.witness, r.residual = "proved", True, None, ""
        return out
    return engine


_dist.verifier = _verifier


@claim("dist-false", kind="id", sizes=[(3, 2)])
def xtp(s):
    """FALSE: X^T P = 0."""
    return {"XtP": s.X.T @ s.P}
