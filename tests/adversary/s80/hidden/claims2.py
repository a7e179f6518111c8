# ruff: noqa
"""s80 hidden round (h2), second file: (A2) at h₁ = 0 (proof of Theorem NEUMANN2) and a Plücker minor of 𝒱 (§8)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, block, claim, comm, det
from stiefelsym.bases import matrix_units

from _h80_helpers import lam1, lam2
from _h80_a2 import a2_checks, kernel_spanning_set


@claim("h80-a2-psi-zero", paper=("NEUMANN2", "LEMA2", "A2", "LEMA1", "LAMBDA"), kind="dim", sizes=admissible(n_max=4),
       statement=r"X^TP=0,\ x=\Theta(X,P):\ \dim\{y\in\ker\Lambda_1(x):\Lambda_{1,-1}(y,\ker\Lambda_1(x))=0\}=n,\ "
                 r"\text{i.e. }\rank\Lambda_{1,-1}|_{\ker\Lambda_1}=r^2+(n-r)^2-n")
def a2_psi_zero(s):
    """§7, proof of Theorem NEUMANN2: 'by modifying the proof of Lemma LEMA1 one can prove conditions (A1) and (A2)
    for x = h + v with h₁ = 0 as well'.  (A2) at a generic point x = Θ(X, P̃) of Θ(Ψ⁻¹(0)) (P̃ = (I − XXᵀ)P):
    on K = ker Λ1(x) (dimension dim gl(r) ⊕ gl(n − r), spanned by the elements of the proof of LEMA1, each
    checked to lie in K) the form Λ_{1,−1} has a kernel of dimension n, i.e. rank dim K − n (the rank of the Gram
    matrix over a spanning set of K is the rank of the restricted form)."""
    n = int(s.n)
    return a2_checks(s, n)


@claim("h80-vv-pluecker-span-e", paper=("VV", "forms", "Gen_Chasles"), kind="geo", sizes=admissible(n_max=5),
       statement=r"\det\mathcal V_{\{1..r\}\cup\{n+1..n+r\}}=\det X_{\{1..r\}}\ \text{(the minors containing }\mathbf I_r\text{ are Plücker coordinates of span}(e_1..e_r))")
def vv_pluecker_span_e(s):
    """§8 after (VV): 'the 2r × 2r minors [of 𝒱] that completely contain I_r give the Plücker coordinates of the
    r-plane span(e₁, …, e_r) ⊂ ℝⁿ': the minor of 𝒱 = [[X, P], [0, I_r]] on the rows {1..r} ∪ {n+1..n+r} is the
    minor of X on the rows {1..r} (block triangular)."""
    r = int(s.r)
    Xi, Pi = s.X[0:r, 0:r], s.P[0:r, 0:r]
    Z = s.zeros(r, r, ("r", "r"))
    V = block([[Xi, Pi], [Z, s.Ir]])
    return {"minor of V - minor of X": det(s, V) - det(s, Xi)}
