"""Threads of the native libraries (BLAS, OpenMP) and the allocator, scoped to a run.

Nothing here runs at import: the package leaves the environment, the BLAS thread counts and the
allocator of a process that imports it alone.  A run asks for what it needs:

- :class:`one_blas_thread`: the float method's matrices (n up to a few hundred) are too small for
  BLAS threads to pay (OpenBLAS's threads wait for each other by spinning: on a busy machine, or
  under ``--jobs``, a 200 x 200 product took 15 ms of CPU with two threads and 0.3 ms with one).
  threadpoolctl finds the BLAS numpy uses (OpenBLAS, MKL, BLIS) portably; the previous count is
  restored on exit.
- :func:`tune_worker_process`: called in the pool's own worker processes (which exist only to run
  verifications): one thread for every native thread pool, and glibc's allocator told to keep the
  float backend's arrays (see :func:`tune_allocator`).
"""
from __future__ import annotations

import threading
from typing import Any

_CONTROLLER: Any = None
_LOCK = threading.Lock()


def controller() -> Any:
    """threadpoolctl's view of the native thread pools loaded in this process (looked up once,
    after numpy is imported; None where threadpoolctl cannot inspect the process)."""
    global _CONTROLLER
    if _CONTROLLER is None:
        with _LOCK:
            if _CONTROLLER is None:
                import numpy  # noqa: F401  (its BLAS must be loaded to be found)
                try:
                    from threadpoolctl import ThreadpoolController
                    _CONTROLLER = ThreadpoolController()
                except Exception:  # noqa: BLE001 - an unusual platform: leave the threads alone
                    _CONTROLLER = False
    return _CONTROLLER or None


class one_blas_thread:
    """A context in which numpy's BLAS and LAPACK calls run on one thread; the previous setting is
    restored on exit (also when the run raises).  Nothing happens where no BLAS is found."""

    def __enter__(self) -> "one_blas_thread":
        ctl = controller()
        self._limiter = ctl.limit(limits=1, user_api="blas") if ctl is not None else None
        return self

    def __exit__(self, *exc: Any) -> None:
        if self._limiter is not None:
            self._limiter.restore_original_limits()


def blas_threads() -> int | None:
    """The largest thread count of the BLAS libraries loaded (None: no BLAS found)."""
    ctl = controller()
    if ctl is None:
        return None
    counts = [info["num_threads"] for info in ctl.info() if info.get("user_api") == "blas"]
    return max(counts) if counts else None


_ALLOCATOR_TUNED = False


def tune_allocator() -> None:
    """Keep glibc's malloc from handing the float backend's arrays (a 200 x 200 matrix is 320 kB)
    back to the system after every evaluation: by default an array above 128 kB is a fresh mmap,
    and the top of the heap is returned to the system once 256 kB of it are free, so every
    evaluation page-faulted its arrays in again (LA1 at (200,100): 22 ms of CPU per run instead of
    12 until glibc's own thresholds had grown).  Arrays up to 32 MB (glibc's largest threshold)
    come from the heap, and up to 256 MB of free heap are kept: the exact method's flint polynomials of
    4-32 MB were a fresh mmap each, page-faulted in again (pencil-rank-a1 at (6,5): 410k page faults and
    3.8 s against 187k and 3.4 s).  Once per process; nothing happens off glibc.  Only the pool's
    worker processes call it (a process that imports stiefelsym keeps its allocator as it is)."""
    global _ALLOCATOR_TUNED
    if _ALLOCATOR_TUNED:
        return
    _ALLOCATOR_TUNED = True
    try:
        import ctypes
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return
    M_TRIM_THRESHOLD, M_TOP_PAD, M_MMAP_THRESHOLD = -1, -2, -3
    mallopt(M_MMAP_THRESHOLD, 32 << 20)
    mallopt(M_TRIM_THRESHOLD, 256 << 20)
    mallopt(M_TOP_PAD, 16 << 20)


def tune_worker_process() -> None:
    """In a worker process of the pool (it only runs verifications, one at a time): one thread for
    every native thread pool (BLAS, OpenMP) and the allocator tuned for the float backend."""
    tune_allocator()
    ctl = controller()
    if ctl is not None:
        ctl.limit(limits=1)
