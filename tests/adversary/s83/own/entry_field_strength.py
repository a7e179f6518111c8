"""Stop 83 (own): a field strength F = c·J whose number c is an entry of a matrix (s82's false refusal: the
skew test of the twisted step did not take an entry as a number).

At r = 2, J = twisted.magnetic_matrix(s) = E₁∧E₂ = [[0, 1], [−1, 0]], and η = η₀₁·J for η ∈ so(2): the twisted
flow with F = η[0, 1]·J is the flow with F = η (true).  η[1, 0] = −η₀₁, so F = η[1, 0]·J = −η gives another flow
(false: the magnetic term ε F changes sign).  X[0, 0]·J is skew too (an entry of the scene's X), and its flow
differs from the flow of F = J where X₀₀ ≠ 1 (false)."""
from stiefelsym import admissible, claim, twisted

R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="r = 2")


def _H(t):
    """The Neumann Hamiltonian ½ tr(PᵀP) + ½ tr(XᵀAX) on T*V(n, r)."""
    return (t.tr(t.P.T @ t.P) + t.tr(t.X.T @ t.A @ t.X)) / 2


def _diff(s, F1, F2):
    f1, f2 = twisted.flow(s, _H, F1), twisted.flow(s, _H, F2)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("s83-entry-times-J", kind="id", sizes=R2)
def entry_times_j(s):
    """F = η[0, 1]·J and F = η give one flow (true)."""
    return _diff(s, s.eta[0, 1] * twisted.magnetic_matrix(s), s.eta)


@claim("s83-entry-times-J-false", kind="id", sizes=R2)
def entry_times_j_false(s):
    """F = η[1, 0]·J = −η against F = η (false)."""
    return _diff(s, s.eta[1, 0] * twisted.magnetic_matrix(s), s.eta)


@claim("s83-x-entry-times-J-false", kind="id", sizes=R2)
def x_entry_times_j_false(s):
    """F = X[0, 0]·J against F = J (false where X₀₀ ≠ 1)."""
    J = twisted.magnetic_matrix(s)
    return _diff(s, s.X[0, 0] * J, J)
