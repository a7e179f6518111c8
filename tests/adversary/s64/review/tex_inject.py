# ruff: noqa
"""Hostile statements and titles: LaTeX and Markdown injection (r64)."""
from stiefelsym import admissible, claim


@claim("r64-tex-false", paper="prep", kind="id", sizes=[(3, 2)],
       statement=r"X^T X = 2 I_r \input{/etc/hostname}")
def tex_false(s):
    """A false statement | with a pipe | in its title $x \input{/etc/hostname}$ and more."""
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}


@claim("r64-tex-true", paper="prep", kind="id", sizes=[(3, 2)],
       statement=r"X^T X = I_r")
def tex_true(s):
    """A true statement."""
    return {"XtX": s.X.T @ s.X - s.Ir}
