"""A claims file imports the helper modules next to it, in this process (``load_claims_file``) as under
``stiefelsym verify --claims`` (whose interpreters put the file's folder last on the search path).  Found by the user
trial of stop 62, whose two claims files share a ``common.py``: the command ran them, the library refused them."""
from __future__ import annotations

import subprocess
import sys
import textwrap

from stiefelsym.claims import Size, load_claims_file
from stiefelsym.run.runner import run_one

HELPER = '''
def psi(s):
    """Ψ = XᵀP − PᵀX."""
    return s.X.T @ s.P - s.P.T @ s.X
'''

CLAIMS = '''
from stiefelsym import claim
from s62_helper_module import psi


@claim("helper-psi", kind="id", section="2")
def helper_psi(s):
    """Ψ of the scene is XᵀP − PᵀX: true."""
    return {"Psi": s.Psi - psi(s)}


@claim("helper-psi-twice", kind="id", section="2")
def helper_psi_twice(s):
    """Ψ = 2(XᵀP − PᵀX): false (the negative control)."""
    return {"Psi": s.Psi - psi(s) * 2}
'''


def _files(tmp_path):
    (tmp_path / "s62_helper_module.py").write_text(textwrap.dedent(HELPER))
    (tmp_path / "claims.py").write_text(textwrap.dedent(CLAIMS))
    return tmp_path / "claims.py"


def test_load_claims_file_imports_a_helper_next_to_the_file(tmp_path):
    reg = {c.id: c for c in load_claims_file(_files(tmp_path))}
    assert str(tmp_path.resolve()) in sys.path      # last, where it was not on the path before
    assert run_one(reg["helper-psi"], Size(3, 2), "exact", 0).verdict == "proved"
    assert run_one(reg["helper-psi-twice"], Size(3, 2), "exact", 0).verdict == "fails"


def test_the_command_imports_it_too(tmp_path):
    run = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(_files(tmp_path)),
                          "--size", "3,2", "--method", "exact", "--no-report"], capture_output=True, text=True,
                         timeout=300, cwd=str(tmp_path.parent))
    assert "helper-psi (3,2) exact: proved" in run.stdout, run.stdout + run.stderr
    assert "helper-psi-twice (3,2) exact: fails" in run.stdout, run.stdout + run.stderr


def test_a_helper_of_the_same_name_as_another_files_helper_is_refused(tmp_path):
    """Two claims files, each next to its own common.py (the second review of stop 62): in one process the second
    file's `from common import ...` gave it the first folder's module (imported once, under its name), and a true claim
    of the second file failed.  Now that load is refused with the reason and the way out; the command line (an
    interpreter per file) verifies both."""
    import pytest
    from stiefelsym.claims import CatalogError
    one, two = tmp_path / "one", tmp_path / "two"
    for folder, body in ((one, "return t.tr(t.X.T @ t.A @ t.X) / 2"), (two, "return t.tr(t.P.T @ t.P) / 2")):
        folder.mkdir()
        (folder / "s62_common_helper.py").write_text(f"def H(t):\n    {body}\n")
    (one / "claims_one.py").write_text(textwrap.dedent('''
        from stiefelsym import claim
        from s62_common_helper import H


        @claim("helper-one", kind="id", section="2")
        def one(s):
            """H is the potential: true with this folder's helper."""
            return {"H": H(s) - s.tr(s.X.T @ s.A @ s.X) / 2}
        '''))
    (two / "claims_two.py").write_text(textwrap.dedent('''
        from stiefelsym import claim
        from s62_common_helper import H


        @claim("helper-two", kind="id", section="2")
        def two(s):
            """H is the kinetic energy: true with this folder's helper."""
            return {"H": H(s) - s.tr(s.P.T @ s.P) / 2}
        '''))
    reg = {c.id: c for c in load_claims_file(one / "claims_one.py")}
    assert run_one(reg["helper-one"], Size(3, 2), "exact", 0).verdict == "proved"
    with pytest.raises(CatalogError, match="has the name of a module this process imported from another claims file"):
        load_claims_file(two / "claims_two.py")
    run = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(one / "claims_one.py"),
                          "--claims", str(two / "claims_two.py"), "--size", "3,2", "--method", "exact", "--no-report"],
                         capture_output=True, text=True, timeout=300, cwd=str(tmp_path))
    assert "helper-one (3,2) exact: proved" in run.stdout and "helper-two (3,2) exact: proved" in run.stdout, \
        run.stdout + run.stderr
