"""s72 review: entries of s.jacobian read as plain list items (attempts J1-J4)."""
from stiefelsym import admissible, claim


def half_norm(t):
    return t.tr(t.X.T @ t.X) / 2


def quad_a(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s72-jac-entry-one", paper="No", kind="id", section="t", sizes=admissible(n_max=4))
def jac_entry_one(s):
    """dF/dX11 = X11 = 1 for F = tr(XᵀX)/2 (false: X11 is not 1 on V; it is at X0 = E)."""
    J = s.jacobian(half_norm)
    return {"J11 - 1": J[0][0] - 1}


@claim("s72-jac-entry-zero", paper="No", kind="id", section="t", sizes=admissible(n_max=4, r_max=1, n_min=2))
def jac_entry_zero(s):
    """dF/dX21 = X21 = 0 (false; true at X0 = E)."""
    J = s.jacobian(half_norm)
    return {"J21": J[0][1]}


@claim("s72-jac-entry-sum", paper="No", kind="id", section="t", sizes=admissible(n_max=4))
def jac_entry_sum(s):
    """Sum of squares of the X-part of the gradient of tr(XᵀX)/2 equals r (true: |X|² = r)."""
    J = s.jacobian(half_norm)
    n, r = int(s.n), int(s.r)
    return {"|dF|^2 - r": sum(J[0][k] * J[0][k] for k in range(n * r)) - r}


@claim("s72-jac-entry-a", paper="No", kind="id", section="t", sizes=admissible(n_max=4, r_max=1, n_min=2))
def jac_entry_a(s):
    """dG/dX11 = (AX)_11 = a_1 X11 for G = tr(XᵀAX)/2: claimed equal to tr(XᵀAX)·X11-free value a-11 entry... (false)."""
    J = s.jacobian(quad_a)
    return {"J11 - tr(XᵀAX)": J[0][0] - s.tr(s.X.T @ s.A @ s.X)}
