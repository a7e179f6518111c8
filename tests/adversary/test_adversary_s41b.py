"""Round 15 (tests/adversary/README.md, the "Round 15" table): the point methods' proof of a generic rank equal
to its matrix's full size at one point of each component (`_point_rank` status "full", `_full_ranks`, the
`full_proof` branch of `_run_points`).  As before every run is the CLI in a fresh process, and each test asserts
the CORRECT outcome."""
import json
import re

from adversary_cli import HERE, PASSING, cli

PROBES = "s41b_full_rank_probes.py"
#: "<claim> (n,r) <method>: <verdict>"
LINE = re.compile(r"^(\S+) \((\d+),(\d+)\) (\w+): (\w+)")
TRUE = ("adv-s41b-full-true", "adv-s41b-second-point-true", "adv-s41b-double-point-true", "adv-s41b-resolvent-true")
FALSE = ("adv-s41b-det-plus-one", "adv-s41b-det-x-plus-det-y", "adv-s41b-residual-inside",
         "adv-s41b-metric-constraint", "adv-s41b-dirac-derivative", "adv-s41b-constant-half",
         "adv-s41b-constant-huge", "adv-s41b-one-above-full", "adv-s41b-wrong-count")


def _run(*args):
    run = cli("verify", "--claims", str(HERE / PROBES), "--jobs", "1", *args)
    got: dict = {}
    for m in map(LINE.match, run.stdout.splitlines()):
        if m:
            got.setdefault(m.group(1), {})[(int(m.group(2)), int(m.group(3)), m.group(4))] = m.group(5)
    return run, got


def test_a_rank_of_full_size_is_proved_only_where_it_holds_on_every_component():
    """Every claim of the probes at every size it is stated for, under modular, rational and auto (auto takes the
    modular method: exact_max_n=1).  The true ranks of full size are proved (r = n: at a point of each component of
    O(n), four pairs with the second point); a rank of full size on one component of O(n) only (det X + 1,
    det X + det Y at (2,2)), a residual that vanishes on T*V inside a matrix of full size (standard and metric
    realizations, a derivative along a Dirac flow), constants beyond the primes (2²⁰⁰ + 1, 1/2), one more than the
    full size: never passed; a wrong count beside a rank of full size fails; a Jacobian of a wide matrix read by
    upper triangles is refused when traced (error).  No hole: the values at a point are the image of the chart's
    rational functions under a homomorphism (constants that vanish or have no inverse mod p redraw the prime)."""
    _, got = _run("--method", "modular", "--method", "rational")
    _, auto = _run("--method", "auto")
    for cid, runs in auto.items():
        got.setdefault(cid, {}).update(runs)
    for cid in TRUE:
        assert got[cid] and set(got[cid].values()) == {"proved"}, (cid, got[cid])
    for cid in FALSE:
        assert got[cid] and not set(got[cid].values()) & set(PASSING), (cid, got[cid])
    assert set(got["adv-s41b-wrong-count"].values()) == {"fails"}, got["adv-s41b-wrong-count"]
    # no rank exceeds the full size: a rank above it is refuted at any point (before: inconclusive)
    assert set(got["adv-s41b-one-above-full"].values()) == {"fails"}, got["adv-s41b-one-above-full"]
    assert set(got["adv-s41b-wide-symmetric-jacobian"].values()) == {"error"}, got["adv-s41b-wide-symmetric-jacobian"]
    assert {m for (_, _, m) in got["adv-s41b-full-true"]} == {"modular", "rational"}, got["adv-s41b-full-true"]


def test_a_hard_case_never_proves_a_rank_of_full_size():
    """A hard point is chosen, not random: the rule is not applied there (undecided), whatever the rank; a hard
    case that changes no parameter of the claim leaves random points, where the rank of full size is proved."""
    _, got = _run("adv-s41b-resolvent-true", "adv-s41b-full-true", "--size", "3,2", "--hard", "near-pole",
                  "--method", "modular", "--method", "rational")
    assert set(got["adv-s41b-resolvent-true"].values()) == {"undecided"}, got
    assert set(got["adv-s41b-full-true"].values()) == {"proved"}, got


def test_check_rejects_a_record_proved_by_the_rule_where_the_rank_is_not_full(tmp_path):
    """A record of det X + 1 at (2,2) (rank 0 on one component of O(2)) forged to the `proved` of a rank of full
    size, with the true claim's certificate: `stiefelsym check` runs it again and rejects it."""
    run, got = _run("adv-s41b-full-true", "adv-s41b-det-plus-one", "--size", "2,2", "--method", "modular",
                    "--report-dir", str(tmp_path))
    assert got["adv-s41b-full-true"] == {(2, 2, "modular"): "proved"}, run.stdout
    path = tmp_path / "results.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    recs = {r["claim"]: r for r in data["results"]}
    good, bad = recs["adv-s41b-full-true"], recs["adv-s41b-det-plus-one"]
    assert bad["verdict"] != "proved"
    for k in ("verdict", "certificate", "message", "checks", "false_pass_bound", "witness"):
        bad[k] = good.get(k)
    bad["expected"] = True
    path.write_text(json.dumps(data), encoding="utf-8")
    checked = cli("check", str(path))
    assert checked.returncode == 1, (checked.stdout, checked.stderr)
    assert "REJECTED adv-s41b-det-plus-one (2,2) modular" in checked.stdout, checked.stdout


def _outcomes(report):
    return {(c.claim, o.index): (o.classification, [(x.n, x.r, x.method, x.verdict) for x in o.cells])
            for c in report.claims for o in c.mutants}


def test_lent_points_decide_a_rank_of_full_size_as_fresh_points_do():
    """The mutation analysis lends the printed claim's points to its mutants and takes a mutant that no parameter
    entered for a constant (one exact evaluation over Q: "no probability involved", its ranks at every point).
    On a lent point that test read the degree bound of the checks, and a rank's bound is that of its (k+1)-minors:
    0 for a rank of its matrix's full size, whatever its entries.  So PᵀX (the mutant X → P of XᵀX = I_r, rank r
    at every point) was `checked` from one point where a fresh run says `undecided` (a rank at every point does
    not follow from points), and the mutants of XᵀAX were decided at one point, refuted with certainty.
    The same for entries c/D whose numerators are constants: the mutant +1/x of [[1/x, 1/y], [1/y, −1/x]] (its
    rank drops where x = ±y) was `checked` at every point.  Closed (`_lent_constant`): on a lent point every entry
    of every rank's matrix must be a constant (numerator and denominator of degree 0); the verdicts on lent points
    are those of fresh points."""
    from stiefelsym.analyses.mutate import run_mutation
    from stiefelsym.api import load
    from stiefelsym.claims import Size
    reg = load([HERE / PROBES], catalog=False)
    claims = [reg.get(c) for c in ("adv-s41b-every-point-gram", "adv-s41b-full-true", "adv-s41b-reciprocal-every-point")]
    kw = dict(methods=("rational", "modular"), sizes=[Size(3, 2)], on="graphs")
    lent, fresh = _outcomes(run_mutation(claims, **kw)), _outcomes(run_mutation(claims, lend=False, **kw))
    assert lent == fresh
    ptx = [o for (cid, _), o in lent.items() if cid == "adv-s41b-every-point-gram" and o[0] != "equivalent"]
    assert any({v for *_, v in cells} == {"undecided"} for _, cells in ptx), lent
    recip = {v for (cid, _), (_, cells) in lent.items() if cid == "adv-s41b-reciprocal-every-point" for *_, v in cells}
    assert "checked" not in recip and "undecided" in recip, lent
    full = {v for (cid, _), (_, cells) in lent.items() if cid == "adv-s41b-full-true" for *_, v in cells}
    assert "proved" in full, lent       # a mutant of full size (A → A⁻¹) is proved on lent points as on fresh ones
