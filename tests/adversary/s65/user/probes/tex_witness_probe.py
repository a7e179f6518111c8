# ruff: noqa
"""Probe: a failing claim whose residual reads only the claim's own generic parameters (no X, P): the
witness 'to check by hand' in verification.md is an empty $$$$ and verification.tex does not compile."""
from stiefelsym import admissible, claim


@claim("s65p-params-only", kind="id", sizes=[(2, 1)], fails_at=lambda n, r: True, erratum="probe: G - G^T is not 0")
def params_only(s):
    G = s.generic("G", "n", "n")
    return {"G - G^T": G - G.T}
