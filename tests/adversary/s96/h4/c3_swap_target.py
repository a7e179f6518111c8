"""Stop 96, h4: the target of api_code_swap.py (true as written: X^T P + P^T X = 0)."""
from stiefelsym import admissible, claim


@claim("h4s-swap", kind="id", sizes=admissible(n_min=2, n_max=3))
def swap(s):
    """True as written: X^T P + P^T X = 0 (its code is replaced by X^T P = 0, false, in api_code_swap.py)."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}
