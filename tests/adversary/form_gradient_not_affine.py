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
  for every Ψ); the fixed-size methods answered `proved`/`checked`.
* adv-fg-quadratic-along-flow (false): inside s.d (the scene's dual numbers) a form affine at the point but
  not along the flow; the check must see both parts of a dual number (it was skipped on dual fields:
  exact `proved`, modular `checked`).
* adv-fg-affine-in-gradient, adv-fg-affine-along-flow (true): affine forms inside an ambient gradient and
  along a flow still pass.
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


@claim("adv-fg-quadratic-along-flow", kind="id", sizes=R2)
def fg_quadratic_along_flow(s):
    """Along a flow that leaves V (the scene's dual numbers): the form y -> <y, y>(tr(X^T X) - 2) + <y, Psi> is
    affine at the point (on V) but not along the flow; the derivative of its 'gradient' on so(2) is
    dPsi + 2 tr(X^T A X) e (false: the secant again; the check must see both parts of a dual number)."""
    fl = {"X": s.A @ s.X, "P": 0 * s.P}
    D = s.d(lambda u: form_gradient(u, lambda t, y: t.killing(y, y) * (t.tr(t.X.T @ t.X) - 2) + t.killing(y, t.Psi),
                                    u.Psi, "so", "r"), fl)
    dPsi = s.d(lambda u: u.Psi, fl)
    return {"v": D - dPsi - 2 * s.tr(s.X.T @ s.A @ s.X) * s.Psi / s.Psi[0, 1]}


def _affine_H(u):
    G = form_gradient(u, lambda t, y: t.killing(y, t.Psi) * t.tr(t.X.T @ t.A @ t.X), u.Psi, "so", "r")
    return u.killing(G, u.eta) + 0 * u.X[0, 0]


@claim("adv-fg-affine-in-gradient", kind="id", sizes=ALL)
def fg_affine_in_gradient(s):
    """An affine form's gradient inside an ambient gradient (the scene's own, an entry forces it) (true)."""
    HX, HP = s.gradient(_affine_H)
    KX, KP = s.gradient(lambda u: u.killing(u.Psi, u.eta) * u.tr(u.X.T @ u.A @ u.X) + 0 * u.X[0, 0])
    return {"x": HX - KX, "p": HP - KP}


@claim("adv-fg-affine-along-flow", kind="id", sizes=ALL)
def fg_affine_along_flow(s):
    """An affine form's gradient along a flow (true)."""
    fl = {"X": s.A @ s.X, "P": s.P}
    a = s.d(lambda u: form_gradient(u, lambda t, y: t.killing(y, t.Psi) * t.tr(t.X.T @ t.A @ t.X), u.Psi,
                                    "so", "r"), fl)
    b = s.d(lambda u: u.Psi * u.tr(u.X.T @ u.A @ u.X), fl)
    return {"v": a - b}
