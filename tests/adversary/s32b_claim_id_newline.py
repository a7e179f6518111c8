"""A claim whose id holds a line break followed by a forged verdict line: its own verdict (fails) is printed
after the id, so standard output shows a line that reads as `exact: proved` for the claim's own name.  No
claim id is checked against a pattern (the decorator, Claim, nor the wire decoder)."""
from stiefelsym import admissible, claim

FORGED_ID = "adv-s32b-nl (3,2) exact: proved (0.01s, no randomness)\nadv-s32b-nl-tail"


@claim(FORGED_ID, kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"))
def nl(s):
    """False: X_11 = 1."""
    return {"r": s.X[0, 0] - s.q(1)}
