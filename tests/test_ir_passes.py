"""stiefelsym.ir.passes.skew_by_construction: which traced matrices the twisted steps take as a field strength."""
from __future__ import annotations

import pytest

from stiefelsym.ir import compile_claim
from stiefelsym.ir.passes import skew_by_construction
from stiefelsym.scene import REALIZATIONS

STANDARD = REALIZATIONS["standard"]

SKEW = {
    "generic skew": lambda s: s.generic("K", "r", "r", "skew"),
    "eta": lambda s: s.eta,
    "theta": lambda s: s.theta,
    "Psi": lambda s: s.Psi,
    "M - M^T": lambda s: s.X.T @ s.A @ s.P - (s.X.T @ s.A @ s.P).T,
    "M^T - M": lambda s: (s.X.T @ s.P).T - s.X.T @ s.P,
    "multiples and sums": lambda s: s.eta * s.tr(s.X.T @ s.P) - s.generic("K", "r", "r", "skew") * 3 + s.eta * s.a[0],
    "negation and transpose": lambda s: -(s.eta.T) + s.eta / s.lam,
    "explicit": lambda s: s.mat([[0, s.lam], [-s.lam, 0]], ("r", "r")),
    "explicit constants": lambda s: s.mat([[0, 2], [-2, 0]], ("r", "r")),
    "zero": lambda s: s.zeros(2, 2, ("r", "r")),
    "skew times an entry of a product": lambda s: s.eta * (s.X.T @ s.X)[0, 1],
    "an entry of eta times an explicit skew matrix": lambda s: s.eta[0, 1] * s.mat([[0, 1], [-1, 0]], ("r", "r")),
    "skew times entries of X and of a generic matrix": lambda s: s.eta * s.X[2, 1] - s.generic("G", "r", "r")[1, 0] * s.eta,
}
NOT_SKEW = {
    "generic general": lambda s: s.generic("G", "r", "r"),
    "generic sym": lambda s: s.generic("S", "r", "r", "sym"),
    "Ir": lambda s: s.Ir,
    "X^T A X": lambda s: s.X.T @ s.A @ s.X,
    "M - N (not M^T)": lambda s: s.X.T @ s.A @ s.P - s.P.T @ s.A @ s.X,
    "product of skew": lambda s: s.eta @ s.generic("K", "r", "r", "skew"),
    "explicit symmetric": lambda s: s.mat([[0, s.lam], [s.lam, 0]], ("r", "r")),
    "explicit nonzero diagonal": lambda s: s.mat([[1, 2], [-2, 0]], ("r", "r")),
    "skew plus sym": lambda s: s.eta + s.generic("S", "r", "r", "sym"),
    "skew times a derivative": lambda s: s.eta * s.d(lambda t: t.tr(t.X.T @ t.P), {"X": s.P}),
    "skew times a block of a matrix": lambda s: s.eta @ s.X[0:2, 0:2],
    "an entry times a general matrix": lambda s: s.eta[0, 1] * s.generic("G", "r", "r"),
}


def _decide(build) -> bool:
    g = compile_claim(lambda s: {"F": build(s)}, 3, 2, (STANDARD.name, STANDARD.build))
    keys, values = g.args[g.output[0]]
    return skew_by_construction(g, values[0])


@pytest.mark.parametrize("name", sorted(SKEW))
def test_skew_constructions_are_recognised(name):
    assert _decide(SKEW[name])


@pytest.mark.parametrize("name", sorted(NOT_SKEW))
def test_other_matrices_are_not(name):
    assert not _decide(NOT_SKEW[name])
