"""Fourth round (AL): claims stated at a union of one-r families (admissible(r_in=...)) in a user's file.  The
file's statement reaches the verifying process as a table (userfile.TabledSizes) without r_in, so no family's
hypothesis (E₁E₁ᵀ = I_r at r = 1, XXᵀ = I_n at r = n) is used for a user's claim: what holds at each declared r
only is left undecided by free, and decided at its sizes by the fixed-size methods; sizes outside the union are
refused."""
from stiefelsym import admissible, claim

U1N = admissible(n_max=4, r_in=(1, "n"))
U2N = admissible(n_max=4, r_in=(2, "n"))
U12 = admissible(n_max=4, r_in=(1, 2))
R1 = admissible(n_max=3, r_in=(1,))


@claim("adv-s34-union-xxtp", paper="t", kind="id", sizes=U1N)
def xxtp(s):
    """False at r = 1 < n: X Xᵀ P = P (true at r = n only)."""
    return {"x": s.X @ s.X.T @ s.P - s.P}


@claim("adv-s34-union-psi", paper="t", kind="id", sizes=U1N)
def psi(s):
    """False at r = n >= 2: Ψ = 0 (true at r = 1 only)."""
    return {"Psi": s.Psi}


@claim("adv-s34-union-psi-12", paper="t", kind="id", sizes=U12)
def psi12(s):
    """False at r = 2: Ψ = 0."""
    return {"Psi": s.Psi}


@claim("adv-s34-union-xxtp-2n", paper="t", kind="id", sizes=U2N)
def xxtp2n(s):
    """False at r = 2 < n: X Xᵀ P = P."""
    return {"x": s.X @ s.X.T @ s.P - s.P}


@claim("adv-s34-union-true", paper="t", kind="id", sizes=U1N)
def union_true(s):
    """True at r = 1 (Ψ = 0) and at r = n (X Xᵀ = I_n), false between: tr(Ψ²) tr(A(XXᵀ − I_n)) = 0."""
    return {"x": s.tr(s.Psi @ s.Psi) * s.tr(s.A @ (s.X @ s.X.T - s.identity(s.n)))}


@claim("adv-s34-union-r1-true", paper="t", kind="id", sizes=R1)
def r1_true(s):
    """True at r = 1, the only r it is stated for: Ψ = 0."""
    return {"Psi": s.Psi}
