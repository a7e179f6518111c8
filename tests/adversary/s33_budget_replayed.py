"""A claims file whose second claim ends its tracing process on purpose (STIEFELSYM_S33_BUDGET: "exit0"
leaves with status 0, "exit1" with status 1, "kill" sends itself SIGKILL, "sleep" outlasts the tracing budget;
unset: the claim is traced normally).  The child records the end as a budget outcome ("exited with status 0",
"killed by SIGKILL", "timeout"), and the verifying process replays it as it happened: in a worker that is the
run's error, but `stiefelsym check` and `stiefelsym derive` call the claim's graph in their own process, so the
file chooses their exit status (or kills them, or makes them wait for ever)."""
import os
import signal
import time

from stiefelsym import admissible, claim

_MODE = os.environ.get("STIEFELSYM_S33_BUDGET", "")


@claim("adv-s33-budget-false", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="X^T X = 2 I_r")
def budget_false(s):
    """False: XᵀX = 2 I_r (a forged `proved` of it must be rejected, and the rejection must count)."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}


@claim("adv-s33-budget-ender", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="X^T X = 2 I_r (its tracing ends its process)")
def budget_ender(s):
    """False: XᵀX = 2 I_r, and its tracing ends its own process as the environment says."""
    if _MODE == "exit0":
        os._exit(0)
    elif _MODE == "exit1":
        os._exit(1)
    elif _MODE == "kill":
        os.kill(os.getpid(), signal.SIGKILL)
    elif _MODE == "sleep":
        time.sleep(10 ** 6)
    return {"r": s.X.T @ s.X - 2 * s.Ir}
