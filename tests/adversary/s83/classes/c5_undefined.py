"""Class 5/3: statements undefined on all of T*V (a division by z = tr(XᵀX) − tr(I_r), identically 0 on V), said to
vanish or not to vanish, beside a rank and a count; none is true or false: every method must answer error (or
undecided/inconclusive), never proved/checked/numeric/fails.

ud-inv-nz:   1/z does not vanish (expect nonzero)
ud-zz-nz:    z·(1/z) does not vanish
ud-zz-id:    z·(1/z) − 1 = 0
ud-zz-id2:   (z/z)·X − X = 0   (X ≠ 0)
ud-rank:     Rank((1/z)·I_r, r)
ud-rank-0:   Rank(z·(1/z)·I_r − I_r, 0)
ud-half:     w/w − 1 with w = tr(PᵀP)·z + tr(PᵀP) (= tr PᵀP on V: defined for P ≠ 0): TRUE (a control, defined
             almost everywhere): proved/checked/numeric
"""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


def _z(s):
    return s.tr(s.X.T @ s.X) - s.tr(s.Ir)


@claim("ud-inv-nz", kind="not", sizes=SZ, expect="nonzero")
def ud_inv_nz(s):
    return {"x": 1 / _z(s)}


@claim("ud-zz-nz", kind="not", sizes=SZ, expect="nonzero")
def ud_zz_nz(s):
    z = _z(s)
    return {"x": z * (1 / z)}


@claim("ud-zz-id", kind="id", sizes=SZ)
def ud_zz_id(s):
    z = _z(s)
    return {"x": z * (1 / z) - 1}


@claim("ud-zz-id2", kind="id", sizes=SZ)
def ud_zz_id2(s):
    z = _z(s)
    return {"x": (z / z) * s.X - s.X}


@claim("ud-rank", kind="dim", sizes=SZ)
def ud_rank(s):
    return {"rank": Rank((1 / _z(s)) * s.Ir, 2)}


@claim("ud-rank-0", kind="dim", sizes=SZ)
def ud_rank_0(s):
    z = _z(s)
    return {"rank": Rank(z * (1 / z) * s.Ir - s.Ir, 0)}


@claim("ud-half", kind="id", sizes=SZ)
def ud_half(s):
    t = s.tr(s.P.T @ s.P)
    w = t * _z(s) + t
    return {"x": w / w - 1}
