"""Batch 9: residuals on the (r - 1)-dimensional object of E_<r (twisted.leading_basis_vectors), empty at r = 1.

  b9-lead-gram        E_<r^T E_<r - I_{r-1} = 0     ((r-1) x (r-1))     TRUE where r >= 2; EMPTY (vacuous) at r = 1
  b9-lead-gram-false  E_<r^T E_<r - 2 I_{r-1} = 0                       FALSE at r >= 2, empty at r = 1
  b9-lead-er          E_<r^T E_r = 0                ((r-1) x 1)         TRUE where r >= 2; empty at r = 1
"""
from stiefelsym import admissible, claim, twisted

SZ = admissible(n_max=4)


@claim("b9-lead-gram", kind="id", sizes=SZ)
def lead_gram(s):
    L = twisted.leading_basis_vectors(s)
    G = L.T @ L
    return {"LtL - I": G - G @ G}


@claim("b9-lead-gram-false", kind="id", sizes=SZ)
def lead_gram_false(s):
    L = twisted.leading_basis_vectors(s)
    G = L.T @ L
    return {"LtL - 2I": G - G @ G * 2}


@claim("b9-lead-er", kind="id", sizes=SZ)
def lead_er(s):
    L, E = twisted.leading_basis_vectors(s), twisted.last_basis_vector(s)
    return {"LtEr": L.T @ E}
