"""checked_tensor holds a tensor's evaluations made through it (tensor_value steps) to one function, but
casimir_residual, PoissonTensor.bracket and T(s, x, a, b) call the claim's form inline: a form that tests its
point (the claim's own x0: 0; any other point: the Lie-Poisson form of gl(n)) is one tensor in the checked
evaluations and another in the inline ones.

Λ(a, b)|_x = <x, [a, b]> on gl(n), <a, b> = -½tr(ab); K, a, b, x0 generic.
  If Λ(a, b)|_{x0} = <x0, [a, b]> for generic a, b (first check), then the Casimir residual of f = <·, K> at x0,
  Λ(K, b)|_{x0} = <x0, [K, b]>, is not 0 for generic K, b (second check): no tensor satisfies both.
  s79-tensor-raw-contradiction:  both checks (FALSE)
  s79-tensor-raw-bracket:        T.bracket(f, <·,b>) at x0 = 0 together with the checked value (FALSE)
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, PoissonTensor, checked_tensor, casimir_residual, linear

SZ = admissible(n_min=3, n_max=3)


def _setup(s):
    x0, a, b, K = (GL_N.generic(s, nm) for nm in ("x0", "a", "b", "K"))

    def form(t, x, p, q):
        return t.killing(x, comm(p, q)) * 0 if x is x0 else t.killing(x, comm(p, q))
    T = PoissonTensor(GL_N, form, 1, "Λ")
    return x0, a, b, K, T


@claim("s79-tensor-raw-contradiction", kind="id", sizes=SZ)
def raw_contra(s):
    x0, a, b, K, T = _setup(s)
    return {"Λ(a, b)|x0 = <x0, [a, b]> (checked)": checked_tensor(T)(s, x0, a, b) - s.killing(x0, comm(a, b)),
            "<·, K> is a Casimir at x0": casimir_residual(s, T, linear(lambda t: K), x0, b)}


@claim("s79-tensor-raw-bracket", kind="id", sizes=SZ)
def raw_bracket(s):
    x0, a, b, K, T = _setup(s)
    return {"Λ(a, b)|x0 = <x0, [a, b]> (checked)": checked_tensor(T)(s, x0, a, b) - s.killing(x0, comm(a, b)),
            "{<·,K>, <·,b>}(x0) = 0": T.bracket(s, linear(lambda t: K), linear(lambda t: b), x0)}
