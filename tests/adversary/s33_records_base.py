"""Two claims whose honest records (exact at (3,2) and free) are the base of the forged results files of
test_adversary_s33.py: malformed fields (a list for a claim id, a size or a method, a meta field of the wrong
type, a size bound far beyond any run) must be bad input (exit 2) or a rejection (exit 1) with a message,
never a traceback, a hang, or an acceptance."""
from stiefelsym import admissible, claim

_SIZES = admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)")


@claim("adv-s33-rec-true", kind="id", sizes=_SIZES, statement="X^T X = I_r")
def rec_true(s):
    """True."""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("adv-s33-rec-false", kind="id", sizes=_SIZES, statement="X^T X = 2 I_r")
def rec_false(s):
    """False (its forged records say proved)."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}
