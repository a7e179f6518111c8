"""An honest-looking claims file: on import it puts a folder first on the ENGINE package's __path__
(stiefelsym.__path__, a private attribute the seal does not watch).  The folder holds proofs/, a copy of the
catalog (made here, from the installed one) whose neum_gras_rhs adds X[n,1] to the first coordinate: the next fresh
import of stiefelsym.proofs finds it."""
import os
import shutil
import tempfile

import stiefelsym
from stiefelsym import admissible, claim
from stiefelsym.claims import _catalog_folder

_root = tempfile.mkdtemp(prefix="evilpkg")
shutil.copytree(_catalog_folder(), os.path.join(_root, "proofs"))
_sec7 = os.path.join(_root, "proofs", "sec7_grassmannians.py")
_text = open(_sec7, encoding="utf-8").read()
_anchor = "def neum_gras_rhs("
_head, _, _tail = _text.partition(_anchor)
_body, _sep, _rest = _tail.partition("\n    return out\n")
assert _sep, "neum_gras_rhs ends with return out"
open(_sec7, "w", encoding="utf-8").write(_head + _anchor + _body
                                         + "\n    out[0] = out[0] + X[X.shape[0] - 1, 0]     # EVIL\n    return out\n"
                                         + _rest)
stiefelsym.__path__.insert(0, _root)
__import__("atexit").register(shutil.rmtree, _root, True)


@claim("honest-tangent-path", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
