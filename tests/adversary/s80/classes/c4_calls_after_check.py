"""Class 4 (state across calls), newest code: calls of a held object made inside an Inverse's op, which the
tracer applies (Trace.inverse) AFTER Trace.check_calls has held the claim's calls to one function.

a(t) is a stateful covector handed to brackets.linear: its odd calls return 0, its even calls Ψ (the counter
is reset at the start of each claim, so both traces of the determinism check agree).  h = linear(a) means
h(x) = <x, a>, ∇h = a (one function a).  For ANY single function a:  h(Ψ) = <Ψ, ∇h>.

i4-false: Inverse(op, id) on Sym(r) × R^{r×r} with op(x1, x2) = (x1 + h(Ψ)·I_r, x2 + (∇h − Ψ)).
   op = id iff h(Ψ) = 0 and ∇h = Ψ; for one function a that means a = Ψ and <Ψ, Ψ> = 0, but
   <Ψ, Ψ> = −½tr(Ψ²) = ½|Ψ|²_F > 0 wherever Ψ ≠ 0 (a generic point at r = 2): so op ≠ id there, and
   inv = id is not op's inverse.  FALSE for every a (verified in c4_calls_after_check_truth.py.in).
i4-true: Inverse(op, id) with op(x) = x + (h(Ψ) − <Ψ, ∇h>)·I_r: TRUE for every single function a (c = 0).
r4-false: the same c of i4-false as a plain residual (its calls are held by check_calls: must be refused).
i4-stateless: i4-false's op with a stateless a = Ψ: c = ½|Ψ|² ≠ 0: FALSE, must fail.
"""
from stiefelsym import Inverse, admissible, claim
from stiefelsym.brackets import linear

SZ = admissible(n_max=3, n_min=2, r_min=2)
STATE = [0]


def a(t):
    STATE[0] += 1
    return t.Psi if STATE[0] % 2 == 0 else t.Psi - t.Psi


def a_plain(t):
    return t.Psi


def _op_false(s, h, x1, x2):
    v = h.value(s, s.Psi)
    g = h.gradient(s, s.Psi)
    return x1 + v * s.Ir, x2 + (g - s.Psi)


def _ident(s, y):
    return y


def _ident2(s, y1, y2):
    return y1, y2


@claim("i4-false", kind="id", sizes=SZ)
def i4_false(s):
    """FALSE (see module docstring)."""
    STATE[0] = 0
    h = linear(a)
    return {"inv": Inverse(lambda t, x1, x2: _op_false(t, h, x1, x2), _ident2, on=("Sym(r)", "R^{r×r}"))}


@claim("i4-true", kind="id", sizes=SZ)
def i4_true(s):
    """TRUE for every single function a."""
    STATE[0] = 0
    h = linear(a)
    return {"inv": Inverse(lambda t, x: x + (h.value(t, t.Psi) - t.killing(t.Psi, h.gradient(t, t.Psi))) * t.Ir,
                           _ident, on="Sym(r)")}


@claim("r4-false", kind="id", sizes=SZ)
def r4_false(s):
    """FALSE: h(Ψ) = 0 and ∇h = Ψ as a residual (calls held by check_calls)."""
    STATE[0] = 0
    h = linear(a)
    v = h.value(s, s.Psi)
    g = h.gradient(s, s.Psi)
    return {"h": v, "grad": g - s.Psi}


@claim("i4-stateless", kind="id", sizes=SZ)
def i4_stateless(s):
    """FALSE: i4-false with a stateless a = Ψ."""
    h = linear(a_plain)
    return {"inv": Inverse(lambda t, x1, x2: _op_false(t, h, x1, x2), _ident2, on=("Sym(r)", "R^{r×r}"))}


# -- the same route through RightInverse and through MatrixFunction.scaled (other held objects) -------------
from stiefelsym import RightInverse  # noqa: E402


@claim("ri4-false", kind="id", sizes=SZ)
def ri4_false(s):
    """FALSE: i4-false's op as a RightInverse (op onto with right inverse id: op = id needed, same contradiction)."""
    STATE[0] = 0
    h = linear(a)
    return {"ri": RightInverse(lambda t, x1, x2: _op_false(t, h, x1, x2), _ident2,
                               on=("Sym(r)", "R^{r×r}"), to=("Sym(r)", "R^{r×r}"))}


CST = [0]


def c_state(t):
    CST[0] += 1
    return t.q(1, 1) if CST[0] % 2 == 0 else t.q(0, 1)


@claim("sc4-false", kind="id", sizes=SZ)
def sc4_false(s):
    """FALSE: h = linear(Ψ).scaled(c): h(Ψ) = c<Ψ,Ψ>, ∇h = cΨ; op = id iff c<Ψ,Ψ> = 0 and cΨ = Ψ, i.e. c = 1
    and <Ψ,Ψ> = 0, impossible where Ψ ≠ 0.  The stateful scalar c is 0 at the value's call, 1 at the gradient's."""
    CST[0] = 0
    h = linear(a_plain).scaled(c_state)
    return {"inv": Inverse(lambda t, x1, x2: _op_false(t, h, x1, x2), _ident2, on=("Sym(r)", "R^{r×r}"))}


@claim("sc4-resid", kind="id", sizes=SZ)
def sc4_resid(s):
    """FALSE: sc4-false's two conditions as plain residuals (must be refused: calls held)."""
    CST[0] = 0
    h = linear(a_plain).scaled(c_state)
    return {"h": h.value(s, s.Psi), "grad": h.gradient(s, s.Psi) - s.Psi}


# -- brackets.quadratic: the value's inline call of op vs the gradient's checked op (stop 79's route) --------
from stiefelsym.brackets import quadratic  # noqa: E402

QST = [0]


def op_state(t, u):
    QST[0] += 1
    return u * 2 if QST[0] % 3 == 0 else u      # every third call (the value's inline call) is 2u


@claim("q4-true", kind="id", sizes=SZ)
def q4_true(s):
    """TRUE for every linear symmetric op: h = quadratic(op) has h(x) = ½<x, op x> and ∇h(x) = op x, so
    h(Ψ) − ½<Ψ, ∇h(Ψ)> = 0.  As an Inverse: op2(x1, x2) = (x1 + that·I_r, x2) is the identity, inv = id."""
    QST[0] = 0
    h = quadratic(op_state)

    def op2(t, x1, x2):
        g = h.gradient(t, t.Psi)        # op's calls 1, 2 (its value and its checked function): u
        v = h.value(t, t.Psi)           # op's call 3 (inline): 2u
        return x1 + (v - t.killing(t.Psi, g) / 2) * t.Ir, x2
    return {"inv": Inverse(op2, _ident2, on=("Sym(r)", "R^{r×r}"))}


@claim("q4-resid", kind="id", sizes=SZ)
def q4_resid(s):
    """TRUE (as q4-true) as a plain residual: its calls are held by check_calls (refused, or proved)."""
    QST[0] = 0
    h = quadratic(op_state)
    g = h.gradient(s, s.Psi)
    v = h.value(s, s.Psi)
    return {"c": v - s.killing(s.Psi, g) / 2}
