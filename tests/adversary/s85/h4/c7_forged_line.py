"""A job's answer forged by the file: the job's pipe takes the first line that is a JSON object with "job" (or
"failed") as the job's answer, whoever wrote it (_job_line).  At its import the file finds its job (frames of
_jobs_lines: the pipe `wfd`, the job `jobs[start]`) and writes {"job": <graph of another function>} before the
engine traces the claim; its own trace's line comes second and is not read.

ln-swap  its code: residual X Xᵀ − I_n (FALSE at r < n).  What is sent first: the graph of Xᵀ X − I_r (TRUE).
Right verdict: fails.
"""
import json
import os
import sys

from stiefelsym import admissible, claim


def _true(s):
    return {"x": s.X.T @ s.X - s.Ir}


def _forge():
    f = sys._getframe()
    while f is not None and f.f_code.co_name != "_jobs_lines":
        f = f.f_back
    if f is None:
        return
    job = f.f_locals["jobs"][f.f_locals["start"]]
    if job[0] != "f":
        return
    uf = sys.modules["stiefelsym.run.userfile"]
    state = uf._trace_one(_true, "stiefel" if False else _real(), job[2])
    os.write(f.f_locals["wfd"], json.dumps({"job": state}).encode() + b"\n")


def _real():
    from stiefelsym.scene import REALIZATIONS
    return next(iter(REALIZATIONS))


@claim("ln-swap", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def ln_swap(s):
    return {"x": s.X @ s.X.T - s.In}


_forge()
