"""Stop 83 review (h2): type and size errors inside the nodes of y that the reassociated trace no longer computes.
The multiplier Λ of a flow (an r × r matrix on ℝʳ) is an engine value: the tracer does not know its shape, so a
product or a sum that mixes it with ℝⁿ is checked only when it is evaluated.  Every claim here is ILL-TYPED
(its expression is an error at every size: the product L @ X of an r × r and an n × r matrix, or the sum of an
ℝʳ-indexed and an ℝⁿ-indexed matrix); the honest verdict is `error` everywhere (modular and the exact method
before 96621a3a give it).  A `proved` is the type/size hole of brief item (2); a `fails` would be a wrong
verdict only where the statement has a meaning."""
from stiefelsym import admissible, claim, comm

S = admissible(n_min=2, n_max=3, r_min=1, r_max=3)


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def _lam(s):
    return s.multiplier_flow(H)["Lambda"]


@claim("adv-s83r-e-cancelled-bad-product", paper="adv", kind="id", sizes=S)
def e_cancel(s):
    """Ill-typed: y = ΦA + ΛX − ΛX; Λ X is an (r × r)(n × r) product (a size error where r ≠ n, ℝʳ against ℝⁿ
    where r = n).  Without the bad product: tr(M y) − tr((MΦ)A) = 0."""
    L = _lam(s)
    M = s.generic("M", "n", "n")
    y = s.Phi @ s.A + L @ s.X - L @ s.X
    return {"c": s.tr(M @ y) - s.tr((M @ s.Phi) @ s.A)}


@claim("adv-s83r-e-cancelled-bad-product-f", paper="adv", kind="id", sizes=S)
def e_cancel_f(s):
    """Ill-typed twin with a false rest: tr(M y) − tr((MA)Φ) (ΦA for AΦ)."""
    L = _lam(s)
    M = s.generic("M", "n", "n")
    y = s.Phi @ s.A + L @ s.X - L @ s.X
    return {"c": s.tr(M @ y) - s.tr((M @ s.A) @ s.Phi)}


@claim("adv-s83r-e-self-commutator-bad", paper="adv", kind="id", sizes=S)
def e_selfcomm(s):
    """Ill-typed: [XᵀΛ... ] the commutator [B, B] of the n × r matrix B = X + 0·(Λ-valued) — here B = Λ X (bad
    product as a factor: computed, must error)."""
    L = _lam(s)
    M = s.generic("M", "n", "n")
    B = L @ s.X
    return {"c": s.tr(M @ comm(B, B))}


@claim("adv-s83r-e-self-commutator-rect", paper="adv", kind="id", sizes=S)
def e_selfcomm_rect(s):
    """Ill-typed: [Λ-side] the commutator [W, W] of W = Λ Xᵀ (r × n, well-typed itself) — W W is an
    (r × n)(r × n) product: a size error where r ≠ n, ℝⁿ against ℝʳ at r = n.  The commutator cancels
    uncomputed: tr(M' [W, W]) with M' an r × r... the trace's x must meet W's rows: x = Λ (r × r)."""
    L = _lam(s)
    W = L @ s.X.T
    return {"c": s.tr(L @ comm(W, W)) + 0 * s.tr(L)}


@claim("adv-s83r-e-mixed-spaces-untyped-x", paper="adv", kind="id", sizes=S)
def e_mixed(s):
    """Ill-typed: y = ΛΛ + ΦΦ + AΦ − AΦ: a sum of an ℝʳ-indexed and an ℝⁿ-indexed matrix (a size error where
    r ≠ n, a space error at r = n), paired with the untyped x = 2·I_n (scalar_matrix, no coordinate read)."""
    L = _lam(s)
    x = s.scalar_matrix(2, s.n)
    y = L @ L + s.Phi @ s.Phi + s.A @ s.Phi - s.A @ s.Phi
    return {"c": s.tr(x @ y) + 4 * s.killing(L, L) + 4 * s.killing(s.Phi, s.Phi)}


@claim("adv-s83r-e-mixed-spaces-untyped-x-f", paper="adv", kind="id", sizes=S)
def e_mixed_f(s):
    """Ill-typed twin with a false rest: − 3 tr(ΛΛ) for − 2 tr(ΛΛ)."""
    L = _lam(s)
    x = s.scalar_matrix(2, s.n)
    y = L @ L + s.Phi @ s.Phi + s.A @ s.Phi - s.A @ s.Phi
    return {"c": s.tr(x @ y) + 6 * s.killing(L, L) + 4 * s.killing(s.Phi, s.Phi)}


@claim("adv-s83r-e-control-typed", paper="adv", kind="id", sizes=S)
def e_control(s):
    """Control, well typed and true: tr(Λ (ΛΛ + XᵀAX − XᵀAX)) = tr(Λ³)."""
    L = _lam(s)
    XAX = s.X.T @ s.A
    return {"c": s.tr(L @ (L @ L + XAX @ s.X - XAX @ s.X)) - s.tr((L @ L) @ L)}


@claim("adv-s83r-e-mixed-spaces-killing", paper="adv", kind="id", sizes=S)
def e_mixed_killing(s):
    """Ill-typed (as e-mixed-spaces-untyped-x, with the pairing and no cancelled pair): <2 I_n, ΛΛ + ΦΦ> — the
    reassociation of a pairing (stop 55) checks each product against x only, never the products against each
    other."""
    L = _lam(s)
    x = s.scalar_matrix(2, s.n)
    return {"c": s.killing(x, L @ L + s.Phi @ s.Phi) - 2 * s.killing(L, L) - 2 * s.killing(s.Phi, s.Phi)}


@claim("adv-s83r-e-cancelled-killing", paper="adv", kind="id", sizes=S)
def e_cancel_killing(s):
    """Ill-typed (as e-cancelled-bad-product, with the pairing): <M, ΦA + ΛX − ΛX>."""
    L = _lam(s)
    M = s.generic("M", "n", "n")
    return {"c": s.killing(M, s.Phi @ s.A + L @ s.X - L @ s.X) - s.killing(M @ s.Phi, s.A)}
