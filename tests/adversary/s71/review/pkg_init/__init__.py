# ruff: noqa
"""The package's __init__.py beside a claims file.  pytest (>= 8) imports it in the pytest process to set up the
package node (Package.setup -> importtestmodule(__init__.py)) before the claims' items run.  The plugin's
guard (`_imported_here`) looks for it in sys.modules when each item runs, i.e. after this code ran: it replaces
the guard and the runner's verify, and every item passes with the verdict "proved".
Run: cp -r pkg_init /tmp/x71/pkg; cd /tmp/x71; pytest --stiefelsym pkg/my_claims.py -p no:cacheprovider -rA
(also `pytest --stiefelsym pkg`)."""
import sys

if "_pytest.python" in sys.modules:
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
