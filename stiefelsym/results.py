"""Result records: one per (claim, size, method).  Renderers read these only."""
from __future__ import annotations

import json
import os
import tempfile
from dataclasses import MISSING, asdict, dataclass, field, fields, replace
from pathlib import Path
from typing import Any, Iterable

VERDICTS = ("proved", "checked", "numeric", "fails", "inconclusive", "undecided", "error")
#: verdicts that establish a claim (proof grade: proved, checked)
PASSING = ("proved", "checked", "numeric")
SCHEMA_VERSION = 1


#: characters of a verdict's reason shown on its terminal line
REASON_LIMIT = 120


def _clip(text: str, limit: int | None) -> str:
    if limit is None or len(text) <= limit:
        return text
    return text[: max(limit - 3, 0)] + "..."


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
    #: for the dimension-free method: the cofactor certificates (JSON; see stiefelsym.certificate_check)
    certificate_data: dict[str, Any] | None = None
    #: the digest of the claim's graph (at this size, or with symbolic sizes) the verdict is about
    digest: str = ""
    #: of a correction's record: what it changes in the claim's graph, in the paper's notation (one
    #: dict per change: where, old, new and their LaTeX old_tex, new_tex; see stiefelsym.ir.notation)
    change: list[dict[str, str]] = field(default_factory=list)

    @property
    def size(self) -> str:
        return "all n, r" if self.n is None else f"({self.n},{self.r})"

    def line(self, limit: int = REASON_LIMIT) -> str:
        """One greppable line for the terminal: a failure with its witness in short, an
        undecided, inconclusive or error verdict with its reason in short."""
        tag = "" if self.expected else "  UNEXPECTED"
        var = f" [{self.variant}]" if self.variant else ""
        bound = f" p<={self.false_pass_bound:.1e}" if self.false_pass_bound is not None else ""
        reason = self.reason(limit)
        seed = f", seed {self.seed}" if self.seed is not None else ", no randomness"
        return (f"{self.claim}{var} {self.size} {self.method}: {self.verdict}{bound}"
                f" ({self.seconds:.2f}s{seed}){tag}" + (f" -- {reason}" if reason else ""))

    def reason(self, limit: int | None = REASON_LIMIT) -> str:
        """Why the verdict, in one line (at most ``limit`` characters; None: all of it):
        for ``fails`` the witness (entry = value, or the rank or count mismatch), for
        ``undecided``, ``inconclusive`` and ``error`` the message; empty otherwise."""
        if self.verdict == "fails":
            w = self.witness or {}
            if w.get("entry") is not None and w.get("value") is not None:
                text = f"witness {w['entry']} = {_clip(str(w['value']), 60)}"
            elif self.residual:
                text = f"residual {self.residual}"
            else:
                text = self.certificate or self.message
        elif self.verdict in ("undecided", "inconclusive", "error"):
            text = self.message or self.certificate
        else:
            return ""
        return _clip(" ".join(str(text).split()), limit)

    @property
    def passed(self) -> bool:
        """Whether the verdict is the one the claim expects (what the exit status counts)."""
        return self.expected

    # residual_sympy() and the Jupyter displays (_repr_markdown_, _repr_latex_) are installed by
    # stiefelsym.notebook, which renders with the report's code (this module sits below the report)

    def to_json(self) -> dict[str, Any]:
        """The record as JSON data: a deep copy of every field but the certificates, which are JSON data
        already (lists, dicts, strings, numbers, booleans; the bulk of a dimension-free pass) and are
        handed out as they are, to be read, not changed."""
        d = asdict(replace(self, certificate_data=None))
        d["certificate_data"] = self.certificate_data
        return d

    @classmethod
    def from_json(cls, d: dict[str, Any]) -> "Result":
        d = dict(d)
        d["checks"] = [CheckOutcome(**c) for c in d.get("checks", [])]
        return cls(**d)


class ResultList(list[Result]):
    """The results of :func:`stiefelsym.verify`, in the order of the plan: a list, with a summary,
    and displays for Jupyter (a summary table and one table per claim)."""

    @property
    def ok(self) -> bool:
        """Every verdict as expected (what ``stiefelsym verify`` reports as exit status 0)."""
        return all(r.expected for r in self)

    @property
    def unexpected(self) -> list[Result]:
        return [r for r in self if not r.expected]

    # summary() and the Jupyter displays are installed by stiefelsym.notebook


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def write_atomic(path: Path, text: str) -> None:
    """Write a file so that an interruption never leaves it half-written.

    The file gets the permissions of any newly created file (0o666 less the umask),
    not the owner-only ones of the temporary file it is renamed from."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        try:
            os.fchmod(fd, 0o666 & ~_umask())
        except (AttributeError, OSError):   # no fchmod (Windows), or a file system without modes
            pass
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
    """The meta data and the results of a results file (``stiefelsym verify --format json``,
    reports/results.json); ValueError, in one line, for anything else."""
    payload = json.loads(Path(path).read_text(encoding="utf-8"))
    if not isinstance(payload, dict) or not isinstance(payload.get("results"), list):
        raise ValueError("no list of results at its top level (a file written by `stiefelsym verify`, "
                         "--format json or reports/results.json, has one)")
    if payload.get("schema", SCHEMA_VERSION) != SCHEMA_VERSION:
        raise ValueError(f"schema {payload.get('schema')!r}, this version reads schema {SCHEMA_VERSION}")
    names = {f.name for f in fields(Result)}
    required = {f.name for f in fields(Result) if f.default is MISSING and f.default_factory is MISSING}
    out = []
    for i, d in enumerate(payload["results"]):
        if not isinstance(d, dict) or not required <= d.keys():
            missing = sorted(required - d.keys()) if isinstance(d, dict) else ["(not an object)"]
            raise ValueError(f"result {i + 1} lacks {', '.join(missing[:4])}{', ...' if len(missing) > 4 else ''}")
        out.append(Result.from_json({k: v for k, v in d.items() if k in names}))
    meta = payload.get("meta", {})
    return meta if isinstance(meta, dict) else {}, out
