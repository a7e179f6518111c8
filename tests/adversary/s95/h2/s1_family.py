"""A claim that needs r as a number (a loop over r) and looks whether n is a number: free_max_r's family."""
from stiefelsym import admissible, claim


def _n_is_number(s):
    return type(s.n) is int


@claim("h2s-family-type", kind="id", sizes=admissible(n_max=6), exact_max_n=3, free_max_r=2)
def family_type(s):
    """False at fixed sizes (X^T P = 0), true with a symbolic n (X^T P + P^T X = 0)."""
    out = s.X.T @ s.P
    for _ in range(int(s.r)):
        out = out + 0 * s.X.T @ s.X
    if _n_is_number(s):
        return {"r": out}
    return {"r": out + s.P.T @ s.X}


@claim("h2s-family-str", kind="id", sizes=admissible(n_max=6), exact_max_n=3, free_max_r=2)
def family_str(s):
    """The same, through the text of n."""
    out = s.X.T @ s.P
    for _ in range(int(s.r)):
        out = out + 0 * s.X.T @ s.X
    if str(s.n).isdigit():
        return {"r": out}
    return {"r": out + s.P.T @ s.X}


@claim("h2s-family-hash", kind="id", sizes=admissible(n_max=6), exact_max_n=3, free_max_r=2)
def family_hash(s):
    """The same, through whether n is hashable like an int (n == 5)."""
    out = s.X.T @ s.P
    for _ in range(int(s.r)):
        out = out + 0 * s.X.T @ s.X
    try:
        fixed = s.n in {4, 5, 6}
    except Exception:
        fixed = False
    if fixed:
        return {"r": out}
    return {"r": out + s.P.T @ s.X}
