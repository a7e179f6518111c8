"""Run with this file, report with expect_swap_b.py (the same claim id, function, docstring and sizes; this one
says the residual does NOT vanish, TRUE)."""
from stiefelsym import claim


@claim("s75-expect-swap", kind="id", expect="nonzero", sizes=[(3, 2)])
def expect_swap(s):
    """XᵀAX = 0."""
    return {"w": s.X.T @ s.A @ s.X}
