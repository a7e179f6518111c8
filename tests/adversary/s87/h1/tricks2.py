"""s87h1 tricks, second file.

 s87h1k-not-xxt (TRUE for r < n, FALSE at r = n): kind="not": XXᵀ − I does not vanish.
 s87h1k-not-psi (TRUE for r ≥ 2, FALSE at r = 1): kind="not": Ψ does not vanish.
 s87h1k-inverse-kappa (FALSE as "invertible at every point, for every κ": at κ = 0 the map a ↦ κa is 0):
   Inverse(a ↦ κa, a ↦ a/κ) on Sym(r).  The guide refuses divisions that may vanish (A⁻¹, tr PᵀP).
 s87h1k-inverse-trA (FALSE for A with tr A = 0): Inverse(a ↦ tr(A)a, a ↦ a/tr(A)) on Sym(r).
 s87h1k-inverse-c (FALSE at c = 0): the same with a claim parameter c = s.scalar("c").
"""
from __future__ import annotations

from stiefelsym import Inverse, admissible, claim

ANY = admissible(n_max=4)


@claim("s87h1k-not-xxt", kind="not", expect="nonzero", section="7", sizes=ANY)
def not_xxt(s):
    """XXᵀ − I ≠ 0 (TRUE for r < n, FALSE at r = n)."""
    return {"XXt - I": s.X @ s.X.T - s.In}


@claim("s87h1k-not-psi", kind="not", expect="nonzero", section="7", sizes=ANY)
def not_psi(s):
    """Ψ ≠ 0 (TRUE for r ≥ 2, FALSE at r = 1)."""
    return {"Psi": s.Psi}


def _op_k(t, a):
    return (t.kappa * a,)


def _inv_k(t, a):
    return (a / t.kappa,)


@claim("s87h1k-inverse-kappa", kind="id", section="6", sizes=ANY)
def inverse_kappa(s):
    """a ↦ κa is invertible on Sym(r) at every point, with inverse a ↦ a/κ (FALSE at κ = 0)."""
    return {"inverse": Inverse(_op_k, _inv_k, on=("Sym(r)",))}


def _op_t(t, a):
    return (t.tr(t.A) * a,)


def _inv_t(t, a):
    return (a / t.tr(t.A),)


@claim("s87h1k-inverse-trA", kind="id", section="6", sizes=ANY)
def inverse_tra(s):
    """a ↦ tr(A)a is invertible (FALSE when tr A = 0)."""
    return {"inverse": Inverse(_op_t, _inv_t, on=("Sym(r)",))}




def _op_c(t, a):
    return (t.scalar("c") * a,)


def _inv_c(t, a):
    return (a / t.scalar("c"),)


@claim("s87h1k-inverse-c", kind="id", section="6", sizes=ANY)
def inverse_c(s):
    """a ↦ ca is invertible (FALSE at c = 0)."""
    return {"inverse": Inverse(_op_c, _inv_c, on=("Sym(r)",))}
