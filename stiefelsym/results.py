"""Result records: one per (claim, size, method).  Renderers read these only."""
from __future__ import annotations

import json
import os
import tempfile
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Iterable

VERDICTS = ("proved", "checked", "numeric", "fails", "inconclusive", "undecided", "error")
#: verdicts that establish a claim (proof grade: proved, checked)
PASSING = ("proved", "checked", "numeric")
SCHEMA_VERSION = 1


@dataclass
class CheckOutcome:
    """What happened to one named check of a claim."""

    name: str
    status: str            # "zero", "nonzero", "rank", "count", "degenerate"
    detail: str = ""
    degree: int | None = None


@dataclass
class Result:
    claim: str
    paper: list[str]
    section: str
    kind: str
    title: str
    statement: str
    n: int | None
    r: int | None
    method: str
    verdict: str
    expected: bool
    seconds: float
    seed: int | None
    reductions: list[str] = field(default_factory=list)
    certificate: str = ""
    residual: str | None = None
    false_pass_bound: float | None = None
    checks: list[CheckOutcome] = field(default_factory=list)
    witness: dict[str, Any] | None = None
    rerun: str = ""
    message: str = ""
    variant: str | None = None
    #: the catalog's explanation when the printed statement is a documented erratum at this size
    erratum: str = ""
    #: for the dimension-free method: LaTeX derivations (residual, rules, normal form)
    derivation: list[str] = field(default_factory=list)

    @property
    def size(self) -> str:
        return "all n, r" if self.n is None else f"({self.n},{self.r})"

    def line(self) -> str:
        """One greppable line for the terminal."""
        tag = "" if self.expected else "  UNEXPECTED"
        var = f" [{self.variant}]" if self.variant else ""
        bound = f" p<={self.false_pass_bound:.1e}" if self.false_pass_bound is not None else ""
        return (f"{self.claim}{var} {self.size} {self.method}: {self.verdict}{bound}"
                f" ({self.seconds:.2f}s, seed {self.seed}){tag}")

    def to_json(self) -> dict[str, Any]:
        d = asdict(self)
        return d

    @classmethod
    def from_json(cls, d: dict[str, Any]) -> "Result":
        d = dict(d)
        d["checks"] = [CheckOutcome(**c) for c in d.get("checks", [])]
        return cls(**d)


def write_atomic(path: Path, text: str) -> None:
    """Write a file so that an interruption never leaves it half-written."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def dump_results(results: Iterable[Result], meta: dict[str, Any]) -> str:
    payload = {"schema": SCHEMA_VERSION, "meta": meta, "results": [r.to_json() for r in results]}
    return json.dumps(payload, indent=1, sort_keys=False, default=str) + "\n"


def load_results(path: str | Path) -> tuple[dict[str, Any], list[Result]]:
    payload = json.loads(Path(path).read_text(encoding="utf-8"))
    return payload.get("meta", {}), [Result.from_json(d) for d in payload["results"]]
