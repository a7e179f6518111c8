"""Hostile strings in a claim's words (docstring/title, statement, erratum, place, paper label, section,
condition, slips, check names) for the Markdown, LaTeX and Jupyter renderers: HTML, Markdown links and
images, MathJax's \\href/\\style/\\class/\\unicode, TeX's \\input/\\write18/\\catcode, unbalanced math.
Each claim's truth: the first three are TRUE (XᵀX = I_r), the erratum one is FALSE as printed (XᵀX = −I_r)."""
from stiefelsym import admissible, claim

LINK = "[click me](javascript:alert(1)) ![img](http://127.0.0.1:9/track.png) <img src=x onerror=alert(1)>"
MJ = r"$\href{javascript:alert(1)}{X^T X} \style{color:red}{I} \class{x}{r} \unicode{x41}$"
TEX = r"$\input{/etc/passwd}$ \input{/etc/passwd} $\immediate\write18{id}$ $\catcode`\^^M=13$ $\csname input\endcsname{/etc/hostname}$"


@claim("s74-html-title", kind="id", sizes=admissible(n_max=2),
       statement=r"X^{T} X = I_r \href{javascript:alert(1)}{x}", paper=("prep",))
def html_title(s):
    """XᵀX = I_r, TRUE. [click me](javascript:alert(1)) ![img](http://127.0.0.1:9/track.png) <img src=x onerror=alert(1)> $\\href{javascript:alert(1)}{X^T X} \\style{color:red}{I}$ `code` <script>alert(1)</script>"""
    return {"id </td><script>alert(1)</script>": s.X.T @ s.X - s.Ir}


@claim("s74-tex-title", kind="id", sizes=admissible(n_max=2, condition=TEX),
       statement=r"X^T X = I_r \input{/etc/passwd}")
def tex_title(s):
    """XᵀX = I_r, TRUE. $\\input{/etc/passwd}$ \\input{/etc/passwd} $\\immediate\\write18{id}$ $\\csname input\\endcsname{/etc/hostname}$ $\\def\\x{y}\\x$ $\\lowercase{\\INPUT}$"""
    return {"id $\\input{/etc/passwd}$": s.X.T @ s.X - s.Ir}


@claim("s74-math-title", kind="id", sizes=admissible(n_max=2),
       statement=r"X^T X = I_r \end{gathered}$$ \input{/etc/passwd} $$\begin{gathered}")
def math_title(s):
    """XᵀX = I_r, TRUE. $X \\end{array}$$ \\input{/etc/passwd} $$\\begin{array}{l} Y$ and $}}}$ and $\\\\$"""
    return {"id": s.X.T @ s.X - s.Ir}


@claim("s74-erratum-text", kind="id", sizes=admissible(n_max=2), fails_at=lambda n, r: True,
       erratum=LINK + " " + MJ + " " + TEX, place=r"the proof \input{/etc/passwd} <b>x</b> [a](javascript:alert(1))",
       slips=(r"\input{/etc/passwd} \write18{id} x^^M", LINK), statement=r"X^T X = -I_r")
def erratum_text(s):
    """XᵀX = −I_r, FALSE (erratum) <iframe src=http://127.0.0.1:9/>."""
    return {"sign $\\href{javascript:alert(1)}{x}$ <b>": s.X.T @ s.X + s.Ir}
