"""What a job of a claims file sees of the processes around it (stop 85): in namespaces each job is process 1 of
a PID namespace of its own, with a /proc of its own, so that no job can count the jobs before it (stop 85's
sweep I1: the job's process id, and the tracing process's context switches in /proc/1/status, grew with each job).

alone: X^T X - I_r (true) when this process is 1, has no parent in its namespace and /proc lists no other
process; X X^T - I_n (false at r < n) otherwise.  So under namespaces it is proved, and where the interpreter is
spawned without them (the jobs are ordinary children) it fails.
"""
import os

from stiefelsym import admissible, claim


def _alone() -> bool:
    others = [p for p in os.listdir("/proc") if p.isdigit() and p != "1"]
    return os.getpid() == 1 and os.getppid() == 0 and not others


ALONE = _alone()


@claim("alone", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def alone(s):
    if ALONE:
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X @ s.X.T - s.In}
