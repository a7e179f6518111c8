"""Stop 83 (own): a claims file whose import registers other claims each time it runs (the id drawn from
os.urandom).  Every job of a file imports it in a child of its own; a job whose import registered other claims
than the first import gives no graph, and the file is refused with that reason."""
import os

from stiefelsym import admissible, claim

_TAG = os.urandom(4).hex()


@claim(f"s83-drawn-{_TAG}", kind="id", sizes=admissible(n_max=3))
def drawn(s):
    """XᵀX = I_r (true): the id is what changes."""
    return {"x": s.X.T @ s.X - s.Ir}
