"""Batch 11: s.conj (complex conjugate of a realified matrix) on block matrices that are not realified (n + r
spaces), on the free scene and at fixed sizes.  conj negates the off-diagonal blocks (J M J).

  b11-conj-nr        conj(conj(M)) - M = 0 for M = [[X Xt, X], [Xt, Ir]] (spaces n + r)       refused at fixed sizes (TypeError)
  b11-conj-nr-false  conj(M) - M = 0 for the same M                                            refused at fixed sizes; false as J M J != M
  b11-conj-nn-true   conj(conj(M)) - M for M = [[X Xt, A], [A, In]] (n + n)                      TRUE
"""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=4)


@claim("b11-conj-nr", kind="id", sizes=SZ)
def conj_nr(s):
    M = block([[s.X @ s.X.T, s.X], [s.X.T, s.Ir]])
    return {"cc": s.conj(s.conj(M)) - M}


@claim("b11-conj-nr-false", kind="id", sizes=SZ)
def conj_nr_false(s):
    M = block([[s.X @ s.X.T, s.X], [s.X.T, s.Ir]])
    return {"c": s.conj(M) - M}


@claim("b11-conj-nn-true", kind="id", sizes=SZ)
def conj_nn(s):
    M = block([[s.X @ s.X.T, s.A], [s.A, s.In]])
    return {"cc": s.conj(s.conj(M)) - M}
