"""The complex scene (Zc, conj, realify; letters U, V with VᵀV → I − UᵀU, VᵀU → UᵀV) and the operator
𝔸 on so(r) in the free algebra: closed doors.

* adv-cx-conj-transpose (false): conj(Zc)ᵀZc = I (conj(Z)ᵀ is the realified Zᵀ, not Z*; ZᵀZ ≠ I).
* adv-cx-tangent-half (false): ZcᵀZc_dot = 0 (only its symmetric part vanishes on T W(n, r)).
* adv-cx-tangent (true): ZcᵀZc_dot + Zc_dotᵀZc = 0.
* adv-op-r-n-same-name (false): X 𝔸(Ψ) Xᵀ = 𝔸(XΨXᵀ), the operator of one name on so(r) and on so(n)
  taken for one equivariant operator (they are independent operators).
* adv-op-r-symmetric-arg (true): 𝔸 on so(r) of a symmetric matrix is 0 (it acts on the skew part).
* adv-fg-sym-r (false): the gradient on Sym(r) of c ↦ ⟨𝔸(c), Ψ⟩ is 𝔸(Ψ) (it is 0: 𝔸 sees the skew part).
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import form_gradient

ALL = admissible(n_max=4, n_min=2)


@claim("adv-cx-conj-transpose", kind="id", sizes=ALL)
def cx_conj_transpose(s):
    """conj(Zc)^T Zc = I (false)."""
    Z = s.Zc
    return {"v": s.conj(Z).T @ Z - s.realify(s.Ir, 0 * s.Ir)}


@claim("adv-cx-tangent-half", kind="id", sizes=ALL)
def cx_tangent_half(s):
    """Zc^T Zc_dot = 0 (false)."""
    return {"v": s.Zc.T @ s.Zc_dot}


@claim("adv-cx-tangent", kind="id", sizes=ALL)
def cx_tangent(s):
    """Zc^T Zc_dot + Zc_dot^T Zc = 0 (true)."""
    return {"v": s.Zc.T @ s.Zc_dot + s.Zc_dot.T @ s.Zc}


@claim("adv-op-r-n-same-name", kind="id", sizes=ALL)
def op_r_n_same_name(s):
    """X AA(Psi) X^T = AA(X Psi X^T) (false: AA on so(r) and AA on so(n) are two operators)."""
    AA = s.sym_operator("AA")
    return {"v": s.X @ AA(s.Psi) @ s.X.T - AA(s.X @ s.Psi @ s.X.T)}


@claim("adv-op-r-symmetric-arg", kind="id", sizes=ALL)
def op_r_symmetric_arg(s):
    """AA on so(r) of the symmetric X^T A X is 0 (true)."""
    return {"v": s.sym_operator("AA")(s.X.T @ s.A @ s.X)}


@claim("adv-fg-sym-r", kind="id", sizes=ALL)
def fg_sym_r(s):
    """The gradient on Sym(r) of c -> <AA(c), Psi> is AA(Psi) (false: 0)."""
    G = form_gradient(s, lambda t, y: t.killing(t.sym_operator("AA")(y), t.Psi), s.Psi, "sym", "r")
    return {"v": G - s.sym_operator("AA")(s.Psi)}
