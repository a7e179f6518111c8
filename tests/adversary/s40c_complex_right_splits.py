"""Round 13, the complex point reduced by U(r) on the right (S11 = 0; Z = I at r = n): reads of C^r that the pass
`methods/complex_right.unitary_right_breaks` let through, written with the public API.

* LA: block matrices joined part by part whatever the parts' sizes.  F = [[Z, Z], [Z, Z]] has its columns split
  (2r, 2r), both moving with R(h); a picker [[1], [0]] split (1, 4r - 1), or a row picker split (i, 1, ...), is joined
  to F part by part, so F·picker (one column of the realified Z, not covariant) was typed as moving with R(h), and
  an entry of Z squared as a number.  On the reduced chart the top r x r block of Z is Hermitian (Z = I at r = n):
  (Im z11)^2 = 0 and (Re z11)^2 = 1 hold there only.
The true control (|z1|^2 = 1 through the same blocks, aligned) is covariant and proved."""
from stiefelsym import Size, SizeSpec, block, claim

SQ = SizeSpec((Size(2, 2), Size(3, 3)), n_min=2, n_max=3, r_is_n=True)
LOW = SizeSpec((Size(3, 2), Size(4, 3)), n_min=3, n_max=4, r_min=2, r_max=3)


def _entry(s, i, j):
    """The realified entry (i, j) of Z as a 1 x 1 matrix, through block pickers whose parts do not align."""
    Z = s.Zc
    n, r = s.n, s.r
    F = block([[Z, Z], [Z, Z], [Z, Z]])                                   # 6n x 4r, rows (2n, 2n, 2n), cols (2r, 2r)
    if i == 0:
        rows = block([[s.identity(1), s.zeros(1, 1), s.zeros(1, 6 * n - 2)]])       # parts (1, 1, 6n - 2)
    else:
        rows = block([[s.zeros(1, i), s.identity(1), s.zeros(1, 6 * n - i - 1)]])   # parts (i, 1, 6n - i - 1)
    cols = block([[s.identity(1)], [s.zeros(4 * r - 1, 1)]])                 # parts (1, 4r - 1); j = 0
    return rows @ F @ cols


@claim("adv-s40c-re-z11-square", paper="adv", kind="id", sizes=SQ)
def re_z11_is_one(s):
    """False: (Re z11)^2 = 1 at r = n (true at Z = I, the reduced chart; Z = e^{i t} I gives cos^2 t) (LA)."""
    x = _entry(s, 0, 0)
    return {"(Re z11)^2 - 1": (x.T @ x).trace() - 1}


@claim("adv-s40c-im-z11", paper="adv", kind="id", sizes=LOW)
def im_z11_is_zero(s):
    """False: Im z11 = 0 (the top r x r block of Z Hermitian on the chart S11 = 0; not at Z h) (LA)."""
    x = _entry(s, s.n, 0)
    return {"(Im z11)^2": (x.T @ x).trace()}


@claim("adv-s40c-im-z11-square", paper="adv", kind="id", sizes=SQ)
def im_z11_is_zero_sq(s):
    """False: Im z11 = 0 at r = n (Z = I on the chart) (LA)."""
    x = _entry(s, s.n, 0)
    return {"(Im z11)^2": (x.T @ x).trace()}


def _aligned_columns(s):
    """[Z; Z; Z] through the same stacked F and a picker split (2r, 2r) as F's columns: covariant."""
    Z = s.Zc
    F = block([[Z, Z], [Z, Z], [Z, Z]])
    two_r = 2 * s.r
    return F @ block([[s.identity(two_r)], [s.zeros(two_r, two_r)]])


@claim("adv-s40c-aligned-true", paper="adv", kind="id", sizes=SizeSpec((Size(2, 2), Size(3, 2), Size(3, 3), Size(4, 3)),
                                                                       n_min=2, n_max=4, r_min=2, r_max=3))
def aligned_true(s):
    """True: [Z; Z; Z]*[Z; Z; Z] = 3 Z*Z = 3 I_r, so its real trace is 6r (the parts aligned: the chart applies)."""
    x = _aligned_columns(s)
    return {"tr - 6r": (x.T @ x).trace() - 6 * s.r}
