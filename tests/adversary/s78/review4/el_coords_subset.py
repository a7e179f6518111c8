"""systems.euler_lagrange / hamiltonian_flow take the claim's coordinates ("an orthogonal basis of each variable's
space", systems.py module doc) and solve in them: nothing checks that they SPAN the variable's space.  With a
coordinate left out, the step returns the accelerations (the flow) of the system confined to point + span(coords),
not those of L (of H).

System: one unconstrained n x r variable X (no constraints), T = ½tr(ẊᵀẊ), U = ½tr(XᵀAX): Ẍ = −AX exactly
(TRUE, r4-el-subset-true).  The coordinates real_coordinates(s, ["X"])[1:] (E_11 left out): the engine's Ẍ has
a zero (1,1) entry; the FALSE twin says Ẍ = −AX + E_11(AX)E_11 (r4-el-subset-false).
Same for hamiltonian_flow of H = ½tr(PᵀP) + ½tr(XᵀAX), no constraints, with coords=lambda s, names:
real_coordinates(s, names)[1:]: Ṗ = −AX (TRUE), Ṗ = −AX + E_11(AX)E_11 (FALSE)."""
from stiefelsym import admissible, claim
from stiefelsym.systems import euler_lagrange, hamiltonian_flow

SZ = admissible(n_max=3, n_min=2)


@claim("r4-el-full-units-true", kind="id", sizes=SZ)
def el_full(s):
    """control: all the units (skip=0), built by the claim: Ẍ = −AX"""
    acc, _ = euler_lagrange(s, T, U, lambda t, q: [], {"X": s.X}, {"X": s.P}, units(s, "X", 0))
    return {"Xdd + AX": acc["X"] + s.A @ s.X}


def T(t, v):
    return t.tr(v["X"].T @ v["X"]) / 2


def U(t, q):
    return t.tr(q["X"].T @ t.A @ q["X"]) / 2


def corner(s, M):
    n, r = int(s.n), int(s.r)
    En = s.mat([[1 if (i, j) == (0, 0) else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    Er = s.mat([[1 if (i, j) == (0, 0) else 0 for j in range(r)] for i in range(r)], ("r", "r"))
    return En @ M @ Er


def units(s, name, skip=1):
    """(name, E_ij) for every unit n x r matrix but the first `skip` (row-major): E_11 left out"""
    n, r = int(s.n), int(s.r)
    out = []
    for k in range(skip, n * r):
        i, j = divmod(k, r)
        out.append((name, s.mat([[1 if (a, b) == (i, j) else 0 for b in range(r)] for a in range(n)], ("n", "r"))))
    return out


def _acc(s):
    coords = units(s, "X")
    acc, _ = euler_lagrange(s, T, U, lambda t, q: [], {"X": s.X}, {"X": s.P}, coords)
    return acc["X"]


@claim("r4-el-subset-true", kind="id", sizes=SZ)
def el_true(s):
    return {"Xdd + AX": _acc(s) + s.A @ s.X}


@claim("r4-el-subset-false", kind="id", sizes=SZ)
def el_false(s):
    AX = s.A @ s.X
    return {"Xdd + AX - E11 AX E11": _acc(s) + AX - corner(s, AX)}


def H(t, z):
    return t.tr(z["P"].T @ z["P"]) / 2 + t.tr(z["X"].T @ t.A @ z["X"]) / 2


def _flow(s):
    fl, _ = hamiltonian_flow(s, H, lambda t, z: [], {"X": s.X, "P": s.P}, [("X", "P")],
                             coords=lambda t, names: units(t, names[0]))
    return fl


@claim("r4-hflow-subset-true", kind="id", sizes=SZ)
def hf_true(s):
    fl = _flow(s)
    return {"Xdot - P": fl["X"] - s.P, "Pdot + AX": fl["P"] + s.A @ s.X}


@claim("r4-hflow-subset-false", kind="id", sizes=SZ)
def hf_false(s):
    fl = _flow(s)
    AX = s.A @ s.X
    return {"Xdot - P + E11 P E11": fl["X"] - s.P + corner(s, s.P), "Pdot + AX - E11 AX E11": fl["P"] + AX - corner(s, AX)}


# -- coordinates that span but are not orthonormal: 2E_ij (an orthogonal basis, as the module doc asks) --------
# hamiltonian_flow pairs coordinate a of the positions with coordinate a of the momenta as canonical conjugates;
# with the basis 2E_ij on both sides the conjugate of x_a = <X, 2E_a>/4 ... is not p_a: the step returns 4 times
# the flow.  (Euler–Lagrange is basis-independent for a spanning basis: control r4-el-scaled-true.)

def scaled_units(s, name):
    return [(nm, B * 2) for nm, B in units(s, name, 0)]


@claim("r4-el-scaled-true", kind="id", sizes=SZ)
def el_scaled(s):
    acc, _ = euler_lagrange(s, T, U, lambda t, q: [], {"X": s.X}, {"X": s.P}, scaled_units(s, "X"))
    return {"Xdd + AX": acc["X"] + s.A @ s.X}


def _flow_scaled(s):
    fl, _ = hamiltonian_flow(s, H, lambda t, z: [], {"X": s.X, "P": s.P}, [("X", "P")],
                             coords=lambda t, names: scaled_units(t, names[0]))
    return fl


@claim("r4-hflow-scaled-true", kind="id", sizes=SZ)
def hf_scaled_true(s):
    fl = _flow_scaled(s)
    return {"Xdot - P": fl["X"] - s.P, "Pdot + AX": fl["P"] + s.A @ s.X}


@claim("r4-hflow-scaled-false", kind="id", sizes=SZ)
def hf_scaled_false(s):
    fl = _flow_scaled(s)
    return {"Xdot - 4P": fl["X"] - s.P * 4, "Pdot + 4AX": fl["P"] + s.A @ s.X * 4}
