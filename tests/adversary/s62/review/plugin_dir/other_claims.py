"""A FALSE claim (XᵀP = 0), written with the module's decorator spelled stiefelsym.claim: the decorator's text (at-sign, claim, paren) is
not in the file."""
import stiefelsym


@stiefelsym.claim("s62-pl-false-dotted", kind="id", sizes=stiefelsym.admissible(n_max=3))
def false_one(s):
    """XᵀP = 0 (false)."""
    return {"XtP": s.X.T @ s.P}
