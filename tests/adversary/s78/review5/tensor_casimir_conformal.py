"""A Poisson tensor of degree 3 in x (poisson_checks' Jacobi identity interpolates at the degree it derives,
never at the declared one; the declared degree is only checked by the "degree in x <= d" residual).

On so(n) with <a, b> = -1/2 tr(ab): Λ_LP(a, b)|_x = <x, [a, b]> is Poisson, and φ(x) = <x, x> is a Casimir of it,
so φ·Λ_LP is Poisson ([φΛ, φΛ] = φ²[Λ, Λ] + 2φ Λ♯(dφ) ∧ Λ = 0).  With ψ(x) = <x, K> (K generic skew), not a
Casimir, ψ·Λ_LP is not Poisson for n >= 4 (at n = 3 every f·Λ_LP is): its Jacobiator at generic x, a, b, c is 2ψ·(Λ♯dψ ∧ Λ)(a, b, c) ≠ 0
(numpy: tensor_casimir_conformal_check.py.in).

  r5-conf-casimir-jacobi-true : Jacobi residual of φ·Λ_LP (declared degree 3) = 0          TRUE
  r5-conf-casimir-deg1-true   : the same tensor declared with degree 1; only the Jacobi residual
                                 is stated (the degree residual is left out)             TRUE
  r5-conf-casimir-deg1-degree-false : its "degree in x <= 1" residual = 0                FALSE (degree 3)
  r5-conf-noncasimir-jacobi-false   : Jacobi residual of ψ·Λ_LP (declared degree 2) = 0  FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import SO_N, PoissonTensor, poisson_checks

SZ = admissible(n_max=4, n_min=3)
SZ4 = admissible(n_max=4, n_min=4)      # in dim so(3) = 3 every f·Λ_LP is Poisson (v·curl v = 0 for v = f x)


def _phi_lp(degree):
    return PoissonTensor(SO_N, lambda s, x, a, b: s.killing(x, x) * s.killing(x, comm(a, b)), degree, "φΛ")


def _psi_lp(degree):
    return PoissonTensor(SO_N, lambda s, x, a, b: s.killing(x, SO_N.generic(s, "K")) * s.killing(x, comm(a, b)),
                         degree, "ψΛ")


def _pick(checks, word):
    return {k: v for k, v in checks.items() if word in k}


@claim("r5-conf-casimir-jacobi-true", kind="pb", sizes=SZ)
def conf_true(s):
    return poisson_checks(s, _phi_lp(3), "φΛ")


@claim("r5-conf-casimir-deg1-true", kind="pb", sizes=SZ)
def conf_deg1_true(s):
    return _pick(poisson_checks(s, _phi_lp(1), "φΛ"), "Jacobi")


@claim("r5-conf-casimir-deg1-degree-false", kind="pb", sizes=SZ)
def conf_deg1_degree_false(s):
    return _pick(poisson_checks(s, _phi_lp(1), "φΛ"), "degree")


@claim("r5-conf-noncasimir-jacobi-false", kind="pb", sizes=SZ4)
def nonconf_false(s):
    return _pick(poisson_checks(s, _psi_lp(2), "ψΛ"), "Jacobi")
