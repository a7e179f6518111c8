"""The modular method's primes are a function of the seed, the claim's id and the size alone (methods.
_prime_field: random.Random(f"{seed}|{id}|{n}|{r}|modular|{t}|prime|{attempt}")), so a claims file can compute
them before it states its claim: with M the product of the primes the method will draw, the residual
1·tr(PᵀP) + (M − 1)·tr(PᵀP) = M·tr(PᵀP) is not zero over Q, but it vanishes modulo every drawn prime while no
constant of the claim does (1 and M − 1 ≡ −1 are units mod each p: the check of ModularField.const does not
see it).  Modular answers `checked` with a false-pass bound of the order of 1e-30 for a false claim."""
import random

from stiefelsym import admissible, claim
from stiefelsym.backends.fields import random_prime

#: the points and prime redraws of one run covered (the run takes far fewer)
POINTS, ATTEMPTS = 48, 2


def _primes(cid, n, r, seed=0):
    return [random_prime(random.Random(f"{seed}|{cid}|{n}|{r}|modular|{t}|prime|{a}"))
            for t in range(POINTS) for a in range(ATTEMPTS)]


def _product(cid, n, r):
    m = 1
    for p in set(_primes(cid, n, r)):
        m *= p
    return m


_SIZE = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)")
_M = _product("adv-s33-seeded-sum", 3, 2)
_M2 = _product("adv-s33-seeded-matrix", 3, 2)
_M3 = _product("adv-s33-seeded-fraction", 3, 2)


@claim("adv-s33-seeded-sum", kind="id", sizes=_SIZE, statement="tr(P^T P) + (M - 1) tr(P^T P) = 0")
def seeded_sum(s):
    """False: the residual is M·tr(PᵀP), M the product of the primes the modular method draws."""
    t = s.tr(s.P.T @ s.P)
    return {"r": t * s.q(1) + t * s.q(_M - 1)}


@claim("adv-s33-seeded-matrix", kind="id", sizes=_SIZE, statement="X + (M - 1) X = 0")
def seeded_matrix(s):
    """False: the residual is M·X."""
    return {"r": s.X + s.X * (_M2 - 1)}


@claim("adv-s33-seeded-fraction", kind="id", sizes=_SIZE, statement="X/3 + (M/3 - 1/3) X = 0")
def seeded_fraction(s):
    """False: the residual is (M/3)·X (constants with a denominator)."""
    return {"r": s.X * s.q(1, 3) + s.X * s.q(_M3 - 1, 3)}


_M4 = _product("adv-s33-seeded-absorbed", 3, 2)
#: a constant that absorbs M·X at every precision of the float method's ladder (30 to 120 digits and beyond)
_C4 = _M4 * 10 ** 400 + 1


@claim("adv-s33-seeded-absorbed", kind="id", sizes=_SIZE, statement="(c X + M X) - c X = 0, c = 10^400 M + 1")
def seeded_absorbed(s):
    """False: the residual is M·X; float and ball absorb it into c·X, and the confirmation of their `numeric` at
    exact points modulo the drawn primes sees M·X ≡ 0 there."""
    return {"r": (s.X * _C4 + (s.X + s.X * (_M4 - 1))) - s.X * _C4}


_M5 = _product("adv-s33-seeded-auto", 13, 2)


@claim("adv-s33-seeded-auto", kind="id", sizes=admissible(n_max=13, n_min=13, r_min=2, r_max=2, condition="(13,2)"),
       statement="X + (M - 1) X = 0 at (13,2)")
def seeded_auto(s):
    """False: the residual is M·X; at (13,2) auto chooses the modular method (exact is beyond its budget there)."""
    return {"r": s.X + s.X * (_M5 - 1)}
