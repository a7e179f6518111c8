# the EL accelerations of T2 = tr(XdᵀYd) + Xd1 Xd2 (g4 Yd1 - g3 Yd2) - tr(XᵀAY), XᵀY = 1 (n=2, r=1) differ from (D-eq)
import sympy as sp, random
random.seed(3)
t = sp.symbols('t')
x = [sp.Function(f'x{i}')(t) for i in range(2)]; y = [sp.Function(f'y{i}')(t) for i in range(2)]
mu = sp.Symbol('mu'); a = [sp.Rational(random.randint(1, 9)), sp.Rational(random.randint(10, 19))]
g = [sp.Rational(random.randint(-9, 9), random.randint(1, 5)) for _ in range(4)]
xd = [v.diff(t) for v in x]; yd = [v.diff(t) for v in y]
L = (xd[0]*yd[0] + xd[1]*yd[1] + xd[0]*xd[1]*(g[3]*yd[0] - g[2]*yd[1]) - (a[0]*x[0]*y[0] + a[1]*x[1]*y[1])
     + mu*(x[0]*y[0] + x[1]*y[1] - 1))
q = x + y
eqs = [sp.diff(sp.diff(L, v.diff(t)), t) - sp.diff(L, v) for v in q] + [(x[0]*y[0] + x[1]*y[1]).diff(t, 2)]
R = lambda: sp.Rational(random.randint(-9, 9), random.randint(1, 4))
X = [R(), R()]; Y0 = [R(), R()]; s_ = X[0]*Y0[0] + X[1]*Y0[1]; Y = [Y0[0]/s_, Y0[1]/s_]
Xd = [R(), R()]; Yd0 = [R(), R()]
# X·Yd + Xd·Y = 0
c = -(Xd[0]*Y[0] + Xd[1]*Y[1] + X[0]*Yd0[0] + X[1]*Yd0[1]) / (X[0]**2 + X[1]**2)
Yd = [Yd0[0] + c*X[0], Yd0[1] + c*X[1]]
sub = {}; accs = sp.symbols('a0 a1 b0 b1')
for v, val, vel, ac in zip(q, X + Y, Xd + Yd, accs):
    sub[v.diff(t, 2)] = ac; sub[v.diff(t)] = vel; sub[v] = val
sol = sp.solve([sp.expand(e.subs(sub)) for e in eqs], list(accs) + [mu], dict=True)[0]
A = sp.diag(*a); Xm = sp.Matrix(X); Ym = sp.Matrix(Y); Xdm = sp.Matrix(Xd); Ydm = sp.Matrix(Yd)
Lam = (Xm.T*A*Ym - Xdm.T*Ydm)[0]
print("EL Xdd:", [sol[accs[0]], sol[accs[1]]], "(D-eq):", list(-A*Xm + Xm*Lam))
