"""The engine's seal (stiefelsym.ir.seal): what changes its fingerprint after a claims file is loaded."""
from __future__ import annotations

import importlib
import sys

import pytest

from stiefelsym.ir import seal


def test_a_module_no_verdict_depends_on_imported_after_sealing_changes_nothing():
    """stiefelsym.run._dask_plugin is imported by a dask run, after the seal of a claims file loaded earlier in
    the same process (a local run after a distributed one gave `error` for every record: the package
    stiefelsym.run had gained the attribute _dask_plugin)."""
    sys.modules.pop("stiefelsym.run._dask_plugin", None)
    run_pkg = importlib.import_module("stiefelsym.run")
    vars(run_pkg).pop("_dask_plugin", None)
    seal.seal()
    importlib.import_module("stiefelsym.run._dask_plugin")
    seal.verify("after the import")


def test_a_watched_submodule_replaced_by_one_no_verdict_depends_on_is_seen(monkeypatch):
    seal.seal()
    run_pkg = importlib.import_module("stiefelsym.run")
    monkeypatch.setattr(run_pkg, "pool", importlib.import_module("stiefelsym.run._dask_plugin"))
    with pytest.raises(seal.EngineChanged):
        seal.verify("after the change")
