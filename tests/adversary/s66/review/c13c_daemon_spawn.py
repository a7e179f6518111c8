# ruff: noqa
"""END-TO-END, SPAWN confinement only, against a COPY of the package (PYTHONPATH=/tmp/s66rv/pkg; the file refuses
to run otherwise).  (1) The claim writes zz_evil.py into the package folder while it is traced, so the child's own
replay accepts the step its graph names; the module deletes itself in the child, so the package's digests are
unchanged when the child exits.  (2) At import, the file leaves a detached process (double fork, setsid) that,
once the file's interpreters are gone, writes zz_evil.py again.  (3) The verifying process's replay of the graph
(stiefelsym/ir/replay.py _registered -> seal.engine_module_of, which lists the package folder on disk at that
moment) imports it: its code runs in the process that computes verdicts and turns the FALSE claim's verdict
into `checked`."""
import os, sys, time
import stiefelsym
from stiefelsym import admissible, claim

PKG = os.path.dirname(stiefelsym.__file__)
if not PKG.startswith("/tmp/s66rv/pkg/"):
    raise SystemExit("run against the copy of the package only")
EVIL = os.path.join(PKG, "zz_evil.py")
SRC = '''
import os, sys
T = sys.modules["stiefelsym.ir.trace"]
if os.environ.get("S66_CHILD"):
    os.unlink(__file__)
with open("/tmp/s66rv/evil_ran.txt", "a") as f:
    f.write(f"zz_evil imported in pid {os.getpid()}\\n")
def step(s):
    if T._ACTIVE:
        return T._ACTIVE[-1].prim("stiefelsym.zz_evil.step", (s,), {})
T._NAMED[id(step)] = ("stiefelsym.zz_evil.step", step)
R = sys.modules.get("stiefelsym.run.runner")
if R is not None and not os.environ.get("S66_CHILD"):
    _orig = R._finish
    def _finish(res, claim, variant, hard=None):
        res = _orig(res, claim, variant, hard)
        if res.claim.startswith("c13c"):
            res.verdict, res.expected, res.witness, res.message = "checked", True, None, ""
        return res
    R._finish = _finish
'''


def _daemon():
    watched = os.getpid()          # the file's interpreter (the child of the verifying process)
    if os.fork():
        return
    os.setsid()
    if os.fork():
        os._exit(0)
    os.closerange(0, 4096)         # hold none of the interpreter's pipes
    try:
        while os.path.exists(f"/proc/{watched}"):
            time.sleep(0.02)
        time.sleep(1.0)            # past the comparison of the package's digests
        with open(EVIL, "w") as f:
            f.write(SRC)
        time.sleep(60)
    finally:
        try:
            os.unlink(EVIL)
        except OSError:
            pass
        os._exit(0)


if not os.environ.get("S66_DAEMON_STARTED"):
    os.environ["S66_DAEMON_STARTED"] = "1"
    _daemon()


@claim("c13c-false", kind="id", sizes=admissible(n_min=3, n_max=9, r_in=(2,)))
def names_module(s):
    """false: X^T P = 0 (the graph also holds a step node naming stiefelsym.zz_evil.step)."""
    os.environ["S66_CHILD"] = "1"
    with open(EVIL, "w") as f:
        f.write(SRC)
    sys.modules["stiefelsym.ir.trace"]._ACTIVE[-1].prim("stiefelsym.zz_evil.step", (s,), {})
    return {"x": s.X.T @ s.P}
