import sympy as sp, random
n, r = 3, 2
t = sp.symbols('t')
Xf = sp.Matrix(n, r, lambda i, j: sp.Function(f'x{i}{j}')(t))
Yf = sp.Matrix(n, r, lambda i, j: sp.Function(f'y{i}{j}')(t))
mu = sp.Matrix(r, r, lambda i, j: sp.Symbol(f'm{i}{j}'))
random.seed(1)
A = sp.diag(*[sp.Rational(random.randint(1, 20), random.randint(1, 5)) for _ in range(n)])
c = 1 + (Xf.T * Xf).trace()
L = c * (Xf.diff(t).T * Yf.diff(t)).trace() - (Xf.T * A * Yf).trace() + (mu.T * (Xf.T * Yf - sp.eye(r))).trace()
eqs = []
for M in (Xf, Yf):
    for i in range(n):
        for j in range(r):
            q = M[i, j]
            eqs.append(sp.diff(sp.diff(L, q.diff(t)), t) - sp.diff(L, q))
g = Xf.T * Yf - sp.eye(r)
eqs += list(g.diff(t, 2))
# random point: X random, Y = X (X^T X)^{-1} + N with X^T N = 0 ; velocities with Xd^T Y + X^T Yd = 0
def rnd(): return sp.Rational(random.randint(-9, 9), random.randint(1, 4))
X = sp.Matrix(n, r, lambda i, j: rnd()); Y = X * (X.T * X).inv()
Xd = sp.Matrix(n, r, lambda i, j: rnd()); Yd0 = sp.Matrix(n, r, lambda i, j: rnd())
# project Yd so that X^T Yd = -Xd^T Y : Yd = Yd0 + X (X^T X)^{-1} (-Xd^T Y - X^T Yd0)
Yd = Yd0 + X * (X.T * X).inv() * (-Xd.T * Y - X.T * Yd0)
sub = {}
acc = []
for M, V, W, name in ((Xf, X, Xd, 'a'), (Yf, Y, Yd, 'b')):
    for i in range(n):
        for j in range(r):
            a = sp.Symbol(f'{name}{i}{j}'); acc.append(a)
            sub[M[i, j].diff(t, 2)] = a
            sub[M[i, j].diff(t)] = W[i, j]
            sub[M[i, j]] = V[i, j]
E = [sp.expand(e.subs(sub)) for e in eqs]
sol = sp.solve(E, acc + list(mu), dict=True)[0]
Xdd = sp.Matrix(n, r, lambda i, j: sol[sp.Symbol(f'a{i}{j}')]); Ydd = sp.Matrix(n, r, lambda i, j: sol[sp.Symbol(f'b{i}{j}')])
cc = 1 + (X.T * X).trace(); cd = 2 * (X.T * Xd).trace(); tau = (Xd.T * Yd).trace()
M = X.T * A * Y - X.T * X * tau - Xd.T * Yd * cc
RX = (-(A * X) - Xd * cd + X * M.T) / cc; RY = (-(A * Y) - Yd * cd + X * (tau * 2) + Y * M) / cc
print("real formula:", sp.simplify(Xdd - RX), sp.simplify(Ydd - RY))
M2 = X.T * A * Y - Xd.T * Yd * cc
NX = (-(A * X) + X * M2.T) / cc; NY = (-(A * Y) + Y * M2) / cc
print("naive:", sp.simplify(Xdd - NX) == sp.zeros(n, r), sp.simplify(Ydd - NY) == sp.zeros(n, r))
