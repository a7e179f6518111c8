"""Claims whose "As traced" text (verification.md/.tex, `stiefelsym show`) reads as another statement than the
graph the methods evaluated.  Each docstring: what the text reads as, what the graph is, the truth.
Truth of each graph: by hand (below) and numerically in truth_numpy.py (no stiefelsym import).

K = ½ tr PᵀP (geodesic), H = ½ tr PᵀP + ½ tr XᵀAX (Neumann).
"""
from stiefelsym import admissible, claim


def K(t):
    return t.tr(t.P.T @ t.P) / 2


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("t1-energy-refuted", kind="id", sizes=admissible(n_max=4, where=lambda n, r: 1 < r < n))
def t1(s):
    """The Neumann energy H is conserved along the Neumann flow (TRUE as worded).
    Graph: dH/dt along the flow of K (the geodesic flow), which is tr(XᵀAẊ) ≠ 0: fails (right for the graph).
    The text shows d/dt(½tr(PᵀP) + ½tr(XᵀAX)) with no flow: a reader sees energy conservation refuted."""
    return {"dH/dt": s.d(H, s.dirac_flow(K))}


@claim("t2-kinetic-proved", kind="id", sizes=admissible(n_max=3))
def t2(s):
    """The kinetic energy ½tr PᵀP is conserved along the Neumann flow (FALSE: d/dt = −tr(PᵀAX) ≠ 0 on T*V).
    Graph: dK/dt along the flow of K itself (TRUE, 0).  Text d/dt(½tr(PᵀP)): proved."""
    return {"dK/dt": s.d(K, s.dirac_flow(H) if False else s.dirac_flow(K))}


@claim("t3-pdot-zero", kind="not", expect="nonzero", sizes=admissible(n_max=4, where=lambda n, r: 1 < r < n))
def t3(s):
    """Ṗ of the geodesic flow minus Ṗ of the Neumann flow (= the constrained −AX term, nonzero): TRUE that it does
    not vanish.  The text: both are written Ṗ (the flow is not shown), so the residual reads Ṗ − Ṗ (or 0):
    a reader sees '0 does not vanish' proved."""
    return {"Pdot(K) - Pdot(H)": s.dirac_flow(K).Pdot - s.dirac_flow(H).Pdot}


@claim("t4-entry-param", kind="not", expect="nonzero", sizes=[(2, 1)])
def t4(s):
    """Text: X₁₁P₁₁ + X₂₁P₂₁ (= XᵀP at (2,1)) does not vanish -- FALSE: on T*V(n,1) XᵀP + PᵀX = 2XᵀP = 0.
    Graph: X₁₁P₁₁ + X₂₁·c with c = s.scalar("P21"), a free parameter: nonzero (TRUE).  Proved."""
    return {"XᵀP": s.X[0, 0] * s.P[0, 0] + s.X[1, 0] * s.scalar("P21")}


@claim("t5-identity-param", kind="not", expect="nonzero", sizes=[(3, 2)])
def t5(s):
    """Text: XᵀX − I₂ does not vanish at r = 2 -- FALSE (XᵀX = I_r).  Graph: XᵀX − G, G = s.generic("I2", "r", "r")."""
    return {"XᵀX − I": s.X.T @ s.X - s.generic("I2", "r", "r")}


@claim("t6-multiplier-param", kind="id", sizes=admissible(n_max=3))
def t6(s):
    """Text: Λ + Λᵀ = 0, i.e. the multiplier Λ of (dot_XP) for the Neumann flow is skew -- FALSE (Λ = XᵀAX − PᵀP
    up to sign, symmetric, nonzero).  Graph: Λ = s.generic("Lambda", "r", "r", "skew"): TRUE, proved.
    The honest graph (multiplier_flow(H)["Lambda"]) prints the same text, Λ + Λᵀ (claim t6b)."""
    L = s.generic("Lambda", "r", "r", "skew")
    return {"Λ skew": L + L.T}


@claim("t6b-multiplier-honest", kind="id", sizes=admissible(n_max=3))
def t6b(s):
    """The honest twin of t6: the multiplier Λ of the Neumann flow is skew (FALSE): fails.  Same text as t6."""
    L = s.multiplier_flow(H)["Lambda"]
    return {"Λ skew": L + L.T}


@claim("t7-tr-param", kind="not", expect="nonzero", sizes=admissible(n_max=4, where=lambda n, r: 1 < r < n))
def t7(s):
    """Text: tr(XᵀP − PᵀX) does not vanish -- FALSE (the trace of a skew matrix is 0).
    Graph: c·(XᵀP − PᵀX), c = s.scalar("tr"): nonzero (TRUE), proved."""
    return {"tr Ψ": s.scalar("tr") * (s.X.T @ s.P - s.P.T @ s.X)}


@claim("t8-product-name", kind="not", expect="nonzero", sizes=admissible(n_max=4, where=lambda n, r: 1 < r < n))
def t8(s):
    """Text: XᵀAX − (XᵀAX)ᵀ does not vanish (XᵀAX not symmetric) -- FALSE (A symmetric).
    Graph: XᵀG − (XᵀG)ᵀ with G = s.generic("AX", "n", "r"), an n×r generic matrix: nonzero, proved."""
    G = s.generic("AX", "n", "r")
    return {"XᵀAX sym": s.X.T @ G - (s.X.T @ G).T}


@claim("t9-twin-names", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def t9(s):
    """Text: XᵀX − Iᵣ does not vanish -- FALSE.  Graph: XᵀX − Iᵣ + G1 − G_1 with two DIFFERENT generic r×r
    parameters named "G1" and "G_1" (both printed G₁, so the notation cancels them): nonzero, proved."""
    return {"XᵀX − Iᵣ": s.X.T @ s.X - s.Ir + s.generic("G1", "r", "r") - s.generic("G_1", "r", "r")}


@claim("t9b-twin-names-id", kind="id", sizes=admissible(n_max=3))
def t9b(s):
    """Text: XᵀP + PᵀX (the tangency condition, TRUE on T*V).  Graph: XᵀP + PᵀX + lam1 − lam_1 (two parameters
    printed λ₁): nonzero, fails -- a true statement shown refuted."""
    return {"XᵀP + PᵀX": s.X.T @ s.P + s.P.T @ s.X + (s.scalar("lam1") - s.scalar("lam_1")) * s.Ir}


@claim("t10-closure-constant", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def t10(s):
    """Text: d/dt(½tr(XᵀAX)) = 0, the potential is conserved along the Neumann flow -- FALSE (its derivative is
    tr(XᵀAP) ≠ 0; truth_numpy.py t1).  Graph: the function differentiated reads the claim's own s.X, s.A (closure
    constants, not differentiated, as the guide says), so its derivative is 0: proved.  The same text is printed
    for lambda t: t.tr(t.X.T @ t.A @ t.X) / 2, whose derivative is not 0 (see `show` of this file's t10b)."""
    return {"dV/dt": s.d(lambda t: s.tr(s.X.T @ s.A @ s.X) / 2, s.dirac_flow(H))}


@claim("t10b-closure-honest", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def t10b(s):
    """The honest twin of t10 (FALSE statement, fails); the same text."""
    return {"dV/dt": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X) / 2, s.dirac_flow(H))}


@claim("t11-bidi-name", kind="id", sizes=admissible(n_max=3))
def t11(s):
    """Graph: Ψ − XᵀP + PᵀX (TRUE: Ψ = XᵀP − PᵀX), proved.  Its check name ends with U+202E (RIGHT-TO-LEFT
    OVERRIDE), which verification.md and `show` pass on unescaped: a bidi renderer (a browser showing the Markdown)
    displays the rest of the line reversed, ": Ψ − XᵀP + PᵀX" as "XᵀP + PᵀX − Ψ :", which reads as the statement
    XᵀP + PᵀX = Ψ -- FALSE (the difference is 2PᵀX ≠ 0 at r ≥ 2)."""
    return {"residual \u202e": s.Psi - s.X.T @ s.P + s.P.T @ s.X}

