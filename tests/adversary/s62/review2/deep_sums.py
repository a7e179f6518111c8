"""Attack on _Sides.alike's depth cut (depth > 32 -> alike): two splittings of one side that differ only at depth
> 32 of a chain of direct sums.  [X; 0; ...; 0]^T [I_r; 0_{n-r}; 0; ...; 0] is the top r x r block X1 of X:
X1 - I_r = 0 is FALSE on T*V but TRUE at the equivariant chart's X0 = (E_1 .. E_r)."""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=4, where=lambda n, r: r < n)


def _pair(s, depth, tag="?"):
    n, r = int(s.n), int(s.r)
    U = s.X
    V = block([[s.Ir], [s.zeros(n - r, r, (tag, "r"))]])
    for _ in range(depth):
        U = block([[U], [s.zeros(r, r, (tag, "r"))]])
        V = block([[V], [s.zeros(r, r, (tag, "r"))]])
    return U, V


def _mk(depth):
    def f(s):
        """FALSE: the top r x r block of X is I_r."""
        U, V = _pair(s, depth)
        return {"X1 - I": U.T @ V - s.Ir}
    return f


for _d in (0, 1, 31, 32, 33, 34, 40):
    claim(f"ds-false-depth{_d}", kind="id", sizes=SZ)(_mk(_d))


@claim("ds-true-depth33", kind="id", sizes=SZ)
def true33(s):
    """TRUE: U^T V - (U^T V) = 0 (control)."""
    U, V = _pair(s, 33)
    return {"0": U.T @ V - (V.T @ U).T}


def _mk_sides(depth):
    # the n-side pieces at depth: [X, 0...]-style column blocks, the other on R^r first
    def f(s):
        """FALSE: X^T [I_r ; 0] (as the top block through two column splittings) = I."""
        n, r = int(s.n), int(s.r)
        U = s.X.T          # r x n
        V = block([[s.Ir, s.zeros(r, n - r, ("r", "?"))]])   # r x n, split (r, ?)
        for _ in range(depth):
            U = block([[U, s.zeros(r, r, ("r", "?"))]])
            V = block([[V, s.zeros(r, r, ("r", "?"))]])
        return {"X1 - I": U @ V.T - s.Ir}
    return f


for _d in (33, 40):
    claim(f"ds-cols-false-depth{_d}", kind="id", sizes=SZ)(_mk_sides(_d))
