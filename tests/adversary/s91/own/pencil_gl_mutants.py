# ruff: noqa
from stiefelsym import claim, admissible
from stiefelsym.proofs.sec6_dimension_lemmas import lambda1, lambda2, form_matrix, gl_basis


def body(s, scale_last, L_on_sym):
    mu, one, zero = s.scalar("mu"), s.q(1), s.q(0)
    h, v = s.generic("K", "n", "n", "skew"), s.generic("S", "n", "n", "sym")
    basis, kinds = gl_basis(s)
    c = mu * mu
    L = s.mat([[((one if L_on_sym else mu) if a[0] == "so" else (mu if L_on_sym else one)) if i == j else zero
                for j in range(len(kinds))] for i, a in enumerate(kinds)])
    psi = h * mu + v - s.A * c
    return {"iso": L @ (lambda1(s, h + v) * (one - c) + lambda2(s, h + v, s.A) * c) @ L
            - s.mat(form_matrix(s, psi, kinds, basis, kinds, False)) * scale_last(mu)}


@claim("pg-true", kind="dim", sizes=admissible(3, n_min=2))
def t(s):
    return body(s, lambda mu: mu, False)


@claim("pg-scale-c", kind="dim", sizes=admissible(3, n_min=2))
def f1(s):
    return body(s, lambda mu: mu * mu, False)


@claim("pg-L-swapped", kind="dim", sizes=admissible(3, n_min=2))
def f2(s):
    return body(s, lambda mu: mu, True)
