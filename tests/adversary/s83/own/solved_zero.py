"""Stop 83 (own): a multiplier that is 0 among the solved multipliers (s83 hidden2's F1: float and ball left
Π = 0 of the twisted Euclidean flow `inconclusive` at every precision, each solved entry having its own size as
its term scale).

For H = ½ tr PᵀP + ½ tr XᵀAX (the Neumann Hamiltonian) the Lagrange form of the flow on T*V has Π = 0: Ẋ = P is
tangent (XᵀP + PᵀX = 0 on T*V) with no correction, twisted (F = η) or not (true).  With the kinetic term
½ tr PᵀAP instead, Ẋ = AP is not tangent: XᵀAP + PᵀAX ≠ 0 in general, and Π, the multiplier that projects it
back, is not 0 (false); nor is Π = 0 for H + tr(XᵀP)·tr(PᵀP)... (the false twins must fail under float and
ball as under exact)."""
from stiefelsym import admissible, claim, twisted

SIZES = admissible(n_max=3, n_min=2, r_min=1)


def _neumann(t):
    return (t.tr(t.P.T @ t.P) + t.tr(t.X.T @ t.A @ t.X)) / 2


def _skewed_kinetic(t):
    return (t.tr(t.P.T @ t.A @ t.P) + t.tr(t.X.T @ t.A @ t.X)) / 2


@claim("s83-pi-zero-twisted", kind="id", sizes=SIZES)
def pi_zero_twisted(s):
    """Π = 0 for the twisted Neumann flow, F = η (true)."""
    return {"Pi": twisted.multiplier_flow(s, _neumann, F=s.eta)["Pi"]}


@claim("s83-pi-zero-false", kind="id", sizes=SIZES)
def pi_zero_false(s):
    """Π = 0 for H = ½ tr PᵀAP + ½ tr XᵀAX, twisted (false)."""
    return {"Pi": twisted.multiplier_flow(s, _skewed_kinetic, F=s.eta)["Pi"]}


@claim("s83-pi-small-false", kind="id", sizes=SIZES)
def pi_small_false(s):
    """Π(H_A) = 10⁻⁹ Π(H_A)... written as Π(H) − Π(H + 10⁻⁹ (H_A − H)) = 0 (false: the multipliers are linear in
    the Hamiltonian's kinetic part here, so the difference is 10⁻⁹ times a nonzero Π)."""
    small = twisted.multiplier_flow(s, lambda t: _neumann(t) + (_skewed_kinetic(t) - _neumann(t)) / 10**9,
                                    F=s.eta)["Pi"]
    return {"Pi": small - twisted.multiplier_flow(s, _neumann, F=s.eta)["Pi"]}


@claim("s83-pi-tiny-false", kind="id", sizes=SIZES)
def pi_tiny_false(s):
    """As s83-pi-small-false with 10⁻³⁰: far below float64's resolution beside Λ, so the column's scale alone
    would let it pass; the float and ball methods' exact confirmation at a point mod p refutes it (false)."""
    tiny = twisted.multiplier_flow(s, lambda t: _neumann(t) + (_skewed_kinetic(t) - _neumann(t)) / 10**30,
                                   F=s.eta)["Pi"]
    return {"Pi": tiny - twisted.multiplier_flow(s, _neumann, F=s.eta)["Pi"]}
