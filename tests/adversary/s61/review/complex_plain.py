"""The complex point reduced by U(r): statements that are not U(r)-covariant (plain transposes, traces of
Z^T Z), each FALSE for a generic unitary frame Z."""
from stiefelsym import admissible, claim
from stiefelsym.systems import complex_point, ctranspose, re_trace

SZ = admissible(n_max=3, n_min=2)


@claim("cp-ztz", paper="t", kind="id", section="A2", sizes=SZ)
def cp1(s):
    """FALSE: Z^T Z = I_r (plain transpose)."""
    Z = complex_point(s)["Z"]
    return {"r": ctranspose(s, Z) @ Z - s.identity(2 * s.r)}


@claim("cp-tr-ztz", paper="t", kind="id", section="A2", sizes=SZ)
def cp2(s):
    """FALSE: Re tr(Z^T Z) = r."""
    Z = complex_point(s)["Z"]
    return {"r": re_trace(s, ctranspose(s, Z) @ Z) - s.tr(s.Ir)}


@claim("cp-zzt-sq", paper="t", kind="id", section="A2", sizes=SZ)
def cp3(s):
    """FALSE: (Z Z^T)(conj Z conj Z^T)... = Z Z*: a plain and a conjugate product."""
    Z = complex_point(s)["Z"]
    M = Z @ ctranspose(s, Z)
    return {"r": M @ s.conj(M) - Z @ Z.T}


@claim("cp-conj-ident", paper="t", kind="id", section="A2", sizes=SZ)
def cp4(s):
    """FALSE: conj(Z)^T Z = I? no: Z^T conj(Z)... Z* Z = I written as conj(Z).T @ conj(Z)."""
    Z = complex_point(s)["Z"]
    return {"r": s.conj(Z).T @ s.conj(Z) - s.identity(2 * s.r) + ctranspose(s, Z) @ Z - s.identity(2 * s.r)}
