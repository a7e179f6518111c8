# ruff: noqa
"""Class 4 (state across calls): a claim whose graph depends on whether another claim of the file was traced
before it in the same interpreter (a module-level list), and a function that counts its own calls."""
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))
SEEN = []


@claim("c4-a-writer", kind="id", sizes=S)
def writer(s):
    """true: X^T X = I."""
    SEEN.append(1)
    return {"x": s.X.T @ s.X - s.Ir}


@claim("c4-b-reader", kind="id", sizes=S)
def reader(s):
    """as written: X^T X = I when c4-a-writer ran before in this interpreter, X = 0 otherwise."""
    if SEEN:
        return {"x": s.X.T @ s.X - s.Ir}
    return {"x": s.X}


CALLS = [0]


def H(t):
    CALLS[0] += 1
    if CALLS[0] % 3 == 0:
        return t.tr(t.P.T @ t.P)          # a different Hamiltonian on every third call
    return t.tr(t.X.T @ t.A @ t.X)


@claim("c4-counting-H", kind="pb", sizes=S)
def counting(s):
    """{H, H} = 0 and dH/dt along X_H = 0 for H traced several times: true for any single H."""
    fl = s.dirac_flow(H)
    return {"{H,H}": s.bracket(H, H), "dH(X_H)": s.d(H, fl), "dH(X_H) again": s.d(H, s.dirac_flow(H))}
