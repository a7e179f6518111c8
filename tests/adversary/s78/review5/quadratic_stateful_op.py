"""brackets.quadratic(op): the operator is checked symmetric inside one engine step (symmetric_operator_check,
which traces op as a function of its argument), while the gradient op(x) is the claim's inline call of op.
An op with state (or one that tests its argument's identity) can be B·y on the gradient's call and the identity
on the check's: is op held to be one function across the two (as checked_tensor holds a tensor, and Inverse
op/inv, with same_step_function / _same_map)?

op_stateful: first call B·y, every later call y.  op_identity: B·y on the claim's own x object, y on any other.
Neither is one function of the matrix: no claim here has a clean truth value unless the engine refuses
(error) -- recorded as a probe.  Twins state the bracket of h with g = <., b> as Λ(x, b) (= 0, the gradient of
½<x, x>) and as Λ(Bx, b) (the carried gradient of the first call)."""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, lie_poisson, quadratic, linear

SZ = admissible(n_max=3, n_min=3)


def _stateful(s):
    B = s.generic("B", "n", "n")
    calls = []

    def op(t, y):
        calls.append(1)
        return B @ y if len(calls) == 1 else y
    return B, op


def _by_identity(s, x):
    B = s.generic("B", "n", "n")

    def op(t, y):
        return B @ y if y is x else y
    return B, op


@claim("r5-quadstate-bx", kind="pb", sizes=SZ)
def stateful_bx(s):
    B, op = _stateful(s)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    br = lie_poisson(GL_N).bracket(s, quadratic(op), linear(lambda t: b), x)
    return {"{h, g} = Λ(Bx, b)": br - s.killing(x, comm(B @ x, b))}


@claim("r5-quadstate-x", kind="pb", sizes=SZ)
def stateful_x(s):
    B, op = _stateful(s)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    br = lie_poisson(GL_N).bracket(s, quadratic(op), linear(lambda t: b), x)
    return {"{h, g} = Λ(x, b) = 0": br}


@claim("r5-quadident-bx", kind="pb", sizes=SZ)
def ident_bx(s):
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    B, op = _by_identity(s, x)
    br = lie_poisson(GL_N).bracket(s, quadratic(op), linear(lambda t: b), x)
    return {"{h, g} = Λ(Bx, b)": br - s.killing(x, comm(B @ x, b))}


@claim("r5-quadstate-contradiction", kind="pb", sizes=SZ)
def stateful_contradiction(s):
    """One claim, two checks that no function h can satisfy together: h = ½<·,·> at a generic point (so everywhere,
    as a polynomial identity in that point's parameters: ∇h(x) = x and {h, <.,b>}(x) = <x,[x,b]> = 0 on gl(n)),
    and {h, <.,b>}(x) = <x, [Bx, b]> ≠ 0.  Both proved means one verdict is wrong whatever h is taken to be."""
    B, op = _stateful(s)
    h = quadratic(op)
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    br = lie_poisson(GL_N).bracket(s, h, linear(lambda t: b), x)      # op's first call: B·x
    return {"{h, g}(x) = <x,[Bx,b]>": br - s.killing(x, comm(B @ x, b)),
            "h(y) = ½<y, y> at a generic y": h(s, y) - s.killing(y, y) / 2}


@claim("r5-quadident-contradiction", kind="pb", sizes=SZ)
def ident_contradiction(s):
    """The same pair with an op that tests its argument's identity instead of keeping state."""
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    B, op = _by_identity(s, x)
    h = quadratic(op)
    br = lie_poisson(GL_N).bracket(s, h, linear(lambda t: b), x)
    return {"{h, g}(x) = <x,[Bx,b]>": br - s.killing(x, comm(B @ x, b)),
            "h(y) = ½<y, y> at a generic y": h(s, y) - s.killing(y, y) / 2}
