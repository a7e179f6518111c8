"""Round 6: two corrections of one claim with the same description (the variant that names a correction in every
record): a true one and a false one, registered by the decorator."""
from stiefelsym import admissible, claim, comm


@claim("adv-s36-dup-corrections", paper="prep", kind="id", sizes=admissible(n_max=3), expect="fails",
       erratum="the printed commutator has the wrong sign")
def printed(s):
    """Printed: [XXᵀ, A] + [A, XXᵀ]·2 = 0 (false)."""
    return {"E": comm(s.X @ s.X.T, s.A) + comm(s.A, s.X @ s.X.T) * 2}


@printed.claim.correction("the factor 2 replaced by 1")
def corrected_true(s):
    return {"E": comm(s.X @ s.X.T, s.A) + comm(s.A, s.X @ s.X.T)}


@printed.claim.correction("the factor 2 replaced by 1")
def corrected_false(s):
    return {"E": comm(s.X @ s.X.T, s.A) + comm(s.A, s.X @ s.X.T) * 3}
