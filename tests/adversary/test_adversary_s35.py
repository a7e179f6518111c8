"""Fifth round: the double Neumann system's point next to the scene's own point, the Inverse statement's
divisors (constants that vanish at some size), and what else was tried (tests/adversary/README.md, the last
table).  As before: every run is the CLI in a fresh process, each test asserts the CORRECT outcome, and a route
open today is a strict xfail."""

from adversary_cli import PASSING
from test_adversary_s34b import by_claim, fixed, run_all

DOUBLE_FALSE = ("adv-s35-dx-in-the-span-of-x", "adv-s35-dx-dy-against-x", "adv-s35-dx-against-p",
                "adv-s35-dx-in-the-span-of-y")


def test_the_double_point_is_independent_of_the_scenes_point():
    """DX = X₀DU was built on the scene's own X: X Xᵀ DX = DX, (XᵀDX)(DYᵀX) = I_r, tr(Pᵀ(I − XXᵀ)DX) = 0 were
    proved / checked / numeric at (3,2) by every fixed-size method (free: undecided, DX is a letter of its
    own), and dDX/dt = 0 along a flow of (X, P), true, failed under every fixed-size method (free: proved).
    Closed: the double point is built on a point of V(n, r) of its own (Scene._double_base)."""
    got = by_claim(run_all("s35_double_point.py"))
    for c in DOUBLE_FALSE:
        assert fixed(got[c]) == {"fails"} and got[c]["free"] == "undecided", (c, got[c])
    true = got["adv-s35-dx-not-moved-by-x"]
    assert fixed(true) <= set(PASSING) and true["free"] == "proved", true
