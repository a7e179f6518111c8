"""Sites: where in the claim's source each node of a graph was built (metadata of a trace, never of a verdict).

A trace asked for sites (:func:`.trace.trace` with ``sites=True``) records, for each node it makes, the
source span of the claim expression that made it: the innermost frame of claim code on the stack (a
frame whose file is not the engine's) and, from that frame's code, the position of the instruction it
is executing (``code.co_positions()`` at ``frame.f_lasti``: line, end line, column, end column).  Frames
of the engine in between are passed over, so a node an API helper builds for a claim expression (the
products and the difference of ``comm(a, b)``) has the site of that expression, and a Hamiltonian or a
helper function of the claim's has the sites of its own lines.  A node made with no claim frame below
the trace (the claim's output, the generic elements and residuals of an Inverse statement, every node
of a replayed graph) has no site, but for the node of a Rank or Count statement: the statement keeps the
site of the expression that made it (:func:`statement_site`), and its node, made when the claim has
returned, takes it.  A node is made once (nodes are shared when equal), at its first site.

Sites are kept out of the graph's digest, its lines and its pickled state: two traces of one claim
with and without sites give the same graph (the same digest), and no method reads them.  The mutation
analysis groups the nodes of a claim's graphs by site (:func:`stiefelsym.ir.mutants.site_mutants`): one
change at one site is made at every node built there, in every size's graph, as an edit of the source
at that place would.
"""
from __future__ import annotations

import linecache
import os
import sys
from dataclasses import dataclass
from types import CodeType, FrameType
from typing import Any

_ENGINE = os.path.realpath(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
#: the catalog, when it is installed inside the engine's folder (a claim module of it is claim code)
_CATALOG = os.path.join(_ENGINE, "proofs")


@dataclass(frozen=True, order=True)
class SourceSite:
    """A span of source: file, first and last line, first and end column (0-based, as Python gives them),
    and the qualified name of the function it is in."""

    file: str
    line: int
    end_line: int
    col: int
    end_col: int
    function: str

    def text(self, width: int = 70) -> str:
        """The source of the span (its first line when it spans several), cut to ``width``."""
        src = linecache.getline(self.file, self.line)
        if not src:
            return ""
        end = self.end_col if self.end_line == self.line else len(src.rstrip("\n"))
        out = src[self.col:end].strip()
        return out if len(out) <= width else out[: width - 1] + "…"

    def where(self) -> str:
        """``line L of f()`` in the claim's file (its base name)."""
        return f"{os.path.basename(self.file)}:{self.line} in {self.function}()"


_IS_ENGINE: dict[str, bool] = {}
_POSITIONS: dict[CodeType, list] = {}
#: the frames that stop the walk: the trace's own entry (below it no claim code runs)
STOP: set[CodeType] = set()
#: how many traces that record sites are running (a statement a claim makes, Rank or Count, then keeps the
#: site of the expression that made it: its node is made after the claim returned, with no claim frame)
RECORDING = [0]


def _engine_file(name: str) -> bool:
    hit = _IS_ENGINE.get(name)
    if hit is None:
        p = os.path.realpath(name) if os.path.isabs(name) else name
        hit = (p == _ENGINE or p.startswith(_ENGINE + os.sep)) and not p.startswith(_CATALOG + os.sep)
        _IS_ENGINE[name] = hit
    return hit


def claim_site(frame: FrameType | None) -> SourceSite | None:
    """The site of the claim expression being executed in ``frame`` or below it on the stack (the caller
    side): the innermost frame of claim code, or None when the walk meets the trace's entry first."""
    f: Any = frame
    while f is not None:
        code = f.f_code
        if code in STOP:
            return None
        name = code.co_filename
        if not _engine_file(name):
            pos = _POSITIONS.get(code)
            if pos is None:
                pos = _POSITIONS[code] = list(code.co_positions())
            k = f.f_lasti // 2
            line, end_line, col, end_col = pos[k] if 0 <= k < len(pos) else (f.f_lineno, f.f_lineno, 0, 0)
            line = line if line is not None else f.f_lineno
            return SourceSite(name, line, end_line if end_line is not None else line,
                              col if col is not None else 0, end_col if end_col is not None else 0,
                              code.co_qualname)
        f = f.f_back
    return None


def here() -> SourceSite | None:
    """The site of the caller's caller's claim expression (for the tracer's node makers)."""
    return claim_site(sys._getframe(2))


def statement_site(obj: Any) -> None:
    """Keep on a statement being made (a Rank or a Count; called from its ``__post_init__``) the site of the
    claim expression that makes it, while a trace records sites: the node of the statement, made when the
    claim has returned, takes it (so its expected rank or count is changed at that site)."""
    if RECORDING[0]:
        object.__setattr__(obj, "_site", claim_site(sys._getframe(3)))   # past __post_init__ and __init__
