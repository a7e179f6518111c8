"""Stop 72: the review's findings (tests/adversary/s72/review, FINDINGS.md).  See tests/adversary/README.md, Stop 72.
No wrong verdict was found; the replays keep the probes of the new paths (counts of integers, two-sided rank
kernels) and the fixes of the mutation tables (D1) and of the correction search's sizes (D2)."""
import json

from pathlib import Path

from adversary_cli import cli

REVIEW = Path(__file__).parent / "s72" / "review"

#: true at (3,2) (a passing verdict is right), false there (a passing verdict is wrong), refused when traced
TRUE = {"s72-count-with-traced-zero", "s72-count-dim-symbolic", "s72-rk-true", "s72-rk-off-v",
        "s72-rk-tangent-kernel", "s72-rk-kernel-psi", "s72-rk-xxt", "s72-rk-xxt-coords"}
FALSE = {"s72-count-with-zero-const", "s72-count-with-traced-false", "s72-count-dim-false", "s72-rk-off-v-false",
         "s72-rk-wrong-kernel-false", "s72-rk-kernel-r1", "s72-rk-xxt-high"}
REFUSED = {"s72-count-nested-dict-false", "s72-count-dict-in-tuple-false", "s72-count-bool-value",
           "s72-count-sub-int"}


def test_counts_and_rank_kernels_get_right_verdicts():
    """Counts of integers nested in containers, beside constants, of int subclasses and bools, and ranks with
    kernels that hold on V only, at r = 1 only, or are wrong: exact and modular at (3,2)."""
    seen = set()
    for name in ("counts_edge.py", "rank_kernels.py"):
        run = cli("verify", "--claims", str(REVIEW / name), "--method", "modular", "--method", "exact",
                  "--size", "3,2", "--jobs", "1", "--no-report")
        for ln in run.stdout.splitlines():
            if not ln.startswith("s72-"):
                continue
            cid, verdict = ln.split()[0], ln.split(": ")[1].split()[0]
            seen.add(cid)
            if cid in TRUE:
                assert verdict in ("proved", "checked"), ln
            elif cid in FALSE:
                assert verdict in ("fails", "inconclusive", "undecided"), ln
            else:
                assert cid in REFUSED and verdict == "error", ln
    assert seen == TRUE | FALSE | REFUSED


def test_mutation_tables_count_refutations_apart_from_undecided_mutants():
    """D1: a mutant (rank 2 -> 3) that exact refutes and modular and rational leave inconclusive was counted as a
    kill of modular and rational ("kill rate 100%"); the tables now count it as undecided, and the refuted % of
    those methods is 50%, their not passed % 100%."""
    run = cli("mutate", "s72-rk-xxt", "--claims", str(REVIEW / "rank_kernels.py"), "--method", "exact",
              "--method", "modular", "--method", "rational", "--size", "4,2", "--jobs", "1", "--format", "json")
    assert run.returncode == 0, run.stderr[-2000:]
    totals = {row["method"]: row for row in json.loads(run.stdout)["totals"]}
    assert totals["modular"]["fails"] == 1 and totals["modular"]["inconclusive"] == 1
    text = cli("mutate", "s72-rk-xxt", "--claims", str(REVIEW / "rank_kernels.py"), "--method", "exact",
               "--method", "modular", "--size", "4,2", "--jobs", "1").stdout
    row = next(ln for ln in text.splitlines() if ln.split()[:3] == ["all", "claims", "modular"])
    assert row.split()[-2:] == ["50.0%", "100%"], row
    assert "refuted %" in text and "not passed %" in text


def test_correction_search_says_a_claim_for_every_n_was_searched_at_small_n():
    """D2: e5(A) = 1 (false) has the candidate e5(A) = 0, which holds at n <= 4 and fails at n = 5; the search says
    that the claim is stated for every n and the candidates ran at n <= 4 only."""
    run = cli("mutate", "s72-e5-one", "--corrections", "--claims", str(REVIEW / "corrections_ch.py"), "--jobs", "1")
    assert run.returncode == 0, run.stderr[-2000:]
    assert "correction passes" in run.stdout
    assert "stated for every n" in run.stdout and "run only at n <= 4" in run.stdout
    assert "with --corrections, rational and modular" in " ".join(cli("mutate", "--help").stdout.split())


def test_a_bool_is_no_number_of_a_statement():
    """D6: Count(True, 1) was refused while X * True was accepted as X (and numpy's True likewise); a bool in +, −,
    · or / is now refused when the claim is traced, under every method, as a Count's is."""
    for method in ("exact", "modular", "free"):
        run = cli("verify", "--claims", str(REVIEW / "disguised_numbers.py"), "s72-y-np-bool", "--method", method,
                  *(() if method == "free" else ("--size", "3,2")), "--jobs", "1", "--no-report")
        line = next(ln for ln in run.stdout.splitlines() if ln.startswith("s72-y-np-bool"))
        assert ": error" in line and "a bool is not a number of the IR" in run.stdout, run.stdout[-2000:]


def test_a_users_symbolic_attempt_is_forked_from_n_2_in_a_worker():
    """Further statements, finding 1: a complex claim of W(3, r) of a claims file ran flint out of memory at n = 3
    inside the worker (its symbolic attempt was forked from n = 4 on only), which ended the run in `error` where auto
    goes on with the modular method (`checked` after the exact attempt died).  A claim the cost model was never
    measured on is now forked from n = 2 on; the catalog's claims keep their measured rule."""
    import dataclasses

    from stiefelsym.claims import load_catalog
    from stiefelsym.methods.fixed_size import isolates
    c = load_catalog().get("neumann-lax")
    user = dataclasses.replace(c, id="s72-user-claim")
    assert isolates(user, 2, 1, in_worker=True) and isolates(user, 3, 2, in_worker=True)
    assert not isolates(c, 3, 1, in_worker=True)


OWN = Path(__file__).parent / "s72" / "own"


def test_a_constant_matrix_of_a_lower_rank_fails_under_rational():
    """Further statements, finding 5 (in part): a rank stated of a matrix none of whose entries depends on the point
    is decided by its rank at one exact point (rational: fails, certain); modular stays inconclusive (the rank of a
    constant matrix may drop mod p), exact refutes it over the function field."""
    run = cli("verify", "--claims", str(OWN / "constant_rank.py"), "--method", "rational", "--method", "modular",
              "--method", "exact", "--size", "3,2", "--jobs", "1", "--no-report")
    verdicts = {ln.split()[2].rstrip(":"): ln.split(": ")[1].split()[0]
                for ln in run.stdout.splitlines() if ln.split()[:1] == ["t72-const-rank"]}
    assert verdicts == {"rational": "fails", "modular": "inconclusive", "exact": "fails"}, run.stdout[-2000:]
    true = {ln.split()[2].rstrip(":"): ln.split(": ")[1].split()[0]
            for ln in run.stdout.splitlines() if ln.split()[:1] == ["t72-const-rank-true"]}
    assert set(true) == {"rational", "modular", "exact"} and set(true.values()) <= {"proved", "checked"}, true


def test_ranks_of_matrices_that_depend_on_the_point_are_not_taken_for_constants():
    """My own attempt at the constant-matrix rule: matrices whose entries are λ, a mix of constants and λ, and
    tr(XᵀX) (a constant on V, built from the point), of true ranks: no method refutes them (the rule reads the
    degree markers the engine computes, which a claim cannot write)."""
    run = cli("verify", "--claims", str(OWN / "point_dependent_ranks.py"), "--method", "rational", "--method",
              "modular", "--method", "exact", "--size", "3,2", "--size", "3,1", "--jobs", "1", "--no-report")
    lines = [ln for ln in run.stdout.splitlines() if ln.startswith("t72-")]
    assert len(lines) == 18 and run.returncode == 0, run.stdout[-3000:]
    assert all(ln.split(": ")[1].split()[0] in ("proved", "checked") for ln in lines), run.stdout[-3000:]


def test_fails_at_must_be_a_function_of_the_size():
    """fails_at="all" was accepted when the file loaded and every run said error ("'str' object is not callable");
    it is refused when the claim is declared, with what fails_at is (exit 2)."""
    run = cli("verify", "--claims", str(OWN / "fails_at_string.py"), "--size", "3,2", "--no-report")
    assert run.returncode == 2 and "fails_at is a function of the size" in run.stderr, run.stderr[-2000:]


REVIEW2 = Path(__file__).parent / "s72" / "review2"


def test_the_checker_refuses_hypotheses_of_one_r_whose_joint_locus_is_a_pole(tmp_path):
    """Second review, W1: a certificate of tr(XᵀX) − r + 1 = 0 (false everywhere) whose hypotheses E1E1t (r = 1 only)
    and XXt (r = n only), or E1E1t+E2E2t and XXt, hold together only at n = r = 1 (n = r = 2), where its coefficient
    1/(n − 1) (1/(n − 2)) has its pole: the standalone checker substituted r = 1 and r = n one at a time and accepted
    it.  The pole check now substitutes the hypotheses' joint locus; `check` refused the record already."""
    import subprocess
    import sys
    run = cli("verify", "--claims", str(REVIEW2 / "scalar_false.py"), "--method", "free", "--jobs", "1",
              "--report-dir", str(tmp_path / "o"))
    assert (tmp_path / "o" / "results.json").is_file(), run.stderr[-2000:]
    for pair, k in (("1n", 1), ("2n", 2)):
        forged = tmp_path / f"forged_{pair}.json"
        subprocess.run([sys.executable, str(REVIEW2 / "forge_joint_locus.py.in"), str(tmp_path / "o" / "results.json"),
                        str(forged), pair], check=True, capture_output=True)
        out = subprocess.run([sys.executable, "-m", "stiefelsym.certificate_check", str(forged)],
                             capture_output=True, text=True)
        assert out.returncode == 1, out.stdout + out.stderr
        assert f"1/(n - {k}) has a pole where" in out.stdout and "XXt hold" in out.stdout, out.stdout
        assert cli("check", str(forged)).returncode == 1


def _verdict(run, cid):
    line = next(ln for ln in run.stdout.splitlines() if ln.startswith(cid + " "))
    return line.split(": ")[1].split()[0]


def test_what_a_claim_traces_does_not_depend_on_what_was_traced_before_it():
    """Second review, W2: claims traced at a size beyond the listed ones share one interpreter of the second phase,
    and a claim read a mark that another left in its private /tmp (or a process it started: an abstract socket):
    `verify CLAIM` said fails, the whole file checked, and `check` accepted the record spliced from one run into
    the other.  The interpreter's /tmp is read-only now, and the processes and IPC objects a job leaves end with it:
    the claim's graph, and its verdict, are the same in both runs."""
    import pytest

    from stiefelsym.run.sandbox import namespaces_available
    if not namespaces_available():
        pytest.skip("no user + pid + mount namespaces here (the plain spawn's stated limit)")
    for name, b in (("tmp_state_select.py", "rw2-sel-b"), ("daemon_state_select.py", "rw2-dmn-b")):
        common = ("--claims", str(REVIEW2 / name), "--size", "7,1", "--method", "modular", "--jobs", "1",
                  "--no-report")
        alone, whole = cli("verify", b, *common), cli("verify", *common)
        assert _verdict(alone, b) == _verdict(whole, b) == "fails", alone.stdout + whole.stdout


def test_a_derivation_puts_a_negative_constant_sum_in_parentheses():
    """Second review, D1: for (n + 1)(tr XᵀX − r) = 0 the derivation printed R = − n r + r + (n + 1) tr(XᵀX) beside
    nf(R) = 0 (the printed R's normal form is 2r); the constant term is − (n r + r)."""
    run = cli("derive", "rw2-derive-sign", "--claims", str(REVIEW2 / "derive_signs.py"))
    assert r"R &= - \left(n r + r\right) + \left(n + 1\right)" in run.stdout, run.stdout[-2000:]
