"""Stop 75's own attempt (s75/own/lax_every_prime.py), on the class of the second review's D1: a Lax partner whose
denominator is the product of the first two primes of the search.  The search cannot see it modulo either, and its
certificate of emptiness must say what it covers (formulas whose denominators are prime to both), never that no
formula holds; the partner itself is proved by the exact method."""
import json
from pathlib import Path

from adversary_cli import cli

OWN = Path(__file__).parent / "s75" / "own" / "lax_every_prime.py"


def test_a_certificate_of_emptiness_says_which_denominators_it_covers():
    run = cli("discover", f"{OWN}:flow_rotate", "--lax", f"{OWN}:L_two_primes")
    assert run.returncode == 1, run.stdout + run.stderr[-2000:]
    assert "no formula in this 28-term space holds with coefficients whose denominators are prime to 2^61 - 1 and " \
           "2^62 - 57" in run.stdout
    assert "no formula in this 28-term space holds:" not in run.stdout


def test_the_partner_the_certificate_does_not_cover_exists():
    run = cli("verify", "--claims", str(OWN), "--method", "exact", "--jobs", "1", "--format", "json", "--no-report")
    data = json.loads(run.stdout)
    recs = data["results"] if isinstance(data, dict) else data
    assert [r["verdict"] for r in recs] == ["proved"]
