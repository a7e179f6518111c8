"""Round 7 (tests/adversary/README.md, the "Round 7" table): fresh routes through the charts, the sites of
the mutation analysis, the degree bounds and the checker.  As before every run is the CLI in a fresh process,
and each test asserts the CORRECT outcome."""
from adversary_cli import PASSING
from test_adversary_s34b import by_claim, fixed, run_all

SECOND = "s37_second_point_components.py"
SECOND_FALSE = ("adv-s37-det-xty", "adv-s37-det-product", "adv-s37-same-det", "adv-s37-rotation", "adv-s37-det-traces",
                "adv-s37-cofactor")
SECOND_TRUE = ("adv-s37-det-product-true", "adv-s37-orthogonal-true")
SECOND_POLE = "adv-s37-pole-mixed"


def test_the_second_point_lies_on_either_component_at_r_equal_n():
    """At r = n a second point Y of V(n, n) = O(n) lies on either component, whatever X's: det(XᵀY) = ±1.
    The Cayley chart built Y with the sign matrix of X's component, so (X, Y) was on one component only:
    det(XᵀY) = 1, M + Mᵀ = tr(M) I for M = XᵀY (no coordinate read) and the cofactor form of det(XᵀY) = 1 were
    checked by modular / rational and numeric by float / ball (exact, on the equivariant chart with its second
    component for Y, failed them), and det X det Y = 1, det X = det Y, which read coordinates of R^n and so
    took the exact method's Cayley chart too, were also proved by exact.  Closed: the chart's component has a
    bit for X and a bit for Y (`Scene._component_of`), and every method that alternates the components takes
    the four pairs once the evaluation read the second point: every false claim fails under every fixed-size
    method, the controls pass, and a statement undefined on the mixed pairs (a divisor tr(XᵀY) that vanishes
    identically there), checked / numeric before, is no longer passed."""
    got = {}
    for size in ("2,2", "3,3"):
        ids = [c for c in SECOND_FALSE + SECOND_TRUE + (SECOND_POLE,)
               if (c == "adv-s37-cofactor") == (size == "3,3") or c == "adv-s37-orthogonal-true"]
        for c, v in by_claim(run_all(SECOND, ids=ids, size=size, free=False)).items():
            got.setdefault(c, {}).update({(m, size): x for m, x in v.items()})
    assert set(got) == set(SECOND_FALSE) | set(SECOND_TRUE) | {SECOND_POLE}, sorted(got)
    for c in SECOND_FALSE:
        assert fixed(got[c]) == {"fails"} and len(got[c]) >= 5, (c, got[c])   # auto names the method it chose
    for c in SECOND_TRUE:
        assert fixed(got[c]) <= set(PASSING), (c, got[c])
    # undefined on the mixed pairs: exact error, the point methods inconclusive (modular, float, ball passed it)
    assert not fixed(got[SECOND_POLE]) & set(PASSING), got[SECOND_POLE]
