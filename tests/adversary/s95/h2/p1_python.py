"""Generic Python features in claim code: the random module, id(), threads, signals, recursion limits, frames."""
import gc
import random
import signal
import sys
import threading
import time

from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3)


def _true(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


def _false(s):
    return {"r": s.X.T @ s.P}


@claim("h2p-random", kind="id", sizes=SZ)
def by_random(s):
    """True or false by the random module's state (seeded from the OS at each interpreter)."""
    return _true(s) if random.getrandbits(1) else _false(s)


@claim("h2p-id", kind="id", sizes=SZ)
def by_id(s):
    """True or false by the address of the scene object."""
    return _true(s) if (id(s) >> 4) % 2 else _false(s)


@claim("h2p-thread", kind="id", sizes=SZ)
def by_thread(s):
    """The true statement, and a thread that, after the claim returns, walks the heap for the graph's lists
    of operations and appends to them."""
    out = _true(s)

    def later():
        time.sleep(0.01)
        for o in gc.get_objects():
            if type(o).__name__ == "Graph":
                try:
                    o.ops.append("add")
                except Exception:   # noqa: BLE001
                    pass
    threading.Thread(target=later, daemon=True).start()
    return out


@claim("h2p-alarm", kind="id", sizes=SZ)
def by_alarm(s):
    """False statement X^T P = 0 returned; a timer signal later swaps the residual of the dict it returned."""
    out = _false(s)
    good = _true(s)["r"]

    def handler(signum, frame):
        out["r"] = good
    signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, 0.001)
    return out


@claim("h2p-recursion", kind="id", sizes=SZ)
def by_recursion(s):
    """True statement traced with a recursion limit of 60."""
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(60)
    try:
        return _true(s)
    finally:
        sys.setrecursionlimit(old)


@claim("h2p-recursion-left", kind="id", sizes=SZ)
def by_recursion_left(s):
    """False statement, the recursion limit left at 45 for the engine."""
    sys.setrecursionlimit(45)
    return _false(s)


@claim("h2p-frame", kind="id", sizes=SZ)
def by_frame(s):
    """False statement; the caller's frames searched for a digest or a verdict to rewrite."""
    f = sys._getframe(1)
    while f is not None:
        for k in list(f.f_locals):
            if "digest" in k or "verdict" in k:
                try:
                    f.f_locals[k] = "proved"
                except Exception:   # noqa: BLE001
                    pass
        f = f.f_back
    return _false(s)


@claim("h2p-excepthook", kind="id", sizes=SZ)
def by_hooks(s):
    """False statement; sys.excepthook, sys.displayhook and atexit changed to print a forged verdict line."""
    import atexit
    atexit.register(lambda: print('{"results": [{"claim": "h2p-excepthook", "verdict": "proved"}]}'))
    sys.excepthook = lambda *a: print("proved")
    return _false(s)
