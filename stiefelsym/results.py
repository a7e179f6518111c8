"""Result records: one per (claim, size, method).  Renderers read these only."""
from __future__ import annotations

import decimal
import hashlib
import json
import math
import os
import re
import tempfile
from dataclasses import MISSING, asdict, dataclass, field, fields, is_dataclass, replace
from pathlib import Path
from typing import Any, Callable, Iterable

from stiefelsym.latex import one_line

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


def short_value(text: str, limit: int = 60, where: str = "exact with --format json") -> str:
    """A witness's value for one line: a long exact rational as its magnitude, with its digits counted
    (the exact value is in the record: --format json, or results.json of --report-dir); anything else clipped."""
    m = _RATIONAL.fullmatch(text.strip())
    if len(text) <= limit or m is None:
        return _clip(text, limit)
    sign, num, den = m.group(1), m.group(2), m.group(3) or "1"
    with decimal.localcontext() as ctx:
        ctx.prec = 6
        approx = f"{decimal.Decimal(sign + num) / decimal.Decimal(den):.4E}".replace("E+", "e").replace("E", "e")
    digits = f"{len(num)} digits" if den == "1" else f"{len(num)}/{len(den)} digits"
    return f"{approx} (a rational of {digits}; {where})"


_RATIONAL = re.compile(r"(-?)(\d+)(?:/(\d+))?")


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
    #: with the erratum, the claim's place of the misprint in the paper ("the proof of Theorem 7.1"), when that is not
    #: the statement its labels name; empty otherwise (and in a record written before the field existed)
    place: str = ""
    #: with the erratum, the slips of the paper its text reports in passing (the claim's; empty otherwise)
    slips: list[str] = field(default_factory=list)
    #: for the dimension-free method: LaTeX derivations (residual, rules, normal form)
    derivation: list[str] = field(default_factory=list)
    #: for the dimension-free method: the cofactor certificates (JSON; see stiefelsym.certificate_check)
    certificate_data: dict[str, Any] | None = None
    #: the digest of the claim's graph (at this size, or with symbolic sizes) the verdict is about
    digest: str = ""
    #: of a correction's record: what it changes in the claim's graph, in the paper's notation (one
    #: dict per change: where, old, new and their LaTeX old_tex, new_tex; see stiefelsym.ir.notation)
    change: list[dict[str, str]] = field(default_factory=list)
    #: the claim's outputs as traced (the graph ``digest`` names, read back in the paper's notation): one
    #: [name, Unicode, LaTeX] per output; what every method evaluated, whatever the claim's code says it is
    #: (``stiefelsym check`` compares it with the graph it traces again).  Empty where the claim does not trace
    traced: list[list[str]] = field(default_factory=list)
    #: the claim's expectation of its residuals ("holds": they vanish; "nonzero": they do not vanish identically)
    #: and its realization of T*V: part of what the verdict is about, bound to the claim like its words
    expect: str = "holds"
    realization: str = "standard"
    #: of a claim of a claims file that has the id of a catalog claim (and replaced it in the run): the record is the
    #: file's claim, not the paper's statement of that id, and the reports file it under its claims file.  Written
    #: only when true (a record of the catalog, or of a claim of a file with an id of its own, has no such key)
    shadows: bool = False

    @property
    def size(self) -> str:
        return "all n, r" if self.n is None else f"({self.n},{self.r})"

    def line(self, limit: int = REASON_LIMIT) -> str:
        """One greppable line for the terminal: a failure with its witness in short, an
        undecided, inconclusive or error verdict with its reason in short."""
        tag = "" if self.expected else "  UNEXPECTED"
        var = f" [{self.variant}]" if self.variant else ""
        p = self.false_pass_bound
        # p = 0: the residual has degree 0 in the random parameters (at (1,1), say, where P = 0 and V(1, 1) is
        # two points, both sampled): its points decide it, nothing is left to chance
        bound = "" if p is None else " p=0 (degree 0 in the random parameters)" if p == 0 else f" p<={p:.1e}"
        reason = self.reason(limit)
        msg = self.message or ""
        if not reason and msg.startswith("exact: ") and "is above this claim's symbolic budget" not in msg:
            # auto ran the exact method first, and its time is in the record's: say why it went on
            reason = _clip("after exact: " + " ".join(msg[len("exact: "):].split("; ", 1)[0].split()), limit)
        seed = f", seed {self.seed}" if self.seed is not None else ", no randomness"
        # a dimension-free proof of a claim stated at one r says so after its verdict ("proved for every n at
        # r = 1"); the size field keeps its one form for every dimension-free run
        scope = free_scope(self) if self.n is None and self.verdict == "proved" else "all n, r"
        scope = f" for {scope}" if scope != "all n, r" else ""
        # (a record read back from results.json has no time: reports keep no timings)
        took = "no time recorded" if self.seconds is None else f"{self.seconds:.2f}s"
        return (f"{self.claim}{var} {self.size} {self.method}: {self.verdict}{scope}{bound}"
                f" ({took}{seed}){tag}" + (f" -- {reason}" if reason else ""))

    def reason(self, limit: int | None = REASON_LIMIT) -> str:
        """Why the verdict, in one line (at most ``limit`` characters; None: all of it):
        for ``fails`` the witness (entry = value, or the rank or count mismatch), for
        ``undecided``, ``inconclusive`` and ``error`` the message; empty otherwise."""
        if self.verdict == "fails":
            w = self.witness or {}
            if w.get("entry") is not None and w.get("value") is not None:
                text = f"witness {w['entry']} = {short_value(str(w['value']))}"
                if self.method in ("float", "ball") and w.get("field") == "rational":
                    # (the float point's own residual, in the message, is another number at another point)
                    text += " at an exact rational point"
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
    # stiefelsym.reports.notebook, which renders with the report's code (this module sits below the report)

    def to_json(self) -> dict[str, Any]:
        """The record as JSON data: a deep copy of every field but the certificates, which are JSON data
        already (lists, dicts, strings, numbers, booleans; the bulk of a dimension-free pass) and are
        handed out as they are, to be read, not changed."""
        d = asdict(replace(self, certificate_data=None))
        d["certificate_data"] = self.certificate_data
        if not self.shadows:
            del d["shadows"]
        return d

    @classmethod
    def from_json(cls, d: dict[str, Any]) -> "Result":
        d = dict(d)
        d["checks"] = [CheckOutcome(**c) for c in d.get("checks", [])]
        return cls(**d)


#: the attribute (not a field: never in a record, results.json or a report) by which a record copied from another
#: run of the same graph (a graph without r, run once per n: :func:`stiefelsym.run.runner._run_shared`) says which,
#: as (n, r) of that record: the run log lists the seconds of the run once, at the record it was made for, and at
#: each copy the record it was copied from
COPY_OF = "_copy_of"


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

    # summary() and the Jupyter displays are installed by stiefelsym.reports.notebook


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


def canonical_json(data: Any) -> str:
    """The canonical JSON text of ``data``: keys sorted, no spaces, ASCII (what two records' fields are compared
    by, and what a shared certificate's key digests)."""
    return json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=True)


def certificate_key(data: Any) -> str:
    """The key of a certificate in a results file's table of shared certificates: the SHA-256 of its
    canonical JSON (:func:`canonical_json`)."""
    return hashlib.sha256(canonical_json(data).encode("ascii")).hexdigest()


def _share_certificates(records: list[dict[str, Any]]) -> dict[str, Any]:
    """Replace a certificate carried by several records (a family's dimension-free proof, specialised at each
    size of the family) by the reference ``{"shared": key}`` in each of them, and return the table
    {key: certificate} that holds it once.  A certificate of one record stays in its record."""
    keys: list[str | None] = []
    seen: dict[int, str] = {}
    count: dict[str, int] = {}
    for d in records:
        data = d["certificate_data"]
        if data is None:
            keys.append(None)
            continue
        key = seen.get(id(data))
        if key is None:
            key = seen[id(data)] = certificate_key(data)
        keys.append(key)
        count[key] = count.get(key, 0) + 1
    table: dict[str, Any] = {}
    for d, key in zip(records, keys):
        if key is not None and count[key] > 1:
            table.setdefault(key, d["certificate_data"])
            d["certificate_data"] = {SHARED: key}
    return table


#: the one key of a record's reference to a certificate of the file's table "certificates"
SHARED = "shared"


def resolve_shared_certificates(payload: dict[str, Any]) -> None:
    """Put back, in a parsed results file, each record's certificate that the file holds once in its table
    "certificates" (:func:`dump_results`), and drop the table.  ValueError, in one line, for a table that
    is not one, a certificate whose key is not its digest, a reference to no certificate of the table, or a
    certificate of the table no record refers to."""
    table = payload.pop("certificates", None)
    records = payload.get("results")
    if table is None or not isinstance(records, list):
        table = {}
    if not isinstance(table, dict):
        raise ValueError(f"its table of shared certificates is a JSON {json_kind(table)}, not an object")
    for key, data in table.items():
        if not isinstance(data, dict) or certificate_key(data) != key:
            raise ValueError(f"the shared certificate {key[:16]} is not the one its key names (the key is the "
                             "SHA-256 of the certificate's canonical JSON)")
    used = set()
    for i, d in enumerate(records if isinstance(records, list) else []):
        data = d.get("certificate_data") if isinstance(d, dict) else None
        if isinstance(data, dict) and SHARED in data:
            key = data[SHARED]
            if len(data) != 1 or not isinstance(key, str) or key not in table:
                raise ValueError(f"result {i + 1} refers to a shared certificate the file does not hold "
                                 f"({_short_repr(key)})")
            d["certificate_data"] = table[key]
            used.add(key)
    if set(table) - used:
        raise ValueError(f"{len(set(table) - used)} shared certificate(s) no result refers to")


def dump_results(results: Iterable[Result], meta: dict[str, Any]) -> str:
    """The results file: ``json.dumps(payload, indent=1, default=str)`` byte for byte (tests/test_report.py
    compares them), written by :func:`_indented`, which encodes strings and numbers with the json module's
    own C functions and leaves out the deep copy of :meth:`Result.to_json` (the encoder only reads).  A
    certificate that several records carry is written once, in the table "certificates" after the results
    (:func:`_share_certificates`); :func:`load_results` puts it back in each record."""
    records = [_record(r) for r in results]
    table = _share_certificates(records)
    payload: dict[str, Any] = {"schema": SCHEMA_VERSION, "meta": meta, "results": records}
    if table:
        payload["certificates"] = table
    out: list[str] = []
    _indented(payload, "\n", out)
    out.append("\n")
    return "".join(out)


def _record(r: Result) -> dict[str, Any]:
    """The fields of a record as to_json gives them, without copying (only to be encoded)."""
    d = {f: getattr(r, f) for f in _FIELDS if f != "shadows" or r.shadows}
    d["checks"] = [asdict(c) for c in r.checks]
    return d


_FIELDS: tuple[str, ...] = tuple(f.name for f in fields(Result))
_ENCODE_STRING = json.encoder.encode_basestring_ascii       # what json.dumps uses (ensure_ascii)


def _float_text(x: float) -> str:
    if x != x:
        return "NaN"
    if x == math.inf:
        return "Infinity"
    if x == -math.inf:
        return "-Infinity"
    return float.__repr__(x)


def _scalar_text(o: Any) -> str | None:
    """The json text of a string, a number, a boolean or None (json.dumps's tests, in its order); None for
    anything else."""
    if isinstance(o, str):
        return _ENCODE_STRING(o)
    if o is None:
        return "null"
    if o is True:
        return "true"
    if o is False:
        return "false"
    if isinstance(o, int):
        return int.__repr__(o)
    if isinstance(o, float):
        return _float_text(o)
    return None


def _key_text(k: Any) -> str:
    if isinstance(k, str):
        return _ENCODE_STRING(k)
    if isinstance(k, float):
        return _ENCODE_STRING(_float_text(k))
    if k is True:
        return '"true"'
    if k is False:
        return '"false"'
    if k is None:
        return '"null"'
    if isinstance(k, int):
        return _ENCODE_STRING(int.__repr__(k))
    raise TypeError(f"keys must be str, int, float, bool or None, not {k.__class__.__name__}")


def _indented(o: Any, newline: str, out: list[str]) -> None:
    """Append json.dumps(o, indent=1, default=str)'s text of ``o`` at the indentation ``newline`` to ``out``."""
    text = _scalar_text(o)
    if text is not None:
        out.append(text)
    elif isinstance(o, (list, tuple)):
        if not o:
            out.append("[]")
            return
        inner = newline + " "
        sep = "," + inner
        out.append("[" + inner)
        first = True
        for x in o:
            if not first:
                out.append(sep)
            first = False
            text = _scalar_text(x)
            if text is not None:
                out.append(text)
            else:
                _indented(x, inner, out)
        out.append(newline + "]")
    elif isinstance(o, dict):
        if not o:
            out.append("{}")
            return
        inner = newline + " "
        sep = "," + inner
        out.append("{" + inner)
        first = True
        for k, v in o.items():
            if not first:
                out.append(sep)
            first = False
            out.append(_key_text(k) + ": ")
            text = _scalar_text(v)
            if text is not None:
                out.append(text)
            else:
                _indented(v, inner, out)
        out.append(newline + "}")
    elif is_dataclass(o) and not isinstance(o, type):
        _indented(asdict(o), newline, out)      # what to_json's asdict makes of it
    else:
        out.append(_ENCODE_STRING(str(o)))      # default=str


def _is_int(x: Any) -> bool:
    return type(x) is int


def record_problems(d: Any) -> list[str]:
    """What is malformed in one record of a results file, field by field (the fields that name the run: its
    claim, size, method, verdict, variant and seed), before anything reads them; [] for a well-formed
    record.  A value of the right type can still be the wrong one: that is `stiefelsym check`'s to find."""
    if not isinstance(d, dict):
        return ["it is not an object"]
    out = []
    for key in ("claim", "method", "verdict"):
        if key in d and type(d[key]) is not str:
            out.append(f"{key} is a {type(d[key]).__name__}, not a string")
    n, r = d.get("n"), d.get("r")
    if (n is None) != (r is None):
        out.append("one of n, r is null and the other not")
    elif n is not None and r is not None and not (_is_int(n) and _is_int(r) and 1 <= r <= n):
        out.append(f"the size (n, r) = ({n!r}, {r!r}) is not integers 1 <= r <= n")
    if d.get("variant") is not None and type(d["variant"]) is not str:
        out.append(f"variant is a {type(d['variant']).__name__}, not a string")
    if d.get("seed") is not None and not _is_int(d["seed"]):
        out.append(f"seed is a {type(d['seed']).__name__}, not an integer")
    for key, ok, what in _FIELD_TYPES:
        if key in d and not ok(d[key]):
            out.append(f"{key} is {_short_repr(d[key], 40)}, not {what}")
    return out


def _number(x: Any) -> bool:
    """A finite number within float's range (an int beyond it is refused by comparison: math.isfinite would raise
    OverflowError converting it, and so would every rendering of it as a float)."""
    return (type(x) is float and math.isfinite(x)) or (type(x) is int and -1e308 <= x <= 1e308)


def _strings(x: Any) -> bool:
    return type(x) is list and all(type(y) is str for y in x)


def _check_outcome(x: Any) -> bool:
    return (type(x) is dict and {"name", "status"} <= x.keys() <= {"name", "status", "detail", "degree"}
            and type(x["name"]) is str and type(x["status"]) is str and type(x.get("detail", "")) is str
            and (x.get("degree") is None or (_is_int(x["degree"]) and x["degree"] >= 0)))


#: the other fields of a record, each with the type a run writes (what renders it and `check` compare)
_FIELD_TYPES: tuple[tuple[str, Callable[[Any], bool], str], ...] = (
    ("paper", _strings, "a list of labels"),
    ("section", lambda x: type(x) is str, "a string"), ("kind", lambda x: type(x) is str, "a string"),
    ("title", lambda x: type(x) is str, "a string"), ("statement", lambda x: type(x) is str, "a string"),
    ("expected", lambda x: type(x) is bool, "true or false"),
    ("seconds", lambda x: x is None or (_number(x) and x >= 0), "a number of seconds or null"),
    ("reductions", _strings, "a list of strings"), ("derivation", _strings, "a list of strings"),
    ("certificate", lambda x: type(x) is str, "a string"), ("rerun", lambda x: type(x) is str, "a string"),
    ("message", lambda x: type(x) is str, "a string"), ("erratum", lambda x: type(x) is str, "a string"),
    ("place", lambda x: type(x) is str, "a string"), ("slips", _strings, "a list of strings"),
    ("shadows", lambda x: type(x) is bool, "true or false"),
    ("digest", lambda x: type(x) is str, "a string"),
    ("residual", lambda x: x is None or type(x) is str, "a string or null"),
    ("false_pass_bound", lambda x: x is None or (_number(x) and 0 <= x <= 1), "a probability or null"),
    ("checks", lambda x: type(x) is list and all(map(_check_outcome, x)), "a list of checks"),
    ("witness", lambda x: x is None or type(x) is dict, "an object or null"),
    ("certificate_data", lambda x: x is None or type(x) is dict, "an object or null"),
    ("change", lambda x: type(x) is list and all(type(c) is dict and all(type(v) is str or _is_int(v)
                                                                         for v in c.values()) for c in x),
     "a list of changes"),
    ("traced", lambda x: type(x) is list and all(type(t) is list and len(t) == 3 and all(type(v) is str for v in t)
                                                 for t in x), "a list of [name, text, LaTeX] outputs"),
)


def meta_problems(meta: Any, methods: Iterable[str], hard_cases: Iterable[str], max_n: int) -> list[str]:
    """What is malformed in a results file's ``meta`` (the command the file is the run of), field by field:
    its methods, sizes, --max-n (at most ``max_n``: every size up to it is listed when the file is
    checked), hard case and claims files."""
    if not isinstance(meta, dict):
        return ["meta is not an object"]
    out = []
    # the words a report prints of its run (its title, where and when it ran, the versions, the sections' names):
    # one line of text each, as verify writes them (a line break would begin a table or a heading of the report's)
    for key in ("title", "date", "platform", "commit"):
        if meta.get(key) is not None and not (meta[key] == "" or one_line(meta[key], 300)):
            out.append(f"meta {key} {_short_repr(meta[key])} is not one line of text")
    for key in ("versions", "sections"):
        v = meta.get(key)
        if v is not None and not (isinstance(v, dict) and all(one_line(k, 300) and (x == "" or one_line(x, 300)) for k, x in v.items())):
            out.append(f"meta {key} {_short_repr(v)} is not a mapping of names to one line of text each")
    ms = meta.get("methods")
    if ms is not None and not (isinstance(ms, list) and all(type(m) is str and m in methods for m in ms)):
        out.append(f"meta methods {_short_repr(ms)} is not a list of methods ({', '.join(methods)})")
    sizes = meta.get("sizes")
    if sizes is not None and not (isinstance(sizes, list) and all(_size_text(t) for t in sizes)):
        out.append(f"meta sizes {_short_repr(sizes)} is not a list of sizes \"n,r\" with 1 <= r <= n")
    mx = meta.get("max_n")
    if mx is not None and not (_is_int(mx) and 1 <= mx <= max_n):
        out.append(f"meta max_n {_short_repr(mx)} is not an integer from 1 to {max_n}")
    hard = meta.get("hard")
    if hard is not None and not (type(hard) is str and hard in hard_cases):
        out.append(f"meta hard {_short_repr(hard)} is not a hard case ({', '.join(hard_cases)})")
    files = meta.get("claims_files")
    if files is not None and not (isinstance(files, list) and all(type(f) is str for f in files)):
        out.append(f"meta claims_files {_short_repr(files)} is not a list of paths")
    if not out and meta.get("command") is not None:
        out += _command_problems(meta)
    return out


#: the options of the command ``verify`` records in a results file's meta (cli._command), each with one value
COMMAND_OPTIONS = ("--claims", "--timeout", "--budget", "--memory", "--max-n", "--size", "--method", "--seed",
                   "--report-dir")
#: the budgets of a run: (option, meta key, default); the command names those that are not the defaults
COMMAND_BUDGETS = (("--timeout", "timeout", 300.0), ("--budget", "budget", 3600.0), ("--memory", "memory_gib", 4.0))


def _command_problems(meta: dict) -> list[str]:
    """Where the command a results file records (which a report prints, and whose claim ids say what it selected)
    is not the one its fields describe: the claims files, sizes, --max-n, methods, seed and budgets from which the
    planned runs are listed and the records were made."""
    import shlex
    cmd = meta.get("command")
    try:
        words = shlex.split(cmd) if type(cmd) is str else None
    except ValueError:
        words = None
    if not words or words[:2] != ["stiefelsym", "verify"]:
        return [f"meta command {_short_repr(cmd)} is not a `stiefelsym verify` command"]
    rest = words[2:]
    while rest and not rest[0].startswith("-"):
        rest = rest[1:]
    given: dict[str, list[str]] = {}
    if len(rest) % 2:
        return [f"meta command {_short_repr(cmd)}: an option without its value"]
    for option, value in zip(rest[::2], rest[1::2]):
        if option not in COMMAND_OPTIONS:
            return [f"meta command {_short_repr(cmd)}: the option {option!r} is not one verify records"]
        given.setdefault(option, []).append(value)
    mx = meta.get("max_n")
    want = {"--claims": list(meta.get("claims_files") or []), "--size": list(meta.get("sizes") or []),
            "--method": list(meta.get("methods") or []), "--max-n": [str(mx)] if mx is not None else [],
            "--seed": [str(meta.get("seed"))] if meta.get("seed") is not None else given.get("--seed", [])}
    for flag, key, default in COMMAND_BUDGETS:
        setting = meta.get(key)
        want[flag] = [f"{setting:g}"] if isinstance(setting, (int, float)) and setting != default else []
    out = [f"meta command {_short_repr(cmd)} gives {option} {given.get(option, [])} where the meta says {values}"
           for option, values in want.items() if [str(v) for v in given.get(option, [])] != [str(v) for v in values]]
    return out


def _size_text(t: Any) -> bool:
    if type(t) is not str or t.count(",") != 1:
        return False
    a, b = t.split(",")
    return a.strip().isdigit() and b.strip().isdigit() and 1 <= int(b) <= int(a)


def _short_repr(x: Any, limit: int = 60) -> str:
    text = repr(x)
    return text if len(text) <= limit else text[:limit] + "..."


#: the most digits of an integer in a file the engine reads (a results file, a mutation analysis): Python's
#: own guard against the quadratic conversion of long decimal texts, which the engine lifts for the texts it
#: writes itself (stiefelsym/__init__.py) and keeps for what it reads from disk
FILE_INT_DIGITS = 4300


def _file_int(text: str) -> int:
    if len(text) > FILE_INT_DIGITS + 1:
        raise ValueError(f"an integer of {len(text)} digits (a file the engine reads has integers of at most "
                         f"{FILE_INT_DIGITS} digits)")
    return int(text)


def parse_json(text: str) -> Any:
    """json.loads of a file's text, with integers of at most FILE_INT_DIGITS digits (ValueError otherwise)."""
    return json.loads(text, parse_int=_file_int)


def json_kind(value: Any) -> str:
    """What JSON calls the kind of a parsed value (object, array, string, number, boolean, null)."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "boolean"
    if isinstance(value, (int, float)):
        return "number"
    if isinstance(value, dict):
        return "object"
    if isinstance(value, list):
        return "array"
    return "string" if isinstance(value, str) else type(value).__name__


def load_results(path: str | Path) -> tuple[dict[str, Any], list[Result]]:
    """The meta data and the results of a results file (``stiefelsym verify --format json``,
    reports/results.json); ValueError, in one line, for anything else."""
    payload = parse_json(Path(path).read_text(encoding="utf-8"))
    if not isinstance(payload, dict):
        raise ValueError(f"its top level is a JSON {json_kind(payload)}, not an object with a list of results (a file "
                         "written by `stiefelsym verify`, --format json or reports/results.json, is one)")
    if not isinstance(payload.get("results"), list):
        raise ValueError("no list of results at its top level (a file written by `stiefelsym verify`, "
                         "--format json or reports/results.json, has one)")
    if payload.get("schema", SCHEMA_VERSION) != SCHEMA_VERSION:
        raise ValueError(f"schema {payload.get('schema')!r}, this version reads schema {SCHEMA_VERSION}")
    resolve_shared_certificates(payload)
    names = {f.name for f in fields(Result)}
    required = {f.name for f in fields(Result) if f.default is MISSING and f.default_factory is MISSING}
    out = []
    for i, d in enumerate(payload["results"]):
        if not isinstance(d, dict) or not required <= d.keys():
            missing = sorted(required - d.keys()) if isinstance(d, dict) else ["(not an object)"]
            raise ValueError(f"result {i + 1} lacks {', '.join(missing[:4])}{', ...' if len(missing) > 4 else ''}")
        problems = record_problems(d)
        if problems:
            raise ValueError(f"result {i + 1}: {'; '.join(problems)}")
        out.append(Result.from_json({k: v for k, v in d.items() if k in names}))
    meta = payload.get("meta", {})
    return meta if isinstance(meta, dict) else {}, out


def free_scope(r: Result) -> str:
    """What a dimension-free proof covers: every n and r, or every n at the one r its claim is stated
    for (a proof that used E₁E₁ᵀ + … = I_r or XXᵀ = I_n says so in its certificate line), or every n at
    each r of a union of them (a certificate of cases, e.g. "every n at r = 1 and at r = n")."""
    text = r.certificate or ""
    union = re.match(r"cofactor certificates of cases \(for (every n at r = \w+(?: and at r = \w+)+),", text)
    if union:
        return union.group(1)
    for scope in ("every n at r = 1", "every n at r = 2", "every n at r = n"):
        if f"(for {scope}," in text:
            return scope
    return "all n, r"
