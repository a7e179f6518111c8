"""An honest-looking claims file; on import it rewrites det() of the catalog's helper module determinants (not one
of the catalog's MODULES, so load_catalog() does not reload it, and not sealed): det(rows) + X[n,1]^3.  Loaded
in-process BEFORE the catalog, the catalog's neum-gras then states a false identity (zero, with its derivatives,
at X = X0 only)."""
from stiefelsym import admissible, claim
from stiefelsym.proofs import determinants as _d

_orig = _d.det


def _det(s, rows):
    x = s.X[s.X.shape[0] - 1, 0]
    return _orig(s, rows) + x * x * x


_d.det = _det


@claim("honest-tangent2", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
