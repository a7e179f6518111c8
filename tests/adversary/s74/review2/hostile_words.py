"""A claim's words that try Markdown around the escaping of s74: bare URLs (GFM autolinks), a link reference
definition in a check name with blank lines, shortcut images ![r], HTML entities, Jupyter's \\( \\) delimiters
(written \\\\( in Markdown), MathJax commands in \\text{} and in math that passes math_ok.  Truth: the first claims are
TRUE (XᵀX = I_r); r2-h-erratum is FALSE as printed (an erratum); legit-math is TRUE."""
from stiefelsym import admissible, claim

DEF = "[r]: http://127.0.0.1:9/def.png"


@claim("r2-h-autolink", kind="id", sizes=admissible(n_max=2))
def autolink(s):
    """XᵀX = I_r, TRUE. See https://127.0.0.1:9/auto.png and www.example.com/track and ![r] and [r] and
    &#60;img src=x onerror=alert(1)&#62; and \\(\\href{https://127.0.0.1:9/}{X}\\) and
    $\\text{\\(x\\)}$ $\\text{$\\href{https://x}{y}$}$ $\\mathrm{a}\\;\\$\\text{\\$\\unicode{x41}\\$}$"""
    return {DEF: s.X.T @ s.X - s.Ir}


@claim("r2-h-erratum", kind="id", sizes=admissible(n_max=2), fails_at=lambda n, r: True,
       erratum="XᵀX is I_r, not −I_r; see https://127.0.0.1:9/err ![r] [r]",
       place="https://127.0.0.1:9/place", statement=r"X^T X = -I_r")
def erratum(s):
    """XᵀX = −I_r, FALSE (erratum)."""
    return {"![q] https://127.0.0.1:9/check": s.X.T @ s.X + s.Ir}


@claim("r2-h-legit-math", kind="id", sizes=admissible(n_max=2), paper=("9",),
       statement=r"[X^T X, \Psi] = 0 \text{ for } \lambda \ne a_i")
def legit(s):
    """(9) §4: $\\lambda \\neq a_i$, [A, B] = AB − BA, $[X^T X, \\Psi] = 0$, $\\frac{1}{2}\\operatorname{tr} P^T P$,
    x < y > z, a*b*c, 2 * 3, snake_case_name: TRUE."""
    return {"[X^T X, Psi]": s.X.T @ s.X @ s.Psi - s.Psi @ s.X.T @ s.X}


@claim("r2-h-entities", kind="id", sizes=admissible(n_max=2),
       erratum="", place="")
def entities(s):
    """XᵀX = I_r, TRUE. &#36;&#92;href{https://127.0.0.1:9/x}{click}&#36; &#92;(&#92;style{color:red}{X}&#92;)
    &#x5c;[&#x5c;unicode{x41}&#x5c;] &#36;&#92;require{action}&#36; &dollar;&bsol;class{x}{y}&dollar;"""
    return {"w &#36;&#92;href{https://127.0.0.1:9/c}{c}&#36;": s.X.T @ s.X - s.Ir}
