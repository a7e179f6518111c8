"""Theorem 10.3: with (I_n - lambda A)^{-1} in the off-diagonal blocks of L(lambda), as printed in
(LA3*), the Neumann system (W-eq) on the complex Stiefel variety W(n, r) does not imply dL/dt = [L, A];
it does with (lambda I_n - A)^{-1} there (the correction)."""
import sympy as sp

CHECK = "d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)]"


def residuals(W):
    A, lam = W["A"], W["lam"]
    Z = W["ReZ"] + sp.I * W["ImZ"]                          # the point Z of W(n, r): conj(Z)^T Z = I_r
    V = W["ReV"] + sp.I * W["ImV"]                          # Z' = V
    n, r = Z.shape
    t = sp.Symbol("t", real=True)
    bar = lambda M: M.applyfunc(sp.conjugate)
    R = (lam * sp.eye(n) - A).inv()                         # (lambda I_n - A)^{-1}
    Lam = bar(Z).T * A * Z - bar(V).T * V                   # (W-L)
    Zdd = -A * Z + Z * Lam                                  # (W-eq)

    def L_W(S, Z, Zb, Zd, Zdb):                             # (LA3*), S in the off-diagonal blocks
        return sp.Matrix(sp.BlockMatrix([[-Z.T * R * Zdb, -Z.T * S * Zb],
                                         [sp.eye(r) + Zd.T * S * Zdb, Zd.T * R * Zb]]))

    A_W = sp.Matrix(sp.BlockMatrix([[sp.zeros(r), sp.eye(r)],                    # (LA3*): A(lambda)
                                    [bar(Lam) - lam * sp.eye(r), sp.zeros(r)]]))

    def realified(M):                                       # each r x r block as [[Re, -Im], [Im, Re]]
        def re(B): return B.applyfunc(lambda x: sp.re(sp.expand(x)))
        def im(B): return B.applyfunc(lambda x: sp.im(sp.expand(x)))
        blk = lambda B: sp.Matrix(sp.BlockMatrix([[re(B), -im(B)], [im(B), re(B)]]))
        return sp.Matrix(sp.BlockMatrix([[blk(M[:r, :r]), blk(M[:r, r:])], [blk(M[r:, :r]), blk(M[r:, r:])]]))

    def lax(S):                                             # dL/dt - [L, A] along (W-eq)
        path = L_W(S, Z + t * V, bar(Z) + t * bar(V), V + t * Zdd, bar(V) + t * bar(Zdd))
        dL = sp.diff(path, t).subs(t, 0)
        L = L_W(S, Z, bar(Z), V, bar(V))
        return realified(dL - (L * A_W - A_W * L))

    printed = lax((sp.eye(n) - lam * A).inv())             # (LA3*) as printed: (I_n - lambda A)^{-1}
    corrected = lax(R)                                      # the correction: (lambda I_n - A)^{-1}
    return {"printed": printed, "corrected": corrected}
