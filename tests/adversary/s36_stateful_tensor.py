"""Round 6: a Poisson tensor whose form is another form on some of its evaluations.  poisson_checks evaluates
the tensor (each evaluation one engine step, its form traced as a function of (x, a, b)) for the antisymmetry
(2 evaluations), the degree (degree + 2) and the Jacobi identity (the rest): a form that counts its
evaluations is (1 + tr(xC))⟨x, [a, b]⟩ for the first two checks and ⟨x, [a, b]⟩ for the Jacobi identity."""
from stiefelsym import admissible, claim
from stiefelsym.brackets import SO_N, PoissonTensor, poisson_checks

SIZES = admissible(n_min=4, n_max=4)


def _scaled_lie_poisson(t, x, a, b):
    C = SO_N.project(t.generic("C", "n", "n"))
    return (1 + t.tr(x @ C)) * t.tr(x.T @ (a @ b - b @ a))


@claim("adv-s36-poisson-counting-form", kind="pb", sizes=SIZES)
def counting_form(s):
    """False: Λ_x(a, b) = (1 + tr(xC))⟨x, [a, b]⟩ (C a generic skew matrix) is a Poisson tensor on so(n)."""
    calls = [0]

    def form(t, x, a, b):
        calls[0] += 1
        if calls[0] <= 6:
            return _scaled_lie_poisson(t, x, a, b)
        return t.tr(x.T @ (a @ b - b @ a))
    return poisson_checks(s, PoissonTensor(SO_N, form, 2, "(1 + tr xC) LP"))


@claim("adv-s36-poisson-counting-control", kind="pb", sizes=SIZES)
def counting_control(s):
    """False (the control, one form): Λ_x(a, b) = (1 + tr(xC))⟨x, [a, b]⟩ is a Poisson tensor on so(n)."""
    return poisson_checks(s, PoissonTensor(SO_N, _scaled_lie_poisson, 2, "(1 + tr xC) LP"))
