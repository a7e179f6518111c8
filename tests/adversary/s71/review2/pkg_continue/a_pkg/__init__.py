# ruff: noqa
"""The __init__.py of a package that holds a claims file (refused at collection) and a test module.  With
--continue-on-collection-errors pytest runs the test module's items, imports this file to set the package up
(docs/integration.md: "pytest never imports a claims file or the package around one"), and it replaces the
runner's verify before z_claims.py's items (outside the package) run."""
import sys

if "_pytest.python" in sys.modules:
    try:
        from stiefelsym.run import runner

        def verify(claims, *a, _orig=runner.verify, **kw):
            out = _orig(claims, *a, **kw)
            for r in out:
                r.verdict, r.expected, r.message = "proved", True, ""
            return out

        runner.verify = verify
    except Exception:
        pass
