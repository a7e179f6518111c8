"""Free method's division door: size poles hidden in a sum whose one group has one sign.

k = 1 - 2 tr(I_r)/(tr(I_n) + tr(I_r)) = (n - r)/(n + r): 0 at r = n.  The free divisor() accepts k since its
expanded form has a group (the constant 1) of one sign; so 1/k = (n + r)/(n - r) has a pole at r = n.

fp-hollow:    k * (1/k) - 1                (a 0/0 at r = n: fixed sizes say error there; "true" only where n > r)
fp-false:     (1/k) * (tr I_n - tr I_r) - (tr I_n + tr I_r)  -- equals 0 where n > r, undefined at r = n.
fp-false-X:   X^T X * (1/k) * k - I_r ... (true where defined)
fp-lt:        the same as fp-hollow stated where r < n (true; a natural control)
fp-cf:        continued fraction k2 = 1/(1 + 1/(n+r)) ... then 1 - k2*(n+r+1)/(n+r)   (0 identically: control)
fp-cf2:       k3 = 1 - r/(n + r) - n/(n+r)*... = (n - r)/(n + r) written as n/(n+r) - r/(n+r) (mixed signs: refused)
fp-lam:       k4 = lam*(n - r) + 1 - ... lambda groups: divisor accepted when the lambda-free group has one sign;
              k4 = lam + (n - r)/(n + r)*... nonzero as a polynomial in lam at every size: sound (control)
fp-r1:        k5 = 1 - 2/(r + 1) = (r - 1)/(r + 1): 0 at r = 1; residual 1/k5 * (r - 1) - (r + 1): hollow at r = 1
fp-r1-false:  X^T X * (1/k5)*(r - 1) - (r + 1) I_r ... at r = 1 undefined.

Truth: every residual is 0 as a rational function in n, r wherever its divisor is nonzero; at r = n (resp. r = 1)
the claim divides by 0 (fixed-size methods: error). A "proved for all n, r" is hollow there (the s82 H2 class).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _k(s):
    N, R = s.tr(s.In), s.tr(s.Ir)
    return 1 - 2 * R / (N + R)


@claim("fp-hollow", kind="id", sizes=SZ)
def fp_hollow(s):
    k = _k(s)
    return {"x": k * (1 / k) - 1}


@claim("fp-false", kind="id", sizes=SZ)
def fp_false(s):
    k = _k(s)
    N, R = s.tr(s.In), s.tr(s.Ir)
    return {"x": (1 / k) * (N - R) - (N + R)}


@claim("fp-lt", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def fp_lt(s):
    k = _k(s)
    return {"x": k * (1 / k) - 1}


@claim("fp-r1", kind="id", sizes=SZ)
def fp_r1(s):
    R = s.tr(s.Ir)
    k5 = 1 - 2 / (R + 1)
    return {"x": (1 / k5) * (R - 1) - (R + 1)}


@claim("fp-matrix", kind="id", sizes=SZ)
def fp_matrix(s):
    k = _k(s)
    return {"x": (s.X / k) * k - s.X}


@claim("fp-cf", kind="id", sizes=SZ)
def fp_cf(s):
    # continued fraction: 1/(1 - 1/(1 + (n+r)/(n-r)...)) built without 1/(n-r): c = 1/(1 - 2r/(n+r))
    N, R = s.tr(s.In), s.tr(s.Ir)
    c = 1 / (1 - 1 / (1 + (N - R) / (2 * R)))   # 1 + (n-r)/(2r) = (n+r)/(2r); 1 - 2r/(n+r) = (n-r)/(n+r)
    return {"x": c * (N - R) - (N + R)}


# stated at r = n only, where k = (n - r)/(n + r) is 0 at EVERY stated size: the free family r = n keeps r apart from n
@claim("fp-square-every", kind="id", sizes=admissible(n_max=3, r_is_n=True))
def fp_square_every(s):
    k = _k(s)
    return {"x": k * (1 / k) - 1}


# a pole at n = 4 only (k4 = (n - 4)/(n + 4) = 1 - 8/(n + 4)); the division probe looks at the first size with n >= 3
@claim("fp-n4", kind="id", sizes=admissible(n_max=4))
def fp_n4(s):
    N = s.tr(s.In)
    k4 = 1 - 8 / (N + 4)
    return {"x": s.X * k4 / k4 - s.X}


# a pole at n = 2r (k = (n - 2r)/(n + r) = 1 - 3r/(n + r)) inside a product with a real residual: X^T X - I_r
@claim("fp-n2r", kind="id", sizes=admissible(n_max=4))
def fp_n2r(s):
    N, R = s.tr(s.In), s.tr(s.Ir)
    k = 1 - 3 * R / (N + R)
    return {"x": (s.X.T @ s.X - s.Ir) / k}
