"""form_gradient of a form that is not affine: the coordinate scenes summed dual_k·(form(e_k) − form(0)) over a
basis e_k of the space without asking whether the form is affine, so for a quadratic form they returned a
secant through the basis vectors, which is the gradient of the form neither at 0 nor at the point (exact
`proved`, modular `checked`, float `numeric` for the false claim below; `fails` for the true one).  The
dimension-free scene refuses such a form (its cyclic gradient still holds the letter C).  Closed: the
coordinate scenes now check form(w) − form(0) = <G, w> at a generic element w of the space (parameters of
the engine's own) and refuse the form otherwise.

* adv-fg-quadratic-at-zero (true): the derivative at 0 of y ↦ ⟨y, y⟩ + ⟨y, Ψ⟩ on so(r) is Ψ; the fixed-size
  methods answer `fails` (they compute Ψ + Σ_{i<j}(E_ij − E_ji)).
* adv-fg-quadratic-secant (false): at r = 2, so(2) is spanned by e = E12 − E21 and Ψ = Ψ[0,1]·e; the claim
  says the gradient of y ↦ ⟨y, y⟩ is e = Ψ/Ψ[0,1] (it is 0 at 0 and 2Ψ at Ψ: no point has gradient e
  for every Ψ); the fixed-size methods answer `proved`/`checked`.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import form_gradient

ALL = admissible(n_max=4, n_min=2)
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2)


@claim("adv-fg-quadratic-at-zero", kind="id", sizes=ALL)
def fg_quadratic_at_zero(s):
    """The gradient at 0 of y -> <y, y> + <y, Psi> on so(r) is Psi (true; not affine)."""
    G = form_gradient(s, lambda t, y: t.killing(y, y) + t.killing(y, t.Psi), s.Psi, "so", "r")
    return {"v": G - s.Psi}


@claim("adv-fg-quadratic-secant", kind="id", sizes=R2)
def fg_quadratic_secant(s):
    """The gradient of y -> <y, y> on so(2) is the unit e = Psi / Psi[0,1] (false: 0 at 0, 2 Psi at Psi)."""
    G = form_gradient(s, lambda t, y: t.killing(y, y), s.Psi, "so", "r")
    return {"v": G - s.Psi / s.Psi[0, 1]}
