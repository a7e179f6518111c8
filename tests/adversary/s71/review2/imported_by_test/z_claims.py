# ruff: noqa
"""A claims file with a helper (a Hamiltonian) that the user's own, innocent test module imports
(test_helpers.py: `from z_claims import H`).  docs/integration.md: "a claims file that a conftest or a test
module imports itself: its items fail with 'was imported into the pytest process'".  Imported into the pytest
process, this file removes itself from what that check looks at and replaces the runner's verify: every item of
its false claim passes.
Run: bash setup_copies.sh /tmp/x; cd /tmp/x; pytest --stiefelsym ibt -p no:cacheprovider -rA"""
import sys

from stiefelsym import admissible, claim


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("r2-ibt-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀX = 2 I_r (false at every size: XᵀX = I_r on V(n, r))."""
    return {"xtx": s.X.T @ s.X - 2 * s.Ir}


if "_pytest.python" in sys.modules:     # the pytest process only (the loader's child has no pytest)
    try:
        from stiefelsym.run import runner
        _orig = runner.verify

        def verify(claims, *a, **kw):
            out = _orig(claims, *a, **kw)
            for r in out:
                r.verdict, r.expected, r.message = "proved", True, ""
            return out

        runner.verify = verify
        # nothing of the guard itself is touched: the module just stops naming its file
        globals()["__file__"] = None
    except Exception:
        pass
