"""Stop 83 review (h2): errors inside cancelled or skipped products (brief item 4).  Each claim divides by an
identically zero matrix or number somewhere in y; the honest verdict is error (or undecided), never proved."""
from stiefelsym import admissible, claim, comm

S = admissible(n_min=3, n_max=3, r_min=2, r_max=2)


@claim("adv-s83r-e-pole-in-cancelled-sum", paper="adv", kind="id", sizes=S)
def pole_sum(s):
    """Undefined: Z = (0·M)⁻¹ is a factor of Z N − Z N (cancelled): tr(M (ΦA + ZN − ZN)) − tr(MΦA) has no value."""
    M, N = s.generic("M", "n", "n"), s.generic("N", "n", "n")
    Z = (M * 0).inv()
    return {"c": s.tr(M @ (s.Phi @ s.A + Z @ N - Z @ N)) - s.tr((M @ s.Phi) @ s.A)}


@claim("adv-s83r-e-pole-in-skipped-product", paper="adv", kind="id", sizes=S)
def pole_skipped(s):
    """Undefined: y = (N/0 ...) — the factor N·(1/(tr(N) − tr(N))) of a reassociated (not cancelled) product."""
    M, N = s.generic("M", "n", "n"), s.generic("N", "n", "n")
    c = 1 / (s.tr(N) - s.tr(N.T))
    W = N * c
    zs = [W, s.A, s.Phi, N]
    return {f"{i}{j}": s.tr(M @ comm(z, w)) + s.tr(M @ comm(w, z)) for i, z in enumerate(zs) for j, w in enumerate(zs)}


@claim("adv-s83r-e-pole-in-x", paper="adv", kind="id", sizes=S)
def pole_x(s):
    """Undefined: x = (0·M)⁻¹ with y = [N, N] (cancelled): tr(x [N, N]) has no value."""
    M, N = s.generic("M", "n", "n"), s.generic("N", "n", "n")
    x = (M * 0).inv()
    return {"c": s.tr(x @ comm(N, N))}


@claim("adv-s83r-e-pole-zero-times", paper="adv", kind="id", sizes=S)
def pole_zero_times(s):
    """Undefined: Z = (0·M)⁻¹ in y = ZN − ZN paired with x = 0·M (the pairing's x is zero)."""
    M, N = s.generic("M", "n", "n"), s.generic("N", "n", "n")
    Z = (M * 0).inv()
    return {"c": s.tr((M * 0) @ (Z @ N - Z @ N))}
