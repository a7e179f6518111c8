"""s77 review: nested derivatives with gradients, Dirac flows, brackets, Ψ, Φ, resolvents, and derivatives on
the claim's scene inside a function of another.  Gradients are ambient (H as written, off T*V too).
-true: TRUE, -false: FALSE (docstring: what changed)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def quad(u):
    return u.tr(u.X.T @ u.A @ u.X)


def norm(u):
    return u.tr(u.X.T @ u.X)


def ham(u):
    return u.tr(u.P.T @ u.P) / 2 + quad(u)


# -- gradients of a function holding a nested derivative whose value vanishes (or is constant) on T*V
@claim("s77r-grad-vanishing-true", kind="id", sizes=SZ)
def grad_vanishing_true(s):
    """H = d_P tr(XᵀX) = 2 tr(PᵀX) (0 on T*V), as written: ∂H/∂X = 2P, ∂H/∂P = 2X."""
    HX, HP = s.gradient(lambda t: t.d(norm, {"X": t.P}))
    return {"x": HX - s.P * 2, "p": HP - s.X * 2}


@claim("s77r-grad-vanishing-false", kind="id", sizes=SZ)
def grad_vanishing_false(s):
    """FALSE: the gradient of the reduced form (0, 0)."""
    HX, HP = s.gradient(lambda t: t.d(norm, {"X": t.P}))
    return {"x": HX, "p": HP}


@claim("s77r-grad-euler-true", kind="id", sizes=SZ)
def grad_euler_true(s):
    """H = d_X tr(XᵀX) = 2 tr(XᵀX) (= 2r on T*V): ∂H/∂X = 4X, ∂H/∂P = 0."""
    HX, HP = s.gradient(lambda t: t.d(norm, {"X": t.X}))
    return {"x": HX - s.X * 4, "p": HP}


@claim("s77r-grad-euler-false", kind="id", sizes=SZ)
def grad_euler_false(s):
    """FALSE: 0 (the reduced form's)."""
    HX, HP = s.gradient(lambda t: t.d(norm, {"X": t.X}))
    return {"x": HX, "p": HP}


@claim("s77r-grad-second-true", kind="id", sizes=SZ)
def grad_second_true(s):
    """H = d_P d_P tr(XᵀAX) = 2 tr(PᵀAP): ∂H/∂X = 0, ∂H/∂P = 4AP."""
    HX, HP = s.gradient(lambda t: t.d(lambda u: u.d(quad, {"X": u.P}), {"X": t.P}))
    return {"x": HX, "p": HP - s.A @ s.P * 4}


@claim("s77r-grad-second-false", kind="id", sizes=SZ)
def grad_second_false(s):
    """FALSE: ∂H/∂P = 2AP."""
    HX, HP = s.gradient(lambda t: t.d(lambda u: u.d(quad, {"X": u.P}), {"X": t.P}))
    return {"x": HX, "p": HP - s.A @ s.P * 2}


# -- s.d along the claim's Dirac flow of a function holding a nested derivative; bracket with one
@claim("s77r-dirac-outer-true", kind="id", sizes=SZ)
def dirac_outer_true(s):
    """F = d_P tr(XᵀAX) = 2tr(PᵀAX); along the Dirac flow of H: d_flow F = {F, H} computed as the bracket of
    the plain function 2tr(PᵀAX)."""
    got = s.d(lambda t: t.d(quad, {"X": t.P}), s.dirac_flow(ham))
    return {"w": got - s.bracket(lambda t: t.tr(t.P.T @ t.A @ t.X) * 2, ham)}


@claim("s77r-dirac-outer-false", kind="id", sizes=SZ)
def dirac_outer_false(s):
    """FALSE: the bracket of tr(PᵀAX) (half)."""
    got = s.d(lambda t: t.d(quad, {"X": t.P}), s.dirac_flow(ham))
    return {"w": got - s.bracket(lambda t: t.tr(t.P.T @ t.A @ t.X), ham)}


@claim("s77r-bracket-second-arg-true", kind="id", sizes=SZ)
def bracket_second_arg_true(s):
    """{F, H'} with H' = d_P H... H' = d_{(0,P)} ham = tr(PᵀP) (ham's P-part along P): equal to {F, tr PᵀP}."""
    F = quad
    got = s.bracket(F, lambda t: t.d(ham, {"P": t.P}))
    return {"w": got - s.bracket(F, lambda t: t.tr(t.P.T @ t.P))}


@claim("s77r-bracket-second-arg-false", kind="id", sizes=SZ)
def bracket_second_arg_false(s):
    """FALSE: {F, tr PᵀP / 2}."""
    F = quad
    got = s.bracket(F, lambda t: t.d(ham, {"P": t.P}))
    return {"w": got - s.bracket(F, lambda t: t.tr(t.P.T @ t.P) / 2)}


@claim("s77r-bracket-nested-moving-true", kind="id", sizes=SZ)
def bracket_nested_moving_true(s):
    """{F, H} with F = d_{AX} tr(XᵀP) = tr(XᵀAP): equal to the bracket of the plain function."""
    got = s.bracket(lambda t: t.d(lambda u: u.tr(u.X.T @ u.P), {"X": t.A @ t.X}), ham)
    return {"w": got - s.bracket(lambda t: t.tr(t.X.T @ t.A @ t.P), ham)}


@claim("s77r-bracket-nested-moving-false", kind="id", sizes=SZ)
def bracket_nested_moving_false(s):
    """FALSE: the bracket of tr(XᵀP) (the direction's motion dropped... F taken as tr(XᵀP))."""
    got = s.bracket(lambda t: t.d(lambda u: u.tr(u.X.T @ u.P), {"X": t.A @ t.X}), ham)
    return {"w": got - s.bracket(lambda t: t.tr(t.X.T @ t.A @ t.X), ham)}


# -- inner derivative along the claim's Dirac flow (constant matrices for the inner, computed at s's point)
@claim("s77r-inner-claim-dirac", kind="id", sizes=SZ)
def inner_claim_dirac(s):
    """d_U [x ↦ dF(x)(Ẋ₀)] with Ẋ₀ the claim's Dirac flow of ham at s's point (constant): 2tr(Ẋ₀ᵀAU).
    TRUE if the flow is read as the claim's constant matrices."""
    U = s.fresh("n", "r")
    fl = s.dirac_flow(ham)
    got = s.d(lambda t: t.d(quad, fl), {"X": U})
    return {"w": got - s.tr(fl.Xdot.T @ s.A @ U) * 2}


# -- Ψ, Φ, resolvent, inverse inside the inner function, moving directions
@claim("s77r-psi-true", kind="id", sizes=SZ)
def psi_true(s):
    """g(x) = d_{(P, X)} tr(ΨΨᵀ) ; commutator d_U g − d_{(P,X)}(d_U tr ΨΨᵀ) = d_{(0,U)} tr(ΨΨᵀ)."""
    U = s.fresh("n", "r")

    def f(u):
        return u.tr(u.Psi @ u.Psi.T)
    one = s.d(lambda t: t.d(f, {"X": t.P, "P": t.X}), {"X": U})
    two = s.d(lambda t: t.d(f, {"X": U}), {"X": s.P, "P": s.X})
    return {"w": one - two - s.d(f, {"P": U})}


@claim("s77r-psi-false", kind="id", sizes=SZ)
def psi_false(s):
    U = s.fresh("n", "r")

    def f(u):
        return u.tr(u.Psi @ u.Psi.T)
    one = s.d(lambda t: t.d(f, {"X": t.P, "P": t.X}), {"X": U})
    two = s.d(lambda t: t.d(f, {"X": U}), {"X": s.P, "P": s.X})
    return {"w": one - two - s.d(f, {"X": U})}


@claim("s77r-phi-resolvent-true", kind="id", sizes=SZ)
def phi_resolvent_true(s):
    """f = tr(Φ R(μ) Φ R(μ)), μ = tr(XᵀAX) moving; commutator with v = AX: d_U d_v f − d_v d_U f = d_{AU} f."""
    U = s.fresh("n", "r")

    def f(u):
        R = u.resolvent(u.tr(u.X.T @ u.A @ u.X))
        return u.tr(u.Phi @ R @ u.Phi @ R)
    one = s.d(lambda t: t.d(f, {"X": t.A @ t.X}), {"X": U})
    two = s.d(lambda t: t.d(f, {"X": U}), {"X": s.A @ s.X})
    return {"w": one - two - s.d(f, {"X": s.A @ U})}


@claim("s77r-phi-resolvent-false", kind="id", sizes=SZ)
def phi_resolvent_false(s):
    U = s.fresh("n", "r")

    def f(u):
        R = u.resolvent(u.tr(u.X.T @ u.A @ u.X))
        return u.tr(u.Phi @ R @ u.Phi @ R)
    one = s.d(lambda t: t.d(f, {"X": t.A @ t.X}), {"X": U})
    two = s.d(lambda t: t.d(f, {"X": U}), {"X": s.A @ s.X})
    return {"w": one - two}


@claim("s77r-resolvent-second-true", kind="id", sizes=SZ)
def resolvent_second_true(s):
    """R(μ), μ = tr(XᵀX): d_V² R = −μ''R² + 2μ'²R³ with μ' = 2tr(VᵀX), μ'' = 2tr(VᵀV)."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.resolvent(u.tr(u.X.T @ u.X)), {"X": V}), {"X": V})
    R = s.resolvent(s.tr(s.X.T @ s.X))
    m1, m2 = s.tr(V.T @ s.X) * 2, s.tr(V.T @ V) * 2
    return {"w": got + R @ R * m2 - R @ R @ R * (m1 * m1 * 2)}


@claim("s77r-resolvent-second-false", kind="id", sizes=SZ)
def resolvent_second_false(s):
    """FALSE: the 2μ'²R³ term dropped."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.resolvent(u.tr(u.X.T @ u.X)), {"X": V}), {"X": V})
    R = s.resolvent(s.tr(s.X.T @ s.X))
    m2 = s.tr(V.T @ V) * 2
    return {"w": got + R @ R * m2}


@claim("s77r-quotient-second-true", kind="id", sizes=SZ)
def quotient_second_true(s):
    """f = tr(XᵀAX)/tr(PᵀP+... ) → g = 1/(1 + tr(PᵀP)): d_W² g with W on P: c = 1+tr(PᵀP), c' = 2tr(WᵀP),
    c'' = 2tr(WᵀW): (1/c)'' = 2c'²/c³ − c''/c²."""
    W = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: 1 / (u.tr(u.P.T @ u.P) + 1), {"P": W}), {"P": W})
    c = s.tr(s.P.T @ s.P) + 1
    c1, c2 = s.tr(W.T @ s.P) * 2, s.tr(W.T @ W) * 2
    return {"w": got - c1 * c1 * 2 / (c * c * c) + c2 / (c * c)}


@claim("s77r-quotient-second-false", kind="id", sizes=SZ)
def quotient_second_false(s):
    W = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: 1 / (u.tr(u.P.T @ u.P) + 1), {"P": W}), {"P": W})
    c = s.tr(s.P.T @ s.P) + 1
    c2 = s.tr(W.T @ W) * 2
    return {"w": got + c2 / (c * c)}


# -- a derivative on the claim's scene s inside a function of another (its flow moves with that function)
@claim("s77r-claim-scene-inside-true", kind="id", sizes=SZ)
def claim_scene_inside_true(s):
    """inner at s's point along t.P: u ↦ tr(uXᵀ X_s)… = d_{P_t}[tr(XᵀX)](X_s) = 2tr(P_tᵀX_s); outer along
    {P: W}: 2tr(WᵀX)."""
    W = s.fresh("n", "r")
    got = s.d(lambda t: s.d(norm, {"X": t.P}), {"P": W})
    return {"w": got - s.tr(W.T @ s.X) * 2}


@claim("s77r-claim-scene-inside-false", kind="id", sizes=SZ)
def claim_scene_inside_false(s):
    """FALSE: 0 (the flow taken as frozen)."""
    W = s.fresh("n", "r")
    got = s.d(lambda t: s.d(norm, {"X": t.P}), {"P": W})
    return {"w": got}


@claim("s77r-claim-scene-inside2-true", kind="id", sizes=SZ)
def claim_scene_inside2_true(s):
    """inner at s's point of u ↦ tr(u.Xᵀ A t.X) along t.P: tr(P_tᵀ A X_t); outer along {X: U, P: W}:
    tr(WᵀAX) + tr(PᵀAU)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: s.d(lambda u: u.tr(u.X.T @ u.A @ t.X), {"X": t.P}), {"X": U, "P": W})
    return {"w": got - s.tr(W.T @ s.A @ s.X) - s.tr(s.P.T @ s.A @ U)}


@claim("s77r-claim-scene-inside2-false", kind="id", sizes=SZ)
def claim_scene_inside2_false(s):
    """FALSE: only tr(WᵀAX)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: s.d(lambda u: u.tr(u.X.T @ u.A @ t.X), {"X": t.P}), {"X": U, "P": W})
    return {"w": got - s.tr(W.T @ s.A @ s.X)}


# -- fresh direction made inside the function
@claim("s77r-fresh-inside", kind="id", sizes=SZ)
def fresh_inside(s):
    """the inner direction is t.fresh (a new generic, independent of the claim's V): FALSE as an identity with
    2tr(VᵀAV) (the two directions are distinct generic matrices)."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.fresh("n", "r")}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ V) * 2}
