# ruff: noqa
"""The documented `pytest --stiefelsym FILE.py` (docs/integration.md): the plugin loads the claims in child
processes, but pytest's own Python collector also imports FILE.py in the pytest process, because a path given
on the command line is collected as a test module whatever its name (an "initial path"; under a directory,
test_*.py files are imported the same way).  That import runs before any item, and here replaces the runner's
verify in the pytest process so that every item gets the verdict `proved`.
Run: cp plugin_inprocess.py /tmp/x/my_claims.py; cd /tmp/x; pytest --stiefelsym my_claims.py -p no:cacheprovider -rA
Honest outcome: s70-plug-false (XᵀP = 0, false for r >= 2) FAILS its items at (2,2), (3,2), (3,3)."""
import sys

from stiefelsym import admissible, claim


@claim("s70-plug-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2: only XᵀP + PᵀX = 0 on T*V)."""
    return {"xtp": s.X.T @ s.P}


if "_pytest.python" in sys.modules:     # only in pytest's own import of the module (the sandbox has no pytest)
    try:
        from stiefelsym.run import runner

        _orig = runner.verify

        def verify(claims, *a, **kw):
            out = _orig(claims, *a, **kw)
            for r in out:
                r.verdict, r.expected, r.message = "proved", True, ""
            return out

        runner.verify = verify
    except Exception:
        pass
