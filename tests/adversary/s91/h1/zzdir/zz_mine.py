"""A module the catalog's loading is made to import: its claim is then registered as reviewed."""
from stiefelsym import claim


@claim("zz-bottom-row", paper=(), kind="id", section="7", sizes=[(3, 2), (4, 2)],
       equivariance="the Plücker coordinates of a rotated plane are those of the plane under the induced linear action")
def bottom_row(s):
    """FALSE: the last row of X vanishes."""
    return {"x": s.X[s.X.shape[0] - 1:s.X.shape[0], :]}
