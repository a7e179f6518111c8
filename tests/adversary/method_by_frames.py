"""A false claim passed by the method that traces it first: the claim is traced inside the method's
own call (run_exact, _run_points, _run_float ... call_claim → compile_claim), so claim code reads the
method from the names of its callers' frames.  Traced twice in the same call, both graphs agree; and
`stiefelsym check`, which traces inside check_results, is told the same story and accepts the record."""
import sys

from stiefelsym import admissible, claim

_SAMPLED = ("_run_points", "run_exact", "check_results")   # check_results: `stiefelsym check` agrees


def _method_is_sampled_or_exact():
    f = sys._getframe(1)
    while f is not None:
        if f.f_code.co_name in _SAMPLED:
            return True
        f = f.f_back
    return False


@claim("adv-frames", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x_is_zero(s):
    """X = 0 on the Stiefel variety (false)."""
    return {"X": s.X - s.X if _method_is_sampled_or_exact() else s.X}
