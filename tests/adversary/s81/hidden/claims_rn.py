"""h81: the r = n statement declared with r_is_n=True (so the dimension-free method may use XXᵀ = I), and its twin."""
from stiefelsym import admissible, claim


@claim("h81-r-equals-n-declared", paper=("Neumann_potential", "dot_XP2"), kind="id",
       sizes=admissible(n_max=5, r_is_n=True))
def r_equals_n_declared(s):
    """As h81-r-equals-n: at r = n, tr(XᵀAX) = tr A and Φ = XΨXᵀ."""
    return {"tr X^T A X - tr A": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A),
            "Phi - X Psi X^T": s.Phi - s.X @ s.Psi @ s.X.T}


@claim("n81-r-equals-n-declared", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def r_equals_n_declared_twin(s):
    """Twin: A² in place of A in the potential."""
    return {"tr X^T A X - tr A": s.tr(s.X.T @ s.A @ s.A @ s.X) - s.tr(s.A),
            "Phi - X Psi X^T": s.Phi - s.X @ s.Psi @ s.X.T}


@claim("n81-r-equals-n-declared-phi", kind="id", sizes=admissible(n_max=5, r_is_n=True, n_min=2))
def r_equals_n_declared_twin2(s):
    """Twin 2: Φ = XΨᵀXᵀ (= −XΨXᵀ; Φ ≠ 0 for n ≥ 2)."""
    return {"tr X^T A X - tr A": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A),
            "Phi - X Psi X^T": s.Phi - s.X @ s.Psi.T @ s.X.T}
