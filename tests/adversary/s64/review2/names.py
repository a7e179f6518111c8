# ruff: noqa
"""Claim-chosen names in the reports (q64): scalars and generics whose names have several underscores,
check names with TeX/Markdown specials.  q64-names-true is true, q64-names-false false (c X != X)."""
from stiefelsym import admissible, claim


@claim("q64-names-true", kind="id", sizes=admissible(n_max=3))
def names_true(s):
    """(c XᵀX − c I) = 0 and G − G = 0 with names a_b_c and g_1_2."""
    c = s.scalar("a_b_c")
    G = s.generic("g_1_2", "n", "r")
    return {"x_1_2 \\begin {matrix} $ <!-- |": c * (s.X.T @ s.X) - c * s.Ir + (G - G).T @ s.X,
            "\n<!--\n": c * (s.X.T @ s.P + s.P.T @ s.X)}


@claim("q64-names-false", kind="id", sizes=admissible(n_max=3))
def names_false(s):
    """c X = X (false)."""
    c = s.scalar("a_b_c")
    G = s.generic("g_1_2", "n", "r")
    return {"x_1_2 \\begin {matrix} $ <!-- |": c * s.X - s.X + 0 * G, "\n<!--\n": c * s.X.T @ s.X - s.Ir}
