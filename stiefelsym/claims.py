"""The claim model and the registry.

A claim is a function of a :class:`~stiefelsym.scene.Scene` that returns named
checks: residuals (matrices or scalars that must vanish on T*V), :class:`Rank`
statements (a rank or dimension the paper asserts) or :class:`Count`
statements (an integer formula against the value the paper prints).  The
engine decides how to check them.
"""
from __future__ import annotations

import dataclasses
import functools

import hashlib
import importlib
import importlib.util
import inspect
import re
import _signal
import signal
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Literal, Mapping

from stiefelsym.latex import one_line
from stiefelsym.ir.statements import Count as Count, Inverse as Inverse, Rank as Rank, RightInverse as RightInverse  # the statements a claim returns (re-exported)


#: seconds a claim's own metadata code (size conditions, erratum sizes) may take per call,
#: and a claims file's import
METADATA_SECONDS = 10.0
IMPORT_SECONDS = 120.0


class Expired(Exception):
    """A deadline expired (:class:`deadline`): what a fallback that catches ``Exception`` must let through, so
    that no memoized answer is made of a computation the deadline stopped."""


class ClaimTimeout(Expired, ValueError):
    """A claim's own code (its file's import, a size condition, its erratum sizes) did not finish."""


#: after a deadline has expired, its alarm comes again every so many seconds until its block is left
REFIRE_SECONDS = 0.05


class deadline:
    """Interrupt Python code that runs past ``seconds`` with ``timeout(message)`` (main thread;
    nests with an outer deadline; ``None``: no deadline).

    The alarm repeats every REFIRE_SECONDS until the block is left: a timeout that a handler on the way
    swallows (an ``except Exception`` that falls back to something else, a weakref callback or a
    ``__del__``, whose exceptions Python ignores) is raised again in the code the deadline limits, so no
    handler can turn the deadline off.  While the deadline is being armed or the block left (in
    :meth:`__exit__`, which disarms it) the alarm raises nothing."""

    def __init__(self, seconds: float | None, what: str,
                 timeout: Callable[[str], BaseException] = ClaimTimeout, cpu: bool = False) -> None:
        self.seconds, self.what, self.timeout = seconds, what, timeout
        #: ``cpu``: the seconds are the process's CPU time (ITIMER_PROF), not the wall clock's: a limit of an engine
        #: computation that decides which route a record takes is then the computation's, not the machine's load
        #: (never for code of a claims file, which may wait without computing)
        self.cpu = cpu
        self.armed = False
        self.raised: list[BaseException] = []

    def __enter__(self) -> "deadline":
        if self.seconds is None or not hasattr(signal, "SIGALRM") \
                or threading.current_thread() is not threading.main_thread():
            return self
        self.timer, self.signum, self.clock = (signal.ITIMER_PROF, signal.SIGPROF, time.process_time) if self.cpu \
            else (signal.ITIMER_REAL, signal.SIGALRM, time.monotonic)
        self.outer = signal.getitimer(self.timer)
        left = self.outer[0]
        self.limit = min(self.seconds, left) if left > 0 else self.seconds
        self.old_hook = sys.unraisablehook
        sys.unraisablehook = self._swallowed
        # the C module's signal(): the same handlers, without the enum conversion of the signal
        # module's wrapper (a few microseconds, on every exact run)
        self.old = _signal.signal(self.signum, self._expire)
        self.armed = True
        self.t0 = self.clock()
        signal.setitimer(self.timer, self.limit, REFIRE_SECONDS)
        return self

    def _expire(self, signum: int, frame: Any) -> None:
        if frame is not None and frame.f_code in _OWN:
            return      # entering (the block, not yet begun, gets the next alarm) or leaving (disarmed there)
        self.raised.append(self.timeout(f"{self.what} did not finish within {self.limit:.0f} s"
                                        f"{' of CPU time' if self.cpu else ''}"))
        raise self.raised[-1]

    def _swallowed(self, info: Any) -> None:
        # the alarm came while Python ran code whose exceptions it ignores: not printed as "Exception
        # ignored in ...", and raised again at the next alarm, in the code the deadline limits
        if not (self.raised and info.exc_value is self.raised[-1]):
            self.old_hook(info)

    def __exit__(self, *exc: Any) -> Literal[False]:
        if not self.armed:
            return False
        self.armed = False
        signal.setitimer(self.timer, 0)
        _signal.signal(self.signum, self.old)
        sys.unraisablehook = self.old_hook
        left, every = self.outer
        if left > 0:
            signal.setitimer(self.timer, max(left - (self.clock() - self.t0), 1e-3), every)
        return False


_OWN = (deadline.__enter__.__code__, deadline.__exit__.__code__)


KINDS = ("id", "lax", "pb", "dim", "not", "geo")
#: the natures of the place of the paper an erratum fails through (``@claim(nature=...)``), in the order the reports
#: count them: "formula", a misprint in a printed formula (a sign, an inverse, a letter or a term, the formula meant
#: being the one the paper's own derivation gives); "size", a misprinted size, index range or group of a size (Iₙ for
#: I₂ᵣ, i = 1, …, n for i = 1, …, r, GL(n) for GL(r)); "range", a statement that fails at some of the sizes it is made
#: for (a bound on n and r, or exceptional sizes, missed); "statement", a wrong statement (a condition, a count or an
#: identification that is false as made, whatever the size); "literal", a statement that fails only when read
#: literally, where a hypothesis is tacit or a formula schematic
NATURES = ("formula", "size", "range", "statement", "literal")
#: the realizations of T*V a claim may be stated on (the keys of stiefelsym.scene.REALIZATIONS, a test holds them
#: equal: the scene is not imported here)
REALIZATION_NAMES = ("standard", "metric")


Checks = Mapping[str, Any]


@dataclass(frozen=True)
class Size:
    n: int
    r: int

    def __str__(self) -> str:
        return f"n={self.n},r={self.r}"


@dataclass(frozen=True)
class SizeSpec:
    """Which (n, r) a claim is stated for, and the default sizes the catalog verifies."""

    sizes: tuple[Size, ...]
    n_min: int = 1
    r_min: int = 1
    r_max: int | None = None
    where: Callable[[int, int], bool] | None = None
    condition: str = ""
    #: the largest n the claim is stated for (None: no upper bound)
    n_max: int | None = None
    #: stated at r = n only (T*SO(n) = T*V(n, n)), declared rather than read from ``where``
    r_is_n: bool = False
    #: stated at these r only, a union of one-r families: ints (r = 1, r = 2) and "n" (r = n), declared
    #: rather than read from ``where`` (the dimension-free method proves each family on its own)
    r_in: tuple = ()

    def admits(self, n: int, r: int) -> bool:
        if not (1 <= r <= n) or n < self.n_min or r < self.r_min or (self.r_is_n and r != n):
            return False
        if self.r_in and not any(r == (n if v == "n" else v) for v in self.r_in):
            return False
        if self.n_max is not None and n > self.n_max:
            return False
        if self.r_max is not None and r > self.r_max:
            return False
        if self.where is None:
            return True
        with deadline(METADATA_SECONDS, "the claim's size condition (where)"):
            return bool(self.where(n, r))

    def describe(self) -> str:
        """The declared sizes in words, e.g. "2 <= n <= 5, r <= 3 (n >= 2r)"."""
        lo = max(self.n_min, 1)
        if self.n_max is not None:
            parts = [f"n <= {self.n_max}" if lo <= 1 else f"{lo} <= n <= {self.n_max}"]
        else:
            parts = [f"n >= {lo}"] if lo > 1 else []
        if self.r_min > 1 and self.r_max is not None:
            parts.append(f"{self.r_min} <= r <= {self.r_max}")
        elif self.r_min > 1:
            parts.append(f"r >= {self.r_min}")
        elif self.r_max is not None:
            parts.append(f"r <= {self.r_max}")
        if self.r_is_n:
            parts.append("r = n")
        if self.r_in:
            parts.append(" or ".join(f"r = {v}" for v in self.r_in))
        text = ", ".join(parts) or "every n >= r >= 1"
        if self.condition and " ".join(self.condition.split()) not in (text, *parts):
            text += f" ({self.condition})"
        elif self.where is not None:
            text += " (with a further condition on n, r)"
        return text

    def __iter__(self):
        return iter(self.sizes)

    def __len__(self) -> int:
        return len(self.sizes)


def statement_state(claim: "Claim") -> tuple:
    """What a claim states, by identity: its fields, the fields of its statement of sizes and its corrections.  A
    claim whose own code changes it while it runs (``object.__setattr__`` on the frozen claim or its frozen
    statement of sizes) is seen by a comparison before and after (:func:`stiefelsym.run.runner._guarded`)."""
    own = vars(claim)
    return (tuple(own), tuple(map(id, own.values())), sizes_state(claim.sizes), tuple(map(id, claim.corrections)))


def sizes_state(spec: Any) -> tuple:
    """A statement of sizes by identity: the object and its fields (what :func:`statement_state` compares, and
    what the families of sizes read from a statement are remembered by)."""
    fields = getattr(spec, "__dict__", None)
    return (id(spec), tuple(fields), tuple(map(id, fields.values()))) if isinstance(fields, dict) else (id(spec),)


def admissible(n_max: int = 5, *, n_min: int = 1, r_min: int = 1, r_max: int | None = None,
               where: Callable[[int, int], bool] | None = None, condition: str = "",
               stated_n_max: int | None = None, r_is_n: bool = False, r_in: tuple = ()) -> SizeSpec:
    """The sizes a claim is stated for: 1 <= r_min <= r <= min(n, r_max), n >= n_min, filtered by
    ``where``, and n <= stated_n_max if given (None: every n).  The catalog verifies them by
    default up to n = n_max; an explicit --size may go further, never outside the statement.

    ``condition`` states the restriction in words for the report (e.g. "n >= 2r"); ``r_is_n`` declares
    the statement to be about r = n only (which the dimension-free method may then use); ``r_in`` declares
    it to be about a union of such r: (1, "n") for r = 1 or r = n (each proved with its own hypotheses)."""
    r_in = tuple(r_in)
    if any(v != "n" and (type(v) is not int or v < 1) for v in r_in) or len(set(r_in)) != len(r_in):
        raise ValueError(f"r_in lists distinct values of r: ints >= 1 and 'n' (r = n), not {r_in!r}")
    if stated_n_max is not None and stated_n_max < n_max:
        n_max = stated_n_max
    out = []
    spec = SizeSpec((), n_min, r_min, r_max, where, condition, stated_n_max, r_is_n, r_in)
    for n in range(max(n_min, 1), n_max + 1):
        for r in range(1, n + 1):
            if spec.admits(n, r):
                out.append(Size(n, r))
    return SizeSpec(tuple(out), n_min, r_min, r_max, where, condition, stated_n_max, r_is_n, r_in)


@dataclass
class Correction:
    """A candidate correction of a printed formula: what changes, and the corrected claim."""

    description: str
    func: Callable
    changes: int = 1
    #: what the corrected statement expects, when the correction changes it (a printed "does not
    #: hold" that does hold: expect="holds"); None keeps the claim's
    expect: str | None = None
    #: (n, largest r) pairs beyond the claim's exact_max_n at which ``auto`` tries the symbolic method
    #: first for the corrected statement (besides the claim's own): a corrected formula may be proved
    #: fast where the printed one, which fails, is not worth a symbolic run (a witness refutes it)
    exact_max_r: tuple[tuple[int, int], ...] = ()
    #: (n, largest n - r) pairs at which ``auto`` tries the symbolic method first for the corrected
    #: statement (besides the claim's own exact_corank)
    exact_corank: tuple[tuple[int, int], ...] = ()
    #: the block matrix of the paper whose blocks the change of the graph is made in, with its display
    #: ("𝓐*_man(λ) in (9) §4"): the change names its blocks as that matrix's, not as the check's
    blocks_of: str = ""


#: the longest place of a misprint (a phrase, not a sentence: the erratum text says what is wrong)
PLACE_CHARS = 160
#: a page reference: the paper's pages depend on its build, its numbers of theorems and equations do not
_PAGE = re.compile(r"\b(?:pp?\.\s*\d|pages?\b)", re.I)


def _place_problem(place: Any) -> str:
    """Why ``place`` is not a place of a misprint ("" if it is one): a phrase of one line of at most PLACE_CHARS
    characters that follows "In " (it does not begin with "in" itself), ends without a full stop and names no page."""
    if not isinstance(place, str) or not one_line(place, PLACE_CHARS) or place != " ".join(place.split()):
        return (f"a place is a phrase of one line of at most {PLACE_CHARS} characters, without leading, trailing or "
                "repeated spaces")
    if "$" in place:
        return "a place is plain words, without $ (the report sets its scripts and symbols)"
    if re.match(r"in\b", place, re.I):
        return 'the report writes "In <place> (involves: ...)": a place does not begin with "in" itself'
    if place.endswith("."):
        return "a place is a phrase, without a full stop at its end"
    if _PAGE.search(place):
        return ("a place names no page (the paper's pages depend on its build): name the theorem, equation, proof "
                "or paragraph")
    return ""


#: what a claim id may be (it starts every verdict line and names the claim in every report)
_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._+-]{0,99}")
_SECTION = re.compile(r"(?:[A-Za-z0-9][A-Za-z0-9.-]{0,19})?")



@dataclass(frozen=True)
class Claim:
    """A registered claim; frozen, so that nothing (a claims file included) rewrites what was
    registered: its statement, its expected verdict, its erratum, its review."""

    id: str
    paper: tuple[str, ...]
    kind: str
    section: str
    func: Callable
    sizes: SizeSpec
    statement: str = ""
    title: str = ""
    realization: str = "standard"
    #: "holds": the printed statement is true; "nonzero": the paper says this does NOT vanish;
    #: "fails": a known erratum (the printed formula is wrong; a correction is registered)
    expect: str = "holds"
    #: largest n for the symbolic exact method (beyond: randomized exact only)
    exact_max_n: int = 7
    #: beyond exact_max_n, (n, largest r) pairs at which the symbolic method is still tried first
    exact_max_r: tuple[tuple[int, int], ...] = ()
    #: (n, largest n - r) pairs at which the symbolic method is still tried first (r close to n: the
    #: right-reduced Cayley chart, X = I at r = n)
    exact_corank: tuple[tuple[int, int], ...] = ()
    #: the largest r at which the dimension-free method is tried on the family of sizes (n, r), every n, for a
    #: claim whose graph needs r as a number (a loop over r): beyond the symbolic budget its proof there is the
    #: exact method's proof at each size of that family (0: never)
    free_max_r: int = 0
    corrections: list[Correction] = field(default_factory=list)
    source: str = ""
    #: sizes at which the printed statement is known to fail (a documented erratum)
    fails_at: Callable[[int, int], bool] | None = None
    erratum: str = ""
    #: where in the paper the misprint of an erratum sits, when that is not the statement its labels name: a short
    #: phrase such as "the proof of Theorem 7.1" or "the paragraph before Theorem 8.6" (the report says "In the proof
    #: of Theorem 7.1 (involves: ...)"); empty: the labelled statements themselves
    place: str = ""
    #: of an erratum, further slips of the paper its text reports in passing (a wrong subscript, a wrong reference),
    #: each a phrase; the headline counts them apart from the errors that make statements fail
    slips: tuple[str, ...] = ()
    #: why the equivariance reduction is valid although the claim reads coordinates (stated in reports)
    equivariance: str = ""
    #: of a statement the paper makes in words, not as a formula (a size, "diffeomorphic to SO(n)"), the printed
    #: words the claim's display is the tool's encoding of (det X = 1, an equation between sizes), in the ASCII
    #: scripts of the reports' words; the report heads the display as that encoding; empty: a formula as printed
    encodes: str = ""
    #: the statements of the paper the claim checks that have no ``\label`` of their own and none inside them, by
    #: the names the paper prints ("Theorem 4.3"); a statement with an equation's label inside it is named through
    #: that label (:func:`stiefelsym.paperref.printed`)
    unlabelled: tuple[str, ...] = ()
    #: of an erratum, the nature of the place of the paper it fails through, one of :data:`NATURES` ("formula": a
    #: misprint in a printed formula, "size", "range", "statement", "literal"); empty: not said (a claim that is
    #: no erratum, or one of a claims file that does not say)
    nature: str = ""

    @property
    def reviewed(self) -> bool:
        """Whether this object was registered by the paper's catalog (whose stated reasons are reviewed with the
        code), or made from such a claim by the engine (:meth:`corrected`): a stated equivariance reason of any
        other claim is printed but not relied on.  Not a field: no argument, copy (``dataclasses.replace``) or
        pickle of a claim gives it; the catalog's loading does, by identity (:func:`_mark_reviewed`)."""
        return bool(reviewed_functions(self))

    def expects_failure(self, n: int | None, r: int | None) -> bool:
        if self.expect == "fails":
            return True
        if self.fails_at is None or n is None:
            return False
        with deadline(METADATA_SECONDS, "the claim's erratum sizes (fails_at)"):
            return bool(self.fails_at(n, r if r is not None else n))

    def exact_at(self, n: int, r: int) -> bool:
        """Whether ``auto`` tries the symbolic method first at (n, r): n <= exact_max_n, or r at most
        the largest r that exact_max_r gives at this n, or n - r at most what exact_corank gives at this n."""
        return (n <= self.exact_max_n or r <= dict(self.exact_max_r).get(n, 0)
                or n - r <= dict(self.exact_corank).get(n, -1))

    def exact_budget_text(self) -> str:
        """The symbolic budget in words, e.g. ``n <= 5; r <= 5 at n = 6, 7``."""
        by_r: dict[int, list[int]] = {}
        for n, r in self.exact_max_r:
            by_r.setdefault(r, []).append(n)
        by_k: dict[int, list[int]] = {}
        for n, k in self.exact_corank:
            by_k.setdefault(k, []).append(n)
        corank = [("r = n" if k == 0 else f"n - r <= {k}") + f" at n = {', '.join(map(str, ns))}"
                  for k, ns in by_k.items()]
        return "; ".join([f"n <= {self.exact_max_n}"] + [f"r <= {r} at n = {', '.join(map(str, ns))}"
                                                          for r, ns in by_r.items()] + corank)

    def __post_init__(self) -> None:
        if not isinstance(self.id, str) or not _ID.fullmatch(self.id):
            raise ValueError(f"claim id {self.id!r}: an id is 1 to 100 letters, digits and . _ + - (starting with a "
                             "letter or digit; no spaces or line breaks: it names the claim on every output line)")
        if self.kind not in KINDS:
            raise ValueError(f"claim {self.id}: unknown kind {self.kind!r} (one of {', '.join(KINDS)})")
        # the words that head a claim's lines in the reports: one line of text each (a line break or a control
        # character would begin a table, a heading or an HTML block of the report's own)
        if not isinstance(self.section, str) or not _SECTION.fullmatch(self.section):
            raise ValueError(f"claim {self.id}: section {self.section!r}: a section is empty or 1 to 20 letters, digits "
                             "and . - (the paper's 5, 7, A1, A2, ...)")
        for label in self.paper:
            if not one_line(label, 60) or "$" in label:
                raise ValueError(f"claim {self.id}: paper label {label!r}: a label is 1 to 60 characters of one line, "
                                 "without $ or a control character (the paper's cond_XP, LA1, ...)")
        if self.expect not in ("holds", "nonzero", "fails"):
            raise ValueError(f"claim {self.id}: expect must be 'holds', 'nonzero' or 'fails'")
        if self.realization not in REALIZATION_NAMES:
            raise ValueError(f"claim {self.id}: realization {self.realization!r} is not one of "
                             f"{', '.join(REALIZATION_NAMES)} (the constraints of T*V the claim is stated on)")
        if type(self.exact_max_n) is not int or self.exact_max_n < 0:
            raise ValueError(f"claim {self.id}: exact_max_n is the largest n (an int >= 0) at which auto tries the "
                             f"symbolic method first; not {self.exact_max_n!r}")
        if not self.sizes:
            raise ValueError(f"claim {self.id}: no sizes")
        for pair in self.exact_max_r:
            if (not isinstance(pair, tuple) or len(pair) != 2 or any(type(x) is not int for x in pair)
                    or pair[0] <= self.exact_max_n or not 1 <= pair[1] <= pair[0]):
                raise ValueError(f"claim {self.id}: exact_max_r gives the largest r (1 <= r <= n) at sizes n above "
                                 f"exact_max_n = {self.exact_max_n}, as {{n: r}}; {pair!r} is not one")
        for pair in self.exact_corank:
            if (not isinstance(pair, tuple) or len(pair) != 2 or any(type(x) is not int for x in pair)
                    or not 0 <= pair[1] < pair[0]):
                raise ValueError(f"claim {self.id}: exact_corank gives the largest n - r (0 <= n - r < n) at which "
                                 f"the symbolic method is tried first, as {{n: n - r}}; {pair!r} is not one")
        if type(self.free_max_r) is not int or self.free_max_r < 0:
            raise ValueError(f"claim {self.id}: free_max_r is the largest r (an int >= 0) at which the "
                             f"dimension-free method is tried on the family of sizes r = k; not {self.free_max_r!r}")
        if self.fails_at is not None and (not callable(self.fails_at) or isinstance(self.fails_at, type)):
            raise ValueError(f"claim {self.id}: fails_at is a function of the size, (n, r) -> bool, True where the "
                             f"statement fails as printed (e.g. fails_at=lambda n, r: r >= 2); not {self.fails_at!r}")
        if (self.expect == "fails" or self.fails_at is not None) and not self.erratum.strip():
            raise ValueError(f"claim {self.id}: a statement expected to fail must be a documented erratum "
                             "(say what is wrong with erratum=...)")
        if self.place:
            place_problem = _place_problem(self.place)
            if place_problem:
                raise ValueError(f"claim {self.id}: place {self.place!r}: {place_problem}")
            if not self.erratum.strip():
                raise ValueError(f"claim {self.id}: place= says where the misprint of an erratum sits; a claim "
                                 "without erratum= has none")
        if self.slips:
            if not self.erratum.strip():
                raise ValueError(f"claim {self.id}: slips= are reported in passing by an erratum's text; a claim "
                                 "without erratum= has none")
            for slip in self.slips:
                problem = _place_problem(slip)
                if problem:
                    raise ValueError(f"claim {self.id}: slip {slip!r}: {problem.replace('a place', 'a slip')}")
        if self.nature:
            if self.nature not in NATURES:
                raise ValueError(f"claim {self.id}: nature {self.nature!r} is not one of {', '.join(NATURES)} (the "
                                 "kind of place of the paper an erratum fails through)")
            if not self.erratum.strip():
                raise ValueError(f"claim {self.id}: nature= says what kind of place of the paper an erratum fails "
                                 "through; a claim without erratum= has none")

    def correction(self, description: str, changes: int = 1, expect: str | None = None,
                   exact_max_r: dict[int, int] | None = None, exact_corank: dict[int, int] | None = None,
                   blocks_of: str = ""):
        """Decorator registering a candidate correction of this claim (errata search); ``expect``
        changes what the corrected statement asserts ("holds" or "nonzero"); ``exact_max_r``
        ({n: largest r}, n above the claim's exact_max_n) and ``exact_corank`` ({n: largest n - r}) widen
        the symbolic budget of the corrected statement alone; ``blocks_of`` names the block matrix (and its
        display) whose blocks the change is made in."""
        if not isinstance(blocks_of, str) or (blocks_of and not one_line(blocks_of, PLACE_CHARS)):
            raise ValueError(f"claim {self.id}: blocks_of is a phrase of one line of at most {PLACE_CHARS} characters")
        if expect not in (None, "holds", "nonzero"):
            raise ValueError(f"a correction expects 'holds' or 'nonzero', not {expect!r}")
        if type(changes) is not int or changes < 0:
            raise ValueError(f"claim {self.id}: correction {description!r}: changes is the number of changes it makes "
                             f"to the printed formula (an int >= 0), not {changes!r}")
        # the description names the correction in every record, report and `check` (the variant of a record):
        # two corrections of one description would be one record's variant, and either one's verdict the other's
        if not one_line(description, 10**4) or not description.strip():
            raise ValueError(f"claim {self.id}: a correction is described by a non-empty string of one line")
        if description != " ".join(description.split()):
            # spaces a report does not show (LaTeX drops them) would make two descriptions that read alike
            raise ValueError(f"claim {self.id}: correction {description!r}: a description has no space at either end "
                             "and single spaces between its words")
        if any(c.description == description for c in self.corrections):
            raise ValueError(f"claim {self.id}: two corrections described {description!r} (the description names "
                             "the correction in the records)")
        pairs, coranks = _pairs(exact_max_r), _pairs(exact_corank, "exact_corank")
        dataclasses.replace(self, exact_max_r=_widened(self.exact_max_r, pairs),   # validated as the claim's
                            exact_corank=_widened(self.exact_corank, coranks))

        def deco(fn):
            self.corrections.append(Correction(description, fn, changes, expect, pairs, coranks, blocks_of))
            return fn
        return deco

    def corrected(self, k: int) -> "Claim":
        """The claim as its k-th correction states it (same id; its function is passed apart): its
        expected verdict, and its symbolic budget widened by the correction's own."""
        corr = self.corrections[k]
        changes: dict[str, Any] = {}
        if corr.expect is not None and corr.expect != self.expect:
            changes["expect"] = corr.expect
        if corr.exact_max_r:
            changes["exact_max_r"] = _widened(self.exact_max_r, corr.exact_max_r)
        if corr.exact_corank:
            changes["exact_corank"] = _widened(self.exact_corank, corr.exact_corank)
        if not changes:
            return self
        out = dataclasses.replace(self, **changes)
        reviewed = reviewed_functions(self)
        if any(corr.func is f for f in reviewed):
            _mark_reviewed(out, reviewed)   # a correction registered with the catalog's claim: reviewed with it
        return out


#: the claims the reviewed catalog registered (and the engine made from them): id(claim) -> (a weak reference to
#: it, the functions its stated reason of equivariance was reviewed with: its own and those of the corrections
#: registered with it when the catalog was loaded; a correction added later, by anyone, is not among them)
_REVIEWED: dict[int, tuple[Any, tuple[Callable, ...]]] = {}


#: id(function) -> (the function, what it computed with when it was first registered as reviewed,
#: :func:`_reach`): a function whose code, defaults, closure or the globals it reads (its helpers', in turn) were
#: changed since is not the function that was reviewed
_PRINTS: dict[int, tuple[Callable, tuple]] = {}


def _code_names(code: Any) -> set[str]:
    """The global and attribute names a code object and the code nested in it (lambdas, comprehensions,
    inner functions) read."""
    import types
    names, stack = set(), [code]
    while stack:
        c = stack.pop()
        names.update(c.co_names)
        stack += [k for k in c.co_consts if isinstance(k, types.CodeType)]
    return names


#: values whose identity is their content (immutable, and not containers of anything mutable)
_IMMUTABLE = (int, float, complex, str, bytes, bool, type(None))


def _reach(func: Callable) -> tuple:
    """What ``func`` computes with, as slots to compare later: the identity of its code, defaults and keyword
    defaults, of each value in its closure cells and of each global (or builtin) it reads, and the contents of
    the mutable values among them, followed into the functions, classes and modules of its own module and of the
    catalog (their code and globals in turn).  The engine's own modules are the seal's (:mod:`stiefelsym.ir.seal`).
    Each slot is (holder, key, identity, contents): a dict and a name, a cell, or a function and "code"."""
    import builtins
    import types
    from stiefelsym.ir.seal import _code_of, _content
    home = getattr(func, "__module__", None) or ""
    mine = lambda m: isinstance(m, str) and (m == home or m == CATALOG or m.startswith(CATALOG + "."))  # noqa: E731
    slots: list[tuple] = []
    seen: set[int] = set()
    stack: list[tuple[Any, frozenset]] = [(func, frozenset())]

    def value(holder: Any, key: Any, v: Any, names: frozenset) -> None:
        slots.append((holder, key, id(v), None if type(v) in _IMMUTABLE or callable(v) else _content(v, 2)))
        stack.append((v, names))

    while stack:
        v, names = stack.pop()
        if isinstance(v, (staticmethod, classmethod)):
            v = v.__func__
        if id(v) in seen and not isinstance(v, types.ModuleType):
            continue
        seen.add(id(v))
        if isinstance(v, types.FunctionType) and (v is func or mine(v.__module__)):
            slots.append((v, "code", _code_of(v), None))
            own = frozenset(_code_names(v.__code__))
            for i, d in enumerate((v.__defaults__ or ()) + tuple((v.__kwdefaults__ or {}).values())):
                slots.append((v, f"default {i}", id(d), None if type(d) in _IMMUTABLE else _content(d, 2)))
            for cell in v.__closure__ or ():
                try:
                    value(cell, "cell", cell.cell_contents, own)
                except ValueError:          # an empty cell
                    slots.append((cell, "cell", None, None))
            g = v.__globals__
            slots.append((g, "__builtins__", id(g["__builtins__"]) if "__builtins__" in g else None, None))
            for name in sorted(own):
                if name in g:
                    value(g, name, g[name], own)
                elif hasattr(builtins, name):
                    # a builtin: absent from the module (a global of that name would shadow it), and itself
                    slots.append((g, name, None, None))
                    slots.append((vars(builtins), name, id(getattr(builtins, name)), None))
        elif isinstance(v, types.ModuleType) and mine(v.__name__):
            attrs = vars(v)
            for name in sorted(names):
                if name in attrs:
                    value(attrs, name, attrs[name], names)
        elif isinstance(v, type) and mine(v.__module__):
            for name, m in sorted(vars(v).items()):
                if isinstance(m, (types.FunctionType, staticmethod, classmethod)):
                    value(vars(v), name, m, frozenset())
    return tuple(slots)


def _intact(slots: tuple) -> bool:
    """Whether every slot of :func:`_reach` still holds what it held."""
    from stiefelsym.ir.seal import _code_of, _content
    now: Any
    for holder, key, ident, contents in slots:
        if key == "code":
            now = _code_of(holder)
        elif key == "cell":
            try:
                v = holder.cell_contents
            except ValueError:
                now = v = None
            else:
                now = id(v)
        elif isinstance(key, str) and key.startswith("default "):
            i = int(key.split()[1])
            ds = (holder.__defaults__ or ()) + tuple((holder.__kwdefaults__ or {}).values())
            v = ds[i] if i < len(ds) else None
            now = id(v) if i < len(ds) else None
        else:
            v = holder.get(key, _intact)
            now = id(v) if v is not _intact else None
        if now != ident or (contents is not None and _content(v, 2) != contents):
            return False
    return True


def reviewed_functions(claim: Any) -> tuple[Callable, ...]:
    """The functions a reviewed claim's stated reason of equivariance holds for; () for a claim the catalog did
    not register (identity, not fields: a claim built, copied or unpickled with the fields of a catalog claim
    is not reviewed).  A function changed since it was registered (its code, defaults or closure swapped, or a
    global it or its helpers read rebound: :func:`_reach`) is no longer one of them."""
    hit = _REVIEWED.get(id(claim))
    if hit is None or hit[0]() is not claim:
        return ()
    from stiefelsym.ir.seal import sealed
    if sealed():
        # a claims file was imported into this process (load_claims_file), with its full powers over it: the
        # import machinery, the catalog's modules, builtins, hooks; what the catalog was reviewed as is no longer
        # certain here, so no stated reason is relied on (the CLI, stiefelsym.load and the pytest plugin import a
        # file in fresh interpreters only, and keep them)
        return ()
    return tuple(f for f in hit[1] if (p := _PRINTS.get(id(f))) is not None and p[0] is f and _intact(p[1]))


def _mark_reviewed(claim: Claim, functions: tuple[Callable, ...] | None = None) -> Claim:
    """Register ``claim`` as reviewed with ``functions`` (default: its own and its corrections' functions now).
    The catalog's loading calls it, and the engine for a claim it makes from a reviewed one (a correction's
    statement, a mutant's expectation); tests call it to stand for the catalog."""
    import weakref
    funcs = tuple(functions) if functions is not None else (claim.func,) + tuple(c.func for c in claim.corrections)
    for f in funcs:             # the print of a function is taken once, when it is first registered
        if (p := _PRINTS.get(id(f))) is None or p[0] is not f:
            _PRINTS[id(f)] = (f, _reach(f))
    key = id(claim)
    _REVIEWED[key] = (weakref.ref(claim), funcs)
    weakref.finalize(claim, _forget_reviewed, key, _REVIEWED[key][0])
    return claim


def _forget_reviewed(key: int, ref: Any) -> None:
    hit = _REVIEWED.get(key)
    if hit is not None and hit[0] is ref:
        del _REVIEWED[key]


class Registry:
    """Claims by id, in registration order."""

    def __init__(self, reviewed: bool = False) -> None:
        self._claims: dict[str, Claim] = {}
        #: claims registered here come from the reviewed catalog
        self.reviewed = reviewed
        #: the file each claim of a user's file comes from (claim id -> path), for messages and rerun commands
        self.origin: dict[str, str] = {}
        #: the claims of a user's file that have the id of a catalog claim (and replace it in a run)
        self.shadowing: set[str] = set()

    def rerun_naming_file(self, result: Any) -> None:
        """The result's rerun command with ``--claims FILE`` added, for a claim of a user's file (the command
        finds the claim there only); a result of a claim that has a catalog claim's id is marked so
        (``Result.shadows``): its identity is the file's claim's, and the reports file it under its file."""
        path = self.origin.get(result.claim)
        if path is not None and result.rerun and "--claims" not in result.rerun:
            import shlex
            result.rerun += " --claims " + shlex.quote(path)
        if path is not None and result.claim in self.shadowing:
            result.shadows = True

    def mark_shadowing(self, catalog_ids: Iterable[str]) -> set[str]:
        """Note (and return) the claims of the users' files here whose ids are among ``catalog_ids``."""
        ids = set(catalog_ids)
        self.shadowing = {cid for cid in self.origin if cid in ids}
        return self.shadowing

    def add(self, c: Claim) -> Claim:
        if c.id in self._claims:
            raise ValueError(f"duplicate claim id {c.id!r}")
        self._claims[c.id] = c
        return c

    def get(self, cid: str) -> Claim:
        try:
            return self._claims[cid]
        except KeyError:
            import difflib
            near = [k for k in self._claims if cid.lower() in k.lower()] or \
                difflib.get_close_matches(cid, list(self._claims), n=3, cutoff=0.75)
            hint = (f"; did you mean {', '.join(near[:3])}?" if near else
                    "; `stiefelsym list` shows all claims (a claim of your own file: name its file with --claims FILE)")
            raise KeyError(f"unknown claim {cid!r}{hint}") from None

    def __iter__(self):
        return iter(self._claims.values())

    def __len__(self) -> int:
        return len(self._claims)

    def __contains__(self, cid: str) -> bool:
        return cid in self._claims

    def ids(self) -> list[str]:
        return list(self._claims)


#: the registry the @claim decorator writes to while a catalog module is imported
_ACTIVE: list[Registry] = [Registry()]


def _size_spec(cid: str, sizes: Any) -> SizeSpec:
    """A claim's ``sizes=``: a :class:`SizeSpec` (``admissible(...)``), or a list of (n, r) pairs
    (or :class:`Size`), meaning exactly those sizes."""
    if sizes is None:
        return admissible()
    if isinstance(sizes, SizeSpec):
        # the sizes a run takes by default must be sizes the statement is about (stop 85's sweep M2: a spec
        # rebuilt with dataclasses.replace kept sizes its new fields exclude, and was run there)
        outside = [f"({s.n},{s.r})" for s in sizes.sizes if not sizes.admits(s.n, s.r)]
        if outside:
            raise ValueError(f"claim {cid}: its sizes list {', '.join(outside)}, which its own statement of sizes "
                             f"({sizes.describe()}) excludes")
        return sizes
    try:
        pairs = [(s.n, s.r) if isinstance(s, Size) else tuple(s) for s in sizes]
    except TypeError:
        raise TypeError(f"claim {cid}: sizes must be admissible(...) or a list of (n, r) pairs, "
                        f"not {type(sizes).__name__}") from None
    for p in pairs:
        if len(p) != 2 or any(type(v) is not int for v in p) or not 1 <= p[1] <= p[0]:
            raise ValueError(f"claim {cid}: the size {p!r} is not a pair (n, r) of ints with 1 <= r <= n")
    if not pairs:
        raise ValueError(f"claim {cid}: no sizes")
    listed = tuple(dict.fromkeys(pairs))
    allowed = frozenset(listed)
    text = ", ".join(f"({n},{r})" for n, r in listed)
    return SizeSpec(tuple(Size(n, r) for n, r in listed), n_max=max(n for n, _ in listed),
                    where=lambda n, r: (n, r) in allowed, condition=f"only {text}")


#: the default symbolic budget of ``auto`` (see :func:`claim`)
IDENTITY_EXACT_MAX_N = 7
DIM_EXACT_MAX_N = 5


def _widened(a: tuple[tuple[int, int], ...], b: tuple[tuple[int, int], ...]) -> tuple[tuple[int, int], ...]:
    """The (n, largest r) pairs of two budgets, the larger r at each n."""
    by_n = dict(a)
    for n, r in b:
        by_n[n] = max(r, by_n.get(n, 0))
    return tuple(sorted(by_n.items()))


def _pairs(by_n: dict[int, int] | None, what: str = "exact_max_r") -> tuple[tuple[int, int], ...]:
    if by_n is None:
        return ()
    if not isinstance(by_n, dict):
        raise ValueError(f"{what} is a dict {{n: {'largest r' if what == 'exact_max_r' else 'largest n - r'}}}, "
                         f"not {type(by_n).__name__}")
    return tuple(sorted((n, r) for n, r in by_n.items()))


def _section_of_labels(labels: tuple[str, ...]) -> str:
    """The paper's section of a claim stated without one, from its labels: the one section they all lie in
    (a user's claim labelled (No) is filed under §5, as the catalog's are), else ""."""
    from stiefelsym.paperref import table
    ref = table()
    secs = {ref[label]["section"] for label in labels if label in ref and ref[label].get("section")}
    return secs.pop() if len(secs) == 1 else ""


def claim(id: str, *, paper: str | Iterable[str] = (), kind: str, section: str | None = None,
          sizes: SizeSpec | Iterable[tuple[int, int] | Size] | None = None, statement: str = "", realization: str = "standard",
          expect: str = "holds", exact_max_n: int | None = None, exact_max_r: dict[int, int] | None = None,
          exact_corank: dict[int, int] | None = None, fails_at: Callable[[int, int], bool] | None = None, erratum: str = "", equivariance: str = "",
          free_max_r: int = 0, place: str = "", slips: Iterable[str] = (), encodes: str = "",
          unlabelled: Iterable[str] = (), nature: str = ""):
    """Register a claim.  The function's docstring (one sentence) goes into the report.

    ``paper``: the paper's equation labels the claim checks; a user's own claim may have none.
    ``exact_max_n``: the largest n at which ``auto`` tries the symbolic exact method first (default:
    7 for identities, whose residuals are matrix products the exact backends prove quickly; 5 for
    dimension statements, whose exact ranks are randomized beyond small sizes anyway).
    ``exact_max_r``: {n: r} for sizes n above exact_max_n at which ``auto`` still tries the symbolic
    method first, up to that r (a claim whose cost grows mainly with r).
    ``exact_corank``: {n: k}: the sizes n, r with n - r <= k at which ``auto`` still tries the
    symbolic method first (a claim that reads coordinates of R^n and nothing of R^r, whose exact chart at
    r close to n is the right-reduced Cayley chart: X = I at r = n, an (n - r) x (n - r) inverse below).
    ``free_max_r``: for a claim whose graph needs r as a number (a loop over r, such as the coefficients
    e_1, ..., e_2r of a 2r x 2r Lax matrix) but not n, the largest r at which the dimension-free method is
    tried on the family of sizes (n, r), for every n at once: beyond the symbolic budget, its proof is the
    exact method's proof at each size of the family (:mod:`stiefelsym.methods.specialise`).
    ``place``: of an erratum, where in the paper the misprint sits when that is not the statement its labels name (a
    proof, a remark, a paragraph or an unnumbered display beside a correct numbered result): a phrase such as "the
    proof of Theorem 7.1", printed as "In the proof of Theorem 7.1 (involves: <labels>)".
    ``slips``: of an erratum, phrases naming further slips of the paper that its text reports in passing ("the
    subscript I_{r+1} for I_{l+1} in (5) §8"), which make no statement fail.
    ``encodes``: where the claim's display is the tool's encoding of words the paper prints rather than a formula it
    prints (det X = 1 for "diffeomorphic to SO(n)", an equation between sizes for "the 2r × (n + r) matrix"), those
    words, in the ASCII scripts of the reports (I_n, B^{-1}); the report heads the display as their encoding.
    ``unlabelled``: the statements the claim checks that the paper prints without a label (and with no labelled
    equation inside), by their printed names ("Theorem 4.3"): the report names them beside the labels.
    ``nature``: of an erratum, the kind of place of the paper it fails through, one of :data:`NATURES`: "formula" (a
    misprint in a printed formula), "size" (a misprinted size or index range), "range" (a statement that fails at
    some of the sizes it is made for), "statement" (a wrong statement), "literal" (a statement that fails only when
    read literally); the headline of the reports counts the places of each nature."""
    if exact_max_n is None:
        exact_max_n = DIM_EXACT_MAX_N if kind == "dim" else IDENTITY_EXACT_MAX_N
    for name, value in (("statement", statement), ("erratum", erratum), ("equivariance", equivariance),
                        ("realization", realization), ("expect", expect), ("nature", nature)):
        if not isinstance(value, str):
            raise ValueError(f"claim {id!r}: {name} is a str, not {value!r}")
    if not isinstance(paper, str) and (not isinstance(paper, (tuple, list)) or any(type(x) is not str for x in paper)):
        raise ValueError(f"claim {id!r}: paper is a label (a str) or a tuple of labels, not {paper!r}")

    def deco(fn):
        labels = (paper,) if isinstance(paper, str) else tuple(paper)
        sec = section
        if sec is None:
            mod = sys.modules.get(fn.__module__)
            sec = getattr(mod, "SECTION", "") if mod else ""
        if sec == "" and labels:
            sec = _section_of_labels(labels)
        c = Claim(id=id, paper=labels, kind=kind, section=str(sec), func=fn,
                  sizes=_size_spec(id, sizes), statement=statement.strip(),
                  title=(inspect.getdoc(fn) or "").strip(), realization=realization,
                  expect=expect, exact_max_n=exact_max_n, exact_max_r=_pairs(exact_max_r),
                  exact_corank=_pairs(exact_corank, "exact_corank"), source=fn.__module__,
                  fails_at=fails_at, erratum=" ".join(erratum.split()), equivariance=" ".join(equivariance.split()),
                  place=" ".join(place.split()) if isinstance(place, str) else place,
                  slips=tuple(slips) if not isinstance(slips, str) else (slips,),
                  free_max_r=free_max_r, encodes=" ".join(encodes.split()),
                  unlabelled=(unlabelled,) if isinstance(unlabelled, str) else tuple(unlabelled), nature=nature)
        if _ACTIVE[-1].reviewed or not _catalog_source(fn):
            # a catalog module imported by a user's file (for a helper) registers its claims with the catalog's
            # loading only, not as the file's own (a function that only names a catalog module is the file's)
            _ACTIVE[-1].add(c)
        fn.claim = c
        return fn
    return deco


def _in_catalog(module: Any) -> bool:
    """Whether ``module`` (a name) is one of the paper's catalog's."""
    return isinstance(module, str) and (module == CATALOG or module.startswith(CATALOG + "."))


def _catalog_source(fn: Callable) -> bool:
    """Whether ``fn`` is a function of a catalog module as it lies in the catalog's folder on disk (its module's
    name and the file its code was compiled from)."""
    code = getattr(fn, "__code__", None)
    if not _in_catalog(getattr(fn, "__module__", None)) or code is None:
        return False
    try:
        return Path(code.co_filename).resolve().parent == _catalog_folder()
    except (OSError, ValueError):
        return False


@functools.lru_cache(maxsize=1)
def _catalog_folder() -> Path | None:
    """The folder of the catalog's modules on disk (as the package's spec names it when first asked)."""
    spec = importlib.util.find_spec(CATALOG)
    where = list(spec.submodule_search_locations or ()) if spec is not None else []
    return Path(where[0]).resolve() if where else None


class CatalogError(Exception):
    """A claims file could not be loaded."""


#: the paper's catalog: the top-level folder proofs/, installed as this package
CATALOG = "stiefelsym.proofs"
#: one loading at a time: the @claim decorator writes to the registry on top of _ACTIVE, and a
#: catalog module re-imported by one thread while another imports it would register half of it
_LOADING = threading.RLock()


def _collect(loader: Callable[[], None], reviewed: bool = False) -> Registry:
    reg = Registry(reviewed)
    with _LOADING:
        _ACTIVE.append(reg)
        try:
            loader()
        finally:
            _ACTIVE.pop()
    if reviewed:
        for c in reg:       # with the corrections registered in its module, none added later
            _mark_reviewed(c)
    return reg


def load_catalog(package: str = CATALOG) -> Registry:
    """Import every module of the paper's catalog and return its claims (safe to call from
    several threads at once: loadings are serialized, and a loading that fails returns nothing)."""
    def loader():
        if package == CATALOG:
            # the catalog as it is on disk: every module of it this process imported (a helper module such as
            # determinants, the package with its MODULES and __path__) is dropped and imported again, so that
            # nothing a caller or a claims file changed in one is registered as reviewed (a reload of MODULES
            # alone kept a helper rebound before the loading, and a module added to the package's path)
            for name in [m for m in sys.modules if _in_catalog(m)]:
                del sys.modules[name]
        pkg = importlib.import_module(package)
        for name in getattr(pkg, "MODULES", ()):
            full = f"{package}.{name}"
            if full in sys.modules:
                importlib.reload(sys.modules[full])
            else:
                importlib.import_module(full)
    return _collect(loader, reviewed=(package == CATALOG))


#: the folders of the claims files loaded in this process (each put on sys.path by :func:`load_claims_file`)
_HELPER_FOLDERS: set[str] = set()


def _refuse_shadowed_helpers(p: Path, folder: str) -> None:
    """A claims file next to a helper module of the same name as one this process already imported from another
    claims file's folder would import that one (a module is imported once per process, under its name): its claims
    would be about another helper's code.  Refused, with the way out; `stiefelsym verify --claims` and
    :func:`stiefelsym.load` import each file in an interpreter of its own and are not affected."""
    for name, mod in list(sys.modules.items()):
        where = getattr(mod, "__file__", None)
        if "." in name or not where:
            continue
        home = Path(where).resolve().parent
        if Path(where).name == "__init__.py":      # a package next to the file: its folder's folder
            home = home.parent
        if str(home) == folder or str(home) not in _HELPER_FOLDERS:
            continue
        mine = Path(folder) / f"{name}.py"
        if mine.is_file() or (Path(folder) / name / "__init__.py").is_file():
            raise CatalogError(
                f"{p}: the module {name!r} next to it ({mine if mine.is_file() else Path(folder) / name}) has the name "
                f"of a module this process imported from another claims file's folder ({where}), which an import of "
                f"{name!r} would give it: rename one of them, or load the files apart (stiefelsym.load or "
                "`stiefelsym verify --claims`, which import each file in an interpreter of its own)")


def claims_file_missing(p: Path) -> str:
    """Why ``p`` is not a claims file that can be read: missing, or there but not a regular file (a device such
    as /dev/stdin, a pipe, a socket), which is never read (a pipe's writer would decide what is imported)."""
    if p.exists() and not p.is_dir():
        return f"claims file {p} is not a regular file (a device, a pipe or a socket): give the path of a .py file"
    return f"claims file not found: {p}"


def load_claims_file(path: str | Path) -> Registry:
    """Load user claims from a Python file written against the public API.

    Whatever the file raises while it is imported (SystemExit included; not a
    Ctrl-C or SIGTERM) is a :class:`CatalogError`, and whatever it prints goes to
    standard error: standard output is left to the command's own output.  Its folder is put last on
    ``sys.path`` (if it is not there), so that it imports the helper modules next to it, as it does under
    ``stiefelsym verify --claims``.

    The file is imported into this process and runs with its full powers: the engine sees a change of its
    code or of a public attribute of its modules, contents included (the seal), and refuses a graph changed
    behind the tracer (the replay), but code that writes the engine's private state (names with a leading
    underscore) can change what is evaluated.  For a file you did not write, use
    :func:`stiefelsym.load` or ``stiefelsym verify --claims``, which import and trace it in fresh
    interpreters only (docs/architecture.md, "Where a claims file is trusted")."""
    from stiefelsym.run.pool import Terminated, stdout_to_stderr
    p = Path(path)
    if not p.is_file():
        raise CatalogError(claims_file_missing(p))
    name = "stiefelsym_user_" + re.sub(r"\W", "_", p.stem)
    other = getattr(sys.modules.get(name), "__file__", None)
    if other and Path(other).resolve() != p.resolve():   # two files of the same name: keep both modules
        name += "_" + hashlib.sha1(str(p.resolve()).encode("utf-8", "surrogateescape")).hexdigest()[:8]

    from stiefelsym.ir.seal import EngineChanged, seal, verify
    seal()      # the engine as it is before the file runs (see stiefelsym.ir.seal)
    # the file imports the helper modules next to it, as under `stiefelsym verify --claims` (whose interpreters
    # put its folder last on the search path: a module there shadows neither the engine nor a library)
    folder = str(p.resolve().parent)
    _refuse_shadowed_helpers(p, folder)
    _HELPER_FOLDERS.add(folder)
    if folder not in sys.path:
        sys.path.append(folder)

    def loader():
        spec = importlib.util.spec_from_file_location(name, p)
        if spec is None or spec.loader is None:
            raise CatalogError(f"not a Python file: {p}")
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod
        try:
            with stdout_to_stderr(), deadline(IMPORT_SECONDS, f"loading {p}"):
                spec.loader.exec_module(mod)
        except (KeyboardInterrupt, Terminated):
            raise
        except BaseException as exc:  # noqa: BLE001 - a user's file: report, never a traceback
            sys.modules.pop(name, None)
            if isinstance(exc, CatalogError):
                raise
            raise CatalogError(f"{p}: {type(exc).__name__}: {exc}") from exc
    try:
        reg = _collect(loader)
        verify(f"importing {p}")
    except (ValueError, TypeError, EngineChanged) as exc:
        raise CatalogError(f"{p}: {exc}") from exc
    if not len(reg):
        raise CatalogError(f"{p}: defines no claims (use the @claim decorator)")
    return reg
