"""Class 5/4: claims that read no leaf of the scene, decided by the modular/rational methods' constant route
(`_run_constant`: "no parameter entered the checks", one seeded point over Q) when the scene drew no parameter.

 cr-inv-true:   Inverse(x ↦ 2x, y ↦ y/2) on Sym(r): TRUE.
 cr-inv-false:  Inverse(x ↦ 2x, y ↦ y/3): FALSE.
 cr-inv-sq-false: Inverse(x ↦ x·x, y ↦ y) on R^{r×r}: FALSE (not linear, not inverted).
 cr-fresh-false: U = s.fresh("r", "r"); U − Uᵀ = 0: FALSE (a generic matrix is not symmetric).
 cr-fresh-true:  U = s.fresh("r", "r"); (U + Uᵀ) − (U + Uᵀ)ᵀ = 0: TRUE.
 cr-op-false:   s.sym_operator() applied to a constant skew E₁₂ − E₂₁ (r×r), minus itself transposed... 𝔸(E) + 𝔸(E)ᵀ
                = 0 is TRUE (𝔸 maps so into so); the FALSE twin 𝔸(E) = 0.
"""
from stiefelsym import Inverse, admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("cr-inv-true", kind="id", sizes=SZ)
def inv_true(s):
    return {"inv": Inverse(lambda t, x: x * 2, lambda t, y: y / 2, on="Sym(r)")}


@claim("cr-inv-false", kind="id", sizes=SZ)
def inv_false(s):
    return {"inv": Inverse(lambda t, x: x * 2, lambda t, y: y / 3, on="Sym(r)")}


@claim("cr-inv-sq-false", kind="id", sizes=SZ)
def inv_sq_false(s):
    return {"inv": Inverse(lambda t, x: x @ x, lambda t, y: y, on="R^{r×r}")}


@claim("cr-fresh-false", kind="id", sizes=SZ)
def fresh_false(s):
    U = s.fresh("r", "r")
    return {"U - Ut": U - U.T}


@claim("cr-fresh-true", kind="id", sizes=SZ)
def fresh_true(s):
    U = s.fresh("r", "r")
    V = U + U.T
    return {"V - Vt": V - V.T}


def _E(s):
    r = int(s.r)
    return s.mat([[(1 if (i, j) == (0, 1) else -1 if (i, j) == (1, 0) else 0) for j in range(r)] for i in range(r)],
                 ("r", "r"))


@claim("cr-op-true", kind="id", sizes=admissible(n_max=3, n_min=2, r_min=2))
def op_true(s):
    O = s.sym_operator()
    W = O(_E(s))
    return {"skew": W + W.T}


@claim("cr-op-false", kind="id", sizes=admissible(n_max=3, n_min=2, r_min=2))
def op_false(s):
    O = s.sym_operator()
    return {"A(E)": O(_E(s))}
