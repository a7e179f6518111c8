# ruff: noqa
"""Constant steps of `twisted` (the reflection S_1, the projector D = diag(I_2, 0), the blocks of R^r, the
annihilator K of W, the last column E_r): statements whose truth depends on the fixed-size matrix the step is
(S_1 commutes with A only while A is diagonal), against the letter of the dimension-free algebra (only its
rules), and against the exact method's equivariant chart (A not diagonal there)."""
from stiefelsym import admissible, claim, twisted


@claim("cs-sa-as", kind="id", sizes=admissible(n_max=4))
def sa_as(s):
    """S_1 A = A S_1 (true: A diagonal)."""
    S = twisted.reflection(s)
    return {"SA-AS": S @ s.A - s.A @ S}


@claim("cs-sx-false", kind="id", sizes=admissible(n_max=4))
def sx_false(s):
    """X^T S_1 X = X^T X (false: S_1 flips the first coordinate)."""
    S = twisted.reflection(s)
    return {"XtSX-XtX": s.X.T @ S @ s.X - s.X.T @ s.X}


@claim("cs-trS", kind="id", sizes=admissible(n_max=4))
def trS(s):
    """tr S_1 = n - 2 (true at fixed sizes)."""
    S = twisted.reflection(s)
    return {"trS": s.tr(S) - s.tr(s.In) + 2}


@claim("cs-DA", kind="id", sizes=admissible(n_max=4, n_min=2))
def DA(s):
    """D A = A D for D = diag(I_2, 0) (true: A diagonal)."""
    D = twisted.eigenspace_projector(s)
    return {"DA-AD": D @ s.A - s.A @ D}


@claim("cs-trD", kind="id", sizes=admissible(n_max=4, n_min=2))
def trD(s):
    """tr D = 2 for D = diag(I_2, 0), n >= 2 (true)."""
    D = twisted.eigenspace_projector(s)
    return {"trD-2": s.tr(D) - 2}


@claim("cs-trD-n1", kind="id", sizes=admissible(n_max=4))
def trD_n1(s):
    """tr D = 2 for D = diag(I_2, 0), at every n >= 1 (false at n = 1: D = (1))."""
    D = twisted.eigenspace_projector(s)
    return {"trD-2": s.tr(D) - 2}


@claim("cs-blocks", kind="id", sizes=admissible(n_max=4))
def blocks(s):
    """D + C = I_r for the blocks of R^r (true at fixed sizes)."""
    D, C = twisted.block_projector(s, 0), twisted.block_projector(s, 1)
    return {"D+C-I": D + C - s.Ir}


@claim("cs-blocks-C0", kind="id", sizes=admissible(n_max=4))
def blocks_c0(s):
    """C = 0 (false at r >= 2; true at r = 1)."""
    C = twisted.block_projector(s, 1)
    return {"C": C}


@claim("cs-blocks-C0-r1", kind="id", sizes=admissible(n_max=4, r_in=(1,)))
def blocks_c0_r1(s):
    """C = 0 at r = 1 (true)."""
    C = twisted.block_projector(s, 1)
    return {"C": C}


@claim("cs-K-false", kind="id", sizes=admissible(n_max=4))
def K_false(s):
    """K W W^T = 0 and K = 0 (false for n > r)."""
    K = twisted.kernel_annihilator(s)
    return {"K": K}


@claim("cs-K-square", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def K_square(s):
    """K = 0 at r = n (true: ker W^T = 0)."""
    K = twisted.kernel_annihilator(s)
    return {"K": K}


@claim("cs-Er-r2", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def er_r2(s):
    """E_r = E_2 at r = 2 (true)."""
    return {"Er-E2": twisted.last_basis_vector(s) - twisted.basis_vector(s, 1)}


@claim("cs-Er-E1-r2", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def er_e1_r2(s):
    """E_r = E_1 at r = 2 (false)."""
    return {"Er-E1": twisted.last_basis_vector(s) - twisted.basis_vector(s, 0)}


@claim("cs-Er-E1-r1", kind="id", sizes=admissible(n_max=4, r_in=(1,)))
def er_e1_r1(s):
    """E_r = E_1 at r = 1 (true)."""
    return {"Er-E1": twisted.last_basis_vector(s) - twisted.basis_vector(s, 0)}


@claim("cs-lead-r2", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def lead_r2(s):
    """(E_1, ..., E_{r-1}) = E_1 at r = 2 (true)."""
    return {"Elead-E1": twisted.leading_basis_vectors(s) - twisted.basis_vector(s, 0)}


@claim("cs-lead-r2-false", kind="id", sizes=admissible(n_max=4, r_in=(2,)))
def lead_r2_false(s):
    """(E_1, ..., E_{r-1}) = E_2 at r = 2 (false)."""
    return {"Elead-E2": twisted.leading_basis_vectors(s) - twisted.basis_vector(s, 1)}


@claim("cs-SXXtS", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def sxxts(s):
    """S_1 X X^T S_1 = I at r = n (true)."""
    S = twisted.reflection(s)
    return {"SXXtS-I": S @ s.X @ s.X.T @ S - s.In}


@claim("cs-SX-XS-square", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def sx_xs(s):
    """X^T S_1 X = S_1 at r = n (false)."""
    S = twisted.reflection(s)
    return {"XtSX-S": s.X.T @ S @ s.X - S}
