"""The replays' way of running a claims file (test_adversary_s78.py onwards): one `stiefelsym verify` of the file in
a fresh interpreter, one job at a time, its records read back from the JSON it prints.

Imported as a plain module, like adversary_cli.py (pytest puts this folder on sys.path: it has no __init__.py).
Unlike adversary_cli.cli, a run here keeps the test's working directory and may take 600 s.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

#: a record's key: (claim id, n, r); n and r are None for a record of every n, r (the dimension-free method)
SizeKey = tuple[str, int | None, int | None]
#: a record's key with its variant: (claim id, variant, n, r); the variant is None for the printed claim
VariantKey = tuple[str, str | None, int | None, int | None]


def verify_json(path: Path, *args: str) -> subprocess.CompletedProcess:
    """`python -m stiefelsym verify --claims PATH --jobs 1 --format json ARGS...` in a fresh interpreter (several
    routes change process-wide state), its output captured as text; ``args`` are the claim ids and options
    (--method, --size, ...)."""
    return subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(path), "--jobs", "1",
                           "--format", "json", *args], capture_output=True, text=True, timeout=600)


def _results(path: Path, *args: str) -> list[dict]:
    """The records of :func:`verify_json`'s run (the run must print them; else its standard error is shown)."""
    out = verify_json(path, *args)
    assert out.stdout.strip(), out.stderr[-2000:]
    return json.loads(out.stdout)["results"]


def records(path: Path, *args: str) -> dict[SizeKey, dict]:
    """{(claim, n, r): record} of one run of :func:`verify_json` (a later record of the same key wins)."""
    return {(r["claim"], r.get("n"), r.get("r")): r for r in _results(path, *args)}


def records_by_variant(path: Path, *args: str) -> dict[VariantKey, dict]:
    """{(claim, variant, n, r): record} of one run of :func:`verify_json`: a claim's corrections (its variants)
    apart from the printed claim."""
    return {(r["claim"], r.get("variant"), r.get("n"), r.get("r")): r for r in _results(path, *args)}


def verdicts_by_size(path: Path, *args: str) -> dict[SizeKey, str]:
    """{(claim, n, r): verdict} of one run of :func:`verify_json`."""
    return {(r["claim"], r.get("n"), r.get("r")): r["verdict"] for r in _results(path, *args)}


def verdicts_by_claim(path: Path, *args: str) -> dict[str, str]:
    """{claim: verdict} of one run of :func:`verify_json`, read through :func:`records_by_variant` (of the records
    of one claim id, the last key's verdict)."""
    return {key[0]: rec["verdict"] for key, rec in records_by_variant(path, *args).items()}


def namespaces() -> bool:
    """Whether the jobs of a claims file run in user + pid + mount namespaces here (stiefelsym.run.sandbox)."""
    from stiefelsym.run.sandbox import namespaces_available
    return namespaces_available()


def requires_namespaces() -> pytest.MarkDecorator:
    """A skipif marker for the tests that need :func:`namespaces` (asked when the marker is made, i.e. when the test
    module is imported)."""
    return pytest.mark.skipif(not namespaces(), reason="no user + pid + mount namespaces here: the jobs are "
                              "ordinary children of the tracing process (the records say so)")
