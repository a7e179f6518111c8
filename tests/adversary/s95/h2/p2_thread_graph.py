"""A claim whose local object, freed when the claim returns, appends an operation to every graph it finds on the
heap (a thread that does it later races the engine; a finalizer runs at once): the graph its child hands on is
refused by the replay (its operations and arguments differ in number), and every sized run says so."""
import gc

from stiefelsym import admissible, claim


class _Later:
    def __del__(self):
        for o in gc.get_objects():
            if type(o).__name__ == "Graph":
                o.ops.append("add")


@claim("h2p-thread-graph", kind="id", sizes=admissible(n_min=2, n_max=3))
def thread_graph(s):
    """True: X^T P + P^T X = 0 (the graph is made malformed as the claim returns)."""
    later = _Later()     # noqa: F841 (freed when the claim returns)
    return {"r": s.X.T @ s.P + s.P.T @ s.X}
