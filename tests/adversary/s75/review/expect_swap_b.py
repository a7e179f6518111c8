"""The same claim as expect_swap_a.py without expect="nonzero": the identity XᵀAX = 0, FALSE."""
from stiefelsym import claim


@claim("s75-expect-swap", kind="id", sizes=[(3, 2)])
def expect_swap(s):
    """XᵀAX = 0."""
    return {"w": s.X.T @ s.A @ s.X}
