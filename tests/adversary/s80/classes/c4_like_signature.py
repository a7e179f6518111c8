"""Class 4 (state across calls), the newest rule (bc2c8569): "a function a step shapes like its argument is held
across steps", keyed by (id(f), the shape of the step's argument) — a dict's keys IN ORDER (_like_signature).
The second euler_lagrange call is handed the same position and velocity as dicts with their keys in the other
order ({"Y": …, "X": …}): the same point, another "shape", so the stateful T is not held across the two calls.

Truth (s79/review2/el_stateful.py, by hand): for ONE function T the two calls give the same accelerations;
  l4-order-contradiction: acc1 = acc(c=1) and acc2 = acc(c=2), acc(1) ≠ acc(2)                FALSE
  l4-same-order:          the same with the keys in the same order (held: must be refused)     FALSE
  l4-order-control:       two different T objects, c = 1 and c = 2, keys reversed in the second  TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SIZES = admissible(n_min=3, n_max=3)


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _el(s, T, reverse=False):
    z = double_point(s)
    if reverse:
        q, v = {"Y": z["Y"], "X": z["X"]}, {"Y": z["Ydot"], "X": z["Xdot"]}
    else:
        q, v = {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]}
    acc, _ = euler_lagrange(s, T, U_double, D0, q, v, real_coordinates(s, ["X", "Y"]))
    return z, acc


def _expected(s, z, c):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y / c - Xd.T @ Yd
    return -(A @ X) / c + X @ Lam.T, -(A @ Y) / c + Y @ Lam


def _contra(s, reverse):
    mode = [1]

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * mode[0]
    z, acc1 = _el(s, T)
    mode[0] = 2
    _, acc2 = _el(s, T, reverse)
    e1, e2 = _expected(s, z, 1), _expected(s, z, 2)
    return {"Xdd (1)": acc1["X"] - e1[0], "Ydd (1)": acc1["Y"] - e1[1],
            "Xdd (2)": acc2["X"] - e2[0], "Ydd (2)": acc2["Y"] - e2[1]}


@claim("l4-order-contradiction", kind="id", sizes=SIZES)
def l4_order(s):
    """FALSE (see the module docstring)."""
    return _contra(s, True)


@claim("l4-same-order", kind="id", sizes=SIZES)
def l4_same(s):
    """FALSE, keys in the same order (held by the rule)."""
    return _contra(s, False)


@claim("l4-order-control", kind="id", sizes=SIZES)
def l4_control(s):
    """TRUE: two T objects."""
    z, acc1 = _el(s, lambda t, v: t.tr(v["X"].T @ v["Y"]))
    _, acc2 = _el(s, lambda t, v: t.tr(v["X"].T @ v["Y"]) * 2, True)
    e1, e2 = _expected(s, z, 1), _expected(s, z, 2)
    return {"Xdd (1)": acc1["X"] - e1[0], "Ydd (1)": acc1["Y"] - e1[1],
            "Xdd (2)": acc2["X"] - e2[0], "Ydd (2)": acc2["Y"] - e2[1]}
