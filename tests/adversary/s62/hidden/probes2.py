"""s62 extra probes 2: statements true on one component of O(n) only (r = n)."""
from stiefelsym import admissible, claim

AT_22 = admissible(n_max=2, n_min=2, r_min=2, stated_n_max=2, condition="(n, r) = (2, 2)")
AT_33 = admissible(n_max=3, n_min=3, r_min=3, stated_n_max=3, condition="(n, r) = (3, 3)")


@claim("p-rotation-only-22", kind="id", sizes=AT_22)
def rotation_only_22(s):
    """FALSE on T*V(2,2) = T*O(2): x11 = x22 holds on SO(2) only (reflections: x11 = -x22)."""
    return {"x11 - x22": s.X[0, 0] - s.X[1, 1]}


@claim("p-rotation-only-33", kind="id", sizes=AT_33)
def rotation_only_33(s):
    """FALSE on T*O(3): e3 = e1 x e2 holds on SO(3) only."""
    X = s.X
    e1, e2, e3 = X[0:3, 0:1], X[0:3, 1:2], X[0:3, 2:3]
    cross = s.mat([[e1[1, 0] * e2[2, 0] - e1[2, 0] * e2[1, 0]],
                   [e1[2, 0] * e2[0, 0] - e1[0, 0] * e2[2, 0]],
                   [e1[0, 0] * e2[1, 0] - e1[1, 0] * e2[0, 0]]])
    return {"e3 - e1 x e2": e3 - cross}


@claim("p-not-rotation-only-22", kind="not", expect="nonzero", sizes=AT_22)
def not_rotation_only_22(s):
    """TRUE: x11 - x22 is not identically 0 on T*O(2) (nonzero on reflections)."""
    return {"x11 - x22": s.X[0, 0] - s.X[1, 1]}


@claim("p-not-x11-plus-x22-22", kind="not", expect="nonzero", sizes=AT_22)
def not_x11_plus_x22(s):
    """TRUE: x11 + x22 is not identically 0 on T*O(2) (nonzero on rotations, 0 on reflections)."""
    return {"x11 + x22": s.X[0, 0] + s.X[1, 1]}
