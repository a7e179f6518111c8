"""Independent check (sympy, ambient derivatives at a random rational point, n = 3, r = 2) of
s77r-third-moving-true: got − part1 − part2 = 0.  Run: .venv/bin/python tests/adversary/s77/review/sympy_third_check.py"""
import random

import sympy as sp

random.seed(1)
n, r = 3, 2


def rm(a, b):
    return sp.Matrix(a, b, lambda i, j: sp.Rational(random.randint(-5, 5), random.randint(1, 3)))


A = rm(n, n)
A = A + A.T
X, P, U, V = rm(n, r), rm(n, r), rm(n, r), rm(n, r)
e, d, h = sp.symbols("e d h")


def F(X, P):
    return (X.T * A * X * X.T * P).trace() + (P.T * A * P).trace()


def D(expr, s):
    return sp.diff(expr, s).subs(s, 0)


y = X + d * U + h * V
xd = X + d * U
got = D(D(D(F(y + e * A * y, P), e), h), d)
part1 = D(D(D(F(y + e * A * xd, P), e), h), d)
part2 = D(D(F(xd + e * A * V, P), e), d)
print("got - part1 - part2 =", sp.simplify(got - part1 - part2))
