"""An honest claims file that reuses a helper of the catalog (plucker) for one claim of its own."""
from stiefelsym import admissible, claim
from stiefelsym.proofs.sec7_grassmannians import columns


@claim("mine-columns", kind="id", sizes=admissible(n_max=3))
def mine(s):
    """The columns of X are unit vectors: sum of squares of the first column is 1."""
    c = columns(s.X, 1)[0]
    tot = c[0] * c[0]
    for x in c[1:]:
        tot = tot + x * x
    return {"unit": tot - 1}
