"""Measuring the cost model: runs of each family's representative claim, for each method, at r = 2 and
r = ceil(n/2) from n = 4 up to the largest n within a cap, with their time and peak memory (the data
:func:`stiefelsym.methods.costmodel.build` fits).  It runs the methods, so it lives above them;
the model itself (:mod:`.costmodel`) only predicts."""
from __future__ import annotations

from typing import Any, Iterable, Sequence

from stiefelsym.methods.costmodel import FAMILIES, SMALL_R


# --------------------------------------------------------------------------- the scale series

#: the sizes of the scale series (r = 2 and r = ceil(n/2)): each method goes as far as its cap allows
SCALE_NS = (4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024, 1536, 2048, 3072, 4096)
#: the methods of the scale series, in the order they are measured
SCALE_METHODS = ("float", "modular", "ball", "exact", "rational")
#: seconds one run of the scale series may take (the issue asks for 60 s; the shared machine gets 20 s)
SCALE_CAP = 20.0
#: a run shorter than this many seconds is repeated (REPEAT times in all) and its least time kept
REPEAT_BELOW = 1.0
REPEAT = 3


def timed_run(claim: Any, n: int, r: int, method: str, seed: int = 0, timeout: float = SCALE_CAP) -> dict[str, Any]:
    """One run in a fresh forked process, as a pool worker runs it (one BLAS thread): its verdict, wall
    seconds and peak resident memory above the process's own at the start (bytes, from the kernel's
    high-water mark, reset in the child, or a child of the run's own).  Past ``timeout`` the child is
    killed: verdict inconclusive."""
    import os
    import pickle
    import signal
    import time
    r_fd, w_fd = os.pipe()
    t0 = time.perf_counter()
    pid = os.fork()
    if pid == 0:                                   # the child: run, report, exit
        code = 0
        try:
            os.close(r_fd)
            from stiefelsym.backends.blas import tune_worker_process
            from stiefelsym.claims import Size
            from stiefelsym.run.runner import run_one
            tune_worker_process()
            base = _reset_peak()
            t1 = time.perf_counter()
            res = run_one(claim, Size(n, r), method, seed)
            secs = time.perf_counter() - t1
            peak = _peak_rss()
            # a run that works in a child of its own (the symbolic methods' isolation): that child's peak
            import resource
            child = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024
            peak = child if peak is None else max(peak, child)
            out = {"verdict": res.verdict, "seconds": secs,
                   "peak_bytes": None if peak is None or base is None else max(0, peak - base)}
            os.write(w_fd, pickle.dumps(out))
        except BaseException:  # noqa: BLE001 - the parent reports an error
            code = 1
        finally:
            os._exit(code)
    os.close(w_fd)
    data = b""
    deadline = t0 + timeout
    import select
    try:
        while True:
            left = deadline - time.perf_counter()
            if left <= 0:
                os.kill(pid, signal.SIGKILL)
                break
            ready, _, _ = select.select([r_fd], [], [], min(left, 1.0))
            if ready:
                chunk = os.read(r_fd, 1 << 16)
                if not chunk:
                    break
                data += chunk
    except BaseException:                          # interrupted: the child goes too
        os.kill(pid, signal.SIGKILL)
        raise
    finally:
        os.close(r_fd)
        os.waitpid(pid, 0)
    wall = time.perf_counter() - t0
    if not data:
        return {"verdict": "inconclusive" if wall >= timeout else "error", "seconds": round(wall, 6),
                "peak_bytes": None}
    out = pickle.loads(data)
    out["seconds"] = round(out["seconds"], 6)
    return out


def _reset_peak() -> int | None:
    """Reset this process's peak resident set (Linux: /proc/self/clear_refs 5); its current size."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
    except OSError:
        pass
    return _status_bytes("VmRSS")


def _peak_rss() -> int | None:
    return _status_bytes("VmHWM")


def _status_bytes(key: str) -> int | None:
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith(key + ":"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        return None
    return None


def measure_scale(methods: Iterable[str] = SCALE_METHODS, families: dict[str, str] | None = None,
                  ns: Sequence[int] = SCALE_NS, cap: float = SCALE_CAP, seed: int = 0, on_point: Any = None,
                  registry: Any = None, r_series: Sequence[str] = ("small", "half"),
                  repeat: int = REPEAT) -> list[dict[str, Any]]:
    """Time and peak memory of each family's representative claim, for each method, at r = 2
    (``small``) and r = ceil(n/2) (``half``), from n = 4 up to the largest n within ``cap`` seconds.

    A run under REPEAT_BELOW seconds is repeated, ``repeat`` times in all, and its least time kept
    (the noise of a shared machine only ever adds time; its peak memory is the largest).  A series
    stops after a run past the cap (or not decided), and before a size whose time, extrapolated from
    the last two runs (exponent at least 1), would exceed the cap."""
    import math
    from stiefelsym.claims import Size, load_catalog
    from stiefelsym.run.runner import run_one
    families = families or FAMILIES
    registry = registry or load_catalog()
    out: list[dict[str, Any]] = []
    for cid in families.values():                  # warm up: the forked children pay no first imports
        for method in methods:
            try:
                run_one(registry.get(cid), Size(4, 2), method, seed)
            except Exception:  # noqa: BLE001 - a warm-up only
                pass
    for fam, cid in families.items():
        claim = registry.get(cid)
        for method in methods:
            if method in ("float", "ball") and claim.kind == "dim":
                continue
            for series in r_series:
                done: list[tuple[int, float]] = []
                for n in ns:
                    r = SMALL_R if series == "small" else (n + 1) // 2
                    if not claim.sizes.admits(n, r):
                        continue
                    if len(done) >= 2 and done[-1][1] >= 0.05:
                        (n1, t1), (n2, t2) = done[-2], done[-1]
                        b = max(1.0, math.log(max(t2, 1e-6) / max(t1, 1e-6)) / math.log(n2 / n1))
                        if t2 * (n / n2) ** b > cap:
                            break
                    rec = {"family": fam, "claim": cid, "method": method, "n": n, "r": r, "series": series,
                           **timed_run(claim, n, r, method, seed, cap)}
                    if rec["verdict"] not in ("inconclusive", "error") and rec["seconds"] < REPEAT_BELOW:
                        for _ in range(repeat - 1):
                            again = timed_run(claim, n, r, method, seed, cap)
                            if again["verdict"] == rec["verdict"]:
                                rec["seconds"] = min(rec["seconds"], again["seconds"])
                                if again.get("peak_bytes") and rec.get("peak_bytes"):
                                    rec["peak_bytes"] = max(rec["peak_bytes"], again["peak_bytes"])
                        rec["runs"] = repeat
                    out.append(rec)
                    if on_point is not None:
                        on_point(rec)
                    if rec["verdict"] in ("inconclusive", "error") or rec["seconds"] > cap:
                        break
                    done.append((n, rec["seconds"]))
    return out
