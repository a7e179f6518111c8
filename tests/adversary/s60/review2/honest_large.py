"""An honest claims file, two true claims; run in-process at a size where the scene draws a block of >= 64
parameters at once (scene.PARAM_BLOCK_MIN), which the engine does with numpy.random.default_rng
(backends/fields.py, _generator) -- importing numpy.random after the seal."""
from stiefelsym import admissible, claim


@claim("s60r2-honest-xtx-a", paper="adv", kind="id", sizes=admissible(n_max=12))
def xtx_a(s):
    """True: XᵀX = I_r."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}


@claim("s60r2-honest-xtp-b", paper="adv", kind="id", sizes=admissible(n_max=12))
def xtp_b(s):
    """True: XᵀP + PᵀX = 0."""
    return {"XtP + PtX": s.X.T @ s.P + s.P.T @ s.X}
