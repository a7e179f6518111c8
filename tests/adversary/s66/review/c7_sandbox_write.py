# ruff: noqa
"""Probe: can the claims file's interpreter write to the host file system (this folder, /tmp, the package's
__pycache__ is not touched)?  The results are files left behind, looked at after the run."""
import os
from stiefelsym import admissible, claim

for target in ("/work/main/tests/adversary/s66/review/written_by_child.txt", "/tmp/s66rv_written_by_child.txt"):
    try:
        with open(target, "w") as f:
            f.write("child wrote here\n")
    except OSError:
        pass


@claim("c7-probe", kind="id", sizes=[(3, 2)])
def probe(s):
    """true: X^T X = I."""
    try:
        with open("/tmp/s66rv_written_by_trace.txt", "w") as f:
            f.write("trace wrote\n")
    except OSError:
        pass
    return {"x": s.X.T @ s.X - s.Ir}
