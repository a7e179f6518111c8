"""Stop 91's replays: an attack on what a catalog claim's review rests on (h1), its tricks kept as tests.

- W1: the function object of a reviewed catalog claim kept, its ``__code__`` replaced in the caller's process: the
  claim's identity and its function's identity held, so its reviewed reason of equivariance reduced the new code to
  X = X0 and exact proved "the last row of X vanishes" at (3, 2).
- W2: the same through the function's globals: a helper of the catalog's module rebound (by the caller, or by a
  claims file loaded into the process after the catalog), which the seal does not watch (the catalog is not the
  engine).  A reviewed function is now bound to what it computes with as well (``claims._reach``): its code,
  defaults, closure and the globals it and its helpers read, recorded when the catalog registers it; a function
  whose record no longer holds is not reviewed, and goes to the Cayley chart like any other.  A claims file loaded
  before the catalog rebound ``determinants.det``, a helper module the loading did not reload, so the catalog
  registered the rebound helper: the loading now imports every module of the catalog afresh from disk.
- W3: a claims file loaded in-process appended its folder to the catalog package's ``__path__`` and a module to its
  ``MODULES``: the next loading registered that module's false claim as reviewed (the fresh import closes it).
- W4: a claims file replaced ``stiefelsym.run.distributed.verifier``, a module the seal left out as one no verdict
  depends on; a run with a scheduler then handed back ``proved`` for anything.  The cluster's client is sealed now,
  and the run checks the seal before it is sent.
- I1: a claims file importing a helper from a catalog module registered that module's claims as its own.
"""
from __future__ import annotations

from pathlib import Path

import subprocess
import sys

import pytest

import stiefelsym
from stiefelsym.claims import reviewed_functions


def _bottom_row(s):
    return {"x": s.X[2:3, :]}


def _verdicts(claim) -> dict[str, str]:
    return {r.method: r.verdict for r in stiefelsym.verify([claim], sizes=[(3, 2)], methods=["exact", "modular"],
                                                            jobs=1)}


def test_a_catalog_function_whose_code_is_swapped_is_not_reviewed():
    c = stiefelsym.load_catalog().get("neum-gras")
    assert c.func in reviewed_functions(c)
    code = c.func.__code__
    try:
        c.func.__code__ = _bottom_row.__code__       # the function (and the claim) keep their identity
        assert c.func not in reviewed_functions(c)
        assert _verdicts(c) == {"exact": "fails", "modular": "fails"}
    finally:
        c.func.__code__ = code
    assert c.func in reviewed_functions(c)        # the code it was reviewed with is back


def test_a_rebound_helper_of_the_catalog_module_unreviews_its_claims(monkeypatch):
    c = stiefelsym.load_catalog().get("neum-gras")
    from stiefelsym.proofs import sec7_grassmannians as m          # the module the claim was loaded from
    assert c.func in reviewed_functions(c)
    orig = m.neum_gras_rhs
    monkeypatch.setattr(m, "neum_gras_rhs", lambda s, X, Xdot: [o + X[X.shape[0] - 1, 0] for o in orig(s, X, Xdot)])
    assert c.func not in reviewed_functions(c)
    assert _verdicts(c) == {"exact": "fails", "modular": "fails"}     # the residual is −X[3,1]: false on T*V
    monkeypatch.undo()
    assert c.func in reviewed_functions(c)


def test_a_changed_default_or_closure_unreviews(monkeypatch):
    from stiefelsym.claims import Claim, _mark_reviewed
    box = [1]

    def f(s, k=2):
        return {"x": s.X.T @ s.X - s.Ir * box[0] * (k - 1)}
    c = _mark_reviewed(Claim(id="closure-probe", paper=("cond_XP",), kind="id", section="t", func=f,
                             sizes=stiefelsym.admissible(3)))
    assert reviewed_functions(c) == (f,)
    box[0] = 2                                        # a global list's contents
    assert reviewed_functions(c) == ()
    box[0] = 1
    monkeypatch.setattr(f, "__defaults__", (3,))
    assert reviewed_functions(c) == ()
    monkeypatch.undo()
    assert reviewed_functions(c) == (f,)


@pytest.mark.parametrize("claim_id", ["neum-gras", "pencil-rank-a1", "manakov-lax", "dual-lax-determines-the-point"])
def test_the_catalog_as_loaded_is_reviewed(claim_id):
    c = stiefelsym.load_catalog().get(claim_id)
    assert reviewed_functions(c)[0] is c.func


def test_a_catalog_module_imported_for_a_helper_adds_none_of_its_claims():
    # h1 I1: `from stiefelsym.proofs.sec7_grassmannians import columns` in a claims file ran the catalog module's
    # decorators inside the file's loading: 56 claims (the catalog's, under the file's name, replacing the
    # catalog's) and a load of 208 s, for a file of one claim
    reg = stiefelsym.load(Path(__file__).parent / "s91" / "h1" / "helper_import.py", sizes=[(3, 1)])
    assert [c.id for c in reg] == ["mine-columns"]


H1 = Path(__file__).parent / "s91" / "h1"


def _script(name: str) -> str:
    out = subprocess.run([sys.executable, name], cwd=H1, capture_output=True, text=True, timeout=600)
    return out.stdout + out.stderr


def test_a_helper_module_rebound_before_the_catalog_is_loaded_is_not_the_catalog_s():
    out = _script("api_file_then_catalog.py")       # evil_det.py rebinds determinants.det, then the catalog loads
    assert "neum-gras (3,2) exact: proved" in out and "neum-gras (3,2) modular: checked" in out, out
    assert "fails" not in out       # the catalog's neum-gras as on disk: true


def test_a_module_added_to_the_catalog_package_is_not_loaded_as_the_catalog():
    out = _script("api_catalog_path.py")
    assert "in the catalog: False" in out and "proved" not in out, out


def test_the_cluster_client_is_sealed():
    code = ("import stiefelsym\n"
            "try:\n    stiefelsym.load_claims_file('evil_dist.py')\n"
            "except stiefelsym.CatalogError as e:\n    print('refused:', e)\n")
    out = subprocess.run([sys.executable, "-c", code], cwd=H1, capture_output=True, text=True, timeout=600)
    assert "refused:" in out.stdout and "the engine was changed" in out.stdout, out.stdout + out.stderr


# h4: the same review attacked again after the fixes above, eight more routes, each closed:
# - W1, W2: a global of the catalog's module shadowing a builtin the function reads (zip), or the module's
#   __builtins__ replaced: the record holds that the name is absent from the module and the module's builtins;
# - W3 (a helper that computes a changed result while traced and puts the original back after) and W4-W8 (the
#   import machinery during the catalog's fresh loading: a stand-in itertools in sys.modules, a folder on
#   stiefelsym.__path__, a meta path finder, a wrapped importlib.import_module; an audit hook that applies @claim
#   while the catalog loads, registering one's own claim as the catalog's): all from a claims file imported into the
#   process, with its full powers.  Such a process relies on no reviewed reason any more (the seal is on): the CLI,
#   stiefelsym.load and the pytest plugin import files in fresh interpreters only, and keep them.
H4 = Path(__file__).parent / "s91" / "h4"


@pytest.mark.parametrize("args", [["b_builtin_shadow.py", "exact", "3.2"], ["g_module_builtins.py", "exact"],
                                  ["c_file_after_catalog.py", "exact"], ["g2_file_builtins.py", "exact"],
                                  ["d_fresh_import_itertools.py", "exact"],
                                  ["e_fresh_import.py", "evil_metapath_file.py", "exact"],
                                  ["e_fresh_import.py", "evil_pkgpath_file.py", "exact"],
                                  ["e_fresh_import.py", "evil_importmodule_file.py", "exact"],
                                  ["f_audit_smuggle.py", "exact"]], ids=lambda a: "-".join(a[:2]))
def test_a_changed_catalog_is_not_proved_under_its_review(args):
    out = subprocess.run([sys.executable, *args], cwd=H4, capture_output=True, text=True, timeout=600)
    lines = [x for x in out.stdout.splitlines() if " exact: " in x]
    assert lines and all(" exact: fails" in x for x in lines), out.stdout + out.stderr


def test_a_function_that_only_names_a_catalog_module_stays_the_file_s():
    # h4 I1: a claim whose function's __module__ named a catalog module was dropped from its file, silently; only a
    # function compiled from the catalog's folder is the catalog's
    reg = stiefelsym.load(H4 / "evil_hide_file.py", sizes=[(3, 2)])
    assert [c.id for c in reg] == ["visible-true", "hidden-false"]


OWN = Path(__file__).parent / "s91" / "own"


def test_the_pencil_isomorphism_check_rejects_its_mutants():
    # the new correction of pencil-gl-isomorphism checks L Λ L = μ⟨ψ(·), [·,·]⟩; μ² in front, or L = μ on Sym(n)
    # instead of so(n), must fail (negative controls of the identity the correction rests on)
    from adversary_replay import verdicts_by_size
    for method in ("exact", "modular"):
        got = verdicts_by_size(OWN / "pencil_gl_mutants.py", "--size", "3,2", "--method", method)
        assert got[("pg-true", 3, 2)] in ("proved", "checked"), got
        assert got[("pg-scale-c", 3, 2)] == "fails" and got[("pg-L-swapped", 3, 2)] == "fails", got


def test_an_empty_matrix_has_rank_zero_and_no_other():
    from adversary_replay import verdicts_by_size
    for method in ("exact", "modular", "rational"):
        got = verdicts_by_size(OWN / "empty_rank.py", "--size", "3,2", "--method", method)
        assert got == {("empty-rank-false", 3, 2): "fails", ("empty-rank-true", 3, 2): "proved"}, got
