# ruff: noqa: F841, E702, F401, E731, E741
"""Review2 s63: the engine's degree bound (fixed_size.degree_bound, the structural markers used by the
modular/rational Schwartz-Zippel bounds) against the true total degree of each residual's reduced numerator,
computed by sympy on the same Cayley chart (X = 2(I+S)^-1 J - J, P = XW + Z - X X^T Z, A = diag(a), lambda).
Usage: .venv/bin/python tests/adversary/s63/review2/degree_truth.py"""
import sys
import sympy as sp
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[3]))
from stiefelsym.claims import load_claims_file          # noqa: E402
from stiefelsym.methods.fixed_size import degree_bound   # noqa: E402


def chart(n, r):
    S = sp.zeros(n, n)
    for i in range(n):
        for j in range(i + 1, n):
            s = sp.Symbol(f"s{i}{j}")
            S[i, j], S[j, i] = s, -s
    W = sp.zeros(r, r)
    for i in range(r):
        for j in range(i + 1, r):
            w = sp.Symbol(f"w{i}{j}")
            W[i, j], W[j, i] = w, -w
    Z = sp.Matrix(n, r, lambda i, j: sp.Symbol(f"z{i}{j}"))
    J = sp.eye(n)[:, :r]
    X = (2 * (sp.eye(n) + S).inv() * J - J).applyfunc(sp.cancel)
    P = (X * W + Z - X * (X.T * Z)).applyfunc(sp.cancel)
    A = sp.diag(*[sp.Symbol(f"a{i}") for i in range(n)])
    lam = sp.Symbol("lam")
    return X, P, A, lam


def truth(cid, X, P, A, lam, n, r):
    I_n, I_r = sp.eye(n), sp.eye(r)
    tr = lambda M: M.trace()
    if cid == "d-inv-r":
        return (X.T * A * X + P.T * P + lam * I_r).inv()
    if cid == "d-inv-n":
        return (A + P * P.T + lam * I_n).inv()
    if cid == "d-resolvent":
        return P.T * (lam * I_n - A).inv() * P
    if cid == "d-det":
        return sp.Matrix([[(A + P * P.T + lam * I_n).det()]])
    if cid == "d-flow":                       # d/dt tr(X^T A^2 X), Xdot = P on T*V (Pi = 0)
        return sp.Matrix([[2 * tr(X.T * A * A * P)]])
    if cid == "d-bracket":                    # {f, g} = <grad f, J grad g>: f_X = 2A^2X, g_P = 2AP; Pi terms vanish?
        Xd = 2 * A * P - X * (X.T * A * P + P.T * A * X)        # the Dirac flow of g (Pi = sym(X^T g_P))
        return sp.Matrix([[2 * tr(X.T * A * A * Xd)]])
    if cid == "d-elem":
        M = A * P * P.T
        return sp.Matrix([[(tr(M) ** 2 - tr(M * M)) / 2]])
    if cid == "d-negpow":
        return sp.Matrix([[tr(X.T * A * X + P.T * P) ** -2]])
    if cid == "d-nested":
        return ((A + lam * I_n).inv() * P * P.T + I_n).inv()
    if cid == "d-divtrace":
        return P / tr(P.T * A * P + I_r)
    if cid == "d-res-moving":
        mu = tr(P.T * P)
        return X.T * (mu * I_n - A).inv() * X
    if cid == "d-tangent-div":
        M = X.T * A * X + P.T * P
        Mi = M.inv()
        return -Mi * (2 * (P.T * A * X + X.T * A * P)) * Mi
    if cid == "d-bracket-flow":
        pass
    if cid == "d-grad":
        return 6 * tr(X.T * A * X) ** 2 * A * X     # the ambient gradient in X
    return None


def numdeg(e):
    e = sp.cancel(sp.together(e))
    num, _ = sp.fraction(e)
    if num == 0:
        return -1
    return sp.Poly(sp.expand(num), *sorted(num.free_symbols, key=str)).total_degree() if num.free_symbols else 0


def main():
    reg = load_claims_file(HERE / "degD.py")
    for n, r in [tuple(map(int, a.split(","))) for a in (sys.argv[1:] or ["2,1"])]:
        X, P, A, lam = chart(n, r)
        for c in reg:
            b = degree_bound(c, n, r)
            T = truth(c.id, X, P, A, lam, n, r)
            if T is None:
                print(f"{c.id:16} ({n},{r}) bound d<={b.numerator} h<={b.height:.1f}  truth: -")
                continue
            d = max(numdeg(x) for x in T)
            flag = "  <-- BOUND TOO SMALL" if d > b.numerator else ""
            print(f"{c.id:16} ({n},{r}) bound d<={b.numerator} h<={b.height:.1f}  true deg={d}{flag}", flush=True)


if __name__ == "__main__":
    main()
