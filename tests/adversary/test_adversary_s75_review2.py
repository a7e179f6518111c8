"""Stop 75 second review (tests/adversary/s75/review2, FINDINGS.md), of the stop's own changes: replays, all closed.
D1, D2: the Lax-partner and correction searches called a space empty from one prime modulo which the sampled system
is inconsistent, where that prime divides a denominator of the true solution (A = XXᵀ/(2^61 − 1)).  A space is now
said to be empty (of formulas whose denominators are prime to the primes named) only where the system is
inconsistent modulo two primes and consistent modulo none.  D3: "the printed formula holds" was read from a
combination said to vanish on the phase space that two agreeing moduli had reconstructed wrongly; every such
combination is now verified.  D4: a reconstruction that verification refuted was the answer; the search now goes on
lifting with the primes that follow, for another reconstruction.  D5: a user's own words "(A2)", "(BB)", "Theorem
ET" were rewritten into the paper's equation numbers; only the catalog's words are."""
import subprocess
import sys
from pathlib import Path

from adversary_cli import cli

REVIEW = Path(__file__).parent / "s75" / "review2"
FLOWS = REVIEW / "flows"


def _python(script: Path) -> str:
    run = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    return run.stdout


def test_a_prime_dividing_a_denominator_does_not_certify_emptiness():
    run = cli("discover", f"{FLOWS / 'lax_hidden_prime.py'}:flow_rotate", "--lax",
              f"{FLOWS / 'lax_hidden_prime.py'}:L_hidden")
    assert run.returncode == 0, run.stdout + run.stderr[-2000:]
    assert "A(λ) = 1/2305843009213693951·XXᵀ    [auto proved, free (all n, r) proved]" in run.stdout
    for script in ("correction_two_constants.py.in", "correction_hidden_prime.py.in"):
        out = _python(REVIEW / script)
        assert "no formula" not in out and "[auto proved]" in out, out
    out = _python(REVIEW / "solve_affine_two_constants.py.in")
    assert "no formula" not in out and "Fraction(1, 2305843009213693951)" in out


def test_containment_rests_on_verified_combinations_only():
    out = _python(REVIEW / "correction_fooled_zero.py.in")
    assert "the printed formula holds" not in out and "the registered correction is in the space" not in out


def test_a_refuted_reconstruction_is_not_the_answer_and_the_lift_goes_on():
    out = _python(REVIEW / "correction_fooled_lift.py.in")
    assert "fails" not in out
    truth = out.split("truth: coefficient of c·XXᵀAX = ")[1].split(" ;")[0]
    assert f"found: {truth}" in out
    run = cli("discover", f"{FLOWS / 'lax_fooled_lift.py'}:flow_fooled", "--lax", "LA2")
    assert run.returncode == 0 and "fails" not in run.stdout, run.stdout
    run = cli("discover", f"{FLOWS / 'lax_fooled_lift.py'}:flow_hidden_p1p2", "--lax", "LA2")
    assert run.returncode == 0 and "fails" not in run.stdout and "A(λ) = 0" not in run.stdout, run.stdout


def test_a_users_words_are_not_rewritten_into_the_papers_numbers(tmp_path):
    run = cli("verify", "--claims", str(REVIEW / "readable_user_words.py"), "--method", "modular", "--jobs", "1",
              "--report-dir", str(tmp_path))
    assert run.returncode == 0, run.stderr[-2000:]
    md = (tmp_path / "verification.md").read_text()
    assert "hypothesis (A2), the Gram matrix (BB) is the identity; Theorem ET is not used" in md
    assert r"\det(BB)\,(dot\_XP3*)" in md and "(22) §6" not in md and "(22) of Section 6" not in md


def test_emptiness_needs_two_primes_and_no_consistent_one():
    from stiefelsym.analyses.discover import EMPTY_PRIMES, AffineSpace, PRIMES
    assert EMPTY_PRIMES == 2
    one = AffineSpace(["a"], None, [], 10, 1, 2, empty_primes=[PRIMES[0]])
    assert not one.certified_empty and "none is excluded" in one.certificate()
    two = AffineSpace(["a"], None, [], 10, 1, 2, empty_primes=list(PRIMES[:2]))
    assert two.certified_empty and "denominators are prime to 2^61 - 1 and 2^62 - 57" in two.certificate()
    mixed = AffineSpace(["a"], None, [], 10, 1, 2, empty_primes=list(PRIMES[:2]), consistent=1)
    assert not mixed.certified_empty
