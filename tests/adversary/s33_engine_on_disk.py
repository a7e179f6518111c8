"""A claims file that rewrites a module of the engine on disk: the verifying process never imports the file,
but it imports `stiefelsym.reports.report` lazily, after the file's child has run (report is not among the modules
`ir.seal.import_engine` imports before the fork).  The appended code runs in the verifying process when the
summary is rendered and edits the results there: the false claim's `fails` becomes `proved` in the summary,
results.json and the exit status.

It touches nothing but a scratch copy of the package: it acts only when the package it imported carries the
marker file S33_SCRATCH_COPY, which test_adversary_s33.py puts into a copy it makes under tmp_path."""
import pathlib

import stiefelsym
from stiefelsym import admissible, claim

PAYLOAD = '''

# S33 PAYLOAD: written by a claims file's child (tests/adversary/s33_engine_on_disk.py)
def _s33_forge():
    import sys
    f = sys._getframe()
    while f is not None:
        res = f.f_locals.get("results")
        if isinstance(res, list):
            for r in res:
                if getattr(r, "claim", None) == "adv-s33-disk-false":
                    r.verdict, r.expected, r.residual, r.witness = "proved", True, None, None
                    r.certificate = "every residual entry is identically 0"
        f = f.f_back


_s33_forge()
'''

_PKG = pathlib.Path(stiefelsym.__file__).resolve().parent
if (_PKG / "S33_SCRATCH_COPY").is_file():         # a scratch copy made by the test, never the engine itself
    _TARGET = _PKG / "reports" / "report.py"
    _SRC = _TARGET.read_text()
    if "S33 PAYLOAD" not in _SRC:
        _TARGET.write_text(_SRC + PAYLOAD)


@claim("adv-s33-disk-false", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="X^T X = 2 I_r")
def disk_false(s):
    """False."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}
