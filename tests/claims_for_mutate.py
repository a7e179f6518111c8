"""A small claims file for `stiefelsym mutate --claims` (tests/test_mutate_claims.py): its module code prints
the process it runs in; one claim traces with symbolic sizes, one is a documented erratum with a sign error,
two read their size as a number (traced per size), the second an erratum with a sign error."""
import os
import sys

from stiefelsym import admissible, claim

print(f"claims-for-mutate-pid {os.getpid()}", file=sys.stderr)     # shown by the verifying process


@claim("mc-psi-skew", paper="prep", kind="id", section="t", sizes=admissible(n_max=3))
def psi_is_skew(s):
    """Ψ = XᵀP − PᵀX is skew."""
    return {"Psi + Psi^T": s.Psi + s.Psi.T}


@claim("mc-wrong-sign", paper="prep", kind="id", section="t", sizes=admissible(n_max=3), expect="fails",
       erratum="the two terms of Ψ are swapped")
def wrong_sign(s):
    """Ψ = PᵀX − XᵀP (printed with the terms swapped: fails)."""
    return {"Psi": s.Psi - (s.P.T @ s.X - s.X.T @ s.P)}


@claim("mc-per-size", paper="prep", kind="id", section="t", sizes=admissible(n_max=3))
def per_size(s):
    """tr(XᵀX) = r, with r read as a number (traced per size)."""
    return {"tr": s.tr(s.X.T @ s.X) - int(s.r)}


@claim("mc-per-size-wrong-sign", paper="prep", kind="id", section="t", sizes=admissible(n_max=3), expect="fails",
       erratum="the sign of r")
def per_size_wrong_sign(s):
    """tr(XᵀX) = −r (printed with the wrong sign: fails), with r read as a number (traced per size)."""
    return {"tr": s.tr(s.X.T @ s.X) + int(s.r)}


@claim("mc-loop-over-r", paper="prep", kind="id", section="t", sizes=admissible(n_max=3))
def loop_over_r(s):
    """tr(XᵀX) added r times is r², a loop over r (its graphs at two sizes are not one computation)."""
    one = s.tr(s.X.T @ s.X)
    total = one
    for _ in range(int(s.r) - 1):
        total = total + one
    return {"sum": total - int(s.r) * int(s.r)}
