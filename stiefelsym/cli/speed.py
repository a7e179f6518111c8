"""``stiefelsym speed``: time and error against n and precision, the cost model, the hard cases.

Writes to the report directory (default reports/speed/): ``speed.json`` (all data),
``speed.md`` with ``speed-FAMILY.png``/``.pdf`` per family of claims, ``costmodel.png``/``.pdf``,
``hard.md`` and ``hard.json``; and regenerates the package's cost model
(``stiefelsym/methods/costmodel.json``) unless ``--quick``.  Exit status 1 when an observed residual
exceeded its predicted bound or a hard case got a wrong verdict.
"""
from __future__ import annotations

import json
import platform
import shlex
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

import click

from stiefelsym.cli import Amount, InputError, SeedType, standalone_command

FLOAT_NS_FULL = [2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 48, 64, 100, 128, 200]
#: r = 2: the sizes to n = 200 (float64 and, as far as the cost model allows, every precision)
NS_200 = [2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 100, 128, 160, 200]
QUICK_PLAN = (("r = n", None, ("neumann-lax", "corrupted-LA1"), ((3, 3),), ("float", "modular"), 30.0),
              ("r = n - 1", None, ("neumann-lax",), ((3, 2),), ("float",), 30.0))
DIM_NOTE = ("Dimensions are integers (exact ranks and counts): there is no rounding error and no float "
            "residual, so this family has time against n only (exact, rational, modular); n = 200 is out of "
            "reach for it: the rank computations grow like n^4 to n^7 (the cost model's exponents below), "
            "{reach}.")


@click.command("speed", cls=standalone_command("stiefelsym speed"))
@click.option("--report-dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              show_default=True, metavar="DIR", help="Where to write the data, plots and tables.")
@click.option("--quick", is_flag=True,
              help="Small sizes only, a reduced hard-case table, and the package's cost model is left alone "
                   "(a copy of the fit goes to DIR).")
@click.option("--seed", type=SeedType(), default="0", show_default=True, metavar="N|random")
@click.option("--no-hard", is_flag=True, help="Skip the hard-case table.")
@click.option("--hard-only", is_flag=True,
              help="Only the hard-case tables (hard.md, hard.json; speed.json and speed.md take their count of "
                   "wrong verdicts), without the measurements of time and residual.")
@click.option("--cost-only", is_flag=True,
              help="Only the cost model: measure time and peak memory (r = 2 and r = ceil(n/2), n = 4 up to the "
                   "cap), fit, and write costmodel.json, its plots and the cost-model sections of speed.md.")
@click.option("--records", "records_file", type=click.Path(dir_okay=False, exists=True, path_type=Path),
              default=None, metavar="FILE",
              help="Fit the cost model's measurements stored in FILE (a costmodel.json) instead of measuring "
                   "again; with --cost-only the same file gives the same fit, plots and tables, byte for byte.")
@click.option("--cap", type=Amount("timeout"), default=None, metavar="SECONDS",
              help="Seconds one run of the cost model's series may take (default 20; the series stops before a "
                   "size predicted beyond it).")
@click.option("--remeasure", "remeasure", multiple=True, metavar="METHOD",
              type=click.Choice(["float", "modular", "ball", "exact", "rational"]),
              help="With --cost-only and --records: measure this method's series again (repeatable) and fit them "
                   "with the other methods' measurements kept from FILE (after a change to one method).")
@click.option("--model-file", type=click.Path(dir_okay=False, path_type=Path), default=None, metavar="FILE",
              help="Where to write the fitted cost model (default: your user cache folder, where "
                   "stiefelsym then reads it; the installed package's fit is never written).")
def speed(report_dir: Path | None, quick: bool, seed: int, no_hard: bool, model_file: Path | None = None,
          hard_only: bool = False, cost_only: bool = False, records_file: Path | None = None,
          cap: float | None = None, remeasure: tuple[str, ...] = ()) -> int:
    """Residual and time against n and precision per family of claims, the fitted cost model
    (time against n per method), and the hard numerical cases."""
    import importlib.util
    if importlib.util.find_spec("matplotlib") is None:
        raise InputError("stiefelsym speed draws its plots with matplotlib, which is not installed: "
                         "pip install 'stiefelsym[plots]'")
    from stiefelsym.methods import costmodel
    from stiefelsym.analyses import speed as sp
    from stiefelsym.claims import load_catalog
    from stiefelsym.results import write_atomic
    t_start = time.perf_counter()
    if report_dir is None:
        raise InputError("give --report-dir DIR (for example reports/speed): the speed report is figures and "
                         "files, written only where asked")
    try:
        report_dir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot write the speed report to {report_dir}: {exc.strerror or exc}") from None
    if cost_only and (hard_only or quick):
        raise InputError("--cost-only excludes --hard-only and --quick")
    if remeasure and not (cost_only and records_file is not None):
        raise InputError("--remeasure takes --cost-only and --records FILE (the measurements it keeps)")
    if cap is not None and records_file is not None and not remeasure:
        raise InputError("--cap is the time of a measured run; --records measures nothing: give one of them")
    registry = load_catalog()
    say = lambda text: click.echo(text, err=True)  # noqa: E731
    if hard_only:
        if no_hard:
            raise InputError("--hard-only and --no-hard exclude each other")
        hard_rows = _hard_tables(report_dir, quick, seed, registry, say)
        wrong = [r for r in hard_rows if r["judgement"].startswith("WRONG")]
        try:
            doc = json.loads((report_dir / "speed.json").read_text(encoding="utf-8"))
        except (OSError, ValueError):
            doc = None
        if doc is not None:
            doc["hard_wrong"] = wrong
            write_atomic(report_dir / "speed.json", json.dumps(doc, indent=1, default=_json_default) + "\n")
            write_atomic(report_dir / "speed.md", sp.markdown(doc))
        say(f"hard cases: {len(hard_rows)} runs, {len(wrong)} wrong; reports in {report_dir}")
        return 1 if wrong else 0

    cm_doc, accuracy = _cost_model(report_dir, quick, seed, registry, say, model_file, records_file, cap,
                                   remeasure)
    if cost_only:
        try:
            doc = json.loads((report_dir / "speed.json").read_text(encoding="utf-8"))
        except (OSError, ValueError):
            doc = None
        if doc is not None:
            doc["costmodel"] = cm_doc
            doc["accuracy"] = costmodel.accuracy_summary(accuracy)
            for fam, sec in doc.get("families", {}).items():
                sec["times"] = [r for r in cm_doc["records"] if r["family"] == fam]
            write_atomic(report_dir / "speed.json", json.dumps(doc, indent=1, default=_json_default) + "\n")
            write_atomic(report_dir / "speed.md", sp.markdown(doc))
        summary = costmodel.accuracy_summary(accuracy)
        say("cost model: " + ", ".join(f"{m} {a['within_3x']}/{a['runs']} within 3x" for m, a in summary.items())
            + f"; reports in {report_dir}")
        return 0
    records = cm_doc["records"]

    families = {}
    everything = []
    for fam, cid in costmodel.FAMILIES.items():
        claim = registry.get(cid)
        say(f"{fam}: {cid}: residual against n and precision ...")
        stops: list[str] = []
        note = ""
        if claim.kind == "dim":
            against_n, against_n2, against_p = [], [], []
            cm = costmodel.CostModel(cm_doc)
            note = DIM_NOTE.format(reach=", ".join(
                f"{m} predicted {costmodel.format_seconds(cm.predict(m, claim, 200, 2))} at (200,2)"
                for m in ("modular", "rational", "exact")))
        else:
            against_n = sp.residual_against_n(claim, [2, 3] if quick else FLOAT_NS_FULL, cap=2.0 if quick else 5.0,
                                              total=5.0 if quick else 20.0, seed=seed, stops=stops)
            against_n2 = sp.residual_against_n(claim, [2, 3, 4] if quick else NS_200, cap=2.0 if quick else 10.0,
                                               total=5.0 if quick else 30.0, seed=seed, r_of=sp.two,
                                               exact_n=4 if quick else 16, stops=stops)
            against_p = against_n2 + sp.residual_against_precision(
                claim, [3, 4] if quick else NS_200[1:], seed=seed, precisions=(30, 50, 100, "ball", "exact"),
                cap=2.0 if quick else 3.0, total=4.0 if quick else 8.0, exact_n=4 if quick else 8, stops=stops)
        everything += against_n + against_p
        times = [r for r in records if r["family"] == fam]
        families[fam] = {"claim": cid, "times": times, "against_n": against_n, "against_n2": against_n2,
                         "against_precision": against_p, "stops": stops, "note": note}
        sp.plot_family(fam, cid, times, against_n, against_p, report_dir, against_n2=against_n2)
    bad = sp.violations(everything)
    command = shlex.join(["stiefelsym", "speed", "--report-dir", str(report_dir)] + (["--quick"] if quick else [])
                         + (["--seed", str(seed)] if seed else []) + (["--no-hard"] if no_hard else [])
                         + (["--records", str(records_file)] if records_file is not None else []))
    doc = {"generated": datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC"),
           "command": command.strip(), "platform": platform.platform(terse=True), "quick": quick, "seed": seed,
           "families": families, "violations": bad, "costmodel": cm_doc,
           "accuracy": costmodel.accuracy_summary(accuracy)}
    hard_rows = [] if no_hard else _hard_tables(report_dir, quick, seed, registry, say)
    doc["hard_wrong"] = [r for r in hard_rows if r["judgement"].startswith("WRONG")]
    doc["tradeoffs"] = sp.tradeoffs(doc)
    doc["seconds"] = round(time.perf_counter() - t_start, 1)
    write_atomic(report_dir / "speed.json", json.dumps(doc, indent=1, default=_json_default) + "\n")
    write_atomic(report_dir / "speed.md", sp.markdown(doc))
    say(f"speed: {len(everything)} evaluations, {len(bad)} over their bound; {len(hard_rows)} hard runs, "
        f"{len(doc['hard_wrong'])} wrong; {doc['seconds']} s; reports in {report_dir}")
    return 1 if bad or doc["hard_wrong"] else 0


def timed(records: list[dict[str, Any]], run_log: Path) -> list[dict[str, Any]]:
    """The records of a committed results.json (which leaves the timings out) with their seconds from the run
    log of the same run beside it (run-log.json, not committed), where it is there and lists the same runs.  A
    record the log marks as a copy of another (one run of a graph without r, its record copied to every r) keeps
    no seconds: the run is counted once, at the record it was made for."""
    try:
        seconds = json.loads(run_log.read_text(encoding="utf-8"))["seconds"]
    except (OSError, ValueError, KeyError):
        return records
    if len(seconds) != len(records) or any([r.get(k) for k in ("claim", "n", "r", "method", "variant")] != s[:5]
                                           for r, s in zip(records, seconds)):
        return records
    return [dict(r, seconds=s[5]) if r.get("seconds") is None else r for r, s in zip(records, seconds)]


def _cost_model(report_dir: Path, quick: bool, seed: int, registry: Any, say: Any, model_file: Path | None,
                records_file: Path | None, cap: float | None,
                remeasure: tuple[str, ...] = ()) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """Measure (or read from ``records_file``) the cost model's runs, fit, calibrate on the catalog's
    own runs, save and plot; the model and its accuracy rows.  With ``remeasure``, those methods'
    series are measured again and replace theirs in ``records_file``."""
    from stiefelsym.analyses import costfit
    from stiefelsym.methods import costmodel
    if records_file is not None:
        try:
            stored = json.loads(records_file.read_text(encoding="utf-8"))
            records = list(stored["records"])
            note = str(stored.get("note", ""))
        except (OSError, ValueError, KeyError, TypeError) as exc:
            raise InputError(f"{records_file} holds no cost model measurements (a costmodel.json with "
                             f"'records'): {exc}") from None
        say(f"fitting the {len(records)} measurements of {records_file} ...")
        if remeasure:
            cap = cap or costfit.SCALE_CAP
            methods = [m for m in costfit.SCALE_METHODS if m in remeasure]
            say(f"measuring {', '.join(methods)} again against n ({cap:g} s per run) ...")
            fresh = costfit.measure_scale(methods=methods, cap=cap, seed=seed, registry=registry,
                                          on_point=lambda r: say(f"  {r['family']:>10} {r['method']:>8} "
                                                                 f"({r['n']},{r['r']}) {r['verdict']} {r['seconds']:.3f}s"))
            records = [r for r in records if r["method"] not in remeasure] + fresh
            note += f"; {', '.join(methods)} measured again by stiefelsym speed --remeasure, {cap:g} s per run"
    else:
        cap = cap or (2.0 if quick else costfit.SCALE_CAP)
        say(f"measuring time and peak memory against n (cost model, {cap:g} s per run) ...")
        records = costfit.measure_scale(ns=(4, 6) if quick else costfit.SCALE_NS, cap=cap, seed=seed,
                                        registry=registry, repeat=1 if quick else costfit.REPEAT,
                                        on_point=lambda r: say(f"  {r['family']:>10} {r['method']:>8} ({r['n']},{r['r']}) "
                                                               f"{r['verdict']} {r['seconds']:.3f}s"))
        note = (f"measured by stiefelsym speed on {platform.platform(terse=True)}, Python "
                f"{platform.python_version()}, {cap:g} s per run" + (" (quick run)" if quick else ""))
    cm_doc = costmodel.build(records, note=note)
    calibration = []
    for f in (Path("reports") / "all" / "results.json", Path("reports") / "results.json"):
        try:
            calibration += timed(json.loads(f.read_text(encoding="utf-8"))["results"], f.with_name("run-log.json"))
        except (OSError, ValueError, KeyError):
            pass
    costmodel.calibrate(cm_doc, calibration)
    cm_doc["catalog_accuracy"] = costmodel.catalog_accuracy(cm_doc, calibration, registry)
    say(f"per-claim factors from {len(calibration)} catalog runs (reports/all/results.json, reports/results.json)")
    if not quick:
        say(f"cost model fit written to {costmodel.save(cm_doc, model_file)}")
    costmodel.save(cm_doc, report_dir / "costmodel.json")
    costmodel.plot(cm_doc, report_dir)
    accuracy = costmodel.accuracy(cm_doc, registry)
    costmodel.plot_accuracy(accuracy, report_dir)
    return cm_doc, accuracy


def _json_default(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return str(x)


def _hard_tables(report_dir: Path, quick: bool, seed: int, registry: Any, say: Any) -> list[dict[str, Any]]:
    """The hard points and the hard sizes, written to hard.md and hard.json; their rows."""
    from stiefelsym.analyses import speed as sp
    from stiefelsym.results import write_atomic
    say("hard cases ...")
    if quick:
        hard_rows = sp.hard_table(cases=["near-pole", "near-equal-a-1e-12"], sizes=((3, 3),), large=None,
                                  timeout=30.0, seed=seed, registry=registry)
    else:
        hard_rows = sp.hard_table(timeout=60.0, seed=seed, registry=registry)
    say("hard sizes (n = 200, r = n, r = n - 1) ...")
    size_rows = sp.hard_sizes_table(QUICK_PLAN if quick else sp.HARD_SIZE_PLAN, seed=seed, registry=registry)
    for r in hard_rows:
        r["table"] = "points"
    for r in size_rows:
        r["table"] = "sizes"
    write_atomic(report_dir / "hard.md", sp.hard_markdown(hard_rows, size_rows))
    rows = hard_rows + size_rows
    write_atomic(report_dir / "hard.json", json.dumps(rows, indent=1, default=_json_default) + "\n")
    return rows
