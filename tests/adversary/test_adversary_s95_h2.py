"""Stop 95, h2 (an adversary of the eight routes of issue 20 and beyond): what `check --no-rerun` says of the
verdicts it did not run again, and a claims path that names a device or a pipe."""
from __future__ import annotations

import json
import os

import pytest

import stiefelsym
from stiefelsym.claims import CatalogError

def _run_cli(args):
    from click.testing import CliRunner

    from stiefelsym.cli import main
    return CliRunner().invoke(main, args, catch_exceptions=False)


def test_check_without_a_run_again_says_which_verdicts_rest_on_the_file(tmp_path):
    """A fixed-size record's verdict forged from 'fails' to 'proved' (with the evidence of a true claim's record)
    passes `check --no-rerun`, which compares digests and certificates only: its count says that the verdicts
    were not run again (it said "1 records checked, 0 rejected"); `check` without the option runs them again."""
    out = tmp_path / "rep"
    r = _run_cli(["verify", "prep", "--size", "3,2", "--method", "modular", "--report-dir", str(out)])
    assert r.exit_code == 0, r.output
    payload = json.loads((out / "results.json").read_text())
    assert [x["verdict"] for x in payload["results"]] == ["checked"]
    r = _run_cli(["check", str(out / "results.json"), "--no-rerun"])
    assert r.exit_code == 0
    assert "1 records checked, 0 rejected (digests and certificates only: the verdict of 1 fixed-size record " \
           "not run again)" in r.output, r.output


@pytest.mark.parametrize("path", ["/dev/null", "fifo"])
def test_a_claims_path_that_is_not_a_regular_file_is_named_so(tmp_path, path):
    """`verify --claims /dev/zero` (or a pipe, /dev/stdin) said "claims file not found" of a path that exists."""
    if path == "fifo":
        path = str(tmp_path / "claims.py")
        os.mkfifo(path)
    r = _run_cli(["verify", "--claims", path, "--no-report"])
    assert r.exit_code == 2 and f"claims file {path} is not a regular file" in r.output, r.output
    with pytest.raises(CatalogError, match="is not a regular file"):
        stiefelsym.load(files=path)
    missing = str(tmp_path / "missing.py")
    r = _run_cli(["verify", "--claims", missing, "--no-report"])
    assert r.exit_code == 2 and f"claims file not found: {missing}" in r.output, r.output
