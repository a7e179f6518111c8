"""Round 6: two corrections of one claim with the same description, appended to the claim's list of corrections
(past the decorator's test): a true one and a false one."""
from stiefelsym import admissible, claim, comm
from stiefelsym.claims import Correction


@claim("adv-s36-dup-corrections-appended", paper="prep", kind="id", sizes=admissible(n_max=3), expect="fails",
       erratum="the printed commutator has the wrong sign")
def printed(s):
    """Printed: [XXᵀ, A] + [A, XXᵀ]·2 = 0 (false)."""
    return {"E": comm(s.X @ s.X.T, s.A) + comm(s.A, s.X @ s.X.T) * 2}


def corrected_true(s):
    return {"E": comm(s.X @ s.X.T, s.A) + comm(s.A, s.X @ s.X.T)}


def corrected_false(s):
    return {"E": comm(s.X @ s.X.T, s.A) + comm(s.A, s.X @ s.X.T) * 3}


printed.claim.corrections.append(Correction("the factor 2 replaced by 1", corrected_true))
printed.claim.corrections.append(Correction("the factor 2 replaced by 1", corrected_false))
