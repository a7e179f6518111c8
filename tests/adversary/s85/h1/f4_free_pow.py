"""Free method: negative powers and reciprocals of size expressions (the pow route of the evaluator).

fw-pow-nr     (n − r)**(−1)·(n − r) − 1           hollow at r = n (0/0): should be refused like 1/(n − r)
fw-pow-k      k**(−1)·k − 1, k = 1 − 2r/(n + r)   hollow at r = n (the F1 route, by pow)
fw-pow-k2     k**(−2)·k·k − 1                     hollow at r = n
fw-pow-n      (n + r)**(−2)·(n + r)² − 1          TRUE everywhere (control)
fw-inv-lam    X·λ**(−1)·λ − X                      TRUE (λ generic)
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _nr(s):
    return s.tr(s.In) - s.tr(s.Ir)


def _k(s):
    N, R = s.tr(s.In), s.tr(s.Ir)
    return 1 - 2 * R / (N + R)


@claim("fw-pow-nr", kind="id", sizes=SZ)
def pow_nr(s):
    d = _nr(s)
    return {"x": d ** -1 * d - 1}


@claim("fw-pow-k", kind="id", sizes=SZ)
def pow_k(s):
    k = _k(s)
    return {"x": k ** -1 * k - 1}


@claim("fw-pow-k2", kind="id", sizes=SZ)
def pow_k2(s):
    k = _k(s)
    return {"x": k ** -2 * k * k - 1}


@claim("fw-pow-n", kind="id", sizes=SZ)
def pow_n(s):
    d = s.tr(s.In) + s.tr(s.Ir)
    return {"x": d ** -2 * d * d - 1}


@claim("fw-inv-lam", kind="id", sizes=SZ)
def inv_lam(s):
    return {"x": s.X * s.lam ** -1 * s.lam - s.X}
