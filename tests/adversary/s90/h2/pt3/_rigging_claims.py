"""A claims file (verify --claims takes it: one TRUE claim) whose name starts with "_"; named on pytest's command
line, pytest imports it in its own process, where it rigs every item of the session."""
from stiefelsym import admissible, claim
from stiefelsym import pytest_plugin as _p


@claim("rig-true", kind="id", sizes=admissible(n_max=3))
def rig_true(s):
    """TRUE: XᵀX = I_r."""
    return {"r": s.X.T @ s.X - s.Ir}


def _pass(self):
    self.user_properties.append(("verdict", "proved"))


_p.ClaimItem.runtest = _pass
