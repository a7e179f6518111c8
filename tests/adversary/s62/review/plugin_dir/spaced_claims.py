"""A FALSE claim whose decorator is written '@ claim (' (legal Python)."""
from stiefelsym import admissible, claim as stated


@ stated ("s62-pl-false-spaced", kind="id", sizes=admissible(n_max=3))
def false_three(s):
    """tr PᵀP = 0 (false)."""
    return {"trPtP": s.tr(s.P.T @ s.P)}
