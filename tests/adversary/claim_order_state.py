"""State across claims: one claim's graph depends on whether another claim of the same file was traced before
it in the same process.  Each claim is traced twice (the two digests agree: the flag is already set), so the
verdict of adv-order-b depends on the run's order, not on its statement: with the whole file it is X - X
(passed), on its own X (fails)."""
from stiefelsym import admissible, claim

_SEEN = []


@claim("adv-order-a", kind="id", sizes=admissible(n_max=3), statement="X^T X = I")
def order_a(s):
    """True; it records that it was traced."""
    _SEEN.append(1)
    return {"r": s.X.T @ s.X - s.Ir}


@claim("adv-order-b", kind="id", sizes=admissible(n_max=3), statement="X = 0 (unless adv-order-a was traced first)")
def order_b(s):
    """False on its own (X = 0); 0 = 0 when adv-order-a was traced before it in the same process."""
    return {"r": s.X - s.X} if _SEEN else {"r": s.X}
