"""Stop 60, after the second review (s60/review2): claim code that changes, while it is traced, what the engine's
code reads without writing an attribute of an engine module: the package's own exports (stiefelsym.comm), a
stand-in module in sys.modules, Python's builtins, a numpy function, and the interpreter's hooks (a profile
function, a garbage-collector callback) through which code runs while a method evaluates.  In-process every
method must give `error` for each; each claim is false, so a run in which the change goes unseen cannot pass."""
import builtins
import gc
import sys
import threading
import types

import numpy

import stiefelsym
from stiefelsym import admissible, claim

_DONE: set = set()


def _package_export():
    honest = stiefelsym.comm
    stiefelsym.comm = lambda a, b: honest(a, b) * 0


def _stand_in_module():
    from stiefelsym.free import algebra
    fake = types.ModuleType(algebra.__name__)
    fake.__dict__.update(vars(algebra))
    fake.DIMENSIONS = dict(algebra.DIMENSIONS, n=algebra.DIMENSIONS["r"])
    sys.modules[algebra.__name__] = fake


def _builtin():
    honest = builtins.sum
    builtins.sum = lambda it, start=0: honest(it, start)


def _numpy_function():
    numpy.argmax = numpy.argmin


def _profile_hook():
    def hook(frame, event, arg):
        return None
    sys.setprofile(hook)
    threading.setprofile(hook)


def _gc_callback():
    gc.callbacks.append(lambda phase, info: None)


WRITES = {"s60-int-package-export": _package_export, "s60-int-stand-in-module": _stand_in_module,
          "s60-int-builtin": _builtin, "s60-int-numpy-function": _numpy_function,
          "s60-int-profile-hook": _profile_hook, "s60-int-gc-callback": _gc_callback}


def _false_claim(cid):
    def body(s):
        if cid not in _DONE:
            _DONE.add(cid)
            WRITES[cid]()
        return {"tr In - tr Ir": s.tr(s.In) - s.tr(s.Ir), "X": s.X}
    body.__name__ = body.__qualname__ = cid.replace("-", "_")
    body.__doc__ = "False: tr I_n = tr I_r and X = 0 (with a change of what the engine's code reads)."
    return claim(cid, paper="adv", kind="id", sizes=admissible(n_max=3))(body)


for _cid in WRITES:
    globals()[_cid.replace("-", "_")] = _false_claim(_cid)
