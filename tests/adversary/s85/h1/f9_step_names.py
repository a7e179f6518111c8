"""Free method's door for divisors (free.algebra.divisor): it writes the sizes as n = 1 + e + d, r = 1 + e in two
symbols named "stiefelsym_size_step_d", "stiefelsym_size_step_e" (plain symengine Symbols, by name) and tests the
result.  A claim's scalar parameter with the same name (s.scalar(name)) might be the same symbol there.

q = (n − r)/c with c = s.scalar("stiefelsym_size_step_d"): q is 0 at r = n whatever c is (every fixed-size method:
a division by an identically zero expression at r = n); the door would see q = d/d = 1.

st-hollow    q·(1/q) − 1 = 0               0/0 at r = n: not a statement for every n, r (fixed sizes: error at r = n)
st-mat       X·(1/q)·q − X = 0             the same
st-e-r1      q1 = (r − 1)/c, c named "stiefelsym_size_step_e": q1·(1/q1) − 1   0/0 at r = 1
st-ctrl      c named "c": (n − r)/c, the same residual: refused by the door (control)
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _q(s, name):
    c = s.scalar(name)
    return (s.tr(s.In) - s.tr(s.Ir)) / c


@claim("st-hollow", kind="id", sizes=SZ)
def st_hollow(s):
    q = _q(s, "stiefelsym_size_step_d")
    return {"x": q * (1 / q) - 1}


@claim("st-mat", kind="id", sizes=SZ)
def st_mat(s):
    q = _q(s, "stiefelsym_size_step_d")
    return {"x": s.X * (1 / q) * q - s.X}


@claim("st-e-r1", kind="id", sizes=SZ)
def st_e_r1(s):
    c = s.scalar("stiefelsym_size_step_e")
    q1 = (s.tr(s.Ir) - 1) / c
    return {"x": q1 * (1 / q1) - 1}


@claim("st-ctrl", kind="id", sizes=SZ)
def st_ctrl(s):
    q = _q(s, "c")
    return {"x": q * (1 / q) - 1}
