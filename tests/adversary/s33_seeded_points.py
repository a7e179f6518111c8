"""The rational method's points are a function of the seed, the claim's id and the size alone (methods.
_run_points: random.Random(f"{seed}|{id}|{n}|{r}|rational|{t}|{attempt}") drives the Cayley chart's
parameters), so a claims file can build the very scenes the method will build, read tr(PᵀP) there (v_t), and
state ∏_t (tr(PᵀP) − v_t) = 0: a nonzero polynomial that vanishes at every point the method draws.  Rational
answers `checked` with a tiny false-pass bound for a false claim (Schwartz–Zippel over points chosen before the
claim, not after it)."""
import random

from stiefelsym import admissible, claim
from stiefelsym.backends.fields import RationalField
from stiefelsym.backends.paired import PairField
from stiefelsym.scene import Scene

#: the points of one run covered (the run takes far fewer)
POINTS = 8
#: the range of the rational method's parameters (methods.RATIONAL_BOUND)
BOUND = 2 ** 62


def _values(cid, n, r, seed=0):
    out = []
    for t in range(POINTS):
        rng = random.Random(f"{seed}|{cid}|{n}|{r}|rational|{t}|0")
        sc = Scene(n, r, PairField(RationalField(BOUND)), chart="cayley", rng=rng, component=0,
                   realization="standard")
        out.append(sc.tr(sc.P.T @ sc.P).v)
    return out


_SIZE = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)")
_V = _values("adv-s33-points-product", 3, 2)


@claim("adv-s33-points-product", kind="id", sizes=_SIZE, statement="prod_t (tr(P^T P) - v_t) = 0")
def points_product(s):
    """False: a nonzero polynomial in the point (it vanishes where tr PᵀP is one of the v_t only)."""
    t = s.tr(s.P.T @ s.P)
    out = s.q(1)
    for v in _V:
        out = out * (t - s.q(int(v.numerator), int(v.denominator)))
    return {"r": out}
