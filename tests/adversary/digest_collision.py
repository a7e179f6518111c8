"""Two different graphs with one digest: the digest hashes a text in which an engine name (``Named``:
any string a claims file registers with the public ``stiefelsym.ir.named``) is written unescaped, so
the name "adv.zero,%1" makes the one-element row ``list(@adv.zero,%1)`` of the symbolic trace read
exactly like the two-element row [zero, λ] of every fixed-size trace.  The comparison of the symbolic
graph with the fixed-size graphs (compile_claim, the free method's check, `stiefelsym check`) then
passes for a claim that tells symbolic sizes from numbers at every size.  (Here the evaluated graph is
refused by the scene, its entry being no scene number; the collision itself is the finding.)"""
from fractions import Fraction

from stiefelsym import admissible, claim
from stiefelsym.ir import named


class _Q(Fraction):
    """A plain exact constant (a Fraction subclass, so that the graph holds it by name)."""


SHORT = named("adv.zero,%1", _Q(0))
ZERO = named("adv.zero", _Q(0))


@claim("adv-digest-collision", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def zero_lambda_row(s):
    """The row (0  λ) is zero (false at every size: λ is a free parameter)."""
    lam = s.lam
    row = [SHORT] if s.n._size.value is None else [ZERO, lam]
    return {"(0 lam)": s.mat([row])}
