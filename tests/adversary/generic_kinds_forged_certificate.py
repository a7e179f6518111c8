"""Adversary (generic kinds): a false claim tr(S X Xᵀ) = tr(G X Xᵀ) (S the symmetric, G the general matrix of the
name G); its free record is forged to `proved` with a certificate that declares the letter gen:G:sym as the
transpose of the general letter gen:G (accepted by check_certificate: the transpose's name is not checked)."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-forged-sym-transpose", paper="adv", kind="id", sizes=S)
def forged_sym_transpose(s):
    """False: tr(S X Xᵀ) = tr(G X Xᵀ) for S = generic("G", sym), G = generic("G")."""
    Sg, G = s.generic("G", "n", "n", "sym"), s.generic("G", "n", "n")
    return {"x": (Sg @ s.X @ s.X.T).trace() - (G @ s.X @ s.X.T).trace()}
