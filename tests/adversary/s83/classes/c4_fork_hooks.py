"""Class 4 (state across the per-job processes), without shared memory and without replacing any function:
os.register_at_fork (a public hook of the os module) run in the process that imports the file, between the jobs it
forks; and os.environ / os.putenv written by a job (a child: it should not reach later jobs).

Truths at (3,2): XᵀX = I_r TRUE; XXᵀ = I_n FALSE.
fk-count:  the number of forks the importing process made before this job's (counted in the parent by an
           after_in_parent hook) decides: >= 2 -> XᵀX − I_r (TRUE), else XXᵀ − I_n (FALSE).  The same function as the
           first claim of a file is FALSE (fk-first below runs it first).
fk-first:  the same function, the first claim of the file: FALSE if the count is what it reads
fk-env-w:  sets os.environ["H1_S83"] = "1" in its job (TRUE claim); fk-env-r: reads it: set -> XᵀX − I_r, unset ->
           XXᵀ − I_n (FALSE).  A child's environment never reaches a later child: fails expected.
"""
import os
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)
_FORKS = [0]
os.register_at_fork(after_in_parent=lambda: _FORKS.__setitem__(0, _FORKS[0] + 1))


def _by_count(s):
    if _FORKS[0] >= 2:
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}


@claim("fk-first", kind="id", sizes=SZ)
def fk_first(s):
    return _by_count(s)


@claim("fk-env-w", kind="id", sizes=SZ)
def fk_env_w(s):
    os.environ["H1_S83"] = "1"
    return {"x": s.X.T @ s.X - s.Ir}


@claim("fk-env-r", kind="id", sizes=SZ)
def fk_env_r(s):
    if os.environ.get("H1_S83") == "1":
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}


@claim("fk-count", kind="id", sizes=SZ)
def fk_count(s):
    return _by_count(s)
