# ruff: noqa
"""API probes for the blocks of the proofs at X0 = (E_1 … E_r) (findings (b)); each is expected to hold
(true statements), so an `error` is the API refusing them."""
from stiefelsym import admissible, block, claim, comm
from stiefelsym.bases import so_basis

sz = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")


def X0_blocks(s):
    return block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])


@claim("p71b-block-x0-meets-a", kind="id", sizes=sz)
def block_x0_meets_a(s):
    """X0 = (I_r; 0) built with `block` from the r and n−r blocks, against A (ℝⁿ): X0ᵀAX0 is symmetric."""
    X0 = X0_blocks(s)
    M = X0.T @ s.A @ X0
    return {"X0ᵀAX0 − (X0ᵀAX0)ᵀ": M - M.T}


@claim("p71b-generic-nr-skew", kind="id", sizes=sz)
def generic_nr_skew(s):
    """s.generic(name, "n-r", "n-r", "skew") is skew."""
    B = s.generic("B", "n-r", "n-r", "skew")
    return {"B + Bᵀ": B + B.T}


@claim("p71b-identity-nr", kind="id", sizes=sz)
def identity_nr(s):
    """s.identity(n − r, "n-r") is the identity of ℝⁿ⁻ʳ."""
    I = s.identity(s.n - s.r, "n-r")
    P2 = s.generic("P2", "n-r", "r")
    return {"I P2 − P2": I @ P2 - P2}


@claim("p71b-so-basis-nr", kind="id", sizes=admissible(n_max=4, where=lambda n, r: n - r >= 2, condition="n − r ≥ 2"))
def so_basis_nr(s):
    """bases.so_basis(s, "n-r"): a basis of so(n − r) (its elements are skew)."""
    return {f"b{i} + b{i}ᵀ": b + b.T for i, b in enumerate(so_basis(s, "n-r"))}


@claim("p71b-x0-mat-with-nr-block", kind="id", sizes=sz)
def x0_mat_with_nr_block(s):
    """X0 as s.mat on (n, r) (the catalog's way) with P0 = (P1; P2) joined from an "n-r" block: XᵀP + PᵀX = 0."""
    n, r = int(s.n), int(s.r)
    X0 = s.mat([[1 if i == j else 0 for j in range(r)] for i in range(n)], ("n", "r"))
    P0 = block([[s.generic("P1", "r", "r", "skew")], [s.generic("P2", "n-r", "r")]])
    return {"(cond_XP)": X0.T @ P0 + P0.T @ X0}
