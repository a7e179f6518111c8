"""A claims file whose child leaves a process behind that escapes the clean-up (a second fork in a session of
its own: `os.killpg` of the tracer's group does not reach it) and waits for the verifying process to end, then
rewrites the run's results.json (the path read from the command line the child inherited): the false claim's
`fails` becomes `proved` in the engine's own output file.  `check` would catch the edit; `report` renders it.

It acts only when STIEFELSYM_S33_DAEMON=1 (set by its test), and the process it leaves lives 30 s at most."""
import json
import os
import sys
import time

from stiefelsym import admissible, claim


def _watch(parent, argv):
    path = None
    if "--report-dir" in argv:
        path = os.path.join(argv[argv.index("--report-dir") + 1], "results.json")
    deadline = time.time() + 30
    while path and time.time() < deadline:
        time.sleep(0.1)
        try:
            os.kill(parent, 0)
            continue            # the verifying process is still running
        except OSError:
            pass
        try:
            with open(path) as f:
                payload = json.load(f)
        except (OSError, ValueError):
            return
        for r in payload.get("results", []):
            if r.get("claim") == "adv-s33-later-false":
                r.update(verdict="proved", expected=True, residual=None, witness=None)
        with open(path, "w") as f:
            json.dump(payload, f, indent=1)
        return


#: the process that forked the file's child: the verifying process
_PARENT = os.getppid()
if os.environ.get("STIEFELSYM_S33_DAEMON") == "1" and os.fork() == 0:
    os.setsid()
    if os.fork() == 0:
        try:
            # nothing inherited stays open: the verifying process reads the child's pipe to its end
            null = os.open(os.devnull, os.O_RDWR)
            for fd in (0, 1, 2):
                os.dup2(null, fd)
            os.closerange(3, 4096)
            _watch(_PARENT, list(sys.argv))
        finally:
            os._exit(0)
    os._exit(0)


@claim("adv-s33-later-false", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="X^T X = 2 I_r")
def later_false(s):
    """False."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}
