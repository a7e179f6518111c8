"""Stop 80's own attempt: a form that is no bivector, yet antisymmetric, of degree 1 in x, and with the Jacobi
identity of linear functions.

Λ(a, b)|_x = <x, [a, b]> + tr(a)·tr(b)·(tr a − tr b): antisymmetric; the added part does not depend on x, so
∇_x Λ(b, c) = [b, c], whose trace is 0, and Λ(a, [b, c]) = <x, [a, [b, c]]> + 0: the jacobiator is the Lie
algebra's, 0.  It is not bilinear (cubic in the traces).  poisson_checks proved it "Poisson" under every method,
free for all n, r included, before its additivity check (the three identities it checked do hold:
nonbilinear-old-checks, true).
  nonbilinear-poisson:     poisson_checks of that form: FALSE (Λ(a + c, b) ≠ Λ(a, b) + Λ(c, b))
  lie-poisson-control:     poisson_checks of the Lie–Poisson form: TRUE
  nonbilinear-old-checks:  antisymmetry, degree and jacobiator of the form, as stated: TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, PoissonTensor, poisson_checks

SZ = admissible(n_min=3, n_max=3)


@claim("nonbilinear-poisson", kind="pb", sizes=SZ)
def nb(s):
    T = PoissonTensor(GL_N, lambda t, x, a, b: t.killing(x, comm(a, b)) + a.trace() * b.trace() * (a.trace() - b.trace()), 1, "N")
    return poisson_checks(s, T)


@claim("lie-poisson-control", kind="pb", sizes=SZ)
def lp(s):
    T = PoissonTensor(GL_N, lambda t, x, a, b: t.killing(x, comm(a, b)), 1, "LP")
    return poisson_checks(s, T)


@claim("nonbilinear-old-checks", kind="pb", sizes=SZ)
def nb_old(s):
    from stiefelsym.brackets import antisymmetry, checked_tensor, degree_residual, jacobiator
    T = checked_tensor(PoissonTensor(GL_N, lambda t, x, a, b: t.killing(x, comm(a, b)) + a.trace() * b.trace() * (a.trace() - b.trace()), 1, "N"))
    x, a, b, c, e = (GL_N.fresh(s) for _ in range(5))
    return {"antisymmetry": antisymmetry(s, T, x, a, b), "degree": degree_residual(s, T, x, e, b, c),
            "Jacobi": jacobiator(s, T, x, a, b, c)}
