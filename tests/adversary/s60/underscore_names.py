"""Stop 60, own attempt on the underscore names the free scene now takes: names that differ only by an
underscore, that look like an entry parameter (S_1) or a transpose (G_T), and one name for a symmetric and a
skew generic.  Each claim is false: no method may pass it (test_adversary_s60.py)."""
from stiefelsym import admissible, claim, comm

@claim("fool-underscore-same-letter", paper="user", kind="id", sizes=admissible(n_max=3))
def a(s):
    """False: two generic matrices whose names differ by an underscore are equal."""
    return {"G - H": s.generic("eta_n", "n", "n", "sym") - s.generic("etan", "n", "n", "sym")}

@claim("fool-underscore-vs-entry", paper="user", kind="id", sizes=admissible(n_max=3))
def b(s):
    """False: a generic named like an entry parameter (S_1) equals the skew generic S."""
    return {"G - K": s.generic("S_1", "n", "n", "skew") - s.generic("S", "n", "n", "skew")}

@claim("fool-underscore-transpose", paper="user", kind="id", sizes=admissible(n_max=3))
def c(s):
    """False: a general generic named G_T is the transpose of G."""
    return {"G^T - G_T": s.generic("G", "n", "r").T - s.generic("G_T", "r", "n")}

@claim("fool-underscore-kinds", paper="user", kind="id", sizes=admissible(n_max=3))
def d(s):
    """False: the sym and skew generics of one underscored name commute with X X^T."""
    v = s.X @ s.X.T
    return {"[eta_n, v]": comm(s.generic("eta_n", "n", "n", "sym"), v),
            "[eta_n skew, v]": comm(s.generic("eta_n", "n", "n", "skew"), v)}
