"""A tensor held to one function through checked_tensor, but composed: checked_tensor(T1 + Z) or
checked_tensor(T1.scaled(c)).  The sum's / multiple's form calls the PARTS' forms directly (self.form), so the
part T1 inside the checked step is held only to T1's own *step* evaluations (_one_function, `hold(part)`), never
to T1's *inline* calls (casimir_residual, T1(s, x, a, b): `_calls`).  A form T1 that tests its point (the claim's
own x0: 0; elsewhere Lie–Poisson) is then LP in the checked steps and 0 in the inline calls.

Truth (by hand): Z ≡ 0 (its form is 0·<x,[p,q]>), so (T1 + Z)(x0, a, b) = <x0, [a, b]> at generic a, b makes
T1(x0, ·, ·) = <x0, [·, ·]> (bilinear), hence the Casimir residual of <·, K> at x0, T1(x0, K, b) =
<x0, [K, b]> ≠ 0 for generic x0, K, b.  No one tensor T1 satisfies both statements: every such claim is FALSE.
  s79r2-sum-contradiction:     checked (T1 + Z)(x0,a,b) = <x0,[a,b]>   and   casimir_residual(T1, <·,K>, x0, b) = 0
  s79r2-scaled-contradiction:  checked (2·T1)(x0,a,b) = 2<x0,[a,b]>   and   T1(s, x0, K, b) = 0
  s79r2-sum-honest (control, false): the same as the first with an honest T1 (no test of x): must fail.
  s79r2-sum-honest-true (control, true): checked (T1h + Z)(x0,a,b) = <x0,[a,b]> and T1h(x0,K,b) = <x0,[K,b]>.
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, PoissonTensor, checked_tensor, casimir_residual, linear

SZ = admissible(n_min=3, n_max=3)


def _setup(s, honest=False):
    x0, a, b, K = (GL_N.generic(s, nm) for nm in ("x0", "a", "b", "K"))

    def form(t, x, p, q):
        if x is x0 and not honest:
            return t.killing(x, comm(p, q)) * 0
        return t.killing(x, comm(p, q))
    T1 = PoissonTensor(GL_N, form, 1, "Λ1")
    Z = PoissonTensor(GL_N, lambda t, x, p, q: t.killing(x, comm(p, q)) * 0, 1, "Z")
    return x0, a, b, K, T1, Z


@claim("s79r2-sum-contradiction", kind="id", sizes=SZ)
def sum_contra(s):
    x0, a, b, K, T1, Z = _setup(s)
    return {"(T1 + Z)(a, b)|x0 = <x0, [a, b]> (checked)": checked_tensor(T1 + Z)(s, x0, a, b) - s.killing(x0, comm(a, b)),
            "<·, K> is a Casimir of T1 at x0": casimir_residual(s, T1, linear(lambda t: K), x0, b)}


@claim("s79r2-scaled-contradiction", kind="id", sizes=SZ)
def scaled_contra(s):
    x0, a, b, K, T1, Z = _setup(s)
    return {"(2 T1)(a, b)|x0 = 2<x0, [a, b]> (checked)":
            checked_tensor(T1.scaled(lambda t: 2))(s, x0, a, b) - s.killing(x0, comm(a, b)) * 2,
            "T1(K, b)|x0 = 0": T1(s, x0, K, b)}


@claim("s79r2-sum-honest", kind="id", sizes=SZ)
def sum_honest(s):
    x0, a, b, K, T1, Z = _setup(s, honest=True)
    return {"(T1 + Z)(a, b)|x0 = <x0, [a, b]> (checked)": checked_tensor(T1 + Z)(s, x0, a, b) - s.killing(x0, comm(a, b)),
            "<·, K> is a Casimir of T1 at x0": casimir_residual(s, T1, linear(lambda t: K), x0, b)}


@claim("s79r2-sum-honest-true", kind="id", sizes=SZ)
def sum_honest_true(s):
    x0, a, b, K, T1, Z = _setup(s, honest=True)
    return {"(T1 + Z)(a, b)|x0 = <x0, [a, b]> (checked)": checked_tensor(T1 + Z)(s, x0, a, b) - s.killing(x0, comm(a, b)),
            "T1(K, b)|x0 = <x0, [K, b]>": T1(s, x0, K, b) - s.killing(x0, comm(K, b))}
