# ruff: noqa
"""Class 2: strings accepted by Trace.arg as operands of arithmetic (type str passes `arg`).
c2-str-mul (FALSE unless '2' read as 2): X*"2" - 2X  (if "2"->2 TRUE-ish) ; we look at what happens.
c2-str-sub (FALSE): tr(XᵀX) - "r"  : if "r" were read as a parameter/size r it would be 0 (true identity tr XᵀX = r).
c2-str-lam (FALSE): lam - "lam" (0 only if the string is read as the parameter λ).
c2-str-zero (FALSE): tr(PᵀP) * "0"  (0 only if "0" read as 0; tr PᵀP is nonzero).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)

@claim("c2-str-sub", kind="id", sizes=SZ)
def a(s):
    """FALSE as a number: tr(XᵀX) − 'r'."""
    return {"r": s.tr(s.X.T @ s.X) - "r"}

@claim("c2-str-lam", kind="id", sizes=SZ)
def b(s):
    """FALSE: λ − 'lam'."""
    return {"r": s.lam - "lam"}

@claim("c2-str-zero", kind="id", sizes=SZ)
def c(s):
    """FALSE: tr(PᵀP)·'0'."""
    return {"r": s.tr(s.P.T @ s.P) * "0"}

@claim("c2-str-mat", kind="id", sizes=SZ)
def d(s):
    """FALSE: X·'0'."""
    return {"r": s.X * "0"}

@claim("c2-str-q", kind="id", sizes=SZ)
def e(s):
    """FALSE: tr(PᵀP)·q('0')."""
    return {"r": s.tr(s.P.T @ s.P) * s.q("0")}

@claim("c2-str-pow", kind="id", sizes=SZ)
def f(s):
    """FALSE: tr(PᵀP)**'0' - 1 ... (x^0 = 1 so TRUE if read as 0); tr(PᵀP)^'1' - 1 FALSE."""
    return {"r": s.tr(s.P.T @ s.P) ** "1" - 1}
