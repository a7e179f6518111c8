"""A scalar that vanishes at one of the claim's sizes (n = 4) divides a residual: the free algebra's
coefficients are rational functions of n, so c^2 / c - c is 0 for every n, and the division probe
looks at one size only (the first with n >= 3, here (3,1)), where c = -1.  At n = 4 the claim is
0/0: the exact method says fails (nan), the modular method inconclusive (every point a pole)."""
from stiefelsym import admissible, claim


@claim("adv-pole-n4", kind="id", sizes=admissible(n_max=5), statement="c^2 / c = c for c = tr(I_n) - 4")
def pole_n4(s):
    """Undefined at n = 4, one of the claim's sizes."""
    c = s.tr(s.In) - 4
    return {"r": (c * c) / c - c}


@claim("adv-pole-n4-phi", kind="id", sizes=admissible(n_max=5), statement="(c Phi) / c = Phi for c = tr(I_n) - 4")
def pole_n4_phi(s):
    """Undefined at n = 4, one of the claim's sizes."""
    c = s.tr(s.In) - 4
    return {"r": s.Phi * (c / c) - s.Phi}


@claim("adv-pole-r-eq-n", kind="id", sizes=admissible(n_max=5), statement="X (c / c) = X for c = tr(I_n) - tr(I_r)")
def pole_r_eq_n(s):
    """Undefined at every r = n among the claim's sizes; the probe's size (3,1) has c = 2."""
    c = s.tr(s.In) - s.tr(s.Ir)
    return {"r": s.X * (c / c) - s.X}
