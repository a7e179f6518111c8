"""s82 hidden (h2): which spellings of the field strength F = <eta, J> J (r = 2, equal to eta) the twisted step takes."""
from stiefelsym import admissible, claim, twisted
from _h82_helpers import H_euclid_neumann

R2 = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="r = 2")


def _cmp(s, F):
    f1 = twisted.flow(s, H_euclid_neumann, s.eta)
    f2 = twisted.flow(s, H_euclid_neumann, F)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("p82f-matrix-times-scalar", kind="id", sizes=R2)
def f1(s):
    """F = J·⟨η, J⟩."""
    J = twisted.magnetic_matrix(s)
    return _cmp(s, J * s.killing(s.eta, J))


@claim("p82f-entry-times-J", kind="id", sizes=R2)
def f2(s):
    """F = η[0, 1]·J."""
    J = twisted.magnetic_matrix(s)
    return _cmp(s, s.eta[0, 1] * J)


@claim("p82f-skew-part", kind="id", sizes=R2)
def f3(s):
    """F = (M − Mᵀ)/2 with M = ⟨η, J⟩J (skew by construction)."""
    J = twisted.magnetic_matrix(s)
    M = s.killing(s.eta, J) * J
    return _cmp(s, (M - M.T) / 2)


@claim("p82f-two-J", kind="id", sizes=R2)
def f4(s):
    """F = 2J vs 2J: a sanity spelling (flows for F = η and F = 2J differ; this compares 2J with J + J)."""
    J = twisted.magnetic_matrix(s)
    f1 = twisted.flow(s, H_euclid_neumann, 2 * J)
    f2 = twisted.flow(s, H_euclid_neumann, J + J)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("p82f-J-plain", kind="id", sizes=R2)
def f5(s):
    """F = J given explicitly equals the default F."""
    J = twisted.magnetic_matrix(s)
    f1 = twisted.flow(s, H_euclid_neumann, J)
    f2 = twisted.flow(s, H_euclid_neumann)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("p82f-eta-scaled-by-scalar", kind="id", sizes=R2)
def f6(s):
    """F = c·η (c = s.scalar) vs η·c."""
    c = s.scalar("c")
    f1 = twisted.flow(s, H_euclid_neumann, c * s.eta)
    f2 = twisted.flow(s, H_euclid_neumann, s.eta * c)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}


@claim("p82f-explicit-J-workaround", kind="id", sizes=R2)
def f7(s):
    """F = s.mat([[0, 1], [-1, 0]]) equals the default F."""
    f1 = twisted.flow(s, H_euclid_neumann, s.mat([[0, 1], [-1, 0]], ("r", "r")))
    f2 = twisted.flow(s, H_euclid_neumann)
    return {"X": f1["X"] - f2["X"], "P": f1["P"] - f2["P"]}
