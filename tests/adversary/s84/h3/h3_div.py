"""h3 (stop 84): divisions on the free scene through the new door (algebra.divisor, FreeField.reciprocal).

Notation: n = tr I_n, r = tr I_r (traced sizes), lam = s.lam (generic), w = tr(P^T P), c = s.scalar("c").
Sizes: 1 <= r <= n <= 3 unless said.  "TRUE" = holds and is well defined at every stated size (generic
parameters); "UNDEF" = 0/0 at some stated size (an `error` at fixed sizes), so no `proved` for all n, r.

h3-a-lamn-lamr     k = (lam + n)(lam - r); X/k*k - X.  TRUE (k is a nonzero polynomial in lam at every size).
h3-a-lamn-lamr-f   X/k - X with the same k.  FALSE.
h3-a-nr1           k = n - r + 1 (>= 1 on n >= r); (1/k)*k - 1.  TRUE.  (The one-sign test refuses: an F at most.)
h3-a-2nr           k = 2n - r (>= 1).  TRUE (refusal expected).
h3-a-quad          k = n^2 - n r + r^2 (>= 1, mixed signs).  TRUE (refusal expected).
h3-a-cancel-num    k = (n*n - r*r)/(n + r) = n - r; (1/k)*k - 1.  UNDEF at r = n.
h3-a-lampole       k = 1/(lam + n) - 1/(lam + r) = (r - n)/((lam+n)(lam+r)); (1/k)*k*w - w.  UNDEF at r = n.
h3-a-lampole2      k = lam/(lam + n) - lam/(lam + r); (1/k)*k - 1.  UNDEF at r = n (numerator lam (r - n)).
h3-a-lamcubic      k = 1/(lam + n) - 1/(lam + r) + lam; (1/k)*k - 1.  TRUE (numerator has lam^3 with coefficient 1).
h3-a-lamcubic-f    (1/k) * k - lam.  FALSE.
h3-a-mixsame       k = lam (n - r) + lam^2 (n - r); (1/k)*k - 1.  UNDEF at r = n (k = 0 for every lam).
h3-a-pow60         k = (n + r)^60; X/k*k - X.  TRUE.
h3-a-pow60-f       X/k*k - 2X.  FALSE.
h3-a-negpow        ((n - r + 1)^-3)*(n - r + 1)^3 - 1.  TRUE (refusal expected).
h3-a-negpow-nr     ((n*n - r*r)^-2)*(n*n - r*r)^2 - 1.  UNDEF at r = n.
h3-a-c             c generic; k = c + n; P/k*k - P.  TRUE.
h3-a-c-nr          k = c (n - r) + c^2 (n - r)... = c(c+1)(n - r); P/k*k - P.  UNDEF at r = n.
h3-a-kappa-eps     k = kappa*eps + n - r; (1/k)*k*w - w.  TRUE (generic kappa, eps).
h3-a-kappa-eps-nr  k = kappa*eps*(n - r) ; (1/k)*k*w - w.  UNDEF at r = n.
h3-a-half          X/2 + X/2 - X and P/(n + r) * (n + r) - P and X/(lam + n) ... combined in one dict.  TRUE.
h3-a-nested        k = 1/(1/n + 1/r) = nr/(n + r); X/k*k - X.  TRUE.
h3-a-nested-nr     k = 1/(1/n - 1/(n + r)) ... = n(n+r)/r ; X/k - X*(r/(n*(n+r))) .  TRUE.
h3-a-trq           k = s.q(1,2)*n + s.q(1,3)*r; X/k*k - X.  TRUE.
h3-a-rminus1-lam   k = (r - 1)*lam + (r - 1); (1/k)*k - 1.  UNDEF at r = 1.
h3-a-zero-rat-lam  k = 1/(lam+n) - 1/(lam+n+1) - 1/((lam+n)(lam+n+1)) = 0 identically; (1/k)*k*w - w.  UNDEF
                   (division by 0 at every size: `error` everywhere).
"""

from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
SZ4 = admissible(n_max=4)


def _n(s):
    return s.tr(s.In)


def _r(s):
    return s.tr(s.Ir)


def _w(s):
    return s.tr(s.P.T @ s.P)


@claim("h3-a-lamn-lamr", kind="id", sizes=SZ)
def a1(s):
    k = (s.lam + _n(s)) * (s.lam - _r(s))
    return {"x": s.X / k * k - s.X}


@claim("h3-a-lamn-lamr-f", kind="id", sizes=SZ)
def a1f(s):
    k = (s.lam + _n(s)) * (s.lam - _r(s))
    return {"x": s.X / k - s.X}


@claim("h3-a-nr1", kind="id", sizes=SZ)
def a2(s):
    k = _n(s) - _r(s) + 1
    return {"x": (1 / k) * k - 1}


@claim("h3-a-2nr", kind="id", sizes=SZ)
def a3(s):
    k = 2 * _n(s) - _r(s)
    return {"x": s.P / k * k - s.P}


@claim("h3-a-quad", kind="id", sizes=SZ)
def a4(s):
    n, r = _n(s), _r(s)
    k = n * n - n * r + r * r
    return {"x": (1 / k) * k - 1}


@claim("h3-a-cancel-num", kind="id", sizes=SZ)
def a5(s):
    n, r = _n(s), _r(s)
    k = (n * n - r * r) / (n + r)
    return {"x": (1 / k) * k - 1}


@claim("h3-a-lampole", kind="id", sizes=SZ)
def a6(s):
    n, r, lam = _n(s), _r(s), s.lam
    k = 1 / (lam + n) - 1 / (lam + r)
    return {"x": (1 / k) * k * _w(s) - _w(s)}


@claim("h3-a-lampole2", kind="id", sizes=SZ)
def a7(s):
    n, r, lam = _n(s), _r(s), s.lam
    k = lam / (lam + n) - lam / (lam + r)
    return {"x": (1 / k) * k - 1}


@claim("h3-a-lamcubic", kind="id", sizes=SZ)
def a8(s):
    n, r, lam = _n(s), _r(s), s.lam
    k = 1 / (lam + n) - 1 / (lam + r) + lam
    return {"x": (1 / k) * k - 1}


@claim("h3-a-lamcubic-f", kind="id", sizes=SZ)
def a8f(s):
    n, r, lam = _n(s), _r(s), s.lam
    k = 1 / (lam + n) - 1 / (lam + r) + lam
    return {"x": (1 / k) * k - lam}


@claim("h3-a-mixsame", kind="id", sizes=SZ)
def a9(s):
    n, r, lam = _n(s), _r(s), s.lam
    k = lam * (n - r) + lam * lam * (n - r)
    return {"x": (1 / k) * k - 1}


@claim("h3-a-pow60", kind="id", sizes=SZ)
def a10(s):
    k = (_n(s) + _r(s)) ** 60
    return {"x": s.X / k * k - s.X}


@claim("h3-a-pow60-f", kind="id", sizes=SZ)
def a10f(s):
    k = (_n(s) + _r(s)) ** 60
    return {"x": s.X / k * k - 2 * s.X}


@claim("h3-a-negpow", kind="id", sizes=SZ)
def a11(s):
    k = _n(s) - _r(s) + 1
    return {"x": (k ** -3) * k ** 3 - 1}


@claim("h3-a-negpow-nr", kind="id", sizes=SZ)
def a12(s):
    n, r = _n(s), _r(s)
    k = n * n - r * r
    return {"x": (k ** -2) * k ** 2 - 1}


@claim("h3-a-c", kind="id", sizes=SZ)
def a13(s):
    c = s.scalar("c")
    k = c + _n(s)
    return {"x": s.P / k * k - s.P}


@claim("h3-a-c-nr", kind="id", sizes=SZ)
def a14(s):
    c = s.scalar("c")
    n, r = _n(s), _r(s)
    k = c * (n - r) + c * c * (n - r)
    return {"x": s.P / k * k - s.P}


@claim("h3-a-kappa-eps", kind="id", sizes=SZ)
def a15(s):
    k = s.kappa * s.eps + _n(s) - _r(s)
    return {"x": (1 / k) * k * _w(s) - _w(s)}


@claim("h3-a-kappa-eps-nr", kind="id", sizes=SZ)
def a16(s):
    k = s.kappa * s.eps * (_n(s) - _r(s))
    return {"x": (1 / k) * k * _w(s) - _w(s)}


@claim("h3-a-half", kind="id", sizes=SZ)
def a17(s):
    n, r, lam = _n(s), _r(s), s.lam
    return {"half": s.X / 2 + s.X / 2 - s.X,
            "n+r": s.P / (n + r) * (n + r) - s.P,
            "lam+n": (s.X / (lam + n)) * lam + s.X * (n / (lam + n)) - s.X,
            "n": s.tr(s.X.T @ s.X) / n - r / n}


@claim("h3-a-nested", kind="id", sizes=SZ)
def a18(s):
    n, r = _n(s), _r(s)
    k = 1 / (1 / n + 1 / r)
    return {"x": s.X / k * k - s.X}


@claim("h3-a-nested-nr", kind="id", sizes=SZ)
def a19(s):
    n, r = _n(s), _r(s)
    k = 1 / (1 / n - 1 / (n + r))
    return {"x": s.X / k - s.X * (r / (n * (n + r)))}


@claim("h3-a-trq", kind="id", sizes=SZ)
def a20(s):
    n, r = _n(s), _r(s)
    k = s.q(1, 2) * n + s.q(1, 3) * r
    return {"x": s.X / k * k - s.X}


@claim("h3-a-rminus1-lam", kind="id", sizes=SZ)
def a21(s):
    r, lam = _r(s), s.lam
    k = (r - 1) * lam + (r - 1)
    return {"x": (1 / k) * k - 1}


@claim("h3-a-zero-rat-lam", kind="id", sizes=SZ)
def a22(s):
    n, lam = _n(s), s.lam
    k = 1 / (lam + n) - 1 / (lam + n + 1) - 1 / ((lam + n) * (lam + n + 1))
    return {"x": (1 / k) * k * _w(s) - _w(s)}
