"""Stop 84's own, after the review: false claims through the free scene's new divisions (FreeField.reciprocal, the
door's test at n = 1 + e + d, r = 1 + e).  Every one is false at every stated size; no method may pass it.

s84-rec-shift:   X/(λ + n)·(λ + n + 1) − X = X/(λ + n) ≠ 0.
s84-rec-square:  X/((n − r)² + 1) − X: the divisor is never 0 (accepted), the claim is false wherever n > r.
s84-rec-pole:    X/(n − r)·(n − r) − X written with a nonzero shift in a second term: (1/(n − r + 1) − 1/(n − r))
                 as a divisor, which is 1/((n − r)(n − r + 1))'s negative: a pole at r = n (refused under free).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


@claim("s84-rec-shift", kind="id", sizes=SZ, expect="fails", erratum="written false on purpose (a twin)")
def rec_shift(s):
    k = s.lam + s.tr(s.In)
    return {"x": s.X / k * (k + 1) - s.X}


@claim("s84-rec-square", kind="id", sizes=SZ, expect="fails", erratum="written false on purpose (a twin)")
def rec_square(s):
    d = s.tr(s.In) - s.tr(s.Ir)
    return {"x": s.X / (d * d + 1) - s.X}


@claim("s84-rec-pole", kind="id", sizes=SZ, expect="fails", erratum="written false on purpose (a twin)")
def rec_pole(s):
    d = s.tr(s.In) - s.tr(s.Ir)
    k = 1 / (d + 1) - 1 / d
    return {"x": s.X / k * k - s.X + s.X}
