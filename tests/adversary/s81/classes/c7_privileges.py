"""Class 7 (engine privileges), new tricks: the claim reaches the running Trace through the module global
``stiefelsym.ir.trace._ACTIVE`` (not through s._t) and edits its per-claim DATA (not an engine function): the
record of held calls ``_calls`` that Trace.check_calls compares when the claim's trace ends.

Each -false claim uses a MatrixFunction whose value is ½<y, y> at its first two traces (the gradient's check step and
its hold) and ¼<y, y> at the claim's own call (a counter): unheld, the claim states <∇h(x), x> = 4h(x) for
h = ¼<y, y> (true: 2h(x)), FALSE (see c4_state.py).  The -true twin: the same edit, a plain ¼<y,y> with gradient y/2.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_max=3, n_min=2)


_MODE = []


def _stateful():
    del _MODE[:]

    def value(t, y):
        return t.killing(y, y) / (4 if _MODE else 2)
    return value


def _switch():
    _MODE.append(1)


def _trace():
    import sys
    return sys.modules["stiefelsym.ir.trace"]._ACTIVE[-1]


@claim("c7-clear-false", kind="id", sizes=SZ)
def c7_clear_false(s):
    h = MatrixFunction(_stateful(), lambda t, y: y)
    x = s.X @ s.X.T
    r = s.killing(h.grad(s, x), x) - (_switch(), h(s, x))[1] * 4
    _trace()._calls.clear()
    return {"r": r}


class _Forget(dict):
    def setdefault(self, k, d=None):
        return {"obj": None, "calls": [], "what": ""}


@claim("c7-forget-false", kind="id", sizes=SZ)
def c7_forget_false(s):
    t = _trace()
    object.__setattr__(t, "_calls", _Forget())
    h = MatrixFunction(_stateful(), lambda t_, y: y)
    x = s.X @ s.X.T
    return {"r": s.killing(h.grad(s, x), x) - (_switch(), h(s, x))[1] * 4}


@claim("c7-clear-true", kind="id", sizes=SZ)
def c7_clear_true(s):
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 4, lambda t, y: y / 2)
    x = s.X @ s.X.T
    r = s.killing(h.grad(s, x), x) - h(s, x) * 2
    _trace()._calls.clear()
    return {"r": r}


@claim("c7-private-false", kind="id", sizes=SZ)
def c7_private_false(s):
    """FALSE: the same through s._t (a private attribute of the scene: expected refused)."""
    h = MatrixFunction(_stateful(), lambda t, y: y)
    x = s.X @ s.X.T
    r = s.killing(h.grad(s, x), x) - (_switch(), h(s, x))[1] * 4
    s._t._calls.clear()
    return {"r": r}


@claim("c7-control-false", kind="id", sizes=SZ)
def c7_control_false(s):
    """FALSE, the same stateful value with the record left alone: expected refused (the hold)."""
    h = MatrixFunction(_stateful(), lambda t, y: y)
    x = s.X @ s.X.T
    return {"r": s.killing(h.grad(s, x), x) - (_switch(), h(s, x))[1] * 4}
