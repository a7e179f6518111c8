"""Round 5: the generic point and covectors at which `brackets.poisson_checks` decides that a tensor is
Poisson are parameters named Bkx, Bka, Bkb, Bkc, Bke, which a claim can name too (s.generic("Bkx", "n", "n")),
or read from a first call of poisson_checks with a tensor that keeps its argument.  A tensor that differs from
a Poisson tensor by |x − x₀|²·(a symmetric form), x₀ the test point, passes antisymmetry, the degree check and
the Jacobi identity at x₀ (value and first derivative in x vanish there) and is not antisymmetric elsewhere."""
from stiefelsym import admissible, claim
from stiefelsym.brackets import SO_N, PoissonTensor, poisson_checks

SIZES = admissible(n_max=4)


def _tensor(point):
    def form(t, x, a, b):
        d = x - point(t)
        return t.tr(x.T @ (a @ b - b @ a)) + t.tr(d.T @ d) * t.tr(a.T @ b)
    return PoissonTensor(SO_N, form, 2, "LP + |x - x0|^2 <a, b>")


@claim("adv-s35-poisson-named-test-point", kind="pb", sizes=SIZES)
def poisson_at_a_point_named_like_the_test_point(s):
    """False: Λ_x(a, b) = ⟨x, [a, b]⟩ + |x − x₀|²⟨a, b⟩ on so(n), x₀ a generic element of the claim's own named Bkx,
    is a Poisson tensor (it is not antisymmetric where x ≠ x₀)."""
    return poisson_checks(s, _tensor(lambda t: SO_N.generic(t, "Bkx")))


@claim("adv-s35-poisson-spied-test-point", kind="pb", sizes=SIZES)
def poisson_at_a_spied_test_point(s):
    """False: the same tensor with x₀ read from a first poisson_checks of a tensor that keeps its argument x."""
    seen = []

    def spy(t, x, a, b):
        seen.append(x)
        return t.tr(x.T @ (a @ b - b @ a))
    poisson_checks(s, PoissonTensor(SO_N, spy, 1, "spy"))
    x0 = seen[0]
    return poisson_checks(s, _tensor(lambda t: x0))


@claim("adv-s35-poisson-control", kind="pb", sizes=SIZES)
def poisson_at_a_point_of_its_own(s):
    """False (control): the same tensor with x₀ a generic element named Cx."""
    return poisson_checks(s, _tensor(lambda t: SO_N.generic(t, "Cx")))
