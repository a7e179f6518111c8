"""The exact method's complex chart reduced by U(r) on the right (at r = n: Z = I).  Quantities that
are covariant only under O(r) (plain transposes), or that pick the real half of the realified C^r side
with a block constant: true at Z = I, false at a general unitary Z.  Each must break the U(r)
reduction (fails), never be proved on the reduced chart."""
from stiefelsym import admissible, block, claim
from stiefelsym.systems import ctranspose, re_trace

SQ = admissible(r_is_n=True, n_min=2, n_max=3)


def _pick(s):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[s.Ir, z], [z, z]])


def _flip(s):
    z = s.zeros(s.n, s.n, ("n", "n"))
    return block([[s.In, z], [z, -s.In]])


@claim("s78-cx-plain-transpose-false", paper="prep", kind="id", sizes=SQ)
def plain_false(s):
    """False: Re tr(ZᵀZ) = n on W(n, n) (true at real orthogonal Z only)."""
    Z = s.Zc
    return {"re tr ZtZ - n": re_trace(s, ctranspose(s, Z) @ Z) - s.tr(s.In)}


@claim("s78-cx-pick-false", paper="prep", kind="id", sizes=SQ)
def pick_false(s):
    """False: tr(diag(I, 0)·Z*·diag(I, −I)·Z) = n on W(n, n)."""
    Z = s.Zc
    return {"pick": (_pick(s) @ Z.T @ _flip(s) @ Z).trace() - s.tr(s.In)}


@claim("s78-cx-pick-true", paper="prep", kind="id", sizes=SQ)
def pick_true(s):
    """tr(diag(I, 0)·Z*Z) = n on W(n, n) (Z*Z = I)."""
    Z = s.Zc
    return {"pick": (_pick(s) @ Z.T @ Z).trace() - s.tr(s.In)}


@claim("s78-cx-pick-flip-true", paper="prep", kind="id", sizes=SQ)
def pick_flip_true(s):
    """tr(Z*·diag(I, −I)·Z) = 0 on W(n, n)."""
    Z = s.Zc
    return {"flip": (Z.T @ _flip(s) @ Z).trace()}
