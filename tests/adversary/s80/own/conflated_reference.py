"""Stop 80's own attempt on its change (a call held to a reference by substitution as well as by shape).

The form below is one function at no two of its calls: at the claim's point y it computes <x, x − q·p> (the
shape the Lie–Poisson form <x, p·q − q·p> has at x = a·b, where p·q IS the node x), anywhere else the
Lie–Poisson form.  Its three calls T(a·b; a, b), T(y; a, b) and T(z; c, d):
  - T(a·b; a, b) is <ab, ab − ba> under both branches: a reference by shape whose graph reads x twice;
  - T(y; a, b) = <y, y − ba> has that reference's shape;
  - T(z; c, d) = <z, [c, d]> is the reference's function only by substitution... at no node: by substitution into
    T(a·b; a, b) it is <z, z − dc>, and by shape it is not that reference's either.
  s80-own-conflated-contradiction: T(y; a, b) = <y, y − ba> and T(z; c, d) = <z, [c, d]> (with T(a·b; a, b) made
      first): no one function has both (z = y, c = a, d = b: <y, y − ba> = <y, ab − ba> for every y, a, b is
      false), so any verdict but a refusal is wrong.
  s80-own-conflated-checked: the same next to checked_tensor(T) (a step's function at its parameters).
  s80-own-lie-poisson-true: the engine's lie_poisson at the same three calls, each its true value (control).
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, PoissonTensor, checked_tensor, lie_poisson

SZ = admissible(n_min=3, n_max=3)


def _calls(s, T):
    a, b, c, d, y, z = (GL_N.generic(s, k) for k in ("a", "b", "c", "d", "y", "z"))
    T(s, a @ b, a, b)
    return a, b, c, d, y, z


def _tricky(s):
    box = {}

    def form(t, x, p, q):
        if x is box.get("y"):
            return t.killing(x, x - q @ p)
        return t.killing(x, comm(p, q))
    return PoissonTensor(GL_N, form, 1, "Λ?"), box


@claim("s80-own-conflated-contradiction", kind="id", sizes=SZ)
def conflated(s):
    T, box = _tricky(s)
    a, b, c, d, y, z = _calls(s, T)
    box["y"] = y
    return {"T(y; a, b) = <y, y - ba>": T(s, y, a, b) - s.killing(y, y - b @ a),
            "T(z; c, d) = <z, [c, d]>": T(s, z, c, d) - s.killing(z, comm(c, d))}


@claim("s80-own-conflated-checked", kind="id", sizes=SZ)
def conflated_checked(s):
    T, box = _tricky(s)
    a, b, c, d, y, z = _calls(s, T)
    box["y"] = y
    C = checked_tensor(T)
    return {"T(y; a, b) = <y, y - ba>": T(s, y, a, b) - s.killing(y, y - b @ a),
            "T(z; c, d) = <z, [c, d]>": C(s, z, c, d) - s.killing(z, comm(c, d))}


@claim("s80-own-lie-poisson-true", kind="id", sizes=SZ)
def honest(s):
    T = lie_poisson(GL_N)
    a, b, c, d, y, z = _calls(s, T)
    return {"T(ab; a, b)": T(s, a @ b, a, b) - s.killing(a @ b, comm(a, b)),
            "T(y; a, b)": T(s, y, a, b) - s.killing(y, comm(a, b)),
            "T(z; c, d)": T(s, z, c, d) - s.killing(z, comm(c, d))}
