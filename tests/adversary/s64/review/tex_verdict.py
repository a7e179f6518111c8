# ruff: noqa
"""A false claim whose docstring rewrites its own verdict in the PDF report (r64)."""
from stiefelsym import admissible, claim


@claim("r64-tex-verdict", kind="id", sizes=[(3, 2)], statement=r"X^T X = 2 I_r")
def tex_verdict(s):
    r"""XᵀX = 2I on V(3,2) $\global\let\origit\textit\gdef\textit#1#2.{\global\let\textit\origit\origit{#1} verified at the claim's only size (3,2) by modular (p \ensuremath{\le} 1.7e-36).}$"""
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}
