# ruff: noqa: E702, F821
"""numpy truth for h2_claims_d.py: on Ψ = 0 (P = (I − XXᵀ)Z), along the Euclidean Neumann flow (NE_XP):
(a) Λ = XᵀAX − ẊᵀẊ for every κ flow (λ = tr Λ of (neum-gras)); twin: XᵀAX + ẊᵀẊ;
(b) r = n − 1, N = I − XXᵀ = e_n⊗e_n: N̈ = AN + NA − 2tr(AN)N + 2Ṅ² − 2tr(Ṅ²)N ((neum-gras**) as a projector); twin: −2tr(AN)N → +… sign of A terms."""
import sys
import numpy as np
sys.argv = sys.argv[:1] + ["11"]
exec(open("/tmp/h2/out/indep.py").read().split("res = {}")[0])
for n in range(1, 6):
    for r in range(1, n + 1):
        A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
        X, P = point(n, r); P = (np.eye(n) - X @ X.T) @ P
        HN = lambda X, P: 0.5 * tr(P.T @ P) - (0.5 + kap) * tr((X.T @ P) @ (X.T @ P)) + 0.5 * tr(X.T @ A @ X)
        Xd, Pd, L, Pi = flow(HN, X, P)
        a = nrm(L - (X.T @ A @ X - Xd.T @ Xd)); at = nrm(L - (X.T @ A @ X + Xd.T @ Xd))
        HE = lambda X, P: 0.5 * tr(P.T @ P) + 0.5 * tr(X.T @ A @ X)
        Xd, Pd, L, Pi = flow(HE, X, P)
        N = np.eye(n) - X @ X.T
        Nd = -(P @ X.T + X @ P.T); Ndd = -(Pd @ X.T + 2 * P @ P.T + X @ Pd.T)
        rhs = A @ N + N @ A - 2 * tr(A @ N) * N + 2 * Nd @ Nd - 2 * tr(Nd @ Nd) * N
        rhst = -(A @ N + N @ A) + 2 * tr(A @ N) * N + 2 * Nd @ Nd - 2 * tr(Nd @ Nd) * N
        print(f"({n},{r}) (a) true {a:.1e} twin {at:.1e}   (b) true {nrm(Ndd - rhs):.1e} twin {nrm(Ndd - rhst):.1e}")
