"""The command line, through click's CliRunner (with a fake runner and catalog) and
as a real subprocess (``python -m stiefelsym``, with the real engine)."""
from __future__ import annotations

import json
import os
import re
import select
import signal
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner

from stiefelsym import cli
from stiefelsym.claims import Claim, Registry, admissible
from stiefelsym.results import PASSING, Result, load_results
from stiefelsym.scene import SizeError

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "my_claims.py"


# --------------------------------------------------------------------------- fakes

class FakeRunner:
    """The runner API of stiefelsym.run.runner, with verdicts chosen per claim id."""

    METHODS = ("auto", "exact", "rational", "modular", "float", "free")

    class BudgetError(ValueError):
        pass

    def __init__(self, verdicts: dict[str, str] | None = None, expected: dict[str, bool] | None = None,
                 interrupt_after: int | None = None) -> None:
        self.verdicts = verdicts or {}
        self.expected = expected or {}
        self.interrupt_after = interrupt_after
        self.calls: list[dict] = []

    def select(self, registry: Registry, ids: list[str]) -> list[Claim]:
        return [registry.get(i) for i in ids]

    def verify(self, claims, *, sizes=None, methods=("auto",), seed=0, on_result=None, on_plan=None, hard=None,
               timeout=300.0, memory=4.0, jobs=1, strict_sizes=False):
        self.calls.append({"claims": [c.id for c in claims], "sizes": sizes, "methods": methods,
                           "seed": seed, "timeout": timeout, "memory": memory, "jobs": jobs,
                           "strict_sizes": strict_sizes})
        for s in sizes or ():
            if s.r > s.n or s.r < 1:
                raise SizeError(f"inadmissible size n={s.n}, r={s.r}")
            if s.n > 6:
                raise self.BudgetError(f"size n={s.n} is beyond the budget of method auto (n <= 6)")
        runs = [(c, s, m) for c in claims for s in (sizes or list(c.sizes)[:2]) for m in methods]
        if on_plan:
            on_plan(len(runs))
        out = []
        for i, (c, s, m) in enumerate(runs):
            if self.interrupt_after is not None and i == self.interrupt_after:
                raise KeyboardInterrupt
            verdict = self.verdicts.get(c.id, "checked")
            r = Result(claim=c.id, paper=list(c.paper), section=c.section, kind=c.kind,
                       title=c.title, statement=c.statement, n=s.n, r=s.r, method=m,
                       verdict=verdict, expected=self.expected.get(c.id, verdict in PASSING),
                       seconds=0.01, seed=seed,
                       false_pass_bound=1e-30 if verdict == "checked" else None,
                       witness={"seed": seed, "entry": "(1,2)", "value": "3/7"}
                       if verdict == "fails" else None,
                       erratum=c.erratum if verdict == "fails" else "",     # the runner's, for a documented erratum
                       place=c.place if verdict == "fails" else "")
            out.append(r)
            if on_result:
                on_result(r)
        return out

    def rerun_command(self, r: Result) -> str:
        return f"stiefelsym verify {r.claim} --size {r.n},{r.r} --method {r.method} --seed {r.seed}"


def _claim(cid: str, section: str, kind: str = "id") -> Claim:
    return Claim(id=cid, paper=(cid.replace("-", "_"),), kind=kind, section=section,
                 func=lambda s: {}, sizes=admissible(n_max=3),
                 statement=r"\frac{d}{dt}\Phi = [XX^T, A]",
                 title="Along every Neumann flow, dΦ/dt = [XXᵀ, A].", source="stiefelsym.proofs.fake")


@pytest.fixture
def catalog() -> Registry:
    reg = Registry()
    for cid, sec in (("prep", "5"), ("Neumann-LA", "5"), ("ddim", "2")):
        reg.add(_claim(cid, sec))
    return reg


@pytest.fixture
def fake(monkeypatch, catalog):
    runner = FakeRunner()
    monkeypatch.setattr(cli, "_runner", lambda: runner)
    monkeypatch.setattr(cli, "_catalog", lambda: catalog)
    return runner


def _one_line_error(result) -> str:
    assert result.exit_code == 2, (result.exit_code, result.output)
    assert "Traceback" not in result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert result.stdout == ""
    return lines[0]


# --------------------------------------------------------------------------- list, show

def test_list_shows_every_claim_with_label_kind_section(fake, run):
    result = run("list")
    assert result.exit_code == 0
    assert result.stdout.splitlines()[0].split() == ["id", "paper", "kind", "§", "sizes"]
    for cid, label, sec in (("prep", "prep", "5"), ("Neumann-LA", "Neumann_LA", "5"),
                            ("ddim", "ddim", "2")):
        row = next(line for line in result.stdout.splitlines() if line.startswith(cid + " "))
        assert row.split()[:4] == [cid, label, "id", sec]
        assert "6 sizes, n 1..3, r 1..3" in row


def test_show_prints_statement_docstring_sizes_source(fake, run):
    result = run("show", "prep")
    assert result.exit_code == 0
    out = result.stdout
    assert r"\frac{d}{dt}\Phi = [XX^T, A]" in out
    assert "Along every Neumann flow" in out
    assert "(1,1) (2,1) (2,2) (3,1) (3,2) (3,3)" in out
    assert "source:" in out and "test_cli.py" in out


def test_show_documents_a_known_erratum(fake, run, catalog):
    c = catalog.get("ddim")
    object.__setattr__(c, "fails_at", lambda n, r: n == 3 and r >= 2)   # a test edits the frozen claim
    object.__setattr__(c, "erratum", "the printed count misses the Pfaffian")
    out = run("show", "ddim").stdout
    assert "erratum:     fails as printed at (3,2) (3,3): the printed count misses the Pfaffian" in out
    assert "except where the erratum below says" in out
    assert "misprinted:" not in out
    object.__setattr__(c, "place", "the proof of Theorem 7.1")
    assert "misprinted:  in the proof of Theorem 7.1" in run("show", "ddim").stdout


def test_show_unknown_claim_is_one_line(fake, run):
    assert "unknown claim 'prepp'" in _one_line_error(run("show", "prepp"))


def test_bare_command_prints_help(run):
    result = run()
    assert result.exit_code == 0
    assert "verify" in result.stdout and "Exit status" in result.stdout


# --------------------------------------------------------------------------- verify

def test_verify_prints_one_line_per_result_and_a_summary(fake, run):
    result = run("verify", "prep", "--size", "4,2", "--method", "modular", "--method", "rational")
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert lines[0].startswith("prep (4,2) modular: checked")
    assert lines[1].startswith("prep (4,2) rational: checked")
    assert lines[2].startswith("summary: 1 claim, 2 runs: 2 as expected, 0 unexpected")
    assert any(line.split()[:2] == ["modular", "-"] for line in lines)
    assert fake.calls[0]["methods"] == ("modular", "rational")
    assert "no report written" in result.stderr


def test_unexpected_verdict_exits_1_and_prints_rerun(fake, run):
    fake.verdicts["prep"] = "fails"
    result = run("verify", "prep", "ddim", "--seed", "7")
    assert result.exit_code == 1
    lines = result.stdout.splitlines()
    i = next(i for i, line in enumerate(lines) if line.startswith("prep (1,1) auto: fails"))
    assert lines[i].endswith("UNEXPECTED -- witness (1,2) = 3/7")   # the witness in short
    assert lines[i + 1] == "  rerun: stiefelsym verify prep --size 1,1 --method auto --seed 7"
    assert "unexpected verdicts:" in result.stdout


def test_expected_failure_exits_0_but_still_prints_rerun(fake, run):
    fake.verdicts["prep"] = "fails"
    fake.expected["prep"] = True
    result = run("verify", "prep")
    assert result.exit_code == 0
    assert "  rerun: stiefelsym verify prep" in result.stdout


def test_format_json_is_the_results_document(fake, run):
    result = run("verify", "prep", "ddim", "--format", "json", "--seed", "3")
    assert result.exit_code == 0
    payload = json.loads(result.stdout)
    assert [r["claim"] for r in payload["results"]] == ["prep"] * 2 + ["ddim"] * 2
    assert payload["meta"]["seed"] == 3
    assert payload["meta"]["command"] == "stiefelsym verify prep ddim --method auto --seed 3"
    assert "prep (1,1) auto: checked" in result.stderr  # the lines go to stderr


def test_format_junit_parses_with_failures_for_unexpected(fake, run):
    fake.verdicts["ddim"] = "error"
    result = run("verify", "--format", "junit")
    assert result.exit_code == 1
    root = ET.fromstring(result.stdout)
    cases = root.findall(".//testcase")
    assert len(cases) == 6
    # (s74: an unexpected error is a JUnit <error>, counted as one, not a <failure>)
    failed = [c.get("name") for c in cases if c.find("error") is not None]
    assert failed == ["ddim[n=1,r=1]-auto", "ddim[n=2,r=1]-auto"]
    assert not [c for c in cases if c.find("failure") is not None]
    assert root.get("errors") == "2" and root.get("failures") == "0"


def test_full_catalog_run_writes_reports_where_asked(fake, run, tmp_path):
    assert run("verify").exit_code == 0
    assert not (tmp_path / "reports").exists()          # never by default
    result = run("verify", "--report-dir", "reports")
    assert result.exit_code == 0
    for name in cli.REPORT_FILES:
        assert (tmp_path / "reports" / name).is_file()
    meta, results = load_results(tmp_path / "reports" / "results.json")
    assert len(results) == 6 and meta["command"] == "stiefelsym verify --method auto --seed 0 --report-dir reports"
    assert "python" in meta["versions"]


def test_partial_run_leaves_default_reports_alone(fake, run, tmp_path):
    for args in (["prep"], ["--size", "3,1"]):
        result = run("verify", *args)
        assert result.exit_code == 0
        assert not (tmp_path / "reports").exists()
        assert "no report written" in result.stderr


def test_partial_run_writes_to_explicit_report_dir(fake, run, tmp_path):
    result = run("verify", "prep", "--report-dir", "out/sub")
    assert result.exit_code == 0
    assert sorted(p.name for p in (tmp_path / "out" / "sub").iterdir()) == sorted(cli.REPORT_FILES)


def test_no_report_writes_nothing(fake, run, tmp_path):
    assert run("verify", "--no-report").exit_code == 0
    assert list(tmp_path.iterdir()) == []


def test_user_claims_file_with_catalog_claim(fake, run, tmp_path):
    path = tmp_path / "mine.py"
    path.write_text(
        "from stiefelsym.claims import admissible, claim\n\n"
        "@claim('mine', paper='prep', kind='id', section='5', sizes=admissible(n_max=2))\n"
        "def mine(s):\n"
        "    \"\"\"A claim of my own.\"\"\"\n"
        "    return {}\n")
    fake.verdicts["mine"] = "fails"
    result = run("verify", "--claims", "mine.py")
    assert result.exit_code == 1
    assert fake.calls[-1]["claims"] == ["mine"]
    assert "  rerun: stiefelsym verify mine --size 1,1 --method auto --seed 0 --claims mine.py" \
        in result.stdout.splitlines()
    result = run("verify", "mine", "ddim", "--claims", "mine.py")
    assert fake.calls[-1]["claims"] == ["mine", "ddim"]


def test_budgets_jobs_and_named_sizes_reach_the_runner(fake, run):
    assert run("verify", "prep").exit_code == 0
    assert fake.calls[-1]["timeout"] == 300 and fake.calls[-1]["memory"] == 4
    assert fake.calls[-1]["jobs"] == 1 and fake.calls[-1]["strict_sizes"] is True
    result = run("verify", "--timeout", "2.5", "--memory", "0.5", "--jobs", "3", "--format", "json")
    assert result.exit_code == 0
    assert (fake.calls[-1]["timeout"], fake.calls[-1]["memory"], fake.calls[-1]["jobs"]) == (2.5, 0.5, 3)
    assert fake.calls[-1]["strict_sizes"] is False
    meta = json.loads(result.stdout)["meta"]
    assert meta["command"] == "stiefelsym verify --timeout 2.5 --memory 0.5 --method auto --seed 0"
    assert (meta["timeout"], meta["memory_gib"], meta["jobs"]) == (2.5, 0.5, 3)


def test_the_p_legend_follows_the_summary(fake, run):
    lines = run("verify", "prep").stdout.splitlines()
    assert lines[-1].startswith("p<=: the Schwartz-Zippel bound")


def test_progress_bar_does_not_touch_stdout(fake, run, monkeypatch):
    monkeypatch.setattr(cli, "_isatty", lambda stream: True)
    result = run("verify", "prep")
    assert result.exit_code == 0
    assert [line.split(":")[0] for line in result.stdout.splitlines()[:2]] == \
        ["prep (1,1) auto", "prep (2,1) auto"]


def test_interrupt_exits_130_and_writes_no_report(fake, run, tmp_path):
    fake.interrupt_after = 1
    result = run("verify")
    assert result.exit_code == 130
    assert "Traceback" not in result.output
    assert result.stderr.strip().splitlines()[-1] == \
        "stiefelsym: interrupted after 1 of 6 runs; no report written"
    assert not (tmp_path / "reports").exists()


def test_interrupt_keeps_existing_reports_whole(fake, run, tmp_path):
    assert run("verify", "--report-dir", "reports").exit_code == 0
    before = {n: (tmp_path / "reports" / n).read_text() for n in cli.REPORT_FILES}
    fake.interrupt_after = 3
    assert run("verify", "--report-dir", "reports").exit_code == 130
    assert {n: (tmp_path / "reports" / n).read_text() for n in cli.REPORT_FILES} == before
    assert sorted(p.name for p in (tmp_path / "reports").iterdir()) == sorted(cli.REPORT_FILES)


# --------------------------------------------------------------------------- bad input

BAD_SIZES = {
    "4": "is not a size",
    "a,b": "is not a size",
    "4,2,1": "is not a size",
    "2,3": "r = 3 > n = 2",
    "3,0": "r = 0",
    "-4,2": "n = -4, but the Stiefel variety V(n,r) needs n >= 1",
}


@pytest.mark.parametrize("size", list(BAD_SIZES))
def test_bad_size_is_one_line(fake, run, size):
    line = _one_line_error(run("verify", "prep", "--size", size))
    assert BAD_SIZES[size] in line and line.startswith("stiefelsym verify: error:")
    assert fake.calls == []


@pytest.mark.parametrize("args, message", [
    (["--method", "exactly"], "unknown method 'exactly'"),
    (["--seed", "-1"], "is not a non-negative integer or 'random'"),
    (["--seed", "x"], "'x' is not a non-negative integer or 'random'"),
    (["--format", "pdf"], "'pdf' is not one of"),
    (["--frobnicate"], "--frobnicate"),
    (["nosuch"], "unknown claim 'nosuch'"),
    (["--claims", "missing.py"], "claims file not found: missing.py"),
    (["--no-report", "--report-dir", "x"], "contradict"),
    (["--timeout", "0"], "0.0 is not in the range 0<x<=1000000000.0"),
    (["--memory", "-1"], "-1.0 is not in the range 0<x<=1000000.0"),
    (["--jobs", "0"], "0 is not in the range x>=1"),
    (["--report-dir", ""], "the report directory is empty"),
])
def test_bad_input_is_one_line(fake, run, args, message):
    assert message in _one_line_error(run("verify", *args))
    assert fake.calls == []


@pytest.mark.parametrize("source, message", [
    ("def f(:\n", "SyntaxError"),
    ("import no_such_module_anywhere\n", "ModuleNotFoundError"),
    ("x = 1\n", "defines no claims"),
    ("from stiefelsym.claims import claim\n"
     "@claim('c', paper='p', kind='nonsense')\ndef c(s):\n    return {}\n", "unknown kind"),
])
def test_malformed_claims_file_is_one_line(fake, run, tmp_path, source, message):
    (tmp_path / "bad.py").write_text(source)
    assert message in _one_line_error(run("verify", "--claims", "bad.py"))


def test_budget_and_size_errors_from_the_runner_are_one_line(fake, run):
    assert "beyond the budget" in _one_line_error(run("verify", "prep", "--size", "9,2"))


def test_report_dir_under_a_file_is_refused_before_running(fake, run, tmp_path):
    (tmp_path / "afile").write_text("")
    line = _one_line_error(run("verify", "--report-dir", "afile/reports"))
    assert "cannot write reports to afile/reports" in line and "not a directory" in line
    assert fake.calls == []


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes to read-only directories")
def test_read_only_report_dir_is_refused_before_running(fake, run, tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o555)
    try:
        assert "cannot write reports" in _one_line_error(run("verify", "--report-dir", "ro/x"))
    finally:
        ro.chmod(0o755)
    assert fake.calls == []


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs /proc")
def test_unwritable_report_dir_is_refused_even_for_root(fake, run):
    assert "cannot write reports" in _one_line_error(
        run("verify", "--report-dir", "/proc/stiefelsym-reports"))
    assert fake.calls == []


# --------------------------------------------------------------------------- report

def test_report_rerenders_from_results(fake, run, tmp_path, monkeypatch):
    assert run("verify", "--report-dir", "r").exit_code == 0
    (tmp_path / "r" / "verification.md").unlink()
    from stiefelsym.run import integrity
    # the fake runner's records carry no graph of their claims: report refuses them (it binds every record to its
    # claim's graph); the rendering is tested with that binding left out
    assert "whose graph is not their catalog claim's" in _one_line_error(run("report", "--results", "r/results.json"))
    monkeypatch.setattr(integrity, "unbound_graphs", lambda records, files: [])
    # the fake runner runs two sizes of each claim, not every run its command plans: report refuses the file
    # (it asks for every planned run, as check does); the rendering is tested with that test left out
    assert "its command planned have no record" in _one_line_error(run("report", "--results", "r/results.json"))
    monkeypatch.setattr(integrity, "missing_runs", lambda records, registry, meta: [])
    result = run("report", "--results", "r/results.json")
    assert result.exit_code == 0, result.output
    assert "`prep`" in (tmp_path / "r" / "verification.md").read_text()
    result = run("report", "--results", "r/results.json", "--report-dir", "elsewhere")
    assert (tmp_path / "elsewhere" / "verification.tex").is_file()


def test_the_place_of_a_misprint_travels_with_the_erratum_and_is_the_claims(fake, run, catalog, tmp_path,
                                                                           monkeypatch):
    """verify writes the claim's place of the misprint into each record of its erratum, and the report names it
    ("In the proof of Theorem 7.1 (involves: ...)"); report --results refuses a record whose place is not the
    claim's, or that has one where the claim documents no erratum, and gives the claim's to a record written
    before records carried it."""
    c = catalog.get("prep")
    object.__setattr__(c, "erratum", "h is r x r, not n x n.")
    object.__setattr__(c, "place", "the proof of Theorem 7.1")
    fake.verdicts["prep"], fake.expected["prep"] = "fails", True
    fake.expected_of = lambda claim, method, verdict, n, r, variant: \
        ((verdict == "fails", True) if claim.id == "prep" else (verdict in PASSING, False))
    from stiefelsym.run import integrity
    monkeypatch.setattr(integrity, "missing_runs", lambda records, registry, meta: [])
    monkeypatch.setattr(integrity, "unbound_graphs", lambda records, files: [])    # the fake runner's records
    assert run("verify", "--report-dir", "r").exit_code == 0
    path = tmp_path / "r" / "results.json"
    data = json.loads(path.read_text())
    records = data["results"]
    assert {x["place"] for x in records if x["claim"] == "prep"} == {"the proof of Theorem 7.1"}
    assert {x["place"] for x in records if x["claim"] != "prep"} == {""}
    note = "In the proof of Theorem 7.1 (involves: (6) §5 [prep]), the statement as printed fails"
    assert note in (tmp_path / "r" / "verification.md").read_text()

    def rewritten(change) -> str:
        copy = json.loads(json.dumps(data))
        for x in copy["results"]:
            change(x)
        path.write_text(json.dumps(copy))
        return "r/results.json"
    edited = rewritten(lambda x: x.update(place="the remark after Theorem 7.1") if x["claim"] == "prep" else None)
    assert "its place of the misprint is not the one the claim declares" in _one_line_error(run("report", "--results", edited))
    stray = rewritten(lambda x: x.update(place="the proof of Theorem 7.1") if x["claim"] == "ddim" else None)
    assert "its place of the misprint is not the one the claim declares" in _one_line_error(run("report", "--results", stray))
    old = rewritten(lambda x: x.pop("place"))
    (tmp_path / "r" / "verification.md").unlink()
    rendered = run("report", "--results", old)
    assert rendered.exit_code == 0, _one_line_error(rendered)
    assert note in (tmp_path / "r" / "verification.md").read_text()


def test_report_bad_results_file_is_one_line(run, tmp_path):
    assert "results file not found" in _one_line_error(run("report"))
    (tmp_path / "junk.json").write_text("{not json")
    assert "not a stiefelsym results file" in _one_line_error(run("report", "--results", "junk.json"))
    (tmp_path / "wrong.json").write_text('{"results": [{"claim": 1}]}')
    assert "not a stiefelsym results file" in _one_line_error(run("report", "--results", "wrong.json"))
    # what the JSON decoder itself refuses: values nested deeper than it goes, an integer of more digits than
    # Python converts; for check as for report
    (tmp_path / "deep.json").write_text('{"meta": {}, "results": [{"claim": ' + "[" * 100_000 + "]" * 100_000 + "}]}")
    (tmp_path / "long.json").write_text('{"meta": {}, "results": [{"seed": ' + "7" * 5000 + "}]}")
    for name in ("deep.json", "long.json"):
        for command in (("report", "--results", name), ("check", name)):
            result = run(*command)
            assert result.exit_code == 2 and "not a stiefelsym results file" in _one_line_error(result), result.output


def test_every_kind_is_explained():
    from stiefelsym.claims import KINDS
    from stiefelsym.reports.report import KIND_MEANING
    assert set(KIND_MEANING) == set(KINDS)


def test_method_help_names_every_runner_method():
    from stiefelsym.run import runner
    for m in runner.METHODS:
        assert f"{m}:" in cli.METHOD_HELP


# --------------------------------------------------------------------------- subprocess

def stiefelsym(*args: str, cwd: Path, timeout: float = 120) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}
    return subprocess.run([sys.executable, "-m", "stiefelsym", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)


def _sub_error(proc: subprocess.CompletedProcess) -> str:
    assert proc.returncode == 2, (proc.returncode, proc.stderr)
    assert "Traceback" not in proc.stderr + proc.stdout
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    return lines[0]


def test_subprocess_help_and_version(tmp_path):
    proc = stiefelsym("--help", cwd=tmp_path)
    assert proc.returncode == 0 and "verify" in proc.stdout
    proc = stiefelsym("--version", cwd=tmp_path)
    assert proc.returncode == 0 and proc.stdout.startswith("stiefelsym, version")


@pytest.mark.parametrize("args, message", [
    (["verify", "--size", "4"], "is not a size"),
    (["verify", "--size", "a,b"], "is not a size"),
    (["verify", "--size", "4,2,1"], "is not a size"),
    (["verify", "--size", "2,3"], "r = 3 > n = 2"),
    (["verify", "--size", "3,0"], "r = 0"),
    (["verify", "--seed", "-5"], "'-5' is not a non-negative integer"),
    (["verify", "--claims", "missing.py"], "claims file not found"),
    (["verify", "--method", "bogus"], "unknown method 'bogus'"),
    (["verify", "no-such-claim"], "unknown claim 'no-such-claim'"),
    (["show", "no-such-claim"], "unknown claim 'no-such-claim'"),
    (["report"], "results file not found"),
])
def test_subprocess_bad_input(tmp_path, args, message):
    assert message in _sub_error(stiefelsym(*args, cwd=tmp_path))


def test_subprocess_unwritable_report_dir(tmp_path):
    (tmp_path / "afile").write_text("")
    assert "not a directory" in _sub_error(
        stiefelsym("verify", "--report-dir", "afile/sub", cwd=tmp_path))


def test_subprocess_list_and_show_the_catalog(tmp_path):
    proc = stiefelsym("list", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    rows = proc.stdout.splitlines()[1:]
    assert rows, "the catalog is empty"
    first = rows[0].split()[0]
    proc = stiefelsym("show", first, cwd=tmp_path)
    assert proc.returncode == 0 and proc.stdout.startswith(first)


def test_subprocess_verify_example_claims_as_json(tmp_path):
    proc = stiefelsym("verify", "--claims", str(EXAMPLE), "--size", "3,2", "--method", "modular",
                      "--format", "json", "--no-report", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    payload = json.loads(proc.stdout)
    assert {r["claim"] for r in payload["results"]} == {"my-prep", "my-psi-conserved"}
    assert all(r["verdict"] in PASSING for r in payload["results"])


def test_subprocess_verify_junit(tmp_path):
    proc = stiefelsym("verify", "--claims", str(EXAMPLE), "--size", "3,1", "--method", "modular",
                      "--format", "junit", "--no-report", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert len(ET.fromstring(proc.stdout).findall(".//testcase")) == 2


def _interrupted_verify(tmp_path):
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTEST")}
    # as from an interactive shell: a test run started in the background inherits SIGINT ignored
    proc = subprocess.Popen([sys.executable, "-m", "stiefelsym", "verify", "--report-dir", "out"],
                            cwd=tmp_path, env=env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        ready, _, _ = select.select([proc.stdout], [], [], 120)
        assert ready, "no result within 120 s"
        assert proc.stdout.readline().strip()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    return proc.returncode, err


def test_subprocess_ctrl_c_exits_130_and_writes_no_report(tmp_path):
    """Ctrl-C: the message, exit status 130, no report.  A known intermittent defect (about one run in 10 to 30 at
    stop 56, cause not found): the process prints its message and then ends by SIGINT itself (status -2, which
    a shell also shows as 130); such a run is retried (up to three runs), so that a consistent failure still fails."""
    for attempt in range(3):
        code, err = _interrupted_verify(tmp_path)
        if code != -signal.SIGINT:
            break
    assert code == 130, err
    assert "Traceback" not in err
    assert re.fullmatch(r"stiefelsym: interrupted after \d+ of \d+ runs; no report written",
                        err.strip().splitlines()[-1])
    assert not any((tmp_path / "out" / name).exists() for name in cli.REPORT_FILES)


def test_derive_prints_a_latex_derivation_or_exits_1():
    from stiefelsym.cli import main
    ok = CliRunner().invoke(main, ["derive", "normal-flow"])
    assert ok.exit_code == 0 and "\\operatorname{nf}(R) &= 0" in ok.output and "proved for all n, r" in ok.output
    no = CliRunner().invoke(main, ["derive", "invariant-metrics"])
    assert no.exit_code == 1 and "undecided" in no.output
    bad = CliRunner().invoke(main, ["derive", "nosuch"])
    assert bad.exit_code == 2


def test_no_command_writes_reports_unless_asked(tmp_path, monkeypatch):
    """A run of a few claims (or any run) never overwrites the committed appendix: reports go only
    where --report-dir says."""
    from click.testing import CliRunner
    from stiefelsym.cli import main
    monkeypatch.chdir(tmp_path)
    runner = CliRunner()
    r = runner.invoke(main, ["verify", "prep", "--size", "3,2", "--method", "modular"])
    assert r.exit_code == 0, r.output
    r = runner.invoke(main, ["tables", "--size", "2,1"])
    assert r.exit_code == 0, r.output
    assert not (tmp_path / "reports").exists()
    r = runner.invoke(main, ["flows", "--quick"])
    assert r.exit_code == 2 and "--report-dir" in r.output
    r = runner.invoke(main, ["verify", "prep", "--size", "3,2", "--method", "modular", "--report-dir", "out"])
    assert r.exit_code == 0 and (tmp_path / "out" / "results.json").is_file()


def test_the_platform_text_is_the_standard_librarys():
    """cli.platform_text() is platform.platform(terse=True) without the processor name the standard library runs
    `uname -p` for (it leaves it out on Linux where it is empty or the machine's name)."""
    import platform
    from stiefelsym.cli import platform_text
    processor = platform.uname().processor
    if processor in ("", platform.machine()) or platform.system() != "Linux":
        assert platform_text() == platform.platform(terse=True)
