"""A false claim that passes on the sampled methods: a primitive of the claims file runs at evaluation
time on the live values and tells the method by its number system."""
from stiefelsym import admissible, claim
from stiefelsym.ir import primitive


@primitive
def vanish_when_sampled(X):
    """X on the symbolic method, 0 elsewhere."""
    if type(X.field).__name__ in ("SymbolicField",):
        return X
    return X - X


@claim("adv-primitive-method", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def x_is_zero(s):
    """X = 0 on the Stiefel variety (false)."""
    return {"X": vanish_when_sampled(s.X)}
