"""``stiefelsym check results.json``: every record re-traced and re-checked.

Each record names the digest of the graph its verdict is about; the claim (from the
catalog, or the claims files the run named) is traced again and the digests compared,
and every dimension-free certificate is re-derived and re-checked by the independent
checker.  A hand-edited or stale results file is caught.

Exit status: 0 every record holds up; 1 some record does not; 2 bad input.
"""
from __future__ import annotations

from pathlib import Path

import click

from stiefelsym.cli import InputError, _record_ids, _registry, recorded_claims_files, require_results_file, standalone_command
from stiefelsym.methods.hard import HARD_CASES
from stiefelsym.run.integrity import MAX_N_CHECKED, check_results, run_origin
from stiefelsym.results import json_kind, meta_problems, parse_json, resolve_shared_certificates
from stiefelsym.run.runner import METHODS

_Command = standalone_command("stiefelsym check")


@click.command("check", cls=_Command, short_help="Re-trace every record of a results file and re-check it.")
@click.argument("results_file", type=click.Path(path_type=Path))
@click.option("--no-rerun", is_flag=True, help="compare digests and certificates only (no method runs again)")
@click.option("--claims", "claims_files", multiple=True, type=click.Path(),
              help="claims files the run used (default: those the results file names)")
def check(results_file: Path, no_rerun: bool, claims_files: tuple[str, ...]) -> None:
    """Re-trace every record's claim, compare the graph digests, run every fixed-size record again
    (its method, size and seed) and compare the verdicts, re-derive and re-check every
    dimension-free certificate; exit 1 if any record does not hold up."""
    require_results_file(results_file)
    try:
        payload = parse_json(results_file.read_text(encoding="utf-8"))
        if not isinstance(payload, dict):
            raise TypeError(f"its top level is a JSON {json_kind(payload)}, not an object with the results "
                            "and the meta of a run (a file written by `stiefelsym verify --report-dir`, or "
                            "--format json, is one)")
        missing = [k for k in ("results", "meta") if k not in payload]
        if missing:
            raise TypeError(f"no {' and no '.join(missing)} at its top level (a file written by `stiefelsym verify "
                            "--report-dir`, or --format json, has the results and the meta of its run)")
        resolve_shared_certificates(payload)
        records = payload["results"]
        meta = payload["meta"]
        if not isinstance(records, list) or not all(isinstance(r, dict) for r in records):
            raise TypeError("results is not a list of records")
        if not isinstance(meta, dict):
            raise TypeError("meta (the command the file is the run of) is not a mapping")
    except (OSError, ValueError, KeyError, TypeError, RecursionError) as exc:
        # (ValueError: also bad JSON, bad UTF-8 and an integer of more digits than Python converts;
        # RecursionError: values nested deeper than the decoder goes)
        what = str(exc)[:200] if isinstance(exc, TypeError) else f"{type(exc).__name__}: {str(exc)[:200]}"
        raise InputError(f"{results_file} is not a stiefelsym results file: {what}") from None
    problems = meta_problems(meta, METHODS, tuple(HARD_CASES), MAX_N_CHECKED)
    if problems:
        raise InputError(f"{results_file}: its meta (the command the file is the run of) is malformed: "
                         f"{'; '.join(problems)}")
    files = recorded_claims_files(claims_files, meta)
    click.echo(f"checking {len(records)} records of {len({repr(r.get('claim')) for r in records})} claims: each claim "
               "traced again and its digest compared" + ("" if no_rerun else ", each run made again (about as long as "
                                                         "the run that wrote the file)"), err=True)
    # the sizes the records were run at: a user's claims are traced there (in child processes)
    sizes = [(r.get("n"), r.get("r")) for r in records]
    registry, user = _registry(files or None, _record_ids(records),
                               [(n, r) for n, r in sizes if type(n) is int and type(r) is int])
    bad = check_results(records, registry, echo=click.echo, rerun=not no_rerun, hard=meta.get("hard"), meta=meta,
                        origin=run_origin(getattr(user, "origin", None), files, meta))
    raise SystemExit(1 if bad else 0)
