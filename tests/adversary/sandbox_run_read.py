"""What is left of route A' once the file is traced in a spawned interpreter: every way a claims file had to
learn the run's command or sizes.  Each claim states X^T X = I unless its way finds the size 7 and 2 (as a run asks
for), where it states X = 0 (false): each would trace different graphs in the run of the free method and in a
run at n = 7, r = 2 if its way saw the run.  The ways: the parent's command line (/proc/<ppid>/cmdline), every process's
command line (/proc/*/cmdline), the environment (a variable the test sets in the run at n = 7 only), the
objects of the interpreter (gc.get_objects(): the parsed options of a forked child), and its own argv."""
import gc
import os
import sys

from stiefelsym import admissible, claim



def _mark():
    """The size as the command line writes it, made at run time (a constant of this file would be one of the objects it walks)."""
    return chr(55) + "," + chr(50)


def _cmdline(pid):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            return f.read().decode(errors="replace")
    except OSError:
        return ""


def _by_parent():
    return _mark() in _cmdline(os.getppid())


def _by_processes():
    try:
        pids = [p for p in os.listdir("/proc") if p.isdigit()]
    except OSError:
        return False
    return any(_mark() in _cmdline(p) for p in pids)


def _by_environ():
    return any(_mark() in v for v in os.environ.values())


def _by_objects():
    for o in gc.get_objects():
        try:
            if isinstance(o, dict):
                items = list(o.values())
            elif isinstance(o, (list, tuple)):
                items = list(o)
            else:
                items = list(getattr(o, "__dict__", {}).values())
        except Exception:   # noqa: BLE001 - an object that does not list
            continue
        if type(o).__name__ == "Size" and getattr(o, "n", None) == 7 and getattr(o, "r", None) == 2:
            return True         # the parsed --size of a forked child
        for v in items:
            if isinstance(v, str) and _mark() in v:
                return True
    return False


def _by_argv():
    return any(_mark() in a for a in list(sys.argv) + list(getattr(sys, "orig_argv", [])))


WAYS = {"parent": _by_parent, "processes": _by_processes, "environ": _by_environ, "objects": _by_objects,
        "argv": _by_argv}
#: what each way saw when the file was imported (the claims are traced later, in children of that process)
SEEN = {name: way() for name, way in WAYS.items()}


def _make(name):
    def by_way(s):
        """X^T X = I, unless this way saw the run's size n = 7: X = 0 there (false)."""
        if SEEN[name] or WAYS[name]():
            return {"X": s.X}
        return {"XtX - I": s.X.T @ s.X - s.Ir}
    by_way.__name__ = f"by_{name}"
    return claim(f"adv-sbx-{name}", kind="id", sizes=admissible(n_max=5))(by_way)


for _name in WAYS:
    _make(_name)
