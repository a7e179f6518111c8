"""Round 55b: the exact method's fused pairing <x, y> (``ir.evaluate._paired_products``): y a product, a sum or
difference of two products, or a commutator read by the pairing alone, computed as <x a, b> or <[x, a], b>
with [x, a] cached per evaluation.  Claims named -t- are true, -f- false (the docstring says why)."""
from stiefelsym import admissible, block, claim, comm

S = admissible(n_min=3, n_max=4, r_min=2, r_max=2)


def _k(s, x, y):
    return s.killing(x, y)


@claim("adv-s55b-t-assoc", paper="adv", kind="id", sizes=S)
def t_assoc(s):
    """True: <Φ, A XXᵀ> = <Φ A, XXᵀ> (the second read twice: no fusion there) and <A, Φ Φ> = -1/2 tr(AΦΦ)."""
    Phi, A, X = s.Phi, s.A, s.X
    XX = X @ X.T
    return {"a": _k(s, Phi, A @ XX) - s.killing(Phi @ A, XX) + 0 * s.tr(XX),
            "b": _k(s, A, Phi @ Phi) + s.tr(A @ Phi @ Phi) / 2}


@claim("adv-s55b-t-comm-identities", paper="adv", kind="id", sizes=S)
def t_comm(s):
    """True: <x, [a, b]> = <[x, a], b> = -<a, [x, b]> for x = A, a = Φ, b = XXᵀ; x equal to a: <Φ, [Φ, b]> = 0;
    <[a, b], [a, b]> = -1/2 tr([a, b]²) read twice (not fused)."""
    A, Phi, X = s.A, s.Phi, s.X
    b = X @ X.T
    c1 = comm(Phi, b)
    c2 = comm(Phi, b)
    return {"1": _k(s, A, comm(Phi, b)) - _k(s, comm(A, Phi), b),
            "2": _k(s, A, comm(Phi, b)) + _k(s, Phi, comm(A, b)),
            "3": _k(s, Phi, comm(Phi, b)),
            "4": _k(s, c1, c2) + s.tr(c1 @ c1) / 2}


@claim("adv-s55b-t-nested", paper="adv", kind="id", sizes=S)
def t_nested(s):
    """True: Jacobi, <x, [a, [b, c]] + [b, [c, a]] + [c, [a, b]]> = 0 (sum of three pairings of nested commutators),
    and <[a, b], [c, d]> = <a, [b, [c, d]]>."""
    A, Phi, X, P = s.A, s.Phi, s.X, s.P
    a, b, c, d = A, Phi, X @ X.T, P @ X.T
    return {"jac": _k(s, d, comm(a, comm(b, c))) + _k(s, d, comm(b, comm(c, a))) + _k(s, d, comm(c, comm(a, b))),
            "cc": _k(s, comm(a, b), comm(c, d)) - _k(s, a, comm(b, comm(c, d)))}


@claim("adv-s55b-f-order", paper="adv", kind="id", sizes=S)
def f_order(s):
    """False: <x, ab> = <ax, b> (the wrong association) for x = A, a = P Xᵀ, b = XXᵀ."""
    A, X, P = s.A, s.X, s.P
    a, b = P @ X.T, X @ X.T
    return {"v": _k(s, A, a @ b) - s.killing(a @ A, b)}


@claim("adv-s55b-f-comm-sign", paper="adv", kind="id", sizes=S)
def f_comm_sign(s):
    """False: <x, [a, b]> = <[a, x], b> (sign) for x = A, a = P Xᵀ, b = X Pᵀ."""
    A, X, P = s.A, s.X, s.P
    a, b = P @ X.T, X @ P.T
    return {"v": _k(s, A, comm(a, b)) - _k(s, comm(a, A), b)}


@claim("adv-s55b-f-comm-order", paper="adv", kind="id", sizes=S)
def f_comm_order(s):
    """False: <x, [a, b]> = <[x, b], a> for x = A, a = P Xᵀ, b = X Xᵀ (the right side is <x, [b, a]> = -<x, [a, b]>)."""
    A, X, P = s.A, s.X, s.P
    a, b = P @ X.T, X @ X.T
    return {"v": _k(s, A, comm(a, b)) - _k(s, comm(A, b), a)}


@claim("adv-s55b-t-anticomm", paper="adv", kind="id", sizes=S)
def t_anticomm(s):
    """True on T*V: <x, ab + ba> = <[x, a], b> (a sum of two products, not a commutator) for x = A, a = PXᵀ,
    b = XXᵀ: the difference is 2<A, ba> = -tr(XᵀAX XᵀP), a symmetric against a skew matrix (exact proved,
    rational checked)."""
    A, X, P = s.A, s.X, s.P
    a, b = P @ X.T, X @ X.T
    return {"v": _k(s, A, a @ b + b @ a) - _k(s, comm(A, a), b)}


@claim("adv-s55b-f-rect", paper="adv", kind="id", sizes=S)
def f_rect(s):
    """False: <Xᵀ A P, Xᵀ P> (r x r, rectangular factors) = <Pᵀ A X, Xᵀ P>; true: <XᵀAX, XᵀP> = -1/2 tr(XᵀAX XᵀP)."""
    A, X, P = s.A, s.X, s.P
    return {"v": _k(s, X.T @ A @ P, X.T @ P) - _k(s, P.T @ A @ X, X.T @ P)}


@claim("adv-s55b-t-rect", paper="adv", kind="id", sizes=S)
def t_rect(s):
    """True: <Xᵀ, A P> (x r x n, y = A P n x r) = <Xᵀ A, P> = -1/2 tr(XᵀAP); <P, Xᵀ... (n x r against r x n)."""
    A, X, P = s.A, s.X, s.P
    return {"v": _k(s, X.T, A @ P) + s.tr(X.T @ A @ P) / 2,
            "w": _k(s, P, (X.T @ A) @ (X @ X.T)) + s.tr(P @ X.T @ A @ X @ X.T) / 2}


@claim("adv-s55b-t-derivative", paper="adv", kind="id", sizes=S)
def t_derivative(s):
    """True: along X' = AX, P' = 0: d<A, [XXᵀ, PXᵀ]>/dt = <A, [AXXᵀ + XXᵀA, PXᵀ]> + <A, [XXᵀ, PXᵀA]>."""
    A, X, P = s.A, s.X, s.P
    flow = {"X": A @ X, "P": 0 * P}
    lhs = s.d(lambda t: t.killing(t.A, comm(t.X @ t.X.T, t.P @ t.X.T)), flow)
    rhs = _k(s, A, comm(A @ X @ X.T + X @ X.T @ A, P @ X.T)) + _k(s, A, comm(X @ X.T, P @ X.T @ A))
    return {"v": lhs - rhs}


@claim("adv-s55b-f-derivative", paper="adv", kind="id", sizes=S)
def f_derivative(s):
    """False: the derivative above with the second term dropped."""
    A, X, P = s.A, s.X, s.P
    flow = {"X": A @ X, "P": 0 * P}
    lhs = s.d(lambda t: t.killing(t.A, comm(t.X @ t.X.T, t.P @ t.X.T)), flow)
    rhs = _k(s, A, comm(A @ X @ X.T + X @ X.T @ A, P @ X.T))
    return {"v": lhs - rhs}


@claim("adv-s55b-t-block", paper="adv", kind="id", sizes=S)
def t_block(s):
    """True: for Z = [[A, 0], [0, XXᵀ]] and W = [[Φ, 0], [0, PXᵀ]], <Z, [W, Z]> = 0, and
    <Z, W Z> = <A, ΦA> + <XXᵀ, PXᵀXXᵀ>."""
    A, X, P, Phi = s.A, s.X, s.P, s.Phi
    Z0 = s.zeros(s.n, s.n, ("n", "n"))
    Z = block([[A, Z0], [Z0, X @ X.T]])
    W = block([[Phi, Z0], [Z0, P @ X.T]])
    return {"c": _k(s, Z, comm(W, Z)),
            "p": _k(s, Z, W @ Z) - _k(s, A, Phi @ A) - _k(s, X @ X.T, (P @ X.T) @ (X @ X.T))}


@claim("adv-s55b-t-resolvent", paper="adv", kind="id", sizes=S)
def t_resolvent(s):
    """True: <R(λ), [A, XXᵀ]> = 0 (R commutes with A: <[R, A], XXᵀ> = 0)."""
    return {"v": _k(s, s.resolvent(s.lam), comm(s.A, s.X @ s.X.T))}


@claim("adv-s55b-f-resolvent", paper="adv", kind="id", sizes=S)
def f_resolvent(s):
    """False: <R(λ), [Φ, XXᵀ]> = 0."""
    return {"v": _k(s, s.resolvent(s.lam), comm(s.Phi, s.X @ s.X.T))}


@claim("adv-s55b-t-self", paper="adv", kind="id", sizes=S)
def t_self(s):
    """True: <a, [a, b]> = 0 and <b, [a, b]> = 0 for a = PXᵀ, b = A (x equal to a, x equal to b)."""
    a, b = s.P @ s.X.T, s.A
    return {"xa": _k(s, a, comm(a, b)), "xb": _k(s, b, comm(a, b))}


@claim("adv-s55b-f-self", paper="adv", kind="id", sizes=S)
def f_self(s):
    """False: <a, a b> = 0 for a = PXᵀ, b = A (no commutator)."""
    a, b = s.P @ s.X.T, s.A
    return {"v": _k(s, a, a @ b) + 0 * _k(s, b, a @ b)}


@claim("adv-s55b-t-transpose", paper="adv", kind="id", sizes=S)
def t_transpose(s):
    """True: <x, (ab)ᵀ> = <xᵀ, ab> and <x, bᵀaᵀ> = <aᵀ xᵀ... : <A, (PXᵀ A)ᵀ> = <A, A X Pᵀ>."""
    A, X, P = s.A, s.X, s.P
    return {"v": _k(s, A, (P @ X.T @ A).T) - _k(s, A, A @ (X @ P.T)),
            "w": _k(s, A, A.T @ (X @ P.T)) - _k(s, A @ A, X @ P.T)}
