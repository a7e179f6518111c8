"""Round 17 (tests/adversary/README.md, the "Round 17" table): the exact method's rank decisions on the components
of O(n), poles along a component, R^r taken for R^n inside a rank, and the route from the dimension-free proof at
the families r = 3 and r = n under `--jobs 1` and `--jobs 2`.  No wrong verdict was found this round: each test
asserts the CORRECT outcome of a trick tried, so that a later change that opens the route is caught.  As before
every run is the CLI in a fresh process (claims file `s42b_exact_rank_probes.py`)."""
from adversary_cli import HERE, PASSING, cli

PROBES = str(HERE / "s42b_exact_rank_probes.py")
COMPONENT = ("adv-s42b-det-plus-one", "adv-s42b-det-minus-one", "adv-s42b-det-plus-one-every-point")
POLES = ("adv-s42b-inverse-on-one-component", "adv-s42b-ratio-on-one-component", "adv-s42b-ratio-residual")
JOINED = ("adv-s42b-untyped-join-rank-zero", "adv-s42b-untyped-join-generic-zero", "adv-s42b-untyped-join-generic-two")
FAMILY_TRUE = ("adv-s42b-r3-count", "adv-s42b-r3-e3", "adv-s42b-square-trace")
FAMILY_FALSE = ("adv-s42b-r3-trace", "adv-s42b-r3-e2", "adv-s42b-square-psi")


def _verdicts(*args):
    """{(claim, size, method): verdict} of one `stiefelsym verify` run."""
    run = cli("verify", "--claims", PROBES, *args)
    got = {}
    for line in run.stdout.splitlines():
        parts = line.split()
        if len(parts) >= 4 and parts[0].startswith("adv-s42b-") and parts[1].startswith("("):
            got[(parts[0], parts[1], parts[2].rstrip(":"))] = parts[3]
    return got, run


def test_a_rank_on_one_component_of_o_n_or_with_a_pole_along_one_is_never_passed():
    """det X ± 1 written with the entries of X at r = n: the exact method evaluates both components of O(n) on the
    Cayley chart (D = I and diag(−1, 1, ..)) and refutes the rank on the one where it is 0 (the function-field rank
    there is 0); the point methods find rank 0 on that component (inconclusive).  A division by det X + 1, which
    is 0 along a whole component, is an error of the exact method (the division probe) and leaves the point
    methods inconclusive: never a pass."""
    got, run = _verdicts(*COMPONENT, *POLES, "--size", "2,2", "--size", "3,3", "--method", "exact",
                         "--method", "modular", "--method", "rational", "--jobs", "1")
    assert len(got) == 36, (run.stdout, run.stderr)
    for (cid, size, method), verdict in got.items():
        assert verdict not in PASSING, (cid, size, method, verdict)
        if method == "exact":
            assert verdict == ("fails" if cid in COMPONENT else "error"), (cid, size, verdict)


def test_an_untyped_identity_joining_r_n_and_r_r_inside_a_rank_is_not_proved_on_a_reduced_chart():
    """X·I₃ − (X·I₃)ᵀ at (3,3): I₃ of the int size 3 joins R^n and R^r, so the claim is not covariant under O(n)
    on either side; on the chart X = I (O(n) acting on the right) it is 0.  A rank is not a coordinate read, so
    a rank statement could have been taken to that chart: rank 0 (at every point or generically) is refuted by
    exact and modular, the true generic rank 2 proved (exact) and checked (modular)."""
    got, run = _verdicts(*JOINED, "--size", "3,3", "--method", "exact", "--method", "modular", "--jobs", "1")
    assert len(got) == 6, (run.stdout, run.stderr)
    for method in ("exact", "modular"):
        assert got[("adv-s42b-untyped-join-rank-zero", "(3,3)", method)] == "fails", got
        assert got[("adv-s42b-untyped-join-generic-zero", "(3,3)", method)] == "fails", got
    assert got[("adv-s42b-untyped-join-generic-two", "(3,3)", "exact")] == "proved", got
    assert got[("adv-s42b-untyped-join-generic-two", "(3,3)", "modular")] == "checked", got


def test_the_route_from_the_dimension_free_proof_at_r_3_and_r_n_does_not_depend_on_the_pool():
    """exact_max_n=1: exact and auto at (6,3), (7,3), (6,6) go through the dimension-free proof of the family r = 3
    (r a number there: a Count of r through its door, e₃(Ψ) from power traces) or r = n; at n >= 6 the symbolic
    attempts may run in a reused worker.  `--jobs 1` and `--jobs 2` give the same verdicts, each the truth."""
    runs = []
    for jobs in ("1", "2"):
        # no ids named: each claim runs at the sizes of its statement among these
        got, run = _verdicts("--size", "6,3", "--size", "7,3", "--size", "6,6", "--method", "exact",
                             "--method", "auto", "--jobs", jobs)
        assert got, (run.stdout, run.stderr)
        runs.append(got)
    assert runs[0] == runs[1]
    got = runs[0]
    for (cid, size, method), verdict in got.items():
        if cid in FAMILY_TRUE and method == "exact":
            assert verdict == "proved", (cid, size, method, verdict)
        if cid in FAMILY_TRUE:
            assert verdict in PASSING, (cid, size, method, verdict)
        else:
            assert verdict == "fails", (cid, size, method, verdict)
    assert {c for c, _, _ in got} == set(FAMILY_TRUE + FAMILY_FALSE), got
