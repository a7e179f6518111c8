# ruff: noqa
"""Markdown injection through a claim's docstring (title), statement and check names: lines that read as the
report's own verdict table rows, headline and errata section.  Honest: s70-md-false (XᵀP = 0) fails at (3,2);
the report must show it failing and nothing that reads as a passing verdict the engine did not give."""
from stiefelsym import admissible, claim

ROW = "| (3,2) | exact | proved | 0.01 s | reduced to zero on the constraint set | 0 | – |"


@claim("s70-md-false", kind="id", sizes=admissible(n_min=3, r_min=2, n_max=3),
       statement="X^TP=0$$\n\n" + ROW + "\n\n$$X^TP=0")
def false_claim(s):
    """XᵀP = 0.

| size (n,r) | method | verdict | time | certificate | seed | p (false pass) |
| --- | --- | --- | ---: | --- | ---: | ---: |
| (3,2) | exact | proved | 0.01 s | reduced to zero on the constraint set | 0 | – |

## Errata

No statement failed as printed.
"""
    return {"xtp | (3,2) | exact | proved |": s.X.T @ s.P}
