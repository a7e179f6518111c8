"""Stop 81's replays: an engine check made at the point (a declared gradient, quadratic's operator) is checked
along the flow of a derivative taken through it, and refused inside the function of s.gradient (stop 80's second
review, W1: the check was a constant step, so its derivative and its adjoint were taken as 0)."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ADVERSARY = Path(__file__).parent
REVIEW2_80 = ADVERSARY / "s80" / "review2"

TRUE = ("proved", "checked", "numeric")
HONEST = ("error", "undecided", "inconclusive")


def _records(path: Path, *args: str) -> dict:
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), "--jobs", "1",
                          "--format", "json", *args], capture_output=True, text=True, timeout=600)
    assert out.stdout.strip(), out.stderr[-2000:]
    return {(r["claim"], r.get("n"), r.get("r")): r for r in json.loads(out.stdout)["results"]}


#: the truth of each claim of the three files (derived by hand in their docstrings)
TRUTH = {
    "tan_grad.py": {"h4-tan-capture-false": False, "h4-tan-capture-truetwin": True, "h4-tan-bracket-false": False,
                    "h4-tan-honest-true": True, "h4-tan-honest-false": False, "h4-tan-add-truetwin": True,
                    "h4-tan-add-false": False},
    "tan_constraint.py": {"h4-con-d-false": False, "h4-con-d-truetwin": True, "h4-con-ctrl-true": True,
                          "h4-con-grad-false": False, "h4-con-grad-truetwin": True},
    "quad_flow.py": {"h4-qf-false": False, "h4-qf-truetwin": True},
}
#: the honest claims, which every fixed-size method decides (the gradient is its value's along every flow)
DECIDED = {"h4-tan-honest-true", "h4-tan-honest-false", "h4-con-ctrl-true"}


@pytest.mark.parametrize("method", ["exact", "modular", "float", "free"])
@pytest.mark.parametrize("name", sorted(TRUTH))
def test_a_check_at_the_point_is_no_check_of_its_derivative(name, method):
    """A declared gradient (or quadratic's operator) right at the point and not along the flow, or right on V(n, r)
    and not off it, had the derivative of the check taken as 0: the contradictions were proved by every method.
    Along a flow the check is now made by the scene's dual numbers (both parts), and inside the function of
    s.gradient it is refused; no claim gets a wrong verdict, the honest ones are decided."""
    size = [] if method == "free" else ["--size", "3,2"]
    recs = _records(REVIEW2_80 / name, "--method", method, *size)
    assert {cid for cid, _n, _r in recs} == set(TRUTH[name])
    for (cid, n, r), rec in recs.items():
        v, true = rec["verdict"], TRUTH[name][cid]
        wrong = ("fails",) if true else TRUE
        assert v not in wrong, (cid, method, v, rec.get("message", "")[:300])
        if cid in DECIDED and method != "free":
            assert v in (TRUE if true else ("fails",)), (cid, method, v, rec.get("message", "")[:300])
        elif method != "free" and cid not in DECIDED:
            assert v in HONEST and ("not to first order along the flow" in rec.get("message", "")
                                    or "its check holds at the point only" in rec.get("message", "")), (
                cid, method, v, rec.get("message", "")[:300])
