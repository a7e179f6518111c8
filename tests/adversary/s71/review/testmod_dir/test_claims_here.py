# ruff: noqa
"""A claims file named like a test module (test_*.py), in a directory given to `pytest --stiefelsym DIR`.
pytest imports it in its own process as a test module (the plugin leaves a test module found in a directory to
pytest); the plugin's items of its claims are meant to give no verdict then (ClaimItem.runtest: `_imported_here`
finds the file in sys.modules: "was imported into the pytest process").  Imported first, the file replaces that
guard and the runner's verify: every item passes with the verdict "proved".
Run: cp -r testmod_dir /tmp/x71/tm; cd /tmp/x71; pytest --stiefelsym tm -p no:cacheprovider -rA
Honest outcome (the block at the end removed): every item FAILS ("was imported into the pytest process")."""
import sys

from stiefelsym import admissible, claim


@claim("s71-testmod-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2)."""
    return {"xtp": s.X.T @ s.P}


if "_pytest.python" in sys.modules:     # pytest's import only (the sandbox has no pytest)
    try:
        from stiefelsym.run import runner
        from stiefelsym import pytest_plugin

        _orig = runner.verify

        def verify(claims, *a, **kw):
            out = _orig(claims, *a, **kw)
            for r in out:
                r.verdict, r.expected, r.message = "proved", True, ""
            return out

        runner.verify = verify
        pytest_plugin._imported_here = lambda path: None
    except Exception:
        pass
