"""Batch 8: the twisted bracket/flow with a field strength F that is not in so(r) (twisted.flow's docstring: F is
"an r x r skew matrix of the scene"; nothing checks it).  The free scene builds the Lagrange form
X' = H_P - X Pi, P' = -H_X - eps X' F + X Lam + P Pi; the coordinate scenes invert the form's matrix.

Residuals (H = 1/2 tr P^T P + 1/2 tr X^T A X, f = tr(B^T X), g = tr(C^T P)):
  b8-skew-antisym      F = eta (skew): {f, g} + {g, f} = 0                      TRUE (control)
  b8-sym-antisym       F = S (symmetric generic): {f, g} + {g, f}               ? (decided by numpy: b8_check.py.in)
  b8-id-antisym        F = I_r: {f, g} + {g, f}                                 ?
  b8-sym-energy        F = S: dH/dt along the twisted flow of H                 ?
  b8-id-energy         F = I_r: dH/dt along the flow of H                       ?
"""
from stiefelsym import admissible, claim, twisted

SZ = admissible(n_max=4)


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def _fg(s):
    B, C = s.generic("B", "n", "r"), s.generic("C", "n", "r")
    return (lambda t: t.tr(B.T @ t.X)), (lambda t: t.tr(C.T @ t.P))


def _anti(s, F):
    f, g = _fg(s)
    return {"{f,g}+{g,f}": twisted.bracket(s, f, g, F) + twisted.bracket(s, g, f, F)}


def _energy(s, F):
    return {"dH/dt": s.d(H, twisted.flow(s, H, F))}


@claim("b8-skew-antisym", kind="id", sizes=SZ)
def skew_antisym(s):
    return _anti(s, s.eta)


@claim("b8-sym-antisym", kind="id", sizes=SZ)
def sym_antisym(s):
    return _anti(s, s.generic("S", "r", "r", "sym"))


@claim("b8-id-antisym", kind="id", sizes=SZ)
def id_antisym(s):
    return _anti(s, s.Ir)


@claim("b8-sym-energy", kind="id", sizes=SZ)
def sym_energy(s):
    return _energy(s, s.generic("S", "r", "r", "sym"))


@claim("b8-id-energy", kind="id", sizes=SZ)
def id_energy(s):
    return _energy(s, s.Ir)


@claim("b8-skew-energy", kind="id", sizes=SZ)
def skew_energy(s):
    return _energy(s, s.eta)
