"""Probes of the free algebra's new letters (issue 23/20): the reflection S of R^n commuting with A, the
projectors D, C of two orthogonal blocks of R^r, the projector Dn of R^n and the resolvent at a spectral
parameter that moves with the point, used where their rules may not hold."""
from stiefelsym import admissible, claim, twisted


def _S(s):
    return twisted.reflection(s)


@claim("adv-refl-commutes-A", kind="id", sizes=admissible(n_max=3), statement="S A = A S")
def refl_commutes_a(s):
    """True control: S commutes with A."""
    S = _S(s)
    return {"r": S @ s.A - s.A @ S}


@claim("adv-refl-commutes-A-plus-XXt", kind="id", sizes=admissible(n_max=3), statement="S (A + X X^T) = (A + X X^T) S")
def refl_commutes_a_plus(s):
    """False: S does not commute with A + XX^T."""
    S, B = _S(s), s.A + s.X @ s.X.T
    return {"r": S @ B - B @ S}


@claim("adv-refl-commutes-Phi", kind="id", sizes=admissible(n_max=3), statement="S Phi = Phi S")
def refl_commutes_phi(s):
    """False."""
    S = _S(s)
    return {"r": S @ s.Phi - s.Phi @ S}


@claim("adv-refl-commutes-moving-resolvent", kind="id", sizes=admissible(n_max=3), statement="S R(mu) = R(mu) S, mu = tr P^T P")
def refl_moving(s):
    """True control: S commutes with every resolvent of A."""
    S, R = _S(s), s.resolvent(s.tr(s.P.T @ s.P))
    return {"r": S @ R - R @ S}


@claim("adv-refl-Dn-commute", kind="id", sizes=admissible(n_max=3), statement="S Dn = Dn S")
def refl_dn(s):
    """True at fixed sizes (S_1, diag(I_2, 0)) only."""
    S, D = _S(s), twisted.eigenspace_projector(s)
    return {"r": S @ D - D @ S}


@claim("adv-Dn-commutes-A", kind="id", sizes=admissible(n_max=3), statement="Dn A = A Dn")
def dn_a(s):
    """True at fixed sizes (A diagonal) only."""
    D = twisted.eigenspace_projector(s)
    return {"r": D @ s.A - s.A @ D}


@claim("adv-split-D-plus-C-idempotent", kind="id", sizes=admissible(n_max=3), statement="(D + C)^2 = D + C")
def split_sum(s):
    """True control: D + C is a projector."""
    D, C = twisted.block_projector(s, 0), twisted.block_projector(s, 1)
    return {"r": (D + C) @ (D + C) - (D + C)}


@claim("adv-split-D-minus-C-square", kind="id", sizes=admissible(n_max=3), statement="(D - C)^2 = I_r")
def split_diff(s):
    """True at fixed sizes only (D + C = I_r there)."""
    D, C = twisted.block_projector(s, 0), twisted.block_projector(s, 1)
    return {"r": (D - C) @ (D - C) - s.Ir}


@claim("adv-moving-mu-trA", kind="id", sizes=admissible(n_max=3), statement="(mu I - A) R(mu) = I, mu = tr A")
def moving_tr_a(s):
    """Undefined at n = 1 (mu = a_1 is the eigenvalue of A), true for n >= 2."""
    mu = s.tr(s.A)
    R = s.resolvent(mu)
    return {"r": (s.In * mu - s.A) @ R - s.In}


@claim("adv-moving-mu-rayleigh", kind="id", sizes=admissible(n_max=3), statement="(mu I - A) R(mu) = I, mu = tr X^T A X")
def moving_rayleigh(s):
    """Undefined at n = r = 1 (mu = a_1)."""
    mu = s.tr(s.X.T @ s.A @ s.X)
    R = s.resolvent(mu)
    return {"r": (s.In * mu - s.A) @ R - s.In}


@claim("adv-moving-mu-vs-parameter", kind="id", sizes=admissible(n_max=3), statement="R(mu) - R(mu) = 0 with mu given as its value")
def moving_mu_value(s):
    """False: tr(A R(mu)) = mu tr R(mu) - n, written with a different mu."""
    mu = s.tr(s.P.T @ s.P)
    R = s.resolvent(mu)
    return {"r": s.tr(s.A @ R) - (mu + 1) * s.tr(R) + s.tr(s.In)}


@claim("adv-moving-mu-trA-commutes", kind="id", sizes=admissible(n_max=3), statement="A R(mu) = R(mu) A, mu = tr A")
def moving_tr_a_commutes(s):
    """At n = 1, mu = tr A = a_1 is the eigenvalue of A: R(mu) does not exist at any point of a stated size."""
    R = s.resolvent(s.tr(s.A))
    return {"r": s.A @ R - R @ s.A}


def _H(t):
    """The Neumann Hamiltonian (kinetic and potential)."""
    return (t.tr(t.P.T @ t.P) + t.tr(t.X.T @ t.A @ t.X)) / 2


@claim("adv-refl-derivative", kind="id", sizes=admissible(n_max=3), statement="d/dt tr(X^T S X) = 2 tr(Xdot^T S X)")
def refl_derivative(s):
    """True control: S is constant along a flow."""
    flow = s.dirac_flow(_H)
    return {"r": s.d(lambda t: t.tr(t.X.T @ _S(t) @ t.X), flow) - 2 * s.tr(flow.Xdot.T @ _S(s) @ s.X)}


@claim("adv-refl-derivative-zero", kind="id", sizes=admissible(n_max=3), statement="d/dt tr(X^T S X) = 0")
def refl_derivative_zero(s):
    """False: tr(X^T S X) is not conserved by the Neumann flow."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ _S(t) @ t.X), s.dirac_flow(_H))}


@claim("adv-refl-bracket", kind="id", sizes=admissible(n_max=3), statement="{tr(X^T S A X), H} = 0")
def refl_bracket(s):
    """False."""
    return {"r": s.bracket(lambda t: t.tr(t.X.T @ _S(t) @ t.A @ t.X), _H)}


@claim("adv-refl-gradient", kind="id", sizes=admissible(n_max=3), statement="grad_X tr(X^T S X) = 2 S X")
def refl_gradient(s):
    """True control (the ambient gradient)."""
    gX, _ = s.gradient(lambda t: t.tr(t.X.T @ _S(t) @ t.X))
    return {"r": gX - 2 * _S(s) @ s.X}


@claim("adv-refl-gradient-half", kind="id", sizes=admissible(n_max=3), statement="grad_X tr(X^T S X) = S X")
def refl_gradient_half(s):
    """False (a factor 2 dropped)."""
    gX, _ = s.gradient(lambda t: t.tr(t.X.T @ _S(t) @ t.X))
    return {"r": gX - _S(s) @ s.X}


@claim("adv-split-bracket", kind="id", sizes=admissible(n_max=3), statement="{tr(D Psi D Psi), tr(C Psi C Psi)} = 0")
def split_bracket(s):
    """The block Casimirs of the two blocks commute (true control)."""
    def f(t, i):
        B = twisted.block_projector(t, i)
        return t.tr(B @ t.Psi @ B @ t.Psi)
    return {"r": s.bracket(lambda t: f(t, 0), lambda t: f(t, 1))}


@claim("adv-split-bracket-mixed", kind="id", sizes=admissible(n_max=3), statement="{tr(D Psi C eta), tr(D Psi D Psi)} = 0")
def split_bracket_mixed(s):
    """False: the mixed block D Psi C is rotated by SO(r_1) (at r >= 2)."""
    def mixed(t):
        D, C = twisted.block_projector(t, 0), twisted.block_projector(t, 1)
        return t.tr(D @ t.Psi @ C @ t.eta)
    def block(t):
        D = twisted.block_projector(t, 0)
        return t.tr(D @ t.Psi @ D @ t.Psi)
    return {"r": s.bracket(mixed, block)}


def _first_eigenvalue(s):
    """(tr Dn A − tr Dn A S)/2 = tr(Dn A (I − S)/2): at fixed sizes (Dn = diag(I_2, 0), S = S_1, A = diag(a))
    (I − S)/2 = e_1 e_1^T and this is exactly a_1, an eigenvalue of A at every size."""
    D = twisted.eigenspace_projector(s)
    return (s.tr(D @ s.A) - s.tr(D @ s.A @ _S(s))) / 2


@claim("adv-moving-mu-eigenvalue-commutes", kind="id", sizes=admissible(n_max=3),
       statement="A R(mu) = R(mu) A, mu = tr(Dn A (I - S))/2")
def moving_eigenvalue_commutes(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there)."""
    R = s.resolvent(_first_eigenvalue(s))
    return {"r": s.A @ R - R @ s.A}


@claim("adv-moving-mu-eigenvalue-reflection", kind="id", sizes=admissible(n_max=3),
       statement="S R(mu) = R(mu) S, mu = tr(Dn A (I - S))/2")
def moving_eigenvalue_reflection(s):
    """R(mu) exists at no point of any stated size (mu = a_1 there)."""
    S, R = _S(s), s.resolvent(_first_eigenvalue(s))
    return {"r": S @ R - R @ S}


@claim("adv-moving-mu-eigenvalue-trace", kind="id", sizes=admissible(n_max=3),
       statement="tr(A R(mu)) tr(R(mu) ... ) : the resolvent identity with lam", )
def moving_eigenvalue_identity(s):
    """R(mu) R(lam) (mu - lam) = R(lam) - R(mu) at mu = a_1: undefined at every stated size."""
    R, Rl = s.resolvent(_first_eigenvalue(s)), s.resolvent(s.lam)
    return {"r": s.A @ R @ Rl - R @ Rl @ s.A}


def _eigenvalue_off_the_probe(s):
    """a_1 + (n − 1)(n − 2)(1 − tr C)/2 at fixed sizes (tr C = ⌊r/2⌋): a_1, an eigenvalue of A, at every
    listed size but (3,1) (and at every size with r >= 2); at (3,1) a_1 + 1."""
    n, C = s.tr(s.In), twisted.block_projector(s, 1)
    return _first_eigenvalue(s) + (n - 1) * (n - 2) * (1 - s.tr(C)) / 2


@claim("adv-moving-mu-eigenvalue-off-probe", kind="id", sizes=admissible(n_max=3),
       statement="A R(mu) = R(mu) A, mu = tr(Dn A (I - S))/2 + (n - 1)(n - 2)(1 - tr C)/2")
def moving_eigenvalue_off_probe(s):
    """R(mu) exists at no point of any listed size but (3,1)."""
    R = s.resolvent(_eigenvalue_off_the_probe(s))
    return {"r": s.A @ R - R @ s.A}


@claim("adv-split-conjugated-idempotent", kind="id", sizes=admissible(n_max=3), statement="(X D X^T)^2 = X D X^T")
def split_conjugated(s):
    """True control: X D X^T is a projector of R^n (X^T X = I_r)."""
    D = twisted.block_projector(s, 0)
    M = s.X @ D @ s.X.T
    return {"r": M @ M - M}


@claim("adv-refl-conjugated-involution", kind="id", sizes=admissible(n_max=3), statement="(X^T S X)^2 = I_r")
def refl_conjugated(s):
    """False for r < n (true at r = n, where X X^T = I_n)."""
    M = s.X.T @ _S(s) @ s.X
    return {"r": M @ M - s.Ir}


@claim("adv-new-letters-symmetric", kind="id", sizes=admissible(n_max=3), statement="S^T = S, D^T = D, C^T = C, Dn^T = Dn")
def new_symmetric(s):
    """True control: the four letters are symmetric."""
    S, D, C, Dn = _S(s), twisted.block_projector(s, 0), twisted.block_projector(s, 1), twisted.eigenspace_projector(s)
    return {"S": S.T - S, "D": D.T - D, "C": C.T - C, "Dn": Dn.T - Dn}


@claim("adv-new-letters-skew-wrong", kind="id", sizes=admissible(n_max=3), statement="X^T S P + P^T S X = 0")
def new_skew_wrong(s):
    """False: X^T S P is not skew (S is not I)."""
    S = _S(s)
    return {"r": s.X.T @ S @ s.P + s.P.T @ S @ s.X}


@claim("adv-refl-trace-SA", kind="id", sizes=admissible(n_max=3), statement="tr(S A) = tr(A S)")
def refl_trace(s):
    """True (a trace of a product of two symmetric matrices)."""
    S = _S(s)
    return {"r": s.tr(S @ s.A) - s.tr(s.A @ S)}


@claim("adv-moving-mu-same-twice", kind="id", sizes=admissible(n_max=3), statement="R(tr P^T P) = R(tr P^T S S P)")
def moving_same_twice(s):
    """True control: two resolvents at one moving parameter, built separately (the second through S^2 = I)."""
    S = _S(s)
    return {"r": s.resolvent(s.tr(s.P.T @ s.P)) - s.resolvent(s.tr(s.P.T @ S @ S @ s.P))}


@claim("adv-moving-mu-two-values", kind="id", sizes=admissible(n_max=3), statement="R(tr P^T P) = R(tr P^T Dn P)")
def moving_two_values(s):
    """False: two different moving parameters (Dn is not I)."""
    D = twisted.eigenspace_projector(s)
    return {"r": s.resolvent(s.tr(s.P.T @ s.P)) - s.resolvent(s.tr(s.P.T @ D @ s.P))}


@claim("adv-mu-constant-through-XtX", kind="id", sizes=admissible(n_max=3), statement="d/dt R(tr X^T X) = 0")
def mu_constant(s):
    """True control: tr X^T X = r does not move; R(r) is constant along a flow."""
    return {"r": s.d(lambda t: t.resolvent(t.tr(t.X.T @ t.X)), s.dirac_flow(_H))}


@claim("adv-moving-mu-eigenvalue-beyond", kind="id", sizes=admissible(n_max=4),
       statement="A R(mu) = R(mu) A, mu = tr(Dn A (I - S))/2 + (tr I_n - 7) tr(X^T X)")
def moving_eigenvalue_beyond_the_stated_sizes(s):
    """mu is a_1 (an eigenvalue of A) at n = 7 only, a size the claim is not stated for: there R(mu) does not
    exist, and the statement holds wherever it does."""
    mu = s.tr(twisted.eigenspace_projector(s) @ s.A @ (s.In - _S(s))) / 2 + (s.tr(s.In) - 7) * s.tr(s.X.T @ s.X)
    R = s.resolvent(mu)
    return {"AR - RA": s.A @ R - R @ s.A}


# -- W and a symmetric K with KW = 0 (det(W^T W) times the projector onto ker W^T at fixed sizes) ----------

def _WK(s):
    return twisted.kernel_frame(s), twisted.kernel_annihilator(s)


@claim("adv-kernel-annihilates", kind="id", sizes=admissible(n_max=3), statement="K W = 0, W^T K W W^T = 0")
def kernel_annihilates(s):
    """True control: K annihilates W on both sides."""
    W, K = _WK(s)
    return {"KW": K @ W, "W^T K W W^T": W.T @ K @ W @ W.T, "(K W W^T K)": K @ W @ W.T @ K}


@claim("adv-kernel-block-derivative", kind="id", sizes=admissible(n_max=3),
       statement="d(K X)/dt = K dX/dt along a flow")
def kernel_block_derivative(s):
    """True control: K and W are constant along a flow."""
    W, K = _WK(s)
    flow = s.dirac_flow(_H)
    return {"r": s.d(lambda t: twisted.kernel_annihilator(t) @ t.X @ twisted.kernel_frame(t).T @ t.X, flow)
            - K @ flow.Xdot @ W.T @ s.X - K @ s.X @ W.T @ flow.Xdot}


@claim("adv-kernel-annihilates-X", kind="id", sizes=admissible(n_max=3), statement="K X = 0")
def kernel_annihilates_x(s):
    """False: K annihilates W, not X."""
    _, K = _WK(s)
    return {"r": K @ s.X}


@claim("adv-kernel-commutes-A", kind="id", sizes=admissible(n_max=3), statement="K A = A K")
def kernel_commutes_a(s):
    """False: K is built from W, not from A."""
    _, K = _WK(s)
    return {"r": K @ s.A - s.A @ K}


@claim("adv-kernel-idempotent", kind="id", sizes=admissible(n_max=3), statement="K^2 = K")
def kernel_idempotent(s):
    """False: K is det(W^T W) times a projector."""
    _, K = _WK(s)
    return {"r": K @ K - K}


@claim("adv-kernel-multiple-of-projector", kind="id", sizes=admissible(n_max=3), statement="K^3 tr K = K^2 tr K^2")
def kernel_multiple_of_projector(s):
    """True for K = c times a projector (fixed sizes), not for every symmetric K with KW = 0."""
    _, K = _WK(s)
    return {"r": K @ K @ K * s.tr(K) - K @ K * s.tr(K @ K)}
