"""The complex point of W(n, r), realified: identities true at r = n only, and their twins."""
from stiefelsym import admissible, claim


@claim("s73-cplx-square-all-r", kind="id", sizes=admissible(n_max=3))
def cplx_square_all_r(s):
    """Z Z^* = I_n (realified Zc Zc^T = I_2n) at every r: FALSE for r < n, TRUE at r = n."""
    Z = s.Zc
    return {"ZZ*": Z @ Z.T - s.identity(2 * s.n, "n+n")}


@claim("s73-cplx-square", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r == n, condition="r = n"))
def cplx_square(s):
    """Z Z^* = I_n at r = n: TRUE (a unitary matrix)."""
    Z = s.Zc
    return {"ZZ*": Z @ Z.T - s.identity(2 * s.n, "n+n")}


@claim("s73-cplx-tangent-sym", kind="id", sizes=admissible(n_max=3))
def cplx_tangent_sym(s):
    """Z^T V + V^T Z = 0 for the realified point Z and tangent V: TRUE (realified Z^*V + V^*Z = 0)."""
    Z, V = s.Zc, s.Zc_dot
    return {"tangent": Z.T @ V + V.T @ Z}


@claim("s73-cplx-tangent-conj", kind="id", sizes=admissible(n_max=3, r_min=1))
def cplx_tangent_conj(s):
    """conj(Z)^T V + conj(V)^T Z = 0 (i.e. Z^T V + V^T Z = 0 over C): FALSE in general."""
    Z, V = s.Zc, s.Zc_dot
    return {"tangent": s.conj(Z).T @ V + s.conj(V).T @ Z}


@claim("s73-cplx-trace-real", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r == n, condition="r = n"))
def cplx_trace_real(s):
    """Im tr Z = 0 at r = n: FALSE (tr of a unitary matrix is complex). Realified: tr(J Zc) = -2 Im tr Z."""
    J = s.conj(s.identity(2 * s.n, "n+n"))    # noqa: F841 - diag(I, -I): not i; use the block [[0,-I],[I,0]] below
    Z = s.Zc
    from stiefelsym import block
    Iz = s.identity(s.n, "n")
    O = s.zeros(s.n, s.n, ("n", "n"))
    Jc = block([[O, -Iz], [Iz, O]])
    return {"Im tr Z": (Jc @ Z).trace()}
