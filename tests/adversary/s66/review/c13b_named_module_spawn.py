# ruff: noqa
"""For SPAWN confinement (no namespaces: STIEFELSYM_CONFINE=spawn, or a machine without user namespaces), run only
against a COPY of the package (see e2e_lazy_import.py).  The claim writes a module zz_evil.py into the engine's
package folder while it is traced, so that the child's own replay finds the step it names; a thread removes
the file again before the child exits (the package's digests are then unchanged).  The graph sent to the
verifying process names stiefelsym.zz_evil.step."""
import os, sys, threading, time
import stiefelsym
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))
PKG = os.path.dirname(stiefelsym.__file__)
EVIL = os.path.join(PKG, "zz_evil.py")
SRC = '''
import os, sys
T = sys.modules["stiefelsym.ir.trace"]
if os.environ.get("S66_CHILD"):
    os.unlink(__file__)         # in the claims file's child: gone before the child exits
with open("/tmp/s66rv/evil_ran.txt", "a") as f:
    f.write(f"zz_evil imported in pid {os.getpid()}\\n")
def step(s):
    if T._ACTIVE:
        return T._ACTIVE[-1].prim("stiefelsym.zz_evil.step", (s,), {})
T._NAMED[id(step)] = ("stiefelsym.zz_evil.step", step)
'''
assert PKG.startswith("/tmp/s66rv/pkg/"), "run against the copy only"


def _remove_later():
    time.sleep(0.5)
    try:
        os.unlink(EVIL)
    except OSError:
        pass


@claim("c13b-names-a-module", kind="id", sizes=S)
def names_module(s):
    """false: X^T P = 0 (the graph also holds one step node naming stiefelsym.zz_evil.step)."""
    with open(EVIL, "w") as f:
        f.write(SRC)
    os.environ["S66_CHILD"] = "1"
    sys.modules["stiefelsym.ir.trace"]._ACTIVE[-1].prim("stiefelsym.zz_evil.step", (s,), {})
    return {"x": s.X.T @ s.P}
