"""s72 review: blocks on R^(n-r) with mismatched space tags (attempts N1-N4)."""
from stiefelsym import admissible, claim, block


@claim("s72-nr-zeros-tag-n", paper="No", kind="id", section="t", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def zeros_tagged_n(s):
    """X - [I_r; 0] with the zero block tagged ("n", "r") though it has n - r rows (false)."""
    Z = s.zeros(s.n - s.r, s.r, ("n", "r"))
    B = block([[s.Ir], [Z]])
    return {"X - X0": s.X - B}


@claim("s72-nr-gp-tag-n", paper="No", kind="id", section="t", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def gp_tagged_n(s):
    """(X - [I_r; G]) with G = general_params on (n-r) x r tagged ("n","r") (false)."""
    G = s.general_params("G", s.n - s.r, s.r, ("n", "r"))
    B = block([[s.Ir], [G]])
    return {"X - B": s.X.T @ B - s.Ir}


@claim("s72-nr-mat-tag", paper="No", kind="id", section="t", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def mat_tag(s):
    """Xᵀ E = I_r with E = s.mat(...) typed ("n","r") built from n-r rows blocks (false)."""
    n, r = int(s.n), int(s.r)
    rows = [[1 if i == j else 0 for j in range(r)] for i in range(n)]
    E = s.mat(rows, ("n", "r"))
    return {"XᵀE - I": s.X.T @ E - s.Ir}
