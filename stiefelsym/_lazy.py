"""Modules imported on first use (start-up time: `stiefelsym list` loads no number library).

``flint = lazy("flint", globals())`` binds a stand-in; the first attribute read imports the module
and puts it in the importing module's namespace under the same name, so later reads cost
nothing."""
from __future__ import annotations

import importlib
from typing import Any


class _LazyModule:
    __slots__ = ("_name", "_alias", "_namespace")

    def __init__(self, name: str, namespace: dict[str, Any], alias: str) -> None:
        self._name, self._namespace, self._alias = name, namespace, alias

    def __getattr__(self, attr: str) -> Any:
        mod = importlib.import_module(self._name)
        self._namespace[self._alias] = mod
        return getattr(mod, attr)

    def __repr__(self) -> str:
        return f"<module {self._name!r}, imported on first use>"


def lazy(name: str, namespace: dict[str, Any], alias: str | None = None) -> Any:
    """A stand-in for ``import name as alias`` in ``namespace`` (a module's globals())."""
    return _LazyModule(name, namespace, alias or name.rsplit(".", 1)[-1])


_OPAQUE: Any = None


def symengine_opaque() -> Any:
    """What the engine's matrices and number types give symengine as their conversion: an empty
    symengine matrix, so that ``symengine_expr * x`` (and +, −, /) leaves the operation to x's
    reflected operator at once instead of trying every SymPy class first (≈0.4 ms a product)."""
    global _OPAQUE
    if _OPAQUE is None:
        import symengine
        _OPAQUE = symengine.DenseMatrix(0, 0, [])
    return _OPAQUE
