"""Public-API tricks (classes 1, 2, 3, 5, 6), no frames, no engine internals.  Truths: by hand here and by
truth.py (numpy, no stiefelsym) at (2,2), (3,2), (4,2) unless said.

Class 1 (the chart from what a claim reads):
  pa-diagcomm-f  [D, X^T A X] = 0, D = diag(1, 2) a constant r x r matrix typed ("r","r").  FALSE: X^T A X is a
                 generic symmetric r x r matrix (off-diagonal entry nonzero).  True on the exact chart where A11 is
                 diagonal: a constant R^r matrix that is not a multiple of I must make the chart visible.
  pa-diagcomm2-f the same with D = I_r + e1 e1^T built from slices of s.Ir (s.Ir[:, :1]).  FALSE.
  pa-x0-f        tr(E^T X) - r = 0 with E = (I_r; 0) built as s.In[:, :r] (a slice of the identity).  FALSE
                 (tr(E^T X) = sum of X's top r x r diagonal, not constant).  True at X0.
  pa-idslice-f   e^T X X^T e - 1 = 0, e = s.In[:, :1], r = 1.  FALSE ((XX^T)_11 = X_11^2).  True at X0.
  pa-adiag-t     (A)_{12} = 0 read through e1^T A e2 with e = slices of s.In.  TRUE: A = diag(a).  (false refusal check)
  pa-adiag-f     e1^T A e1 - e2^T A e2 = 0.  FALSE (a1 != a2 generically).
Class 2 (numbers in disguise, refused or exact):
  pa-boolq-t     X * s.q(True, 3) * 3 - X = 0  TRUE if bool is read as 1 (or refused: honest).
  pa-fracsub-f   X * F(1, 3) - X * F(1, 2) with F a Fraction subclass whose numerator reads 1/2's.  FALSE as written
                 (= -X/6 for the real values).  Must be refused or fail.
  pa-npint-t     X * numpy.int64(3) - 3 X = 0  TRUE (or refused).
Class 3 (exceptions as a side channel):
  pa-exc-f       try: s.X @ s.X (refused unless r = n) except: residual X X^T - I_n; else X^T X - I_r.
                 Stated for r < n.  FALSE at r < n (the except branch is taken: X X^T - I_n).
Class 5 (float cancellation):
  pa-cancel-f    tr((X^TX + c I_r)^2) - r (1 + c)^2 - 1 = 0 with c = 2^30.  FALSE (= -1).  Float can't see it.
  pa-cancel-t    the same without the - 1.  TRUE.
  pa-tiny-f      (1 + 2^-80) X - X = 0.  FALSE (= 2^-80 X).
  pa-huge-t      2^600 * 2^600 * tr(X^T X) - r * 2^1200 = 0.  TRUE (float overflows: must not fail).
  pa-huge-f      the same minus 2^1190 (nonzero).  FALSE.
Class 6 (copies):
  pa-copy-f      copy.copy(X) and X mixed: copy.copy(X) @ X.T - I_n.  FALSE at r < n (refused is fine).
"""
import copy
from fractions import Fraction

import numpy

from stiefelsym import admissible, claim, comm

SZ2 = admissible(n_max=4, r_min=2, r_max=2)
SZ1 = admissible(n_max=3, r_max=1, where=lambda n, r: r < n)
SZ = admissible(n_max=3, where=lambda n, r: r < n)


@claim("pa-diagcomm-f", kind="id", sizes=SZ2)
def _dc(s):
    D = s.mat([[1, 0], [0, 2]], ("r", "r"))
    return {"c": comm(D, s.X.T @ s.A @ s.X)}


@claim("pa-diagcomm2-f", kind="id", sizes=SZ2)
def _dc2(s):
    e = s.Ir[:, :1]
    D = s.Ir + e @ e.T
    return {"c": comm(D, s.X.T @ s.A @ s.X)}


@claim("pa-x0-f", kind="id", sizes=SZ)
def _x0(s):
    E = s.In[:, :int(s.r)]
    return {"t": s.tr(E.T @ s.X) - s.tr(s.Ir)}


@claim("pa-idslice-f", kind="id", sizes=SZ1)
def _ids(s):
    e = s.In[:, :1]
    return {"t": s.tr(e.T @ s.X @ s.X.T @ e) - 1}


@claim("pa-adiag-t", kind="id", sizes=SZ2)
def _adt(s):
    e1, e2 = s.In[:, :1], s.In[:, 1:2]
    return {"t": s.tr(e1.T @ s.A @ e2)}


@claim("pa-adiag-f", kind="id", sizes=SZ2)
def _adf(s):
    e1, e2 = s.In[:, :1], s.In[:, 1:2]
    return {"t": s.tr(e1.T @ s.A @ e1) - s.tr(e2.T @ s.A @ e2)}


@claim("pa-boolq-t", kind="id", sizes=SZ)
def _bq(s):
    return {"x": s.X * s.q(True, 3) * 3 - s.X}


class _F(Fraction):
    @property
    def numerator(self):
        return 1

    @property
    def denominator(self):
        return 2


@claim("pa-fracsub-f", kind="id", sizes=SZ)
def _fs(s):
    return {"x": s.X * _F(1, 3) - s.X * Fraction(1, 2)}


@claim("pa-npint-t", kind="id", sizes=SZ)
def _np(s):
    return {"x": s.X * numpy.int64(3) - 3 * s.X}


@claim("pa-exc-f", kind="id", sizes=SZ)
def _exc(s):
    try:
        s.X @ s.X
    except Exception:       # noqa: BLE001
        return {"x": s.X @ s.X.T - s.In}
    return {"x": s.X.T @ s.X - s.Ir}


C = 2 ** 30


@claim("pa-cancel-f", kind="id", sizes=SZ)
def _cf(s):
    M = s.X.T @ s.X + C * s.Ir
    return {"t": s.tr(M @ M) - s.tr(s.Ir) * (1 + C) ** 2 - 1}


@claim("pa-cancel-t", kind="id", sizes=SZ)
def _ct(s):
    M = s.X.T @ s.X + C * s.Ir
    return {"t": s.tr(M @ M) - s.tr(s.Ir) * (1 + C) ** 2}


@claim("pa-tiny-f", kind="id", sizes=SZ)
def _tf(s):
    return {"x": (1 + Fraction(1, 2 ** 80)) * s.X - s.X}


@claim("pa-huge-t", kind="id", sizes=SZ)
def _ht(s):
    return {"t": 2 ** 600 * (2 ** 600 * s.tr(s.X.T @ s.X)) - s.tr(s.Ir) * 2 ** 1200}


@claim("pa-huge-f", kind="id", sizes=SZ)
def _hf(s):
    return {"t": 2 ** 600 * (2 ** 600 * s.tr(s.X.T @ s.X)) - s.tr(s.Ir) * 2 ** 1200 - 2 ** 1190}


@claim("pa-copy-f", kind="id", sizes=SZ)
def _cp(s):
    return {"x": copy.copy(s.X) @ s.X.T - s.In}
