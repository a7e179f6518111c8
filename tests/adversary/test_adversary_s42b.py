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


def _forged(tmp_path, data, name, edit):
    import json
    copy = json.loads(json.dumps(data))
    for r in copy["results"]:
        if r["claim"] == "adv-s42b-r3-trace":
            edit(r)
    folder = tmp_path / name
    folder.mkdir()
    (folder / "results.json").write_text(json.dumps(copy), encoding="utf-8")
    return folder


def test_a_records_rerun_command_and_message_are_its_own(tmp_path):
    """QA: the words of a run a report prints beside a failure were not compared by `check` nor bound by `report`:
    the rerun command of a `fails` record edited to another claim's (`stiefelsym verify adv-s42b-r3-count ...`, whose
    run proves), and its message to "the residual is 0 on T*V; the witness is an artefact of rounding": `check` said
    "0 rejected", and `report` wrote "The seeded run that found the failure: ...; rerun: `stiefelsym verify
    adv-s42b-r3-count ...`" and the forged message among the notes.  Now the rerun command must be the one that
    reproduces the record (its claim, size, method, seed, hard case, the claims file that defines it as the command
    spelled it, the command's budgets): `check` and `report` refuse another; and `check` compares a decided
    record's message with a run again.  A check from another directory, the claims file spelled otherwise,
    accepts the honest file."""
    import json
    import os
    folder = tmp_path / "run"
    run = cli("verify", "adv-s42b-r3-trace", "adv-s42b-r3-count", "--claims", PROBES, "--size", "5,3",
              "--method", "exact", "--timeout", "120", "--jobs", "1", "--report-dir", str(folder))
    assert "adv-s42b-r3-trace (5,3) exact: fails" in run.stdout, (run.stdout, run.stderr)
    data = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    honest = cli("check", str(folder / "results.json"))
    assert honest.returncode == 0, (honest.stdout, honest.stderr)
    elsewhere = cli("check", str(folder / "results.json"), "--claims", os.path.relpath(PROBES, tmp_path), cwd=tmp_path)
    assert elsewhere.returncode == 0, (elsewhere.stdout, elsewhere.stderr)
    other = next(r["rerun"] for r in data["results"] if r["claim"] == "adv-s42b-r3-count")

    def rerun(r):
        r["rerun"] = other

    def message(r):
        r["message"] = "the residual is 0 on T*V; the witness is an artefact of rounding"

    def seed(r):
        r["rerun"] = r["rerun"].replace("--seed 0", "--seed 7")
    for name, edit, why in (("rerun", rerun, "its rerun command"), ("seed", seed, "its rerun command"),
                            ("message", message, "(message)")):
        forged = _forged(tmp_path, data, name, edit)
        checked = cli("check", str(forged / "results.json"))
        assert checked.returncode == 1, (name, checked.stdout, checked.stderr)
        assert "REJECTED adv-s42b-r3-trace (5,3) exact" in checked.stdout and why in checked.stdout, checked.stdout
        if name != "message":
            report = cli("report", "--report-dir", str(forged))
            assert report.returncode != 0 and "rerun command is not their own" in report.stderr, \
                (report.stdout, report.stderr)
            assert not (forged / "verification.md").exists()


def test_the_message_of_an_auto_record_is_compared_beyond_the_reason_auto_gives(tmp_path):
    """auto beyond a claim's symbolic budget runs the modular method and begins its record's message with "exact:
    <why not>; ": `check` runs the record's own method again, so the message is compared as auto wrote it (the
    reason beyond the budget is its text); an honest file passes, a message with words added is rejected."""
    import json
    folder = tmp_path / "run"
    run = cli("verify", "adv-s42b-r3-trace", "--claims", PROBES, "--size", "6,3", "--method", "auto", "--jobs", "1",
              "--report-dir", str(folder))
    assert "adv-s42b-r3-trace (6,3) modular: fails" in run.stdout, (run.stdout, run.stderr)
    data = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    assert data["results"][0]["message"].startswith("exact: n = 6 is above"), data["results"][0]["message"]
    honest = cli("check", str(folder / "results.json"))
    assert honest.returncode == 0, (honest.stdout, honest.stderr)

    def added(r):
        r["message"] += "; the failure is an artefact of the prime"

    def reason(r):
        r["message"] = r["message"].replace("is above", "is within")
    for name, edit in (("added", added), ("reason", reason)):
        forged = _forged(tmp_path, data, name, edit)
        checked = cli("check", str(forged / "results.json"))
        assert checked.returncode == 1 and "(message)" in checked.stdout, (name, checked.stdout, checked.stderr)


def test_the_command_of_a_results_file_is_the_one_its_fields_describe(tmp_path):
    """QA′: the meta's command (which a report prints, and whose claim ids say which claims the file must have) was
    not compared with the fields the planned runs are listed from (claims files, sizes, --max-n, methods, seed,
    budgets): a command edited to `--size 3,2 --method modular` over records made at (5,3) by exact was printed by
    the report as the command the file is the run of.  Now `check` and `report` refuse such a meta (exit 2)."""
    import json
    folder = tmp_path / "run"
    run = cli("verify", "adv-s42b-r3-trace", "--claims", PROBES, "--size", "5,3", "--method", "exact", "--jobs", "1",
              "--report-dir", str(folder))
    assert "adv-s42b-r3-trace (5,3) exact: fails" in run.stdout, (run.stdout, run.stderr)
    data = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    for name, edit in (("size", lambda c: c.replace("--size 5,3", "--size 3,2")),
                       ("method", lambda c: c.replace("--method exact", "--method modular")),
                       ("seed", lambda c: c.replace("--seed 0", "--seed 4")),
                       ("claims", lambda c: c.replace("--claims ", "--claims /elsewhere/")),
                       ("timeout", lambda c: c + " --timeout 5"),
                       ("option", lambda c: c + " --hard near-pole")):
        forged = json.loads(json.dumps(data))
        forged["meta"]["command"] = edit(forged["meta"]["command"])
        assert forged["meta"]["command"] != data["meta"]["command"], name
        out = tmp_path / name
        out.mkdir()
        (out / "results.json").write_text(json.dumps(forged), encoding="utf-8")
        checked = cli("check", str(out / "results.json"), "--no-rerun")
        assert checked.returncode == 2 and "meta command" in checked.stderr, (name, checked.stdout, checked.stderr)
        report = cli("report", "--report-dir", str(out))
        assert report.returncode == 2 and "meta command" in report.stderr, (name, report.stdout, report.stderr)
    assert cli("check", str(folder / "results.json"), "--no-rerun").returncode == 0
