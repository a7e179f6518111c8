# ruff: noqa: F841, E702, F401
from stiefelsym import admissible, claim

SZ = admissible(n_max=2)


@claim("u2-bad-hang", kind="id", sizes=SZ)
def hang(s):
    """An infinite loop while traced."""
    while True:
        pass
