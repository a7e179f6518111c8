"""Public-API tricks, batch 2 (classes 1, 2, 5).  Truths by hand and truth.py (numpy, no stiefelsym).

  pb-x0block-f   tr(X0^T X) - r = 0, X0 = block([[I_r], [zeros(n-r, r) typed ("n-r","r")]]).  FALSE (tr of X's top
                 block is not constant); true at X0 only.
  pb-dir-f       the derivative of t -> tr(t.X^T t.X X0-ish) along {"X": E} with E = s.In[:, :r] (a constant
                 direction built from coordinates): d/dt tr(X^T X) along X' = E is 2 tr(E^T X); claim 2 tr(E^T X) - 2r = 0.
                 FALSE (true at X0 only).
  pb-underflow-t (c A) @ (X / c) - A @ X = 0 with c = 2^-1100.  TRUE (float: c A underflows, X/c overflows).
  pb-underflow-f the same minus c X.  FALSE (c X != 0).
  pb-chain-t     ((X * 2^-1074) * 2^-1074) * 2^2148 - X = 0.  TRUE.
  pb-fromfloat-f X * Fraction.from_float(0.1) - X / 10 = 0.  FALSE: Fraction(0.1) = 3602879701896397/2^55 != 1/10.
  pb-fromfloat-t X * Fraction.from_float(0.1) - X * 3602879701896397 / 2^55 = 0.  TRUE.
  pb-boolmul-t   X * True - X = 0.  TRUE if bool is 1; a refusal is honest.
  pb-xi-f        comm(xi, X X^T) = 0 at r = 1 with xi generic in so(n).  FALSE.  (control)
  pb-sym-f       tr(X^T A X) - tr(A) r / n = 0.  FALSE (control: no coordinates read).
"""
from fractions import Fraction

from stiefelsym import admissible, block, claim, comm

SZ = admissible(n_max=4, where=lambda n, r: r < n)


@claim("pb-x0block-f", kind="id", sizes=SZ)
def _x0b(s):
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    return {"t": s.tr(X0.T @ s.X) - s.tr(s.Ir)}


@claim("pb-dir-f", kind="id", sizes=SZ)
def _dir(s):
    E = s.In[:, :int(s.r)]
    d = s.d(lambda t: t.tr(t.X.T @ t.X), {"X": E})
    return {"t": d - 2 * s.tr(s.Ir)}


C = Fraction(1, 2 ** 1100)


@claim("pb-underflow-t", kind="id", sizes=SZ)
def _uf_t(s):
    return {"x": (C * s.A) @ (s.X / C) - s.A @ s.X}


@claim("pb-underflow-f", kind="id", sizes=SZ)
def _uf_f(s):
    return {"x": (C * s.A) @ (s.X / C) - s.A @ s.X - C * s.X}


@claim("pb-chain-t", kind="id", sizes=SZ)
def _ch(s):
    return {"x": ((s.X * Fraction(1, 2 ** 1074)) * Fraction(1, 2 ** 1074)) * 2 ** 2148 - s.X}


@claim("pb-fromfloat-f", kind="id", sizes=SZ)
def _ff_f(s):
    return {"x": s.X * Fraction.from_float(0.1) - s.X / 10}


@claim("pb-fromfloat-t", kind="id", sizes=SZ)
def _ff_t(s):
    return {"x": s.X * Fraction.from_float(0.1) - s.X * Fraction(3602879701896397, 2 ** 55)}


@claim("pb-boolmul-t", kind="id", sizes=SZ)
def _bm(s):
    return {"x": s.X * True - s.X}


@claim("pb-xi-f", kind="id", sizes=admissible(n_max=4, r_max=1, where=lambda n, r: n > 2))
def _xi(s):
    return {"c": comm(s.xi, s.X @ s.X.T)}


@claim("pb-sym-f", kind="id", sizes=SZ)
def _sy(s):
    return {"t": s.tr(s.X.T @ s.A @ s.X) * s.n - s.tr(s.A) * s.r}
