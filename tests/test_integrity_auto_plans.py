"""A results file of a command that plans auto beside a method auto may choose: the run of a size under that
method then has two records (the named run and auto's), and the corrections auto ran are ones the command made."""
from types import SimpleNamespace

from stiefelsym.run.integrity import _missing_corrections


class _Registry(dict):
    def get(self, cid):         # noqa: D401 - the claim of an id
        return self[cid]


REGISTRY = _Registry(c=SimpleNamespace(corrections=[SimpleNamespace(description="fix")]))
META = {"methods": ["auto", "modular"]}


def _rec(n, method, verdict, variant=None):
    return {"claim": "c", "variant": variant, "n": n, "r": 1, "method": method, "verdict": verdict}


def _file(auto_failed: bool = True):
    printed = [_rec(1, "exact", "proved"), _rec(1, "modular", "checked"), _rec(2, "modular", "fails")]
    if auto_failed:             # auto chose modular at (2,1) and it failed there too
        printed.append(_rec(2, "modular", "fails"))
    else:
        printed.append(_rec(2, "exact", "proved"))
    fixed = [_rec(1, "exact", "proved", "fix"), _rec(1, "modular", "checked", "fix"),
             _rec(2, "modular", "checked", "fix")]
    return printed + fixed + ([_rec(2, "modular", "checked", "fix")] if auto_failed else [])


def test_auto_choosing_a_named_method_is_told_apart_by_the_second_record():
    assert _missing_corrections(_file(), REGISTRY, META) == []


def test_a_correction_auto_did_not_run_is_still_refused():
    out = _missing_corrections(_file(auto_failed=False), REGISTRY, META)
    assert out and all("(1,1) auto" in line and "does not make" in line for line in out), out


def test_a_missing_correction_of_auto_is_still_found():
    records = [r for r in _file() if not (r["variant"] and r["n"] == 1)]
    out = _missing_corrections(records, REGISTRY, META)
    assert any("(1,1) auto" in line and "no record of the run" in line for line in out), out


def test_a_correction_under_a_method_that_never_failed_is_refused():
    records = _file() + [_rec(3, "rational", "checked", "fix")]
    out = _missing_corrections(records, REGISTRY, {"methods": ["auto", "modular", "rational"]})
    assert any("(3,1)" in line and "does not make" in line for line in out), out
