# ruff: noqa
"""s78 hidden round: variants of statements 1 and 2 that exercise other engine paths (canonical bracket, generic
matrices as velocities).  fails_at = where numpy (scratch check recorded in FINDINGS.md) finds the variant false."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm

from _h78_helpers import killing, phi0, thimm_gradient

ERR = "variant probe (s78 hidden round)"


@claim("p78-thimm-canonical", kind="pb", sizes=admissible(n_max=4), fails_at=lambda n, r: n >= 2, erratum=ERR)
def thimm_canonical(s):
    """Statement 1 with the canonical bracket of R^{2nr} in place of the Dirac bracket: FALSE (n >= 2)."""
    S = s.generic("S", "r", "r", "sym")
    C = s.generic("C", "r", "r")
    F = lambda t: t.tr(S @ t.P.T @ t.P)
    G = lambda t: t.tr(C @ t.X.T @ t.P)
    return {"{F,G}_0 + <Phi,[dF,dG]>": s.canonical_bracket(F, G)
            + killing(s, s.Phi, comm(thimm_gradient(s, F), thimm_gradient(s, G)))}


@claim("p78-edelman-generic-v", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: True, erratum=ERR)
def edelman_generic_v(s):
    """Statement 2 at a generic V ∈ R^{n×r} (not tangent: XᵀV not skew): FALSE."""
    V, X = s.generic("V", "n", "r"), s.X
    return {"L0 - Edelman form": killing(s, phi0(s, V), phi0(s, V)) / 2
            - (s.tr(V.T @ V) / 2 - s.tr(V.T @ X @ X.T @ V) / 4)}


@claim("p78-edelman-tangent-generic", kind="id", sizes=admissible(n_max=4))
def edelman_tangent_generic(s):
    """Statement 2 at the tangent vector V = Xω + (I − XXᵀ)Z built from a generic skew ω and a generic Z: TRUE."""
    X = s.X
    w = s.generic("w", "r", "r", "skew")
    V = X @ w + (s.In - X @ X.T) @ s.generic("Z", "n", "r")
    return {"L0 - Edelman form": killing(s, phi0(s, V), phi0(s, V)) / 2
            - (s.tr(V.T @ V) / 2 - s.tr(V.T @ X @ X.T @ V) / 4)}
