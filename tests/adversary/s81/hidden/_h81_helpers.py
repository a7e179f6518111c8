"""Helpers of the h81 trial (no claims): Hamiltonians and functions on so(n), so(r), gl(n)."""
from stiefelsym.brackets import linear, quadratic, trace_power


def Phi(t):
    return t.Phi


def Psi(t):
    return t.Psi


def Theta(t):
    return t.Phi + t.X @ t.X.T


def so_n_functions():
    """h1 = ½<μ, 𝔸μ> (𝔸 generic symmetric), h2 = tr(μ + λA)³ (not ad-invariant, gradient with a Sym part)."""
    return [("h_AA", quadratic(lambda t, x: t.sym_operator("AA")(x))),
            ("tr(mu+lam A)^3", trace_power(3, shift=lambda t: t.lam * t.A))]


def B_r(t):
    G = t.generic("B", "r", "r")
    return G + G.T


def so_r_functions():
    """f1 = <η, θ>² (a product of MatrixFunctions), f2 = tr(η + μB)³ (B generic symmetric r×r)."""
    lin = linear(lambda t: t.theta, "<eta, theta>")
    return [("<eta,theta>^2", lin * lin),
            ("tr(eta+mu B)^3", trace_power(3, shift=lambda t: t.scalar("mu") * B_r(t)))]


def gl_functions():
    """F1 = tr(x + C)³ (C a generic n×n matrix), F2 = ½<x, x + xᵀ> (quadratic, op symmetric for <,>)."""
    return [("tr(x+C)^3", trace_power(3, shift=lambda t: t.generic("C", "n", "n"))),
            ("1/2<x, x+x^T>", quadratic(lambda t, x: x + x.T))]


def H_neum(t):
    """(neumann) with a generic κ."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2
