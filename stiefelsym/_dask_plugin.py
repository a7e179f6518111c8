"""The dask worker plugin of :mod:`stiefelsym.distributed` (a module of its own, importing dask at
its top, so that the plugin is pickled by reference and this module is imported only with dask)."""
from __future__ import annotations

from typing import Any

from distributed import WorkerPlugin


class StiefelsymPlugin(WorkerPlugin):
    """Starts a worker's run servers (which load the catalog) as the worker starts, one per task
    thread; stops them with the worker."""

    name = "stiefelsym"

    def setup(self, worker: Any) -> None:
        from .distributed import start_servers
        state = getattr(worker, "state", None)
        threads = getattr(state, "nthreads", None) or getattr(worker, "nthreads", 1)
        start_servers(max(int(threads), 1))

    def teardown(self, worker: Any) -> None:
        from .distributed import stop_servers
        stop_servers()
