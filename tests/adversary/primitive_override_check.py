"""The forged results file that `stiefelsym check` accepts: this claims file (named by the results
file's meta.claims_files) overrides the engine primitive ``stiefelsym.twisted.form`` (see
primitive_override.py) and imports the catalog module, whose @claim decorators then register the
catalog's claims in this file's registry; `check` finds the catalog claim there, re-traces it (same
digest: a prim node is named by its qualified name only), re-runs it with this file's form and agrees.

    stiefelsym verify magnetic-form-kirillov-kostant --claims primitive_override_check.py --size 3,2 \
        --method modular --report-dir D && stiefelsym check D/results.json     # exit 0, record 'fails'
"""
from stiefelsym.ir import primitive
import stiefelsym.twisted  # noqa: F401  (the engine registers its primitive first; this file's comes after)


def form(s, u, v, F=None):
    """ω₀(u, v): the canonical form with the magnetic term dropped (not the engine's ω_ε)."""
    return s.tr(u["P"].T @ v["X"]) - s.tr(u["X"].T @ v["P"])


form.__module__ = "stiefelsym.twisted"
form.__qualname__ = "form"
primitive(form)

# Importing a catalog module while this file loads registers its claims in this file's registry (the
# @claim decorator writes to the registry being loaded), so `stiefelsym check`, which looks claims up in
# the files a results file names, finds the catalog claim here and re-runs it with this file's form.
import stiefelsym.proofs.app1_magnetic_neumann  # noqa: E402,F401

