"""Round 5, CC continued: the test elements of `brackets.poisson_checks` and `brackets.compatibility` are fresh
elements (s.fresh: numbered by the engine, new at every call).  More ways to reach them: a point kept from a
first `compatibility`, by a `PoissonTensor.__call__` of a subclass, from one of two calls of poisson_checks in
one claim, within the same call (a form that keeps the first point it is evaluated at), and an element the
claim draws with s.fresh itself."""
from stiefelsym import admissible, claim
from stiefelsym.brackets import SO_N, PoissonTensor, compatibility, lie_poisson, poisson_checks

SIZES = admissible(n_max=4)


def _tensor(point):
    def form(t, x, a, b):
        d = x - point(t)
        return t.tr(x.T @ (a @ b - b @ a)) + t.tr(d.T @ d) * t.tr(a.T @ b)
    return PoissonTensor(SO_N, form, 2, "LP + |x - x0|^2 <a, b>")


@claim("adv-s35-poisson-point-of-compatibility", kind="pb", sizes=SIZES)
def poisson_at_the_point_of_compatibility(s):
    """False: Λ_x(a, b) = ⟨x, [a, b]⟩ + |x − x₀|²⟨a, b⟩ with x₀ the point of a first compatibility check (read by a
    tensor that keeps its argument) is a Poisson tensor, and compatible with Lie–Poisson at that point."""
    seen = []

    def spy(t, x, a, b):
        seen.append(x)
        return t.tr(x.T @ (a @ b - b @ a))
    compatibility(s, PoissonTensor(SO_N, spy, 1, "spy"), lie_poisson(SO_N))
    x0 = seen[-1]           # the last evaluation is at the point (the first at a gradient's parameter)
    out = poisson_checks(s, _tensor(lambda t: x0))
    out.update(compatibility(s, _tensor(lambda t: x0), lie_poisson(SO_N), "with LP"))
    return out


class _Spy(PoissonTensor):
    """A tensor whose __call__ keeps every point it is evaluated at."""

    def __call__(self, s, x, a, b):
        KEPT.append(x)
        return super().__call__(s, x, a, b)


KEPT: list = []


@claim("adv-s35-poisson-call-spy", kind="pb", sizes=SIZES)
def poisson_at_a_point_kept_by_call(s):
    """False: the tensor above with x₀ the first point a Lie–Poisson tensor's __call__ (a subclass) was evaluated
    at in a first poisson_checks."""
    del KEPT[:]
    spy = _Spy(SO_N, lambda t, x, a, b: t.tr(x.T @ (a @ b - b @ a)), 1, "spy")
    checks = poisson_checks(s, spy, "first")
    x0 = KEPT[0]
    checks.update(poisson_checks(s, _tensor(lambda t: x0), "second"))
    return checks


@claim("adv-s35-poisson-two-calls", kind="pb", sizes=SIZES)
def poisson_at_a_point_of_the_other_call(s):
    """False: two poisson_checks in one claim, the second's tensor built on the point a tensor that keeps its
    argument x (and is Lie–Poisson) was evaluated at in the first."""
    seen = []

    def keeper(t, x, a, b):
        seen.append(x)
        return t.tr(x.T @ (a @ b - b @ a))
    checks = poisson_checks(s, PoissonTensor(SO_N, keeper, 1, "keeper"), "first")
    x0 = seen[-1]
    checks.update(poisson_checks(s, _tensor(lambda t: x0), "second"))
    return checks


@claim("adv-s35-poisson-own-fresh", kind="pb", sizes=SIZES)
def poisson_at_a_fresh_element_of_its_own(s):
    """False: the tensor built on a fresh element the claim drew itself (s.fresh, before poisson_checks)."""
    w = SO_N.fresh(s)
    return poisson_checks(s, _tensor(lambda t: w))


@claim("adv-s35-poisson-fresh-true", kind="pb", sizes=SIZES)
def lie_poisson_twice(s):
    """True (control): the Lie–Poisson tensor on so(n) is Poisson, checked twice, and compatible with itself."""
    checks = poisson_checks(s, lie_poisson(SO_N), "first")
    checks.update(poisson_checks(s, lie_poisson(SO_N), "second"))
    checks.update(compatibility(s, lie_poisson(SO_N), lie_poisson(SO_N, -1), "pair"))
    return checks


@claim("adv-s35-poisson-in-call-keeper", kind="pb", sizes=SIZES)
def poisson_at_the_first_point_of_its_own_call(s):
    """False: the tensor above with x₀ the first point it is evaluated at within the same poisson_checks (a form
    that keeps state between its evaluations)."""
    seen = []

    def keeper(t, x, a, b):
        seen.append(x)
        d = x - seen[0]
        return t.tr(x.T @ (a @ b - b @ a)) + t.tr(d.T @ d) * t.tr(a.T @ b)
    return poisson_checks(s, PoissonTensor(SO_N, keeper, 2, "keeper"))
