# ruff: noqa: E702
"""Paper check (§6, 'For λ2 ≠ 0, Λ_{λ1,λ2} is isomorphic to the Lie–Poisson bracket of gl(n)'): the linear part of
Λ_{λ1,λ2} is the Lie–Poisson bracket of (so(n) ⊕ Sym(n), [ξ+η, ζ+θ]_c = [ξ,ζ] + [ξ,θ] + [η,ζ] + c²[η,θ]) times
(λ1+λ2), c² = λ2/(λ1+λ2).  Killing form signature: c² > 0 → gl(n) (split), c² < 0 → u(n) (compact: semidefinite).
At λ1 + λ2 = 0 the linear part is nilpotent (only [η,θ]) and the constant part <A,[y,z]> has rank n² − n
everywhere (see h2-lambda-1m1-rank-everywhere), while gl(n)* has rank 0 at the origin."""
import numpy as np
n = 3
basis = []
for i in range(n):
    for j in range(n):
        E = np.zeros((n, n)); E[i, j] = 1; basis.append(E)
B = np.array([b.ravel() for b in basis]).T
def sk(m): return (m - m.T)/2
def sy(m): return (m + m.T)/2
for c2 in (1.0, -1.0, 0.0):
    def br(y, z):
        xi, eta, ze, th = sk(y), sy(y), sk(z), sy(z)
        return xi@ze - ze@xi + xi@th - th@xi + eta@ze - ze@eta + c2*(eta@th - th@eta)
    ad = [np.array([br(b, e).ravel() for e in basis]).T for b in basis]
    K = np.array([[np.trace(ad[a]@ad[b]) for b in range(n*n)] for a in range(n*n)])
    ev = np.linalg.eigvalsh((K+K.T)/2)
    print(f"c^2 = {c2:+.0f}: Killing form eigenvalues: {np.sum(ev > 1e-9)} positive, {np.sum(ev < -1e-9)} negative, {np.sum(abs(ev) <= 1e-9)} zero")
