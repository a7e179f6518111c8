"""The engine sealed against claims files: what a user's claims file may not change.

A claims file is Python: importing it, and tracing its claims, runs its code in
the engine's process, where nothing can be made unreachable.  What can be made
certain is that a change is *seen*.  When the first user claims file is loaded,
:func:`seal` imports every module a verdict depends on and records a
fingerprint of the engine: every attribute of those modules (by identity), the
code of every function and method, the contents of every public attribute of
those modules and of their classes (dicts, lists, tuples, sets, flags, the
attributes of an engine object such as a bracket, to a fixed depth), and the
contents of the registries a claim could use to reach a method (engine steps,
engine constants, whole-matrix backends, the evaluator's operations), with the
public attributes of the numerical libraries the backends call and of Python's
builtins (by identity), and the interpreter's trace, profile and garbage
collection hooks (code that runs while the engine evaluates without being called
by it).  The modules are read as they were when sealed, so a stand-in put in
``sys.modules`` hides nothing (and is itself a change).  Private
attributes (a leading underscore) are the engine's memos and caches, which
change as it runs: code that writes them in the calling process is beyond what
loading a file into that process can promise (docs/architecture.md, "Where a
claims file is trusted").  After the file is imported, and before
every evaluation of a graph, :func:`verify` computes the fingerprint again; a
difference makes the file's loading fail (exit 2) or the run an ``error``.
After sealing, the engine's registries take no new entries
(:func:`stiefelsym.ir.primitive`, :func:`stiefelsym.ir.named`, backends).

The catalog of the paper is not sealed against (it is part of the reviewed
source); a run that loads no claims file pays nothing.
"""
from __future__ import annotations

import hashlib
import importlib
import pkgutil
import sys
import types
from fractions import Fraction
from pathlib import Path
from typing import Any

#: modules a verdict does not depend on (renderers, the CLI, optional integrations, the flows report's numerical
#: integration with scipy, which registers nothing and costs most of a sealing's imports): not imported at
#: sealing time (a claims file that changes one of them changes no verdict).  The cluster's client
#: (stiefelsym.run.distributed) is not among them: its verifier hands the verdicts of a run back
_NOT_VERDICT = ("cli", "cli_", "notebook", "pytest_plugin", "_dask_plugin", "speed", "costfit",
                "report", "latex", "flows_report", "integrate", "mutate", "discover", "__main__", "proofs")
#: third-party modules whose top-level attributes the backends call (every public one is watched by identity:
#: numpy's ufuncs and array functions too), and Python's builtins
_LIBRARIES = ("numpy", "flint", "symengine", "fractions", "operator", "math", "mpmath", "random", "hashlib",
              "builtins", "json", "json.encoder", "json.decoder", "os", "posix")
#: classes of those libraries written in Python whose members a verdict reads (a graph's constants are sent as a
#: Fraction's numerator and denominator, its data as JSON): each member is watched by identity too (stop 85's
#: sweep: ``Fraction.denominator`` replaced at import, the class itself unchanged, sent 1/3 as 1/2)
_LIBRARY_CLASSES = (("fractions", "Fraction"), ("json.encoder", "JSONEncoder"), ("json.decoder", "JSONDecoder"))
#: submodules of the libraries the engine reaches through their package on first use (numpy loads them on
#: first access): imported when sealing, so that a claims file cannot put its own module there first
_LIBRARY_SUBMODULES = ("numpy.random", "numpy.linalg")
#: registries (module, attribute) whose contents are fingerprinted
_REGISTRIES = (("stiefelsym.ir.trace", "PRIMITIVES"), ("stiefelsym.ir.trace", "_NAMED"),
               ("stiefelsym.ir.trace", "CONSTANT_PRIMITIVES"), ("stiefelsym.ir.trace", "ZERO_PRIMITIVES"),
               ("stiefelsym.ir.trace", "VALUE_ATTRS"), ("stiefelsym.backends.native", "_REGISTERED"),
               ("stiefelsym.methods.fixed_size", "_REGISTERED"), ("stiefelsym.ir.evaluate", "_ARITH"))


#: module attributes watched whatever their name: code, classes and modules; every public attribute of an
#: engine module (and of its classes) is watched too, with its contents (:func:`_content`); private values,
#: flags and containers are the engine's state and caches (the registries below are watched by their contents)
_CODE = (types.FunctionType, staticmethod, classmethod, property, types.BuiltinFunctionType)
_WATCHED = _CODE + (type, types.ModuleType)
_CONSTANTS = (int, float, complex, str, bytes)
#: values whose text is their content (exact types: a subclass is watched by identity and contents)
_PLAIN = (int, float, complex, str, bytes, bool, type(None), Fraction)
#: how deep the contents of a public attribute are read (a dict of tuples of sets: 3)
_DEPTH = 4


class EngineChanged(RuntimeError):
    """A claims file changed the engine (a module attribute, a function's code, a registry)."""


_STATE: dict[str, Any] = {"modules": None, "print": None, "objects": None, "submodules": None}


def sealed() -> bool:
    if not isinstance(_STATE, dict) or "modules" not in _STATE:
        raise EngineChanged("the engine was changed by claim code: the seal's own record of the engine is gone; no "
                            "verdict is given")
    return _STATE["modules"] is not None


def _excluded(name: str) -> bool:
    return any(last == x or (x.endswith("_") and last.startswith(x))
               for last in name.split(".")[1:] for x in _NOT_VERDICT)


def _verdict_modules() -> list[str]:
    """The engine's modules a verdict depends on, found on disk (a package that is not one of them, e.g.
    the command line's, is neither imported nor walked into)."""
    names = []

    def walk(folder: str, prefix: str) -> None:
        for info in pkgutil.iter_modules([folder]):
            name = prefix + info.name
            if _excluded(name):
                continue
            names.append(name)
            if info.ispkg:
                walk(str(Path(folder) / info.name), name + ".")
    walk(str(Path(__file__).resolve().parents[1]), "stiefelsym.")      # the engine's package folder
    return names


#: the engine's modules that register steps and constants a graph may name (:func:`stiefelsym.ir.trace.primitive`,
#: :func:`~stiefelsym.ir.trace.named`) and that the IR's own modules do not import: the only modules a replay
#: imports on first need (a fixed list in the engine's code, never read off the disk or a graph; the tests check
#: that every registered name belongs to one of them or to a module :mod:`stiefelsym.ir` imports)
STEP_MODULES = ("stiefelsym.twisted", "stiefelsym.systems", "stiefelsym.brackets")


def engine_module_of(qualname: str) -> str | None:
    """The module of :data:`STEP_MODULES` whose name begins ``qualname`` (``stiefelsym.twisted`` of
    ``stiefelsym.twisted.at_point``); None for any other name."""
    for name in STEP_MODULES:
        if qualname.startswith(name + "."):
            return name
    return None


def _code_of(v: Any) -> str:
    # only true functions are looked into (an arbitrary object's attributes may compute, import or
    # change things when they are read)
    if isinstance(v, (staticmethod, classmethod)):
        v = v.__func__
    if not isinstance(v, types.FunctionType):
        return ""
    return f"{id(v.__code__)}/{id(v.__defaults__)}/{id(v.__kwdefaults__)}"


def _own_attributes(v: Any) -> dict | None:
    """The instance attributes of an engine object (its ``__dict__`` and its slots), read without running
    any of its code (no ``__getattr__``, no property); None for anything else."""
    cls = type(v)
    members = _SLOTS.get(cls)
    if members is None:
        members = _SLOTS[cls] = (
            None if not str(getattr(cls, "__module__", "")).startswith("stiefelsym.") else
            tuple((slot, m) for klass in cls.__mro__ for slot, m in vars(klass).items()
                  if type(m) is types.MemberDescriptorType))
    if members is None:
        return None
    out: dict = {}
    try:
        out.update(object.__getattribute__(v, "__dict__"))
    except AttributeError:
        pass
    for slot, member in members:
        try:
            out[slot] = member.__get__(v, cls)
        except AttributeError:
            pass
    return out


#: class -> its slots' member descriptors (None: not an engine class), read once per class
_SLOTS: dict[type, tuple | None] = {}


def _content(v: Any, depth: int = _DEPTH, seen: dict | None = None) -> str:
    """The text of a value by its contents: plain values by their repr, containers and engine objects by the
    contents of their items (to ``depth`` levels), anything else by identity (and a function by its code and
    the cells it closes over).  Every container is named by its identity too, so that a rebinding to an equal
    copy is seen as well.  ``seen``: the objects whose contents one fingerprint has already read (by identity,
    at the depth read), which are then named by identity only (a registry imported by five modules is read
    once)."""
    t = type(v)
    if t in _PLAIN:
        return f"{t.__name__}:{v!r}"
    head = f"#{id(v)}:{_code_of(v)}"
    if depth <= 0:
        return head
    if seen is not None:
        if seen.get(id(v), -1) >= depth:
            return head
        seen[id(v)] = depth
    if t is dict or t is types.MappingProxyType:
        return head + "{" + ",".join(f"{_content(k, 1)}:{_content(w, depth - 1, seen)}"
                                     for k, w in list(v.items())) + "}"
    if t in (list, tuple, set, frozenset):
        return head + "[" + ",".join(_content(w, depth - 1, seen) for w in list(v)) + "]"
    if t is types.FunctionType:
        return head + "(" + ",".join(_content(c, depth - 1, seen) for c in (v.__closure__ or ())) + ")"
    if t is types.CellType:
        try:
            return head + _content(v.cell_contents, depth - 1, seen)
        except ValueError:
            return head
    own = _own_attributes(v)
    if own is not None:
        return head + "{" + ",".join(f"{k}:{_content(w, depth - 1, seen)}" for k, w in own.items()
                                     if not k.startswith("_")) + "}"
    return head


def _hooks() -> str:
    """The interpreter's hooks through which code runs while the engine evaluates, without being called by it:
    the trace and profile functions (of this thread and of new threads) and the garbage collector's callbacks."""
    import gc
    import threading
    return (f"trace={id(sys.gettrace())} profile={id(sys.getprofile())} thread-trace={id(threading.gettrace())} "
            f"thread-profile={id(threading.getprofile())} gc={[id(c) for c in list(gc.callbacks)]}")


def _fingerprint(modules: list[str], objects: dict[str, Any] | None = None,
                 submodules: frozenset | None = None) -> str:
    """The fingerprint of ``modules``: read from ``objects`` (the module objects recorded when sealing, so that
    a stand-in put in ``sys.modules`` hides nothing; whether ``sys.modules`` still holds them is part of the
    fingerprint), with the interpreter's hooks.  ``submodules``: the (library, attribute) pairs that were
    submodules when sealing (a library's submodule imported later, e.g. by the claims file, is not a change)."""
    h = hashlib.sha256()
    code_of = _code_of
    seen: dict[int, int] = {}
    h.update(f"{_hooks()}\n".encode())

    for name in modules:
        mod = sys.modules.get(name) if objects is None else objects.get(name)
        h.update(f"{name}:{id(mod)}:{id(sys.modules.get(name))}\n".encode())
        if mod is None:
            continue
        engine = name.startswith("stiefelsym")
        for attr, v in list(vars(mod).items()):
            public = not attr.startswith("_")
            if not engine and public:
                if isinstance(v, types.ModuleType) and submodules is not None and (name, attr) not in submodules:
                    continue        # a submodule of the library imported since (by the claims file, say)
                h.update(f"{name}.{attr}={id(v)}:{code_of(v)}\n".encode())
                continue
            if engine and public and not isinstance(v, (type, types.ModuleType)):
                # every public attribute of an engine module, with its contents (a dict of methods, the
                # free algebra's dimensions, a set of leaves, a flag, a bracket object)
                h.update(f"{name}.{attr}={_content(v, _DEPTH, seen)}\n".encode())
                continue
            if not (isinstance(v, _WATCHED) or (isinstance(v, _CONSTANTS) and type(v) is not bool and public)):
                continue            # caches, flags and other state the engine changes as it runs
            if isinstance(v, types.ModuleType) and v.__name__ == f"{name}.{attr}" and _excluded(v.__name__):
                continue            # a submodule no verdict depends on, imported later under its own name
            h.update(f"{name}.{attr}={id(v)}:{code_of(v)}\n".encode())
            if isinstance(v, type) and getattr(v, "__module__", None) == name:
                for k, w in list(vars(v).items()):
                    if isinstance(w, _CODE):
                        h.update(f"{name}.{attr}.{k}={id(w)}:{code_of(w)}\n".encode())
                    elif engine and not k.startswith("_"):
                        h.update(f"{name}.{attr}.{k}={_content(w, _DEPTH, seen)}\n".encode())
    def module(name: str) -> Any:
        return sys.modules.get(name) if objects is None else objects.get(name, sys.modules.get(name))

    for name, attr in _REGISTRIES:
        reg = getattr(module(name), attr, None)
        if isinstance(reg, dict):
            for k, v in list(reg.items()):
                h.update(f"{name}.{attr}[{k!r}]={id(v)}\n".encode())
    for name, cls in _LIBRARY_CLASSES:
        for k, w in list(vars(getattr(module(name), cls, object)).items()):
            h.update(f"{name}.{cls}.{k}={id(w)}\n".encode())
    # the encoder json.dumps uses (an instance: a method set on it is no change of its class; stop 85's h4)
    encoder = getattr(module("json"), "_default_encoder", None)
    h.update(f"json._default_encoder={id(encoder)}:{sorted((k, id(w)) for k, w in vars(encoder).items())}\n".encode()
             if encoder is not None else b"")
    ops = getattr(getattr(module("stiefelsym.ir.evaluate"), "Evaluator", None), "_ops", {})
    for k, v in list(ops.items()):
        h.update(f"_ops[{k!r}]={id(v)}:{code_of(v)}\n".encode())
    return h.hexdigest()


def import_engine() -> list[str]:
    """Import every module a verdict depends on (and those they import on first use); their names, the
    package's own first."""
    names = ["stiefelsym"] + _verdict_modules()
    for name in names:
        importlib.import_module(name)
    for name in names:              # modules imported on first use: imported now (see stiefelsym._lazy)
        for attr, v in list(vars(sys.modules[name]).items()):
            if type(v).__name__ == "_LazyModule":
                getattr(v, "__name__", None)
    return names


def seal() -> None:
    """Record the engine's fingerprint (once per process; before the first user claims file runs)."""
    if sealed():
        return
    names = import_engine()
    for name in names:              # memos a claims file could write into are switched off (e.g. free.mat)
        hook = vars(sys.modules[name]).get("_on_seal")
        if isinstance(hook, types.FunctionType):
            hook()
    for name in _LIBRARY_SUBMODULES:
        importlib.import_module(name)
    modules = names + [m for m in _LIBRARIES if m in sys.modules]
    objects = {name: sys.modules.get(name) for name in modules}
    submodules = frozenset((name, attr) for name in modules if not name.startswith("stiefelsym")
                           for attr, v in list(vars(objects[name]).items()) if isinstance(v, types.ModuleType))
    _STATE["print"] = _fingerprint(modules, objects, submodules)
    _STATE.update(modules=modules, objects=objects, submodules=submodules, hooks=_hooks())


def verify(when: str) -> None:
    """Raise :class:`EngineChanged` when the engine is not what it was when sealed."""
    if not sealed():
        return
    if _fingerprint(_STATE["modules"], _STATE["objects"], _STATE["submodules"]) != _STATE["print"]:
        if _hooks() != _STATE.get("hooks"):
            raise EngineChanged(f"the engine was changed by claim code ({when}): a trace, profile or garbage-collection "
                                "hook was installed since the first claims file was loaded into this process (by the "
                                "file's code, or by a debugger or profiler started since: start it before loading the "
                                "file); no verdict is given")
        raise EngineChanged(f"the engine was changed by claim code ({when}): a claims file may use the public "
                            "API, not replace engine functions, steps, constants, backends or their data, nor install "
                            "trace, profile or garbage-collection hooks; no verdict is given")


def refuse_registration(what: str) -> None:
    """Registries take no entry once sealed (claims files may not add engine steps or constants)."""
    if sealed():
        raise EngineChanged(f"{what} is registered by the engine's own modules, not by a claims file")
