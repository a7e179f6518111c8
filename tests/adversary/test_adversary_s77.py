"""Stop 77: the float method at a pole.  A claim dividing by n − 100 took the float method three minutes at
(100, 1), climbing its precision ladder (float64, ball arithmetic, 30, 60 and 120 digits at n = 100) to the
same division by 0.  When float64 meets a division by a number indistinguishable from 0, exact points modulo
primes now say whether the divisor vanishes wherever the claim is evaluated; if so the ladder stops
(``inconclusive``, the pole named), otherwise it climbs as before."""
import json
from pathlib import Path

from adversary_cli import cli

HERE = Path(__file__).parent / "s77"


def _records(*args):
    out = cli("verify", "--claims", str(HERE / "own" / "float_pole.py"), *args, "--jobs", "1", "--format", "json",
              "--no-report")
    return {(r["claim"], r["n"], r["r"]): r for r in json.loads(out.stdout)["results"]}, out


def test_a_pole_at_every_point_stops_the_float_ladder():
    recs, out = _records("s77-pole-at-n-100", "s77-pole-on-v", "--size", "100,1", "--size", "3,2",
                         "--method", "float")
    for key in (("s77-pole-at-n-100", 100, 1), ("s77-pole-on-v", 100, 1), ("s77-pole-on-v", 3, 2)):
        rec = recs[key]
        assert rec["verdict"] == "inconclusive", (key, rec)
        assert rec["message"].startswith("a pole wherever the claim is evaluated"), rec["message"]
        assert "every one of 8 sampled points was degenerate" in rec["message"]
    assert "at the division by tr(Iₙ) − 100" in recs[("s77-pole-at-n-100", 100, 1)]["message"]
    # away from its pole the same claim is evaluated as before
    assert recs[("s77-pole-at-n-100", 3, 2)]["verdict"] == "numeric"


def test_a_divisor_float64_cannot_resolve_still_climbs_the_ladder():
    recs, out = _records("s77-tiny-divisor", "--size", "3,2", "--method", "float")
    rec = recs[("s77-tiny-divisor", 3, 2)]
    assert rec["verdict"] == "numeric", rec
    assert "pole" not in (rec["message"] or "")
