"""Fourth round (AO): a module the verifying process imports after the file's child has run, found on its import
path outside the package.  The child writes `platformdirs.py` and `sympy.py` into the working directory, the first
entry of sys.path under `python -m stiefelsym`; the verifying process imports platformdirs (the cost model's user
file) and sympy (the exact method) lazily, after the child ran, so the file's code runs there: it installs a
profile hook that turns the false claim's `fails` into `proved` as the run's functions return it (the verdict
line, the summary, results.json and the exit status).  The digest of the package's files (AI) does not look at
other directories of sys.path.

It writes only into a scratch working directory that holds the marker file S34_SCRATCH_CWD (made by
test_adversary_s34.py under tmp_path), never elsewhere."""
import os
import pathlib

from stiefelsym import admissible, claim

PAYLOAD = '''# S34 PAYLOAD: written by a claims file's child (tests/adversary/s34_module_on_the_path.py)
import importlib
import os
import sys
import threading

_here = os.path.dirname(os.path.abspath(__file__))
_saved = list(sys.path)
sys.path[:] = [p for p in sys.path if os.path.realpath(p or os.getcwd()) != os.path.realpath(_here)]
del sys.modules[__name__]
try:
    _real = importlib.import_module(__name__)     # the library itself, from the rest of sys.path
finally:
    sys.path[:] = _saved
sys.modules[__name__] = _real
open(os.path.join(_here, "S34_IMPORTED_IN_" + str(os.getpid())), "w").close()


def _s34_hook(frame, event, arg):
    if event == "return" and type(arg).__name__ == "Result" and arg.claim == "adv-s34-path-false" and \\
            arg.verdict == "fails":
        arg.verdict, arg.expected, arg.residual, arg.witness = "proved", True, None, None
        arg.certificate, arg.message = "every residual entry is identically 0", ""


if os.getpid() == VERIFYING_PROCESS:            # the process that forked the file's child
    sys.setprofile(_s34_hook)
    threading.setprofile(_s34_hook)
'''

_CWD = pathlib.Path(os.getcwd())
if (_CWD / "S34_SCRATCH_CWD").is_file():          # a scratch directory made by the test, never anything else
    _HOW = (_CWD / "S34_SCRATCH_CWD").read_text().strip() or "module"
    _TEXT = PAYLOAD.replace("VERIFYING_PROCESS", str(os.getppid()))
    for _lib in ("platformdirs", "sympy"):
        if _HOW == "module":                      # platformdirs.py
            (_CWD / f"{_lib}.py").write_text(_TEXT)
        elif _HOW == "package":                   # platformdirs/__init__.py (its own folder: the library's name)
            (_CWD / _lib).mkdir(exist_ok=True)
            (_CWD / _lib / "__init__.py").write_text(_TEXT.replace("os.path.dirname(os.path.abspath(__file__))",
                                                                   "os.path.dirname(os.path.dirname("
                                                                   "os.path.abspath(__file__)))"))
        elif _HOW == "bytecode":                  # platformdirs.pyc without a source (imported as well)
            import importlib._bootstrap_external as _ext
            import marshal
            _code = compile(_TEXT, str(_CWD / f"{_lib}.py"), "exec")
            (_CWD / f"{_lib}.pyc").write_bytes(_ext._code_to_timestamp_pyc(_code, 0, 0) if hasattr(
                _ext, "_code_to_timestamp_pyc") else marshal.dumps(_code))


@claim("adv-s34-path-false", kind="id", sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2, condition="(3,2)"),
       statement="X^T X = 2 I_r")
def path_false(s):
    """False: Xᵀ X = 2 I_r."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}
