"""Check names (dict keys) with characters the reports pass on: U+0085, U+2028/2029 (line/paragraph separators),
U+202E (bidi override), U+200B (zero width), U+009B (C1 CSI), Markdown math, HTML, LaTeX.  Every graph is XᵀX − Iᵣ
(TRUE) except "math", XᵀP + PᵀX (TRUE).  verification.md and `show` print the names raw (C0 controls and newlines
are refused; LaTeX names the others [U+202E]); the PDF compiles."""
from stiefelsym import claim

@claim("p-names", kind="id", sizes=[(3, 2)])
def p_names(s):
    return {
        "nel\u0085## Proved\u2028- fake: XᵀX − Iᵣ\u2029x": s.X.T @ s.X - s.Ir,
        "math $X^T P + P^T X \\neq 0$ z": s.X.T @ s.P + s.P.T @ s.X,
        "bidi \u202eXᵀX": s.X.T @ s.X - s.Ir,
        "zw\u200b\u200b": s.X.T @ s.X - s.Ir,
        "comment <!-- ": s.X.T @ s.X - s.Ir,
        "html <span style='display:none'>": s.X.T @ s.X - s.Ir,
        "tex \\end{itemize}\\section{X}": s.X.T @ s.X - s.Ir,
        "c1\x9bXXᵀ − Iₙ": s.X.T @ s.X - s.Ir,
    }
