"""The dask worker plugin of :mod:`stiefelsym.run.distributed` (a module of its own, importing dask at
its top, so that the plugin is pickled by reference and this module is imported only with dask)."""
from __future__ import annotations

from typing import Any, Callable

from distributed import WorkerPlugin


class StiefelsymPlugin(WorkerPlugin):
    """Starts a worker's run servers (which load the catalog) as the worker starts, one per task
    thread; stops them with the worker."""

    name = "stiefelsym"

    def __init__(self, start: Callable[[int], None], stop: Callable[[], None]) -> None:
        # the functions of stiefelsym.run.distributed, pickled by reference (this module imports none of it)
        self.start, self.stop = start, stop

    def setup(self, worker: Any) -> None:
        state = getattr(worker, "state", None)
        threads = getattr(state, "nthreads", None) or getattr(worker, "nthreads", 1)
        self.start(max(int(threads), 1))

    def teardown(self, worker: Any) -> None:
        self.stop()
