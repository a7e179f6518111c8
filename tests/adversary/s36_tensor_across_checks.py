"""Round 6: a Poisson tensor that is one form in its own poisson_checks and another in compatibility.  On so(3),
Λ_x(a, b) = ⟨V(x), [a, b]⟩ with V(x) = x₁₃²(E₂₃ − E₃₂) (the vector field (x₂², 0, 0): v·curl v = 0, so Λ is
Poisson) is not compatible with Lie–Poisson (x·curl v ≠ 0).  The claim's tensor is Λ in poisson_checks and
Lie–Poisson in compatibility (a flag the claim sets between the two calls): each call evaluates one form."""
from stiefelsym import admissible, claim
from stiefelsym.brackets import SO_N, PoissonTensor, compatibility, lie_poisson, poisson_checks

SIZES = admissible(n_min=3, n_max=3)


def _field_tensor(t, x, a, b):
    e23 = SO_N.basis(t)[2][0]
    V = e23 * (x[0, 2] * x[0, 2])
    return t.tr(V.T @ (a @ b - b @ a))


def _lie_poisson(t, x, a, b):
    return t.tr(x.T @ (a @ b - b @ a))


@claim("adv-s36-poisson-two-faces", kind="pb", sizes=SIZES)
def two_faces(s):
    """False: Λ (above) is a Poisson tensor on so(3), compatible with Lie–Poisson."""
    state = {"second": False}

    def form(t, x, a, b):
        return (_lie_poisson if state["second"] else _field_tensor)(t, x, a, b)
    T = PoissonTensor(SO_N, form, 2, "Λ")
    out = poisson_checks(s, T, "Λ")
    state["second"] = True
    out.update(compatibility(s, T, lie_poisson(SO_N), "pencil"))
    return out


@claim("adv-s36-poisson-two-faces-control", kind="pb", sizes=SIZES)
def two_faces_control(s):
    """False (the control, one form): Λ is a Poisson tensor on so(3), compatible with Lie–Poisson."""
    T = PoissonTensor(SO_N, _field_tensor, 2, "Λ")
    out = poisson_checks(s, T, "Λ")
    out.update(compatibility(s, T, lie_poisson(SO_N), "pencil"))
    return out


@claim("adv-s36-poisson-field-alone", kind="pb", sizes=SIZES)
def field_alone(s):
    """True: Λ is a Poisson tensor on so(3)."""
    return poisson_checks(s, PoissonTensor(SO_N, _field_tensor, 2, "Λ"))


@claim("adv-s36-poisson-same-object-true", kind="pb", sizes=SIZES)
def same_object_true(s):
    """True: Lie–Poisson (one object) is Poisson, and compatible with Lie–Poisson."""
    T = PoissonTensor(SO_N, _lie_poisson, 1, "LP")
    out = poisson_checks(s, T, "LP")
    out.update(compatibility(s, T, lie_poisson(SO_N), "pencil"))
    return out


@claim("adv-s36-poisson-two-faces-scaled", kind="pb", sizes=SIZES)
def two_faces_scaled(s):
    """False: Λ (above) is a Poisson tensor on so(3), and 1·Λ is compatible with Lie–Poisson."""
    state = {"second": False}

    def form(t, x, a, b):
        return (_lie_poisson if state["second"] else _field_tensor)(t, x, a, b)
    T = PoissonTensor(SO_N, form, 2, "Λ")
    out = poisson_checks(s, T, "Λ")
    state["second"] = True
    out.update(compatibility(s, T.scaled(lambda t: t.q(1)), lie_poisson(SO_N), "pencil"))
    return out


class _OwnSum(PoissonTensor):
    """A tensor whose sum is built by its own __add__ (a plain PoissonTensor, no parts)."""

    def __add__(self, o):
        return PoissonTensor(self.space, lambda s, x, a, b: self.form(s, x, a, b) + o.form(s, x, a, b),
                             max(self.degree, o.degree), f"{self.name} + {o.name}")


@claim("adv-s36-poisson-two-faces-own-sum", kind="pb", sizes=SIZES)
def two_faces_own_sum(s):
    """False: Λ (above) is a Poisson tensor on so(3), compatible with Lie–Poisson (its sum built by its own
    __add__)."""
    state = {"second": False}

    def form(t, x, a, b):
        return (_lie_poisson if state["second"] else _field_tensor)(t, x, a, b)
    T = _OwnSum(SO_N, form, 2, "Λ")
    out = poisson_checks(s, T, "Λ")
    state["second"] = True
    out.update(compatibility(s, T, lie_poisson(SO_N), "pencil"))
    return out
