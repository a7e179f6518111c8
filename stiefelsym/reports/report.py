"""Renderers: terminal summary, JUnit XML, Markdown and LaTeX reports.

Every renderer reads :class:`~stiefelsym.results.Result` records (and a ``meta``
dict describing the run) and nothing else, so a report can be re-rendered from
``results.json`` at any time.  ``meta`` keys are all optional: ``title``,
``command``, ``seed``, ``date``, ``seconds``, ``versions`` (name -> version),
``platform``, ``commit``, ``sections`` (section number -> section title).

The mutation analysis (``mutation.json``, written by ``stiefelsym mutate``) is a
record too: :func:`render_mutation_markdown` renders it on its own, and
``render_markdown``/``render_latex`` add a section "Mutation analysis" when its
parsed contents are passed as ``mutation=``.
"""
from __future__ import annotations

import dataclasses
import re
import functools
import shlex
import unicodedata
from fractions import Fraction
from collections import Counter
from typing import Any, Callable, Iterable, Sequence

from stiefelsym import paperref, sizerules
from stiefelsym.latex import greek_words, unicode_name, unicode_words, math_ok, split_math, tex_balanced, tex_display, tex_escape, tex_words, tt_escape
from stiefelsym.ir import notation
from stiefelsym.ir.notation import changes_text as change_text
from stiefelsym.results import PASSING, VERDICTS, Result, free_scope

DEFAULT_TITLE = ("Verification of Fedorov & Jovanović, "
                 "“Geodesic Flows and Neumann Systems on Stiefel Varieties”")

#: what each verdict means, for a mathematician reading the report
VERDICT_MEANING = {
    "proved": ("The statement holds identically.  At a size (n, r): exact symbolic "
               "computation reduced every residual to zero on the constraint set, or "
               "the dimension-free proof of the same graph holds there (the record says "
               "so: auto takes it first from n = 5 on, and beyond the size's symbolic "
               "budget; at n ≤ 4 the exact computation is an independent proof); a rank equal to its matrix's full "
               "size is proved by a nonzero maximal minor at a point.  "
               "At size “all n, r”: a dimension-free computation with the letters "
               "X, Xᵀ, P, Pᵀ, A, … of a free noncommutative algebra proves it for "
               "every n and r at once.  A statement the paper makes only at one r is "
               "proved for every n at that r, with the relation that holds there alone "
               "(at r = n, XXᵀ = Iₙ; at r = k = 1 or 2, E₁E₁ᵀ + … + EₖEₖᵀ = Iᵣ for the "
               "standard basis E₁, …, Eₖ of ℝʳ), and the verdict says so (“every n at r = n”); "
               "one made at r = 1 and at r = n is proved for every n at each, with one "
               "certificate per case.  In the metric realization (the constraint "
               "XᵀA⁻¹P + PᵀA⁻¹X = 0 of the metric given by A) a proof assumes A symmetric "
               "positive definite: the flow's Lagrange multipliers then solve Sylvester "
               "equations with a unique solution, which gives Π = 0 and Λ as a symmetric "
               "letter bound by its Sylvester equation."),
    "checked": ("Randomized exact check: every residual vanished exactly (no rounding) "
                "at independent random points over ℚ or a prime field.  A false "
                "statement passes with probability at most the stated bound p "
                "(Schwartz–Zippel, see below)."),
    "numeric": ("Floating-point evidence at random real points, with a running error "
                "bound and precision escalation: every residual entry is within its "
                "rounding-error bound, and that bound is below 10⁻⁸ of the size of the "
                "terms; strong evidence, not a proof."),
    "fails": ("The statement as printed is false at this size: an exact witness is given, either a "
              "point and a nonzero residual entry there (reproducible from the seed) or, for a "
              "dimension, rank or count (or a property such as regularity, counted 1 if it holds and 0 if "
              "not), its value computed exactly against the printed one; for a statement that something "
              "does not vanish, the exact proof that it vanishes identically there."),
    "inconclusive": ("The method ran but could not decide: only degenerate random "
                     "points, a floating-point residual no precision resolved, a "
                     "false-pass bound above 10⁻³⁰, or the run's time budget.  Never "
                     "expected."),
    "undecided": ("The method does not apply here: the dimension-free method on a "
                  "statement that needs coordinates, a randomized method on a rank "
                  "“at every point”, or a chosen (hard) point; an expected non-answer, "
                  "the other methods decide."),
    "error": ("The claim could not be evaluated as written: ill-typed (ℝⁿ and ℝʳ "
              "indices mixed), empty, dividing by zero, or crashed; the message is "
              "given.  Never expected."),
}

#: what each kind of claim is
KIND_MEANING = {
    "id": "an identity (its residuals must vanish at every point of the space it is stated on: T*V, or the phase "
          "space its claim names)",
    "lax": "a Lax equation implied by a flow",
    "pb": "a Poisson-bracket statement",
    "dim": "a dimension, rank or count",
    "not": "the statement says this does NOT hold (needs a certified witness: one residual shown nonzero)",
    "geo": "a geometric statement, checked through its algebraic form",
}

def kind_words(c: "ClaimResults") -> str:
    """What a claim of this kind states, and, where its residuals are expected not to vanish (``expect="nonzero"``),
    that too: the kind alone would say they must vanish.  The realization of T*V when it is not the standard one."""
    words = KIND_MEANING.get(c.kind, "")
    if c.expect == "nonzero" and c.kind != "not":
        words += ("; its residuals are stated NOT to vanish identically all at once (needs a certified witness: one "
                  "residual shown nonzero)")
    if c.realization != "standard":
        words += f"; in the {c.realization} realization of T*V"
    return words


#: what each method does, for a mathematician reading "passes at … by modular"
METHOD_MEANING = {
    "exact": ("symbolic computation at one size (n, r) in exact arithmetic: the residuals reduced to "
              "zero on the constraint set, or a rank or count computed over the field of the chart's "
              "parameters; proves or refutes.  A graph the dimension-free method proved for every n, r is "
              "proved at (n, r) by that proof (the same graph, the reduction stated), cross-checked by the "
              "modular method's points there: under auto from n = 5 on, and beyond a claim's symbolic budget."),
    "rational": "random exact points over ℚ; passes with the bound p below.",
    "modular": "random exact points over prime fields (primes near 2⁶²); passes with the bound p below.",
    "auto": ("the fastest proof-grade method for the claim at that size: the exact method within the claim's "
             "symbolic budget (from n = 5 on, the dimension-free proof of the same graph first, where there is "
             "one), the modular method beyond it."),
    "float": "floating point at random real points, with a running error bound and precision escalation.",
    "ball": ("rigorous interval (ball) arithmetic at the float method's points: a certified nonzero "
             "residual refutes, otherwise it is evidence."),
    "free": ("the dimension-free method: the letters of a free noncommutative algebra reduced by the "
             "constraints of T*V (a terminating, confluent rewriting system); a proof is a cofactor "
             "certificate that an independent checker re-expands.  It does not apply to statements that "
             "read coordinates (an entry, a rank, a count)."),
}

METHODS_INTRO = "Each verdict names the method that reached it (“passes at (4,2) by modular”):"

BOUND_EXPLANATION = (
    "Schwartz–Zippel lemma: a nonzero polynomial of total degree d, evaluated at a "
    "point whose coordinates are drawn independently and uniformly from a finite set "
    "S of field elements, vanishes with probability at most d/|S|.  The residuals of "
    "a claim are rational functions in the free parameters of a chart of T*V; a "
    "randomized check evaluates their numerators exactly at several independent "
    "points.  Over a prime field each point has its own prime, drawn from the seed "
    "among the primes in [2⁶², 2⁶³), and the bound adds the chance h/(62·K) that the "
    "prime divides the numerator (h bounds its height, K ≥ 7.6·10¹⁶ primes).  The "
    "number of points is chosen so that p ≤ 10⁻³⁰.  The bound p is the probability "
    "that a false statement would have passed this run.  It concerns the random "
    "choices of the run only, which the seed fixes, for a claim written independently "
    "of the seed.")

GRAPH_EXPLANATION = (
    "A claim is a function of the matrices X, P, A, … that returns its residuals (left side minus "
    "right side).  It is evaluated on symbols, which records it as a graph of matrix "
    "operations (products, transposes, inverses, derivatives along a flow) with exact constants; "
    "it is evaluated twice and the two graphs must agree (a claim of a user's file is also replayed "
    "from its graph by the engine alone, which must give the same graph).  Every method computes "
    "from that graph, never from the claim's code.  The digest is a "
    "SHA-256 hash of the graph (its first 12 hex digits are shown): two records with the same "
    "digest are about the same computation, and the command stiefelsym check compares it when it "
    "traces every record again.  The verdicts shown are those results.json records; stiefelsym check (and "
    "stiefelsym report with its check option) also runs every record again and refuses a file whose verdicts "
    "the runs do not give again.  Each record also carries its graph's outputs as traced, read back in the "
    "paper's notation from the graph (never from the claim's code); the Markdown report prints them under each "
    "claim, the LaTeX report under each claim of a claims file.  They are cut to a reader's length: a long sum "
    "ends in …, a matrix of many blocks is named by its shape, and a graph of more than "
    f"{notation.TRACED_NODES:,} nodes by its size; `stiefelsym show CLAIM --full` prints them whole.")

REFERENCES_EXPLANATION = (
    "A reference such as (9) §4 is equation (9) of Section 4: the paper numbers its equations afresh in each "
    "section, and its theorems, propositions and lemmas by section (Theorem 4.4).  The word in brackets after a "
    "reference, as in (9) §4 [LA-MAN3], is the paper's own label of it in its LaTeX source.  The paper's two "
    "appendices are numbered sections too: Appendix 1 (magnetic Neumann systems) is Section 9 and Appendix 2 "
    "(double, coupled and complex systems) is Section 10, so that (4) §9 is equation (4) of Appendix 1 and "
    "Theorem 10.1 a theorem of Appendix 2.")

SCOPE_EXPLANATION = (
    "A claim checks its statement as its display writes it.  Where the paper states a family for every power "
    "(the integrals tr L(λ)ᵏ, k = 1, …, n, and their Poisson brackets), the display names the powers checked, "
    "k, m ≤ 3 for the brackets of most claims; the other powers are not checked (their conservation, not their "
    "involution, follows from the Lax equations proved here).  A statement for every n is checked at the sizes "
    "listed, or for every n and r at once where the dimension-free method proves it; the tables of dimensions "
    "(tables.md) go further, to n = 12.  Where the appendix states a form of its own (a corrected statement, a "
    "statement at every rank that the paper makes at r = 2, a lemma of a proof), its title says so.")

REDUCTIONS_EXPLANATION = (
    "Each run states how the points of T*V were reached.  A chart is a rational parametrization of the points "
    "(X, P) of T*V by free parameters: the Cayley chart X = (I − S)(I + S)⁻¹X₀, with S skew-symmetric and X₀ = (E₁ … Eᵣ) "
    "the first r columns of the identity, and P tangent there, covers a dense open set of T*V; at r = n its two "
    "components (det X = 1 and −1, the two components of O(n)) each get one.  An equivariance reduction uses a "
    "symmetry of the statement (a group that acts on X, P, A and maps residuals to residuals) to move every point "
    "into a smaller chart, the equivariant one, X = X₀; each such run names the group and why the statement is covariant.  A proof "
    "for every n and r rewrites the residual modulo XᵀX = I and XᵀP + PᵀX = 0 in the free algebra of the "
    "letters X, P, A; its cofactor certificate writes the residual as a sum of products of those relations "
    "(its hypotheses) and is checked on its own, without the rewriting.")

EXPECTED_EXPLANATION = (
    "Each verdict is compared with what the catalog expects: a statement of the paper "
    "is expected to hold; a printed formula already known to be wrong is expected to "
    "fail as printed.  A verdict the catalog does not expect is marked UNEXPECTED; the "
    "command exits with status 1 if there is any.")

SECTION_TABLE_INTRO = (
    "Per section of the paper: its claims; those proved as printed for every n and r at once "
    "(dimension-free); those stated at one r and proved for every n at that r (and for one made at r = 1 "
    "and at r = n, every n at each); those that hold as printed at every size computed (proved, checked "
    "at random exact points, or numeric: within a floating-point error bound), and those of them proved "
    "at every size computed (for every size at once, or by some method at each size); those that fail as "
    "printed (the errata); and those with a verdict the catalog does not expect.")

ERRATA_INTRO = (
    "Statements that fail as printed.  Each comes with a witness, reproducible with the rerun "
    "command: an exact point where a residual entry is nonzero, or for a dimension, rank or "
    "count the exactly computed value against the printed one.  Then the candidate "
    "corrections that were checked.")
NO_POINT = "no witness point: the computed value below contradicts the printed one"
#: the witness of a statement that something does NOT hold, found to hold identically (exact) or at every
#: random point drawn (a randomized method: a nonzero residual would have shown but with probability p)
NOT_ZERO_WITNESS = ("no witness point: the statement says this is not identically zero, and exact "
                    "computation finds it identically zero")
NOT_ZERO_AT_POINTS = ("no witness point: the statement says this is not identically zero, and the {method} "
                      "method finds it zero at every random point it drew (a randomized result, with the bound p "
                      "of its run)")


def no_point_text(w: Result) -> str:
    """What stands in a failing run's witness list where it has no point: the computed value against
    the printed one (a rank or count, listed below), or, for a statement that something does not hold,
    the exact proof that it does."""
    if any(ch.status in DIMENSION_STATUSES for ch in w.checks):
        return NO_POINT
    if w.kind == "not":
        words = NOT_ZERO_WITNESS if w.method == "exact" else NOT_ZERO_AT_POINTS.format(method=w.method)
        return words + (f": {w.certificate}" if w.certificate else "")
    return "no witness point recorded"

#: the paper's operator names, expanded for Markdown viewers that do not know them
OPERATORS = {"tr": "tr", "diag": "diag", "ad": "ad", "Ad": "Ad", "rank": "rank",
             "ddim": "ddim", "pr": "pr", "Span": "span"}
WITNESS_WIDTH = 400
MAX_DERIVATIONS = 20


# --------------------------------------------------------------------------- grouping

#: what a change of the graph says nothing with: a check added or dropped (the statement replaced as a
#: whole), one written the same, a matrix shown only by its size, a computed number against a printed
#: one (a count: the registered words say what is counted), an expression cut short
_UNTELLING = (notation.NO_SUCH_CHECK, notation.DROPPED, notation.SAME_TEXT, "…", notation.BIG_MATRIX)
_COUNT = re.compile(r"^\d+ = \d+$")
TELLING_WIDTH = 160


def telling(changes: list[dict[str, str]]) -> list[dict[str, str]]:
    """A correction's change of the graph where it tells the reader something, else [] (the correction
    is then shown in its registered words alone)."""
    for ch in changes:
        old, new = ch.get("old", ""), ch.get("new", "")
        if any(t in old + new + ch.get("where", "") for t in _UNTELLING) or (old == new and not ch.get("more")) \
                or _COUNT.match(old) or _COUNT.match(new) or max(len(old), len(new)) > TELLING_WIDTH:
            return []
    return changes


def traced_intro(where: str, graphs: int, expect: str = "holds", sizes: int | None = None) -> str:
    """The words before a claim's outputs as traced (:meth:`ClaimResults.traced`); ``sizes``: how many
    sizes the graphs were traced at (:meth:`ClaimResults.traced_sizes`), when more than the graphs."""
    own = (f"each of its {graphs} sizes has a graph of its own" if sizes is None or sizes <= graphs else
           f"its graph depends on the size: its {sizes} sizes give {graphs} distinct graphs")
    at = ("one graph for every size run" if not where else f"at {where}" if graphs == 1 else
          f"at {where} only: the claim's code reads the sizes, and {own}, "
          "about which that size's verdict is (results.json and stiefelsym show --size n,r give each); shown: the "
          "smallest size with 1 < r < n, else the smallest, whose graph was read back")
    stated = ("the residuals are stated not to vanish identically all at once: one shown nonzero proves the claim, "
              "and a residual that vanishes beside it is not reported") if expect == "nonzero" else \
        "each residual is stated to vanish"
    return f"As traced (what every method evaluated, read back from the claim's graph, not its code; {at}; {stated})"


class ClaimResults:
    """All results of one claim: as printed, and per candidate correction."""

    def __init__(self, first: Result) -> None:
        self.id = first.claim
        self.paper = list(first.paper)
        self.section = first.section
        self.kind = first.kind
        self.title = first.title
        self.statement = first.statement
        self.expect = first.expect
        self.realization = first.realization
        #: a claim of a claims file with the id of a catalog claim: shown as the file's claim, under its file
        self.shadows = bool(first.shadows)
        self.claims_file = claims_file_of(first)
        #: the statements without a label of the paper the claim checks, by their printed names ("Theorem 4.3"),
        #: for the catalog's claim only
        self._unlabelled = [] if self.shadows or self.claims_file else unlabelled_statements(self.id)
        #: of an erratum of the catalog, the nature of the place of the paper it fails through ("formula", "size",
        #: ...: :data:`stiefelsym.claims.NATURES`); "" for a claims file's claim
        self.nature = "" if self.shadows or self.claims_file else erratum_nature(self.id)
        self.printed: list[Result] = []
        self.variants: dict[str, list[Result]] = {}

    def add(self, r: Result) -> None:
        if r.variant is None:
            self.printed.append(r)
        else:
            self.variants.setdefault(r.variant, []).append(r)

    def change_of(self, variant: str) -> list[dict[str, str]]:
        """What a correction changes in the claim's graph (paper notation), from its records: that of
        symbolic sizes, else of the smallest size with 1 < r < n, else of the smallest size."""
        rs = [r for r in self.variants.get(variant, []) if r.change]
        rs.sort(key=lambda r: (r.n is not None, r.n is None or not 1 < r.r < r.n, r.n or 0, r.r or 0))
        return telling(rs[0].change) if rs else []

    @property
    def failures(self) -> list[Result]:
        return [r for r in self.printed if r.verdict == "fails"]

    @property
    def slips(self) -> list[str]:
        """The further slips of the paper the erratum's text reports in passing, as its records give them."""
        return next((list(r.slips) for r in self.failures if r.slips), [])

    @property
    def place(self) -> str:
        """Where in the paper the misprint sits, as the erratum's records give it ("the proof of Theorem 7.1"); ""
        when it is the statement the labels name."""
        return next((r.place for r in self.failures if r.place), "")

    @property
    def unlabelled(self) -> list[str]:
        """The statements without a label the claim checks ("Theorem 4.3"), but one the place of its misprint names
        already ("in Proposition 4.6 and its proof", not again among the labels it involves)."""
        return [name for name in self._unlabelled if not re.search(rf"\b{re.escape(name)}\b", self.place)]

    @property
    def own(self) -> bool:
        """A statement of a claims file (its records' rerun commands name the file, as verify writes them):
        a user's own statement, whatever paper labels it cites, not the paper's as printed."""
        return any("--claims" in r.rerun.split() for r in self.printed)

    @property
    def unexpected(self) -> list[Result]:
        return [r for r in self.printed + [v for vs in self.variants.values() for v in vs]
                if not r.expected]

    def how_obtained(self) -> list[tuple[str, str]]:
        """(method, reductions) in order of appearance: once per method where all its runs used the same
        reductions, otherwise once per set of reductions, the method named with the sizes that used it
        ("exact at (4,4), (5,5)"), so that a reader sees which chart or reduction proved which size."""
        out: dict[str, dict[tuple[str, ...], list[str]]] = {}
        for r in self.printed:
            if r.reductions:
                out.setdefault(r.method, {}).setdefault(tuple(r.reductions), []).append(r.size)
        how = []
        for m, groups in out.items():
            for reductions, sizes in groups.items():
                label = m if len(groups) == 1 else f"{m} at {', '.join(dict.fromkeys(sizes))}"
                how.append((label, "; ".join(reductions)))
        return how

    def traced(self) -> tuple[str, list[list[str]], int]:
        """The outputs as traced of the claim as printed: (where, outputs, how many graphs), read from its
        records.  One graph for every record (one digest): where = "" when it is more than one size's run, else
        the size; several graphs (a claim traced at each size): the outputs of the smallest size's graph and
        where = that size.  ("", [], 0) when no record has them."""
        rs = [r for r in self.printed if r.traced and r.digest]
        if not rs:
            return "", [], 0
        graphs = len({r.digest for r in rs})
        # the smallest size with 1 < r < n (the generic case: at r = 1 or r = n blocks vanish or merge), else the
        # smallest, whose graph was read back (a graph of tens of thousands of nodes is only named)
        sized = sorted((r for r in rs if r.n is not None),
                       key=lambda r: (r.traced[0][1].startswith(notation.NOT_READ_BACK), not 1 < r.r < r.n,
                                      _size_key((r.n, r.r))))
        if graphs == 1:
            return ("" if len(rs) > 1 or not sized else sized[0].size), rs[0].traced, 1
        return sized[0].size, sized[0].traced, graphs

    def traced_sizes(self) -> int:
        """How many sizes the claim as printed was traced at (each with its graph; several sizes may
        share one graph)."""
        return len({(r.n, r.r) for r in self.printed if r.traced and r.digest and r.n is not None})

    def notes(self) -> list[Result]:
        """Results whose message the reader needs: not passing, or not expected."""
        return [r for r in self.printed
                if r.message and (r.verdict not in PASSING or not r.expected)]


def _section_key(section: str) -> tuple:
    parts = re.split(r"(\d+)", section or "")
    return (section == "",) + tuple((0, int(p)) if p.isdigit() else (1, p) for p in parts)


def claims_file_of(r: Result) -> str:
    """The claims file a record's rerun command names (``--claims FILE``), "" for a record of the catalog."""
    try:
        words = shlex.split(r.rerun or "")
    except ValueError:
        return ""
    return next((words[i + 1] for i, w in enumerate(words[:-1]) if w == "--claims"), "")


def _file_name(path: str) -> str:
    return path.replace("\\", "/").rstrip("/").rsplit("/", 1)[-1] or path


#: the key of the group of a claims file's claims that have catalog claims' ids (never a section: sections are
#: letters, digits, dots and hyphens), followed by the file's path
SHADOW_GROUP = "claims file: "


def group_of(c: "ClaimResults") -> str:
    """Where a claim is shown: its section (its record's), or, for a claims file's claim with the id of a catalog
    claim, the group of its file, whatever section its own labels give it (the catalog's section of that id is
    the paper's statement's, not the file's)."""
    return SHADOW_GROUP + c.claims_file if c.shadows else (c.section or "")


def shadow_words(c: "ClaimResults") -> str:
    """What a reader is told of a claims file's claim with the id of a catalog claim ("" for any other)."""
    if not c.shadows:
        return ""
    where = _file_name(c.claims_file) if c.claims_file else "a claims file"
    return (f"A claim of {where}, not of the paper's catalog: it has the id of a catalog claim, which it replaced in "
            "this run (it shadows it). Its statement, labels and verdicts are the file's own; they are not the "
            "paper's statement of that id, which this run did not verify.")


def _shadow_tag(c: "ClaimResults") -> str:
    """After a claim's id in a list: whose claim it is, for a claims file's claim with a catalog claim's id."""
    return f" (the claim of {_file_name(c.claims_file) or 'a claims file'}, not the catalog's)" if c.shadows else ""


def readable_results(results: Iterable[Result]) -> list[Result]:
    """Copies of the catalog's records whose words cite the paper by its printed numbers ((5) §4, Theorem 4.4)
    where they name its label keys ((dot_XP3*), Theorem man-dual): what a reader looks up
    (:func:`.paperref.readable`).  The records themselves, and results.json, keep the words as the claims give
    them; the records of a user's claims are left as they are."""
    rd = paperref.readable
    # only the catalog's words: the labels are the paper's keys, and in a user's words "(A2)" or "BB" is the user's
    return [dataclasses.replace(r, title=rd(r.title), statement=rd(r.statement, statement=True), erratum=rd(r.erratum),
                                place=rd(r.place), slips=[rd(x) for x in r.slips]) if of_catalog(r) else r
            for r in results]


def group_by_claim(results: Iterable[Result]) -> list[ClaimResults]:
    """Claims ordered by section, then by first appearance, each with its results."""
    out: dict[str, ClaimResults] = {}
    for r in results:
        if r.claim not in out:
            out[r.claim] = ClaimResults(r)
        out[r.claim].add(r)
    # a claims file's claims with catalog claims' ids last, by file (never among the paper's sections)
    return sorted(out.values(), key=lambda c: (c.shadows, c.claims_file if c.shadows else "", _section_key(c.section)))


def group_by_section(claims: list[ClaimResults]) -> list[tuple[str, list[ClaimResults]]]:
    secs: dict[str, list[ClaimResults]] = {}
    for c in claims:
        secs.setdefault(group_of(c), []).append(c)
    return list(secs.items())


def _section_heading(section: str, meta: dict[str, Any]) -> str:
    if section.startswith(SHADOW_GROUP):
        return f"Claims of {_file_name(section[len(SHADOW_GROUP):]) or 'a claims file'} with the ids of catalog claims"
    if not section:
        return "Claims outside the paper's sections"
    name = (meta.get("sections") or {}).get(section, "")
    if name.startswith("Appendix"):
        return name                      # the appendices are named, not numbered
    return f"§{section} {name}".strip()


# --------------------------------------------------------------------------- formatting

def format_seconds(s: float | None) -> str:
    if s is None:
        return "–"
    if s < 60:
        return f"{s:.2f} s"
    m, sec = divmod(int(round(s)), 60)
    return f"{m} min {sec} s" if m < 60 else f"{m // 60} h {m % 60} min"


_E_NOTATION = re.compile(r"(?<![\w.])(<= ?)?(\d(?:\.\d+)?)e-(\d+)\b")


def probability_words(text: str) -> str:
    """The engine's words with a probability in e-notation written as the report writes one: "<= 1e-30" as "≤ 10⁻³⁰",
    "2.5e-31" as "2.5·10⁻³¹"."""
    def one(m: re.Match) -> str:
        exp = ("-" + str(int(m.group(3)))).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
        mant = "" if m.group(2) == "1" else m.group(2) + "·"
        return ("≤ " if m.group(1) else "") + f"{mant}10{exp}"
    return _E_NOTATION.sub(one, text or "")


def format_bound(p: float | None) -> str:
    """A false-pass probability as the whole report writes one: m·10⁻ᵏ (:func:`_power_of_ten`), "0", "–" for none."""
    if p is None:
        return "–"
    return "0" if p == 0 else _power_of_ten(p)


def short(text: Any, width: int = 90) -> str:
    """``text`` on one line, cut to ``width`` characters."""
    line = " ".join(str(text or "").split())
    return line if len(line) <= width else line[: width - 1] + "…"


def format_value(v: Any) -> str:
    """A witness value on one line: dicts as ``k = v; ...``, lists as ``[a, b]``."""
    if isinstance(v, dict):
        return "; ".join(f"{k} = {format_value(x)}" for k, x in v.items())
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(format_value(x) for x in v) + "]"
    return str(v)


#: a witness's bookkeeping, left out of the reports (the rerun command reproduces it)
WITNESS_INTERNAL = ("trial", "attempt", "component", "small", "seed")


def witness_lines(w: dict[str, Any] | None, where: str = "results.json") -> list[tuple[str, str]]:
    """(key, value) of a witness, each value cut to WITNESS_WIDTH characters (``where``: where it is in full)."""
    out = []
    for k, v in (w or {}).items():
        if k in WITNESS_INTERNAL:
            continue
        text = format_value(v)
        if len(text) > WITNESS_WIDTH:
            text = short(text, WITNESS_WIDTH) + f" (in full in {where})"
        out.append((str(k), text))
    return out


def case_name(r: Result) -> str:
    """A name that reads like the claim: ``prep[n=4,r=2]-modular``."""
    var = f"[{r.variant}]" if r.variant else ""
    size = "[all n,r]" if r.n is None else f"[n={r.n},r={r.r}]"
    return f"{r.claim}{var}{size}-{r.method}"


def labels(paper: Sequence[str], unlabelled: Sequence[str] = ()) -> str:
    """The paper's numbers of a claim's labels, each label kept in brackets: "(4) §2 [cond_XP]", "(3) §4 in Theorem 4.2
    [man]"; a label the paper does not number (a user's own) is printed as "(label)"; then the statements without a
    label the claim checks, by their printed names ("Theorem 4.3")."""
    return ", ".join([f"{paperref.printed(p)} [{p}]" if p in paperref.table() else f"({p})" for p in paper]
                     + list(unlabelled))


def tex_labels(paper: Sequence[str], unlabelled: Sequence[str] = ()) -> str:
    """LaTeX of :func:`labels`: the paper's numbers, each label in small type (breakable)."""
    def one(p: str) -> str:
        key = r"{\scriptsize[\texttt{" + tex_escape(p).replace(r"\_", r"\_\allowbreak{}") + "}]}"
        return (tex_escape(paperref.printed(p)).replace(" ", "~") + " " + key) if p in paperref.table() \
            else tex_escape(f"({p})").replace(r"\_", r"\_\allowbreak{}")
    return ", ".join([one(p) for p in paper] + [tex_escape(name).replace(" ", "~") for name in unlabelled])


def _run_facts(meta: dict[str, Any]) -> list[str]:
    """Plain-text sentences on how the run can be reproduced and where it ran."""
    facts = []
    if meta.get("seed") is not None:
        facts.append(f"Seed {meta['seed']}: every random choice (points, primes) is drawn from "
                     "it, so the command reproduces every verdict, witness and bound of this report.")
    run = [f"on {meta['date']}" if meta.get("date") else "",
           f"in {format_seconds(meta['seconds'])}" if meta.get("seconds") is not None else "",
           f"at commit {meta['commit']}" if meta.get("commit") else "",
           f"on {meta['platform']}" if meta.get("platform") else ""]
    if any(run):
        facts.append("Run " + " ".join(x for x in run if x) + ".")
    versions = meta.get("versions") or {}
    if versions:
        facts.append("Versions: " + ", ".join(f"{k} {v}" for k, v in versions.items()) + ".")
    return facts


#: a check's status in a failing run's witness list, in words
CHECK_STATUS_WORDS = {"rank": "rank as printed", "rank-mismatch": "rank not as printed",
                      "count": "count as printed", "count-mismatch": "count not as printed",
                      "nonzero": "residual nonzero"}


def check_line(ch: Any) -> str:
    """One check of a failing run: its name as mathematics, its status in words, its detail (the printed value
    said as the witness sentence says it, :func:`printed_value_words`, in the paper's notation, :func:`engine_words`)."""
    return (f"check {unicode_name(ch.name)}: {CHECK_STATUS_WORDS.get(ch.status, ch.status)}"
            + (f", {engine_words(printed_value_words(ch.detail))}" if ch.detail else ""))


#: the engine's ASCII for mathematics in its own words (a chart, a reduction, a rank's matrix): (pattern,
#: replacement), in this order; the scripts (X^T, (I + S)^{-1}) are set by unicode_words and tex_words after
_ENGINE_IDIOMS = (
    (re.compile(r"(?<![\w.])(\d+)x(\d+)(?![\w.])"), r"\1 × \2"),             # a matrix's size 15x15
    (re.compile(r"\bover Q\b"), "over ℚ"),
    (re.compile(r"\bQ\((?=chart parameters\))"), "ℚ("),                          # the field ℚ(chart parameters)
    (re.compile(r"\((\w)-(\w)\)"), r"(\1 − \2)"),                               # (n-r) as (n − r)
    (re.compile(r"(?:(?<=[\[(])|(?<=[,;] ))-(?=\w)"), "−"),                                  # a leading minus: −2K, (−1, …)
    (re.compile(r"(?<![\w^])R\^(n|r)\b"), r"ℝ^\1"),                          # the spaces ℝⁿ, ℝʳ
    (re.compile(r"\b(T\*?)?([VW])\(([nr]|\d+), ([nr]|\d+)\)"), r"\1\2_{\3,\4}"),  # V_{n,r}, T*V_{n,n}, TW_{n,r}
    (re.compile(r"(?<=[\w)\]]) - (?=[\w(\[])"), " − "),                         # a minus sign: n − r, I − S
    # a rank of 0 needs no lower bound: "rank ≥ 0" is no evidence, and is not printed as such (the records of
    # earlier runs; the engine now says so itself)
    (re.compile(r"\brank 0 at an exact rational point \(rank >= 0 over the function field\)(?= and|;)"),
     "no lower bound (none is needed: no rank is below 0)"),
    (re.compile(r"\b([XPYQZ])dot\b"), "\\1\u0307"),                                 # Zdot as Ż
    # the real form of a complex matrix acting on a realified point: realify(g) as g_ℝ, said once
    (re.compile(r"realify\((\w)\) (\w) realify\((\w)\)(\^T|ᵀ)"),
     r"\1_ℝ \2 \3_ℝ^T (\1_ℝ: the complex matrix \1 written as a real one)"),
)


def engine_words(text: str) -> str:
    """The engine's words (how a verdict was obtained, what a rank or count check computed) with its ASCII for
    mathematics in the paper's notation: a size 15x15 as 15 × 15, Q as ℚ, R^n as ℝ^n, V(n, r) as V_{n,r}, a spaced
    hyphen between two terms as a minus sign; to be set by :func:`unicode_words` or :func:`tex_words`."""
    for pattern, repl in _ENGINE_IDIOMS:
        text = pattern.sub(repl, text)
    return text


#: the value a Count or Rank check's detail quotes of the statement: "...: 2 (paper: 1)", "... (paper: 4)",
#: "...; paper: 13" ("claimed" for a statement of one's own)
_COUNT_DETAIL = re.compile(r"(^|: )(\d+) \((paper|claimed): (\d+)\)$")
_QUOTED_VALUE = re.compile(r"(?:;\s*|\s*\()(paper|claimed): (\d+)\)?$")


def printed_value_words(detail: str) -> str:
    """A check's detail with the value the statement gives said in words: "...: 2 (paper: 1)" as "...: computed
    2, where the printed statement gives 1" (as the witness to check by hand says it; "(paper: 1)" alone reads
    as if the paper gave 1 for the computed quantity), "...; paper: 13" as "...; the printed statement gives 13"."""
    text = detail.strip()
    m = _COUNT_DETAIL.search(text)
    if m:
        whose = "the printed statement gives" if m.group(3) == "paper" else "the claim states"
        if m.group(2) == m.group(4):        # agreeing: "computed 0, where the statement gives 0" reads as a contrast
            return f"{text[:m.start()]}{m.group(1)}computed {m.group(2)}, as {whose}"
        return f"{text[:m.start()]}{m.group(1)}computed {m.group(2)}, where {whose} {m.group(4)}"
    m = _QUOTED_VALUE.search(text)
    if m:
        whose = "the printed statement gives" if m.group(1) == "paper" else "the claim states"
        return f"{text[:m.start()]}; {whose} {m.group(2)}"
    return detail


#: a number the statement gives, quoted in a check's detail: "2 (paper: 1)" after a colon, or "(paper: 30" alone
_COMPUTED_AGAINST = re.compile(r"(^|: )(\d+) \((paper|claimed): (\d+)\)")
_QUOTED_ANYWHERE = re.compile(r"(\(|; )(paper|claimed): ")


def of_catalog(r: Result) -> bool:
    """Whether a record is of a claim of the paper's catalog: its rerun command names no claims file (the command
    is the record's own, which report and check compare with what the run writes)."""
    return _names_no_file(r.rerun or "")


@functools.lru_cache(maxsize=1 << 14)
def _names_no_file(rerun: str) -> bool:
    """Whether a rerun command names no claims file (a pure function of the text: the reports ask it of every
    record several times)."""
    try:
        return "--claims" not in shlex.split(rerun)
    except ValueError:
        return False


def quoted_value_words(detail: str) -> str:
    """A check's detail for a table row, every value the statement gives said as the printed (or the claimed)
    one: "...: 2 (paper: 1)" as "...: computed 2, printed 1", "(paper: 30; certain)" as "(printed: 30; certain)",
    "; paper: 4" as "; printed: 4" ("paper: 30" alone reads as if the paper gave 30 for the quantity computed just
    before).  For the records of the catalog only (:func:`of_catalog`): a claims file's words are its own."""
    text = _COMPUTED_AGAINST.sub(lambda m: f"{m.group(1)}computed {m.group(2)}, "
                                 f"{'printed' if m.group(3) == 'paper' else 'claimed'} {m.group(4)}", detail)
    return _QUOTED_ANYWHERE.sub(lambda m: m.group(1) + ("printed: " if m.group(2) == "paper" else "claimed: "), text)


def _witness_heading(w: Result) -> str:
    seed = f", seed {w.seed}" if w.seed is not None else ""
    return f"Witness at size {w.size}, method {w.method}{seed}:"


def _size_key(size: tuple[int, int]) -> tuple[int, int]:
    return size


def format_sizes(sizes: Iterable[tuple[int, int]], limit: int = 4,
                 universe: Iterable[tuple[int, int]] = ()) -> str:
    """``(3,1), (4,2)``.  A list longer than ``limit`` is stated by its rule within ``universe``
    (the computed sizes) where one separates it ("every computed size with r ≥ 2 (12 sizes)"), and
    otherwise listed in full: never an ellipsis, which would suggest every size in between."""
    ss = sorted(set(sizes), key=_size_key)
    text = ", ".join(f"({n},{r})" for n, r in ss)
    if len(ss) <= limit:
        return text
    rest = set(universe) - set(ss)
    if universe and not rest:
        return f"every computed size ({len(ss)})"
    cond = sizerules.rule(ss, rest) if rest else None
    if not cond:
        return text
    said = at_the_largest(cond, ss + sorted(rest))
    return (f"every computed size with {said[:-1]}; {len(ss)} sizes)" if said.endswith(" computed)") else
            f"every computed size with {said} ({len(ss)} sizes)")


def at_the_largest(cond: str, universe: Iterable[tuple[int, int]]) -> str:
    """A rule of sizes that names the largest r (or n) computed, "r = 3" where no size has r > 3, says so:
    "r = 3 (the largest r computed)", which is not read as "fails only at r = 3"."""
    sizes = list(universe)
    if not sizes:
        return cond
    top = {"n": max(n for n, _ in sizes), "r": max(r for _, r in sizes)}
    return re.sub(r"\b([nr]) = (\d+)\b(?! [+−])",
                  lambda m: m.group(0) + (f" (the largest {m.group(1)} computed)" if int(m.group(2)) == top[m.group(1)]
                                          else ""), cond)


def _fails_holds_text(fails: Iterable[tuple[int, int]], holds: Iterable[tuple[int, int]]) -> str:
    """:func:`sizerules.fails_holds_text`, its rule saying where it names the largest r or n computed."""
    fails, holds = sorted(set(fails)), sorted(set(holds))
    text = sizerules.fails_holds_text(fails, holds)
    cond = sizerules.rule(fails, holds)
    head = f"fails at every computed size with {cond}"
    return text.replace(head, f"fails at every computed size with {at_the_largest(cond, fails + holds)}", 1) \
        if cond and text.startswith(head) else text


def planned_sizes(c: "ClaimResults") -> list[tuple[int, int]]:
    """The sizes at which the printed claim was run (the sizes a correction must cover)."""
    return sorted({(r.n, r.r) for r in c.printed if r.n is not None}, key=_size_key)


def _method_name(m: str) -> str:
    return "the dimension-free method" if m == "free" else m


#: how the record of a size proved by the dimension-free proof specialised to it begins its reductions
#: (methods/specialise.py): not an independent computation at that size
SPECIALISED = "the dimension-free proof, specialised"


def is_specialised(r: Result) -> bool:
    """The record's verdict at its size is the dimension-free proof specialised to the size (with a
    cross-check at random points), not a computation of its own there."""
    return r.n is not None and bool(r.reductions) and str(r.reductions[0]).startswith(SPECIALISED)


def _specialised_words(rs: list[Result], ok: Sequence[tuple[int, int]], planned: Sequence[tuple[int, int]]) -> str:
    """The words after "verified at … by exact" saying at which of the sizes ``ok`` the verdict is the
    dimension-free proof specialised to the size, and at which the method's own computation ("" when none
    is specialised)."""
    spec = {(r.n, r.r) for r in rs if is_specialised(r) and r.verdict in PASSING}
    own = {(r.n, r.r) for r in rs if r.n is not None and r.verdict in PASSING and not is_specialised(r)}
    spec -= own
    if not spec:
        return ""
    universe = planned or ok
    proof = "the dimension-free proof specialised to the size (cross-checked at random points)"
    if not own:
        return f": at each size {proof}"
    own_at, spec_at = format_sizes(own, 4, universe), format_sizes(spec, 4, universe)
    # a list of sizes that no rule states is given once: the other set is "the other k sizes"
    if len(own) > 6 and not own_at.startswith("every") and (len(spec) <= len(own) or spec_at.startswith("every")):
        own_at = f"the other {len(own)} sizes"
    elif len(spec) > 6 and not spec_at.startswith("every"):
        spec_at = f"the other {len(spec)} sizes"
    return f": its own computation at {own_at}, {proof} at {spec_at}"


def correction_summary(rs: list[Result], planned: Sequence[tuple[int, int]]) -> tuple[str, list[str]]:
    """The status of a candidate correction, aggregated over sizes, and one phrase per method.

    ``verified`` only when it passes at every planned size of the claim (at least one method
    passing at each size) and fails nowhere; ``rejected`` when it fails somewhere; otherwise
    ``not verified`` (some planned size was not covered, or no method decided)."""
    planned = sorted(set(planned), key=_size_key)
    by_method: dict[str, list[Result]] = {}
    for r in rs:
        by_method.setdefault(r.method, []).append(r)
    phrases, passed_at, failed_at = [], set(), set()
    free_proved = False
    for m, mrs in by_method.items():
        ok = sorted({(r.n, r.r) for r in mrs if r.n is not None and r.verdict in PASSING}, key=_size_key)
        bad = sorted({(r.n, r.r) for r in mrs if r.n is not None and r.verdict == "fails"}, key=_size_key)
        other: dict[str, set] = {}
        for r in mrs:
            if r.n is None:
                if r.verdict == "proved":
                    free_proved = True
                    phrases.append(f"proved for {free_scope(r)} by {_method_name(m)}")
                elif r.verdict == "fails":
                    failed_at.add(None)
                    phrases.append(f"fails by {_method_name(m)}")
                else:
                    phrases.append(f"{r.verdict} for all n, r by {_method_name(m)}")
            elif r.verdict not in PASSING and r.verdict != "fails":
                other.setdefault(r.verdict, set()).add((r.n, r.r))
        passed_at.update(ok)
        failed_at.update(bad)
        bounds = [r.false_pass_bound for r in mrs if r.false_pass_bound is not None and r.verdict in PASSING]
        bound = (f" (p ≤ {format_bound(max(bounds))})" if bounds and max(bounds) > 0
                 else " (exact)" if bounds else "")
        if ok:
            how = _specialised_words(mrs, ok, planned)
            if planned and set(ok) >= set(planned) and len(planned) > 1:
                phrases.append(f"verified at all {len(planned)} computed sizes by {m}{bound}{how}")
            elif planned and set(ok) >= set(planned):
                phrases.append(f"verified at the claim's only size {format_sizes(ok)} by {m}{bound}{how}")
            else:
                phrases.append(f"passes at {format_sizes(ok, 6, planned)} by {m}{bound}{how}")
        if bad:
            phrases.append(f"fails at {format_sizes(bad, 6, planned)} by {m}")
        for v, where in other.items():
            phrases.append(f"{v} at {format_sizes(where, 6, planned)} by {m}")
    if failed_at:
        status = "rejected"
    elif planned and passed_at >= set(planned):
        status = "verified"
    elif not planned and free_proved:
        status = "verified"
    else:
        status = "not verified"
    missing = [s for s in planned if s not in passed_at and s not in failed_at]
    if missing and status != "rejected":
        phrases.append(f"not verified at {format_sizes(missing, 6, planned)}")
    return status, phrases


def _status_label(status: str, rs: list[Result]) -> str:
    """A correction's status as a reader sees it: "verified" says whether a proof for every n and r stands behind it
    (the dimension-free method's) or the computed sizes only."""
    if status != "verified":
        return status
    free = [r for r in rs if r.n is None and r.verdict == "proved"]
    return f"proved for {free_scope(free[0])}" if free else "verified at the computed sizes"


def _correction_status(rs: list[Result], planned: Sequence[tuple[int, int]] = ()) -> str:
    return correction_summary(rs, planned)[0]


#: the order of authority of the methods for a check's detail (most rigorous first)
METHOD_ORDER = ("exact", "rational", "modular", "auto", "ball", "float", "free")
DIMENSION_STATUSES = ("rank", "rank-mismatch", "count", "count-mismatch")


def dimension_checks(c: "ClaimResults") -> list[tuple[str, str, str, str, str]]:
    """(check, size, method, status, detail) of the rank and count statements of a claim as
    printed: at each size, from the most rigorous method that decided it.  The detail is the
    CheckOutcome's (with its ``meaning`` in front when the record carries one)."""
    best: dict[tuple[str, tuple], tuple[int, Result, Any]] = {}
    order: list[tuple[str, tuple]] = []
    for r in c.printed:
        rank = METHOD_ORDER.index(r.method) if r.method in METHOD_ORDER else len(METHOD_ORDER)
        seen = set()
        for ch in r.checks:
            if ch.status not in DIMENSION_STATUSES or ch.name in seen:
                continue
            seen.add(ch.name)
            key = (ch.name, (r.n, r.r))
            if key not in best:
                order.append(key)
            if key not in best or rank < best[key][0]:
                best[key] = (rank, r, ch)
    out = []
    for name in dict.fromkeys(k[0] for k in order):
        for key in sorted((k for k in order if k[0] == name), key=lambda k: (k[1][0] or 0, k[1][1] or 0)):
            _, r, ch = best[key]
            meaning = getattr(ch, "meaning", "") or ""
            said = quoted_value_words(ch.detail) if of_catalog(r) else ch.detail
            detail = said if not meaning or ch.detail.startswith(meaning) else f"{meaning}: {said}"
            out.append((ch.name, r.size, r.method,
                        "as printed" if ch.status in ("rank", "count") else "mismatch", detail))
    return out


def grouped_dimension_checks(c: "ClaimResults") -> list[tuple[str, str, str, str, str]]:
    """:func:`dimension_checks` with the sizes at which one check says the same thing (the same method, outcome and
    detail) in one row: (check, sizes, method, status, detail), in the order of each group's first size."""
    groups: dict[tuple[str, str, str, str], list[str]] = {}
    for name, size, m, st, detail in dimension_checks(c):
        groups.setdefault((name, m, st, detail), []).append(size)
    return [(name, ", ".join(sizes), m, st, detail) for (name, m, st, detail), sizes in groups.items()]


_REPEATED_SCALAR = re.compile(r"(?<![A-Za-zα-ωΑ-Ω])([λμνκ])(\1+)(?![₀-₉ᵀ⁻¹²³⁴⁵⁶⁷⁸⁹′'_])")
_SUPERSCRIPTS = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def traced_words(text: str) -> str:
    """A formula as traced, as a reader writes it: a scalar multiplied by itself is a power ("λλA" is "λ²A")."""
    return _REPEATED_SCALAR.sub(lambda m: m.group(1) + str(1 + len(m.group(2))).translate(_SUPERSCRIPTS), text)


# --------------------------------------------------------------------------- terminal

def render_summary(results: Sequence[Result]) -> str:
    """The summary table printed after a run: verdict counts by method."""
    if not results:
        return "summary: no runs\n"
    claims = {r.claim for r in results}
    unexpected = [r for r in results if not r.expected]
    head = (f"summary: {len(claims)} claim{'s' * (len(claims) != 1)}, {len(results)} "
            f"run{'s' * (len(results) != 1)}: {len(results) - len(unexpected)} as expected, "
            f"{len(unexpected)} unexpected")
    methods = list(dict.fromkeys(r.method for r in results))
    counts = Counter((r.method, r.verdict) for r in results)
    w0 = max(len("method"), *(len(m) for m in methods), len("total"))
    cols = list(VERDICTS) + ["total"]
    widths = [max(len(c), 5) for c in cols]

    def row(name: str, cells: list[str]) -> str:
        return "  " + name.ljust(w0) + "".join(c.rjust(w + 2) for c, w in zip(cells, widths))

    lines = [head, row("method", cols)]
    for m in methods:
        cells = [str(counts[(m, v)] or "-") for v in VERDICTS]
        lines.append(row(m, cells + [str(sum(counts[(m, v)] for v in VERDICTS))]))
    if len(methods) > 1:
        tot = Counter(r.verdict for r in results)
        lines.append(row("total", [str(tot[v] or "-") for v in VERDICTS] + [str(len(results))]))
    if unexpected:
        lines.append("unexpected verdicts:")
        for r in unexpected:
            lines.append("  " + r.line())
            if r.rerun:
                lines.append(f"    rerun: {r.rerun}")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- JUnit

#: the characters XML 1.0 does not allow (its Char is \t, \n, \r, U+0020-U+D7FF, U+E000-U+FFFD and U+10000-U+10FFFF),
#: written as the small class of what is left out: the same set, compiled in a twentieth of the time (the other
#: form took 8 ms of every start-up)
_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def _xml(text: Any) -> str:
    return _XML_BAD.sub("?", str(text))


def render_junit(results: Sequence[Result], meta: dict[str, Any] | None = None) -> str:
    """JUnit XML: one testsuite per paper section, one testcase per result.

    An unexpected verdict is a ``<failure>`` (an unexpected ``error``, a claim that could not be
    evaluated, an ``<error>``) whose text holds the line, the message, the witness and the rerun
    command."""
    import xml.etree.ElementTree as ET     # only for this format
    def errors(rs: Sequence[Result]) -> int:
        return sum(not r.expected and r.verdict == "error" for r in rs)

    def failures(rs: Sequence[Result]) -> int:
        return sum(not r.expected and r.verdict != "error" for r in rs)

    root = ET.Element("testsuites", name="stiefelsym", tests=str(len(results)),
                      failures=str(failures(results)), errors=str(errors(results)),
                      time=f"{sum(r.seconds or 0.0 for r in results):.3f}")
    by_section: dict[str, list[Result]] = {}
    for r in results:
        # a claims file's claim with a catalog claim's id is not filed under the paper's section of that id
        by_section.setdefault("" if r.shadows else r.section or "", []).append(r)
    for sec, rs in sorted(by_section.items(), key=lambda kv: _section_key(kv[0])):
        suite = ET.SubElement(root, "testsuite", name=f"section {sec}" if sec else "other",
                              tests=str(len(rs)), failures=str(failures(rs)), errors=str(errors(rs)),
                              skipped="0", time=f"{sum(r.seconds or 0.0 for r in rs):.3f}")
        for r in rs:
            case = ET.SubElement(suite, "testcase", name=_xml(case_name(r)),
                                 classname=_xml(f"stiefelsym.section{sec}.{r.claim}"),
                                 time=f"{r.seconds or 0.0:.3f}")
            detail = [r.line()] + ([r.message] if r.message else [])
            detail += [f"{k}: {v}" for k, v in witness_lines(r.witness, where="the record: --format json")]
            detail += [f"rerun: {r.rerun}"] if r.rerun else []
            if r.expected:
                ET.SubElement(case, "system-out").text = _xml("\n".join(detail))
            else:
                fail = ET.SubElement(case, "error" if r.verdict == "error" else "failure", type=r.verdict,
                                     message=_xml(f"{r.verdict}: not the expected verdict"))
                fail.text = _xml("\n".join(detail))
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"


# --------------------------------------------------------------------------- Markdown

def _md_escape(text: Any) -> str:
    """Escape Markdown emphasis, HTML, links and images in running text, keeping ``$...$`` math whose
    vocabulary is mathematics (:func:`math_ok`; other "math", \\href say, and the words of the text with a backslash
    or a $ are shown as code); the rest as :func:`_md_text`."""
    out: list[str] = []
    code: list[str] = []          # consecutive pieces shown as code: one span (two adjacent ones would read as ``)
    for is_math, seg in split_math(str(text)):
        if is_math and math_ok(seg):
            if code:
                out.append(_md_code("".join(code)))
                code = []
            out.append(f"${_md_math(seg)}$")
            continue
        if is_math:
            # LaTeX that is not mathematics: shown verbatim as code, which no Markdown reader takes for math (a
            # notebook's MathJax reads \\( in the text as the start of math, and skips code)
            code.append(f"${seg}$")
            continue
        # in running text, only the words with a backslash or a lone $ are code; the words around them stay text
        for i, piece in enumerate(re.split(r"(\S*[\\$]\S*)", seg)):
            if i % 2:
                code.append(piece)
            elif piece:
                if code:
                    out.append(_md_code("".join(code)))
                    code = []
                out.append(_md_text(piece))
    if code:
        out.append(_md_code("".join(code)))
    return "".join(out)


def _md_text(text: str) -> str:
    """Running text without mathematics or code, escaped: emphasis, HTML and what would read as an entity
    (``&#36;``: the claim's own entities stay text), and a bracket that would close a link's text before a
    destination, ``](``, which is written ``] (`` (not ``\\]``, which a notebook's MathJax takes for the end of a
    display, nor an entity, which the raw file would show); ``][`` is left as it is (no reference of a link is
    defined in the reports, so it makes none)."""
    text = re.sub(r"([\\*_`<>])", r"\\\1", re.sub(r"&(?=#?[A-Za-z0-9]+;)", "&amp;", text))
    return text.replace("](", "] (")


def _md_paragraph(text: Any) -> str:
    """A claim's words (its title, a statement that is not math) as one paragraph of running text: its lines
    joined, so that they make no table, heading, list or code block of the report's own, and a first character
    that would begin one escaped."""
    out = _md_escape(" ".join(str(text).split()))
    if out.startswith("["):           # (a link's reference definition, "[x]: url", begins a line)
        return "&#91;" + out[1:]
    return "\\" + out if re.match(r"[#>+=|~-]|\d+[.)]\s", out) else out


def _md_words(text: Any) -> str:
    """Words that write scripts in ASCII (the catalog's words of a correction, of what is wrong), for a
    Markdown reader: the scripts in Unicode where they have one (Iₙ, ⁻¹), then escaped."""
    return _md_escape(unicode_words(str(text)))


def _md_cell(text: Any) -> str:
    return _md_escape(" ".join(str(text).split())).replace("|", r"\|")


def _md_code(text: Any) -> str:
    """Inline code; backticks inside are replaced (they would end it)."""
    return "`" + " ".join(str(text).split()).replace("`", "'") + "`"


def _md_math(tex: str) -> str:
    """Expand the paper's macros, which Markdown math viewers do not know; < and > as \\lt and \\gt (a Markdown
    reader takes "<" for the start of HTML, a comment that hides the report's own lines, even inside $...$), on one
    line (no line of it begins a table or a block of the report's own)."""
    tex = " ".join(tex.split())
    tex = re.sub(r"\s*([<>])\s*", lambda m: r" \lt " if m.group(1) == "<" else r" \gt ", tex)
    tex = re.sub(r"\\(" + "|".join(OPERATORS) + r")(?![A-Za-z])",
                 lambda m: r"\operatorname{" + OPERATORS[m.group(1)] + "}", tex)
    tex = re.sub(r"\\R(?![A-Za-z])", r"\\mathbb{R}", tex)
    tex = re.sub(r"\\g(?![A-Za-z])", r"\\mathfrak{g}", tex)
    # a viewer's \text{} is plain text (MathJax without its text macros shows "\_" as it is): the
    # underscore of a name, \text{along (dot\_XP3*)}, is set in math between two pieces of text
    return re.sub(r"\\text\{[^{}]*\\_[^{}]*\}", lambda m: m.group(0).replace("\\_", r"}\_\text{"), tex)


def _md_statement(statement: str) -> str:
    s = statement.strip()
    if not s:
        return ""
    if not math_ok(s):
        return _md_paragraph(s)
    s = _md_math(s)
    if len(s) > 70 or "\\\\" in s or "\\begin" in s:
        return f"$$\n{s}\n$$"
    return f"${s}$"


def _md_table(header: list[str], rows: list[list[str]], align: str) -> list[str]:
    sep = ["---:" if a == "r" else "---" for a in align]
    out = ["| " + " | ".join(header) + " |", "| " + " | ".join(sep) + " |"]
    return out + ["| " + " | ".join(row) + " |" for row in rows] + [""]


def _md_verdict(r: Result) -> str:
    v = f"**{r.verdict}**" if r.verdict in ("fails", "error") else r.verdict
    return v if r.expected else f"{v} (UNEXPECTED)"


#: consecutive runs of a claim that say the same thing at this many sizes or more are one row of the table
MD_RUNS_MERGED = 3


def _md_results(rs: list[Result]) -> list[str]:
    """The runs of a claim, a row each; consecutive runs at fixed sizes that differ in nothing but their size (the
    same method, verdict, certificate, seed and bound, and no time shown) are one row naming their sizes."""
    cells = [[_md_cell(r.size), r.method, _md_verdict(r), format_seconds(r.seconds),
              _md_cell(short(probability_words(certificate_words(quoted_value_words(r.certificate) if of_catalog(r)
                                                                 else r.certificate)))
                       or "–"),
              str(r.seed if r.seed is not None else "–"), format_bound(r.false_pass_bound)] for r in rs]
    universe = [(r.n, r.r) for r in rs if r.n is not None]
    rows: list[list[str]] = []
    i = 0
    while i < len(rs):
        j = i + 1
        if rs[i].n is not None:
            while j < len(rs) and rs[j].n is not None and cells[j][1:] == cells[i][1:]:
                j += 1
        if j - i >= MD_RUNS_MERGED:
            sizes = [(r.n, r.r) for r in rs[i:j]]
            rows.append([_md_cell(format_sizes(sizes, MD_RUNS_MERGED, universe))] + cells[i][1:])
        else:
            rows += cells[i:j]
        i = j
    return _md_table(["size (n,r)", "method", "verdict", "time", "certificate", "seed",
                      "p (false pass)"], rows, "lllrlrr")


def _summary_rows(claims: list[ClaimResults]) -> tuple[list[str], list[tuple[ClaimResults, list[int], str]]]:
    """The verdicts that occur, and per claim its counts (as printed) and status."""
    sized = lambda c: [r for r in c.printed if r.n is not None]
    present = [v for v in VERDICTS if any(r.verdict == v for c in claims for r in sized(c))]
    rows = []
    for c in claims:
        cnt = Counter(r.verdict for r in sized(c))
        fr = next((r for r in c.printed if r.n is None), None)
        # a proof at particular r says where ("proved, every n at r = n"), as the headline counts it
        free = "–" if fr is None else fr.verdict if fr.verdict != "proved" or free_scope(fr) == "all n, r" \
            else f"proved, {free_scope(fr)}"
        bad = len(c.unexpected)
        rows.append((c, [free] + [cnt[v] for v in present],
                     "as expected" if not bad else f"{bad} unexpected"))
    return ["all n, r"] + present, rows


def render_markdown(results: Sequence[Result], meta: dict[str, Any] | None = None,
                    mutation: Any = None) -> str:
    """The Markdown report: the headline, the errata, the summary, the sections, how to reproduce,
    the vocabulary, and the mutation analysis when ``mutation`` (the parsed ``mutation.json``) is given."""
    meta = meta or {}
    results = readable_results(results)
    claims = group_by_claim(results)
    unexpected = sum(not r.expected for r in results)
    text, errata = headline(claims, paper=not meta.get("claims_files"))
    slips, spelling = typographical_slips(meta), spelling_slips(meta)
    text += _typo_words(len(slips), len(spelling))
    out = [f"# {_md_escape(meta.get('title') or DEFAULT_TITLE)}", "",
           "Generated by `stiefelsym` from `results.json`; do not edit by hand.", "",
           _md_escape(text), "",
           f"{len(results)} runs; " + (("every verdict is the one the catalog expects (the errata are expected "
                                        "to fail as printed)." if not meta.get("claims_files") else
                                        "every verdict is the one its claim expects.") if not unexpected
                                       else f"**{unexpected} verdicts not as expected.**"), ""]
    if errata:
        out += ["Fails as printed:", ""]
        out += [f"- `{c.id}`{_md_escape(_shadow_tag(c))} {_placed(c, _md_escape(labels(c.paper, c.unlabelled)), lambda s: _md_escape(unicode_words(s)))}"
                + _md_escape(_listed_correction(c, unicode_words, errata if not meta.get("claims_files") else ())
                             + (_nature_tag(c) if not meta.get("claims_files") else ""))
                for c in errata]
        out += [""]

    # the vocabulary before its first use: the errata speak of verdicts, methods and the bound p
    out += ["## What the verdicts mean", ""]
    out += [f"- **{v}**: {_md_escape(VERDICT_MEANING[v])}" for v in VERDICTS]
    out += ["", f"**The methods.** {METHODS_INTRO}", ""]
    out += [f"- **{m}**: {_md_escape(t)}" for m, t in METHOD_MEANING.items()]
    out += ["", f"**The bound p.** {_md_escape(BOUND_EXPLANATION)}", "",
            f"**Graphs and digests.** {_md_escape(GRAPH_EXPLANATION)}", "",
            f"**Charts, reductions, certificates.** {_md_escape(REDUCTIONS_EXPLANATION)}", "",
            f"**References to the paper.** {_md_escape(REFERENCES_EXPLANATION)}", "",
            *([f"**What a claim covers.** {_md_escape(SCOPE_EXPLANATION)}", ""] if not meta.get("claims_files") else []),
            f"**Expected verdicts.** {_md_escape(EXPECTED_EXPLANATION)}", ""]

    out += ["## Errata", ""]
    out += _errata_body(claims, _md_escape, _md_erratum,
                        lambda c: [_md_heading(c), ""]
                        + ([f"**{_md_escape(shadow_words(c))}**", ""] if c.shadows else []) + _md_corrections(c))
    out += _md_typo_section(slips)
    out += _md_spelling_section(spelling)

    present, rows = _summary_rows(claims)
    # the PDF's table by section first (the same numbers), then the table by claim
    out += ["## Summary", "", _md_escape(SECTION_TABLE_INTRO), ""]
    total: Counter = Counter()
    section_rows = []
    for sec, cs in group_by_section(claims):
        k = section_counts(cs)
        total.update(k)
        section_rows.append([_md_cell(_section_heading(sec, meta))] + [str(v) for v in k.values()])
    keys = list(section_counts([]))
    out += _md_table(["section"] + keys, section_rows + [["**total**"] + [f"**{total[k]}**" for k in keys]],
                     "l" + "r" * len(keys))
    out += ["For each claim as printed: the verdict of the dimension-free method (all n, r "
            "at once), then the runs at fixed sizes (n, r) by verdict.", ""]
    out += _md_table(["claim", "paper", "§", "kind"] + present + ["status"],
                     [[f"`{c.id}`", _md_cell(labels(c.paper, c.unlabelled)), "–" if c.shadows else c.section or "–", c.kind]
                      + [str(k or "") for k in counts] + [status if status == "as expected"
                                                          else f"**{status}**"]
                      for c, counts, status in rows],
                     "llll" + "r" * len(present) + "l")

    for sec, cs in group_by_section(claims):
        out += [f"## {_md_escape(_section_heading(sec, meta))}", ""]
        for c in cs:
            out += _md_claim(c)

    out += ["## How to reproduce", "", "```sh", meta.get("command") or "stiefelsym verify", "```", ""]
    out += [_md_escape(f) for f in _run_facts(meta)] + [""]
    if mutation:
        out += _md_mutation_section(_mutation_data(mutation))
    return "\n".join(out).rstrip() + "\n"


def _md_heading(c: ClaimResults) -> str:
    """A claim's heading: its id and its labels, led by the place of its misprint where it has one (the statement
    may be a numbered environment without a label, Proposition 4.6, which its labels alone would not name)."""
    return f"### `{c.id}` {_placed(c, _md_escape(labels(c.paper, c.unlabelled)), lambda s: _md_escape(unicode_words(s)))}".rstrip()


def _md_claim(c: ClaimResults) -> list[str]:
    out = [_md_heading(c), ""]
    if c.shadows:
        out += [f"**{_md_escape(shadow_words(c))}**", ""]
    if c.title:
        out += [_md_paragraph(c.title), ""]
    st = _md_statement(c.statement)
    if st:
        out += [st, ""]
    out += [f"Kind: {c.kind}, {_md_escape(kind_words(c))}.", ""]
    if c.printed:
        out += _md_results(c.printed)
    dims = grouped_dimension_checks(c)
    if dims:
        out += ["Rank and count statements (at each size, from the most rigorous method that ran; the sizes at "
                "which a check says the same thing share a row):", ""]
        out += _md_table(["check", "sizes (n,r)", "method", "outcome", "what was computed"],
                         [[_md_cell(name), _md_cell(size), m, st if st == "as printed" else f"**{st}**",
                           _md_cell(unicode_words(engine_words(detail)))] for name, size, m, st, detail in dims], "lllll")
    how = c.how_obtained()
    if how:
        out += ["How the verdicts were obtained:", ""]
        out += [f"- {m}: {_md_escape(unicode_words(engine_words(text)))}" for m, text in how] + [""]
    where, traced, graphs = c.traced()
    if traced:
        out += [f"{_md_escape(traced_intro(where, graphs, c.expect, c.traced_sizes()))}:", ""]
        out += [f"- {_md_escape(name) + ': ' if name else ''}{_md_escape(traced_words(text))}"
                for name, text, _tex in traced] + [""]
    if any(r.derivation and r.verdict == "proved" for r in c.printed):
        out += ["The dimension-free derivation (residual, rules applied, normal form) is in "
                "`verification-runs.tex`.", ""]
    summaries = certificate_summaries(c.printed).values()
    out += [_md_escape(line) + "." for line in summaries] + ([""] if summaries else [])
    notes = c.notes()
    if notes:
        out += ["Notes:", ""]
        out += [f"- {_md_cell(r.size)} {r.method}: {_md_cell(unicode_words(engine_words(r.message)))}" for r in notes] + [""]
    if c.failures:
        out += ["Fails as printed: see [Errata](#errata).", ""]
    elif c.variants:
        out += [f"{len(c.variants)} candidate correction(s) also checked: see [Errata](#errata).", ""]
    return out


#: at most this many rerun commands of failures listed per erratum
MAX_ERRATUM_RERUNS = 8


def _erratum_facts(c: ClaimResults) -> dict[str, Any]:
    """What a referee's note on a printed failure needs: where it holds as printed, the rerun command
    of every failure (one per size and method), and the corrections verified at every size."""
    holds = sorted({(r.n, r.r) for r in c.printed if r.n is not None and r.verdict in PASSING}, key=_size_key)
    fails = sorted({(r.n, r.r) for r in c.failures if r.n is not None}, key=_size_key)
    reruns = list(dict.fromkeys(r.rerun for r in c.failures if r.rerun))
    planned = planned_sizes(c)
    verified = [var for var, rs in c.variants.items() if correction_summary(rs, planned)[0] == "verified"]
    free = [r for r in c.printed if r.n is None]
    return {"holds": [s for s in holds if s not in fails], "fails": fails, "reruns": reruns,
            "verified": verified, "free": free[0].verdict if free else None}


def _note_heading(c: ClaimResults) -> str:
    """A paper's erratum is a note for its authors; a statement of one's own (no label of the paper, or a claims
    file's, whatever labels it cites) is not."""
    return "Note for the authors." if c.paper and not c.own else "Note."


def _erratum_note(c: ClaimResults, facts: dict[str, Any], escape=lambda s: s, correction=lambda s: s,
                  words=lambda s: s) -> str:
    """One paragraph a referee could send: the place of the misprint and the labels it involves, where it fails,
    the witness, the correction (``escape`` renders the prose, ``correction`` a correction's description,
    ``words`` the place of the misprint)."""
    w = c.failures[0]
    where = (f"Appendix {c.section[1:]}, " if c.section.startswith("A") else f"§{c.section}, ") \
        if c.section and not c.shadows and not all(p in paperref.table() for p in c.paper) else ""
    at = f"{where}{labels(c.paper, c.unlabelled)}".removesuffix(", ")
    if c.place:
        # the misprint sits beside the labelled statements (in a proof, a remark, a paragraph): named first, so
        # that the authors do not look for it in a correct theorem
        lead = escape("In ") + words(c.place) + escape(f" (involves: {at}), the " if at else ", the ")
    else:
        lead = escape(f"In {at}, the " if at else "The ")
    text = f"statement as printed {_fails_holds_text(facts['fails'], facts['holds'])}"
    small = small_witness_of(c)
    if small is not None:
        text += f". A witness to check by hand, at size {small[0].size}, follows"
    else:
        text += f". A witness: size {w.size}, method {w.method}"
        if w.seed is not None:
            text += f", seed {w.seed}"
        if w.residual:
            text += f", residual {short(w.residual, 120)}"
    text = lead + escape(text + ".")
    if facts["verified"]:
        text += escape(" It holds at every size checked with the correction: ") \
            + escape("; or ").join(correction(v) for v in facts["verified"]) + escape(".")
    elif c.variants:
        text += escape(" No candidate correction was verified at every size.")
    return text


def _errata_body(claims: list[ClaimResults], escape: Callable[[str], str], erratum: Callable[[ClaimResults], list[str]],
                 corrections: Callable[[ClaimResults], list[str]]) -> list[str]:
    """The errata section of either document: each claim that fails as printed, then the candidate
    corrections checked for claims that hold as printed."""
    errata = [c for c in claims if c.failures]
    out = [escape(ERRATA_INTRO), ""] if errata else ["No statement failed as printed.", ""]
    for c in errata:
        out += erratum(c)
    others = [c for c in claims if c.variants and not c.failures]
    if others:
        out += ["Candidate corrections were also checked for claims that hold as printed:", ""]
        for c in others:
            out += corrections(c)
    return out


@functools.lru_cache(maxsize=1)
def _catalog_claims() -> dict[str, Any]:
    """The paper's catalog's claims by id, for the metadata the report reads from a claim itself."""
    from stiefelsym.claims import load_catalog
    return {c.id: c for c in load_catalog()}


def unlabelled_statements(cid: str) -> list[str]:
    """The statements of the paper a catalog claim checks that have no label, by their printed names
    (``@claim(..., unlabelled=...)``): "Theorem 4.3"."""
    c = _catalog_claims().get(cid)
    return list(c.unlabelled) if c is not None else []


def erratum_nature(cid: str) -> str:
    """The nature of the place of the paper a catalog erratum fails through (``@claim(..., nature=...)``): "formula",
    "size", "range", "statement" or "literal"; "" where the claim says none."""
    c = _catalog_claims().get(cid)
    return c.nature if c is not None else ""


def encoded_statements() -> dict[str, str]:
    """The catalog's errata whose display is the tool's encoding of words of the paper (a size read as an equation
    between sizes, "diffeomorphic to SO(n)" read as det X = 1), not a formula the paper prints, each with those words
    as its claim declares them (``@claim(..., encodes=...)``, in the ASCII scripts of :func:`unicode_words` and
    :func:`tex_words`): their display is headed as the encoding, beside the printed words."""
    return {cid: c.encodes for cid, c in _catalog_claims().items() if c.encodes}


def statement_heading(c: ClaimResults, words: Callable[[str], str]) -> str:
    """The words over an erratum's display: "As printed:", or, where the display is the tool's encoding of words of
    the paper (:func:`encoded_statements`), that it is, with those words (``words`` sets them)."""
    printed = encoded_statements().get(c.id) if not (c.shadows or c.claims_file) else None
    if printed is None:
        return "As printed:"
    return f"Checked as (the tool's encoding of the printed words “{words(printed)}”, not a formula of the paper):"


def _md_erratum(c: ClaimResults) -> list[str]:
    facts = _erratum_facts(c)
    out = [_md_heading(c), ""]
    if c.shadows:
        out += [f"**{_md_escape(shadow_words(c))}**", ""]
    out += [f"**{_note_heading(c)}** "
            f"{_md_escape(_erratum_note(c, facts, correction=lambda v: _with_change(c, v, note=True), words=unicode_words))}",
            ""]
    st = _md_statement(c.statement)
    if st:
        out += [statement_heading(c, lambda t: _md_escape(unicode_words(t))), "", st, ""]
    out += ["Failing runs: " + ", ".join(f"{_md_escape(r.size)} {r.method}" for r in c.failures)
            + ".", ""]
    w = _witness_run(c)
    if w.erratum:
        out += [f"What is wrong: {_md_escape(unicode_words(greek_words(w.erratum)))}", ""]
    out += _md_small_witness(c)
    if small_witness_of(c) is not None and "point" in (w.witness or {}):
        out += [f"The seeded run that found the failure: size {_md_escape(w.size)}, method {w.method}"
                + (f", seed {w.seed}" if w.seed is not None else "") + f"; rerun: {_md_code(w.rerun)}.", ""]
        return _md_erratum_tail(c, facts, w, out)
    out += [_md_escape(_witness_heading(w)), ""]
    out += [f"- {_md_escape(k)}: {_md_code(v)}" for k, v in witness_lines(w.witness)] \
        or [f"- ({_md_escape(no_point_text(w))})"]
    if w.residual:
        out.append(f"- residual: {_md_code(short(w.residual, WITNESS_WIDTH))}")
    # the checks in the paper's notation, as the PDF sets them (pᵢ ∧ pⱼ, 1 ≤ i < j ≤ n, Iₙ, λ)
    out += [f"- {_md_escape(unicode_words(greek_words(check_line(ch))))}" for ch in w.checks if ch.status != "zero"][:10]
    if w.message:
        out.append(f"- {_md_escape(w.message)}")
    if w.rerun:
        out.append(f"- rerun: {_md_code(w.rerun)}")
    out.append("")
    return _md_erratum_tail(c, facts, w, out)


def _shown(items: Sequence[Any], limit: int) -> int:
    """How many of ``items`` a list shows when it shows at most ``limit`` and says how many more: all of them
    when only one would be left, which takes no more room than the line that says so."""
    return len(items) if len(items) <= limit + 1 else limit


def grouped_reruns(commands: Sequence[str]) -> list[str]:
    """Rerun commands of one claim, those that differ only in their size joined into one command per method and
    seed, or per method where the runs draw nothing (``--size`` repeated: the same runs, each with its own draws, which depend on its size and not on the
    other runs); a command alone in its group, and any other command, as it is.  The order of first appearance
    is kept."""
    groups: dict[tuple[str, ...], list[str]] = {}
    out: list[Any] = []
    for cmd in commands:
        try:
            words = shlex.split(cmd)
        except ValueError:
            words = []
        if (len(words) in (7, 9) and words[:2] == ["stiefelsym", "verify"] and words[3] == "--size"
                and words[5] == "--method" and (len(words) == 7 or words[7] == "--seed")):
            key = (words[2], words[6]) + tuple(words[7:])
            if key not in groups:
                groups[key] = []
                out.append(key)
            groups[key].append((words[4], cmd))
        else:
            out.append(cmd)
    return [x if isinstance(x, str) else groups[x][0][1] if len(groups[x]) == 1 else " ".join(
        shlex.quote(w) for w in ["stiefelsym", "verify", x[0], "--method", *x[1:]]
        + [v for size, _cmd in groups[x] for v in ("--size", size)]) for x in out]


def _md_erratum_tail(c: ClaimResults, facts: dict[str, Any], w: Result, out: list[str]) -> list[str]:
    others = grouped_reruns([x for x in facts["reruns"] if x != w.rerun])
    if others:
        out += ["Every other failure, reproducible with:", ""]
        shown = _shown(others, MAX_ERRATUM_RERUNS)
        out += [f"- {_md_code(x)}" for x in others[:shown]]
        if len(others) > shown:
            out.append(f"- … and {len(others) - shown} more (in results.json)")
        out.append("")
    # the verified corrections are in the note for the authors and in the list of candidates below: not
    # a third time here
    return out + _md_corrections(c)


def _witness_run(c: ClaimResults) -> Result:
    """The failing run an erratum shows: the one whose small witness is checked by hand, when there is one (the
    hand witness and the run's own witness block then speak of one size), else the first."""
    small = small_witness_of(c)
    return small[0] if small is not None else c.failures[0]


def small_witness_of(c: ClaimResults) -> tuple[Result, dict[str, Any]] | None:
    """The failing run that carries a small witness (see :mod:`stiefelsym.methods.witness`), and that witness."""
    for r in c.failures:
        if isinstance(r.witness, dict) and isinstance(r.witness.get("small"), dict):
            w = r.witness["small"]
            if w.get("kind") != "count" and (w.get("complete") is False or not w.get("letters")):
                continue    # a point that does not state every parameter the residual reads: not for a hand check
            return r, w
    return None


WITNESS_SCRIPT_DIR = "witnesses"


def _point_witness(w: dict[str, Any]) -> tuple[list[str], list[str], str]:
    """Of a small witness at a point: the constraints found to hold exactly, each letter as LaTeX
    ("X = \\begin{pmatrix}…"), and the failing value as LaTeX."""
    from stiefelsym.methods.witness import decoded, matrix_tex, q_tex
    w = decoded(w)
    on = [k for k, ok in w.get("on T*V", {}).items() if ok]
    parts = [_tex_letter(f"{_own_name_tex(name, w['letters'])} = {matrix_tex(v) if isinstance(v, list) else q_tex(v)}")
             for name, v in w["letters"].items()]
    return on, parts, q_tex(Fraction(w["value"]))


#: the complex Stiefel variety's constraints (11) §10 and their derivative as the paper writes them, for the keys
#: of a witness's check (computed realified: they hold iff their realified forms do)
_COMPLEX_ON = {"Z*Z = I": ("Z̄ᵀZ = Iᵣ", r"$\bar Z^TZ=I_r$"), "Z*V + V*Z = 0": ("Z̄ᵀV + V̄ᵀZ = 0", r"$\bar Z^TV+\bar V^TZ=0$")}


def _witness_place(w: dict[str, Any], on: list[str], tex: bool) -> str:
    """Where a witness point lies: ", a point of T*V (XᵀX = I, … hold exactly)", or for the complex Stiefel variety
    ", a point (Z, V) of TW_{n,r}, V = Ż, …" (Z̄ᵀ as the paper writes it); "" when no constraint was checked."""
    if not on:
        return ""
    if "Re Z" in w.get("letters", {}) and all(k in _COMPLEX_ON for k in on):
        held = ", ".join(_COMPLEX_ON[k][tex] for k in on)
        if tex:
            return (r", a point $(Z,V)$ of $TW_{n,r}$, $V=\dot Z$, given by the real and imaginary parts of $Z$ and $V$ ("
                    + held + " hold exactly)")
        return (", a point (Z, V) of TW\\_{n,r}, V = Ż, given by the real and imaginary parts of Z and V ("
                + held + " hold exactly)")
    # a second point (Y, Q: the double and the coupled systems) puts the witness on another phase space than T*V
    space = "the claim's phase space" if any("Y" in k or "Q" in k for k in on) else "T*V"
    if tex:
        return tex_escape(f", a point of {space} ({', '.join(on)} hold exactly)")
    return f", a point of {_md_escape(space)} ({', '.join(_md_escape(k) for k in on)} hold exactly)"


def _realified(w: dict[str, Any]) -> str:
    """What the residual of a point of TW_{n,r} is: the complex residual realified, as the engine computes it."""
    return (" realified (each r × r block B written as the real block matrix (Re B, −Im B; Im B, Re B)),"
            if "Re Z" in w.get("letters", {}) else "")


def _md_small_witness(c: ClaimResults) -> list[str]:
    found = small_witness_of(c)
    if found is None:
        return []
    r, w = found
    if w.get("kind") == "count":
        return [_count_witness_text(c, r, w, _md_words) + (f" The script `{WITNESS_SCRIPT_DIR}/{c.id}.py` "
                                                            "(Python with sympy, no stiefelsym) recomputes it from "
                                                            "the paper's definitions." if _has_script(c) else ""), ""]
    on, parts, value = _point_witness(w)
    out = [f"**A witness to check by hand** at (n, r) = {r.size}" + _witness_place(w, on, False) + ":", ""]
    out += ["$$" + r",\quad ".join(parts) + "$$", ""]
    out += [f"There the residual {_md_escape(_entry_words(w['entry'], _realified(w)))} is ${value} \\neq 0$."
            + (f" A self-contained script (Python with sympy, no stiefelsym) rebuilds this point and evaluates "
               f"the printed formula and the correction: `{WITNESS_SCRIPT_DIR}/{c.id}.py`." if _has_script(c) else ""),
            ""]
    return out


def _tex_small_witness(c: ClaimResults) -> list[str]:
    found = small_witness_of(c)
    if found is None:
        return []
    r, w = found
    if w.get("kind") == "count":
        # in words whose ASCII scripts are set as scripts: diag(I_{n-r}, B^{-1})
        return [r"\textbf{A witness to check by hand:} " + _count_witness_text(c, r, w, tex_words)
                + ((tex_escape(" The script ") + _tt(f"{WITNESS_SCRIPT_DIR}/{c.id}.py")
                    + tex_escape(" (Python with sympy, no stiefelsym) recomputes it from the paper's definitions."))
                   if _has_script(c) else ""), ""]
    on, parts, value = _point_witness(w)
    out = [r"\textbf{A witness to check by hand} " + tex_escape(f"at (n, r) = {r.size}") + _witness_place(w, on, True) + ":"]
    rows = [r",\quad ".join(parts[k:k + 3]) for k in range(0, len(parts), 3)]
    # three letters a line, the whole shrunk to the line's width when wider; the rows of a matrix of fractions
    # spaced so that the fractions do not touch
    out += [r"\begin{center}\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{$\displaystyle"
            r"\renewcommand{\arraystretch}{1.4}\begin{gathered}" + r"\\[2pt]".join(rows) + r"\end{gathered}$}\end{center}"]
    out += [tex_words(f"There the residual {_entry_words(w['entry'], _realified(w))} is ") + f"${value} \\neq 0$."
            + ((tex_escape(" A self-contained script (Python with sympy, no stiefelsym) rebuilds this point and "
                           "evaluates the printed formula and the correction: ")
                + _tt(f"{WITNESS_SCRIPT_DIR}/{c.id}.py") + ".") if _has_script(c) else ""), ""]
    return out


def _count_witness_text(c: ClaimResults, r: Result, w: dict[str, Any], escape: Any) -> str:
    """The two numbers of a count's witness, or, where the claim's count template declares that the printed
    statement is about a kernel (``KERNEL``, see :func:`count_kernel`), the paper's quantity, the number of
    unknowns minus each rank, with the two ranks of the check (the numbers the engine computed) beside it."""
    head = "**A witness to check by hand:** " if escape is _md_words else ""
    kernel = None if c.own else count_kernel(c.id)
    # a rank computed at an exact point bounds the generic rank from below only: a rank above the printed one
    # refutes it, and says no more than "at least" (the kernel: "at most")
    lower = any(ch.name == w["check"] and "so rank >= " in (ch.detail or "") for ch in r.checks)
    if kernel is not None:
        quantity, unknowns, system = kernel
        value, paper = w["value"], w["paper"]
        if lower:
            return head + escape(f"at (n, r) = {r.size}, {quantity}: at most {unknowns - value}, where the printed "
                                 f"statement gives {unknowns - paper}; that is {unknowns} − {value} against {unknowns} − "
                                 f"{paper}, where {value} is the rank of {system} at an exact point, so that its rank at a "
                                 f"generic point is at least {value}.")
        return head + escape(f"at (n, r) = {r.size}, {quantity}: computed {unknowns - value}, where the printed "
                             f"statement gives {unknowns - paper}; that is {unknowns} − {value} against {unknowns} − "
                             f"{paper}, where {value} is the computed rank of {system}.")
    what = w.get("meaning") or unicode_name(w["check"])
    if lower:
        return head + escape(f"at (n, r) = {r.size}, {what}: at least {w['value']} (the rank at an exact point), where "
                             f"the printed statement gives {w['paper']}.")
    return head + escape(f"at (n, r) = {r.size}, {what}: computed {w['value']}, where the printed statement "
                         f"gives {w['paper']}.")


def count_kernel(cid: str) -> tuple[str, int, str] | None:
    """Of a claim whose count template computes a rank where the printed statement gives the dimension of the kernel
    (the number of invariant forms, of independent solutions): the template's ``KERNEL = (the quantity in words, the
    number of unknowns, the system in words, which name that number)``, a literal the template's own ``counts()``
    checks against the unknowns it builds; None for any other claim."""
    from stiefelsym.methods.witness_scripts import template_constant, template_kind
    kernel = template_constant(cid, "KERNEL") if template_kind(cid) == "count" else None
    if kernel is None:
        return None
    quantity, unknowns, system = kernel
    return str(quantity), int(unknowns), str(system)


def _entry_words(entry: str, realified: str = "") -> str:
    """"d𝓛(λ)/dt − [𝓛(λ), 𝓐(λ)], entry (1,1)," for a matrix residual; the name alone for a scalar one; with
    ``realified`` (how the matrix was made real) said after the name."""
    text = unicode_name(entry)
    if realified and ", entry (" in text:
        text = text.replace(", entry (", "," + realified + " entry (", 1)
    return text + "," if "entry (" in text else text


def _has_script(c: ClaimResults) -> bool:
    """Whether a witness script is written for the claim: a template of the catalog's claim of its id recomputes the
    paper's formula, never a claims file's claim's (which may have that id; its scripts are not written)."""
    from stiefelsym.methods.witness_scripts import template
    return not c.own and template(c.id) is not None


#: a claim's own parameter named by a Greek letter's name is written as that letter
GREEK_NAMES = frozenset("alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau "
                        "upsilon phi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega".split())


def _own_name_tex(name: str, letters: dict[str, Any]) -> str:
    """A claim's own name of a parameter (letters, digits, underscores) in math: the Greek letter it names
    unless the witness has that letter of the engine's (``letters``: the witness's names), else upright when
    longer than one letter, its underscores as such (h_2 is not h with the subscript 2 of the engine's notation,
    and a_b_c is no double subscript)."""
    if name in GREEK_NAMES:
        case = "CAPITAL" if name[0].isupper() else "SMALL"
        if unicodedata.lookup(f"GREEK {case} LETTER {name.upper().replace('LAMBDA', 'LAMDA')}") not in letters:
            return "\\" + name
    if len(name) > 1 and re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name):
        return r"\mathrm{" + name.replace("_", r"\_") + "}"
    return name


def _tex_letter(part: str) -> str:
    """A letter of a witness in LaTeX: Greek letters and 'Re Z' spelled for math mode."""
    for a, b in (("Ẋ", r"\dot X"), ("Ẏ", r"\dot Y"), ("λ", r"\lambda"), ("κ", r"\kappa"), ("ε", r"\varepsilon"), ("ξ", r"\xi"), ("ζ", r"\zeta"),
                 ("η", r"\eta"), ("θ", r"\theta"), ("Re ", r"\operatorname{Re} "), ("Im ", r"\operatorname{Im} ")):
        part = part.replace(a, b)
    return part


#: what the note for the authors says of a correction whose change of the formula was computed: the note quotes the
#: paper (the place of the error, the registered correction's words); the change as the graphs give it (in the
#: engine's normal form, at the checks' names) is in the list of candidate corrections
NOTE_CHANGE_ELSEWHERE = " (the change of the formula as computed is in the candidate corrections below)"


def _with_change(c: ClaimResults, variant: str, note: bool = False) -> str:
    """A registered correction, in Unicode: its change of the graph in the paper's notation, then its
    own words (the catalog's, unchanged); in the ``note`` for the authors its words alone, which quote the paper,
    and a pointer to the change in the list of candidates."""
    change = change_text(c.change_of(variant))
    if note:
        return unicode_words(variant) + (NOTE_CHANGE_ELSEWHERE if change else "")
    return f"{change} (registered as: {unicode_words(variant)})" if change else unicode_words(variant)


def _tex_with_change(c: ClaimResults, variant: str, note: bool = False) -> str:
    if note:
        return tex_words(variant) + (tex_escape(NOTE_CHANGE_ELSEWHERE) if change_text(c.change_of(variant)) else "")
    change = _tex_change(c.change_of(variant))
    return (f"{change} {{\\small (registered as: {tex_words(variant)})}}" if change else tex_words(variant))


def _md_corrections(c: ClaimResults) -> list[str]:
    if not c.variants:
        return ["No candidate correction was checked.", ""]
    planned = planned_sizes(c)
    rows = []
    for var, rs in c.variants.items():
        status, phrases = correction_summary(rs, planned)
        change = _md_change(c.change_of(var)).replace("|", r"\|")
        label = _status_label(status, rs)
        rows.append([change or "–", _md_cell(unicode_words(var)), f"**{label}**" if status == "verified" else label,
                     _md_cell("; ".join(phrases))])
    # after the colon the sentence goes on in lower case, as in the PDF
    where = f" {_corrections_rule(planned)}" if planned else ""
    return [f"Candidate corrections:{where}", ""] + _md_table(["correction (change of the formula)", "registered as", "status",
                                                               "runs"], rows, "llll")


# --------------------------------------------------------------------------- LaTeX

TEX_PREAMBLE = r"""\documentclass[10pt,a4paper]{article}
\usepackage[margin=2.2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{longtable,booktabs,array,graphicx}
\DeclareMathOperator{\tr}{tr}
\DeclareMathOperator{\diag}{diag}
\DeclareMathOperator{\ad}{ad}
\DeclareMathOperator{\Ad}{Ad}
\DeclareMathOperator{\rank}{rank}
\DeclareMathOperator{\ddim}{ddim}
\DeclareMathOperator{\pr}{pr}
\DeclareMathOperator{\Span}{span}
\providecommand{\R}{\mathbb{R}}
\providecommand{\g}{\mathfrak{g}}
\newcolumntype{P}[1]{>{\raggedright\arraybackslash}p{#1}}
% the default bullet and \S, \P, \dag in text mode come from a TS1 font that
% Debian's texlive-latex-base has only as bitmaps
\renewcommand{\labelitemi}{$\bullet$}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.6ex}
% claims are subsections: a little space above, less below
\makeatletter
\renewcommand\subsection{\@startsection{subsection}{2}{\z@}{1.6ex plus .4ex minus .2ex}{0.6ex}{\normalfont\normalsize\bfseries}}
% displays (center) and lists with little space around them
\def\@listi{\leftmargin\leftmargini \parsep 0pt \topsep 2pt plus 1pt \itemsep 0pt}
\let\@listI\@listi
\@listi
\makeatother
\setlength{\LTpre}{0.6ex}
\setlength{\LTpost}{0.6ex}
\raggedbottom
\sloppy
\usepackage[hidelinks]{hyperref}
"""


def _tex_bound(p: float | None) -> str:
    if p is None:
        return "--"
    if p == 0:
        return "0"
    mant, exp = f"{p:.1e}".split("e")
    return f"${mant}\\cdot 10^{{{int(exp)}}}$"


def _tex_verdict(r: Result) -> str:
    v = r.verdict if r.verdict not in ("fails", "error") else f"\\textbf{{{r.verdict}}}"
    return v if r.expected else v + r" \textsc{unexpected}"


def _tt(text: Any) -> str:
    """Monospace text that may break at spaces, after commas (not between two numbers) and inside long runs of
    digits."""
    # (not inside a pair of numbers: "--size 2,2" stays whole, for copying; an option stays with its value, the
    # line breaks before "--size", never after it)
    text = re.sub(r"(?<!\S)(--[a-z][a-z-]*) (?=[^-\s])", "\\1\u00a0", str(text))
    body = re.sub(r",(?![0-9])", r",\\allowbreak{}", tt_escape(text)).replace(";", r";\allowbreak{}")
    body = re.sub(r"[0-9/]{16,}", lambda m: r"\allowbreak{}".join(m.group(0)[i:i + 12]
                                                                   for i in range(0, len(m.group(0)), 8)), body)
    return r"\texttt{" + body + "}"


def _tex_results(rs: list[Result]) -> list[str]:
    out = [r"{\small", r"\begin{longtable}{@{}llP{2.2cm}rP{5.0cm}rl@{}}", r"\toprule",
           r"size $(n,r)$ & method & verdict & time & certificate & seed & $p$ (false pass)\\",
           r"\midrule", r"\endhead"]
    for r in rs:
        out.append(" & ".join([
            tex_escape(r.size), tex_escape(r.method), _tex_verdict(r),
            tex_escape(format_seconds(r.seconds)),
            re.sub(r"([*+,=])", r"\1\\allowbreak{}", tex_words(short(certificate_words(
                quoted_value_words(r.certificate) if of_catalog(r) else r.certificate), 120) or "--")),
            str(r.seed if r.seed is not None else "--"), _tex_bound(r.false_pass_bound)]) + r"\\")
    return out + [r"\bottomrule", r"\end{longtable}", "}"]


def _tex_items(items: list[str], ragged: bool = False) -> list[str]:
    """An itemize of ``items``; ``ragged``: set ragged right, for items in typewriter type (commands), whose spaces do
    not stretch: justified, their lines are underfull."""
    if not items:
        return []
    body = ([r"\begin{itemize}\setlength{\itemsep}{0pt}\setlength{\parskip}{0pt}"]
            + [r"\item " + x for x in items] + [r"\end{itemize}"])
    return [r"{\raggedright"] + body + [r"\par}"] if ragged else body


def _toc_section(title: str) -> list[str]:
    return [r"\section*{" + title + "}", r"\addcontentsline{toc}{section}{" + title + "}"]


def headline(claims: list[ClaimResults], paper: bool = True) -> tuple[str, list[ClaimResults]]:
    """What a reader came for, in one paragraph: how many claims hold, which fail as printed (``paper``:
    the claims are the paper's catalog; otherwise a claims file's, possibly with the catalog's)."""
    errata = [c for c in claims if c.failures]
    free = [c for c in claims if any(r.n is None and r.verdict == "proved" for r in c.printed)]
    corrected_free = [c for c in claims
                      if any(r.n is None and r.verdict == "proved" for vs in c.variants.values() for r in vs)]
    scopes = Counter(next(free_scope(r) for r in c.printed if r.n is None and r.verdict == "proved") for c in free)
    # the claims stated at one r (or at r = 1 and at r = n) by that scope, the unions last
    one_r = sorted(((k, v) for k, v in scopes.items() if k != "all n, r"), key=lambda kv: (" and " in kv[0], kv[0]))
    at_once = (f"{len(free)} of them proved for every n and r at once" if not one_r else
               f"{len(free)} of them proved for every size at once: {scopes['all n, r']} for every n and r, "
               "and, stated at particular r, for every n: "
               + ", ".join(f"{v} {k.removeprefix('every n ')}" for k, v in one_r))
    holds = sum(map(holds_at_every_size, claims))
    proved = sum(map(proved_at_every_size, claims))
    # a claim that no method decided at some computed size is not said to hold there
    undecided = [c for c in claims if not c.failures and not holds_at_every_size(c)]
    open_ = [c.id for c in undecided if any(r.verdict in PASSING for r in c.printed)]
    nowhere = [c.id for c in undecided if not any(r.verdict in PASSING for r in c.printed)]
    named = ", ".join(open_[:5]) + (f" and {len(open_) - 5} more" if len(open_) > 5 else "")
    unnamed = ", ".join(nowhere[:5]) + (f" and {len(nowhere) - 5} more" if len(nowhere) > 5 else "")
    whose = (f"the catalog's {len(claims)} claims (the paper's checkable statements, and some forms of them: "
             f"corrected, more general, or lemmas of a proof)" if paper else
             f"the {len(claims)} {'statement' if len(claims) == 1 else 'statements'} verified")
    text = (f"Of {whose}, {holds} {'holds' if holds == 1 else 'hold'} as printed at "
            f"every size computed{_proved_words(claims, holds, proved, at_once)}, "
            + (f"{len(open_)} {'holds' if len(open_) == 1 else 'hold'} where decided but "
               f"{'was' if len(open_) == 1 else 'were'} left undecided at some size ({named}), " if open_ else "")
            + (f"{len(nowhere)} {'was' if len(nowhere) == 1 else 'were'} decided at no size ({unnamed}), "
               if nowhere else "")
            + f"and {len(errata)} {'fails' if len(errata) == 1 else 'fail'} as printed{_misprint_words(errata) if paper else ''}"
            f"{_errata_words(errata)} ({_corrections_proved_words(corrected_free, errata if paper else [])})."
            + (_slips_words(errata) if paper else "") + _shadowing_words(claims))
    return text, errata


def _proved_words(claims: list[ClaimResults], holds: int, proved: int, at_once: str) -> str:
    """The headline's words after the count of the claims that hold as printed at every size computed: how
    many of them are proved at every size and how many rest, at some size, on a randomized or numerical
    check alone (with the largest false-pass bound of those checks)."""
    if holds == 0:
        return ""
    if proved == holds:
        return f" ({'it is' if holds == 1 else 'all are'} proved at every size computed; {at_once})"
    rest = holds - proved
    sizes = [r for c in claims if holds_at_every_size(c) and not proved_at_every_size(c)
             for r in c.printed if r.n is not None and r.verdict in PASSING
             and not any(o.verdict == "proved" and (o.n, o.r) == (r.n, r.r) for o in c.printed)]
    bounds = [r.false_pass_bound for r in sizes if r.verdict == "checked" and r.false_pass_bound is not None]
    numeric = any(r.verdict == "numeric" for r in sizes)
    # a randomized exact check has a false-pass probability; a numerical one has none (it holds within an error
    # bound of floating-point arithmetic), and is not said to have one
    randomized = ("at random points" + (f" (false-pass probability at most {_power_of_ten(max(bounds))} per check)"
                                        if bounds else ""))
    numerical = "numerically (within a floating-point error bound; no probability attaches to such a check)"
    kinds = (randomized if not numeric else f"{randomized} or {numerical}"
             if any(r.verdict == "checked" for r in sizes) else numerical)
    return (f" ({proved} proved at every size computed; {at_once}; " if proved else " (none proved at every size computed: ")\
        + (f"{rest} {'rests' if rest == 1 else 'rest'} at some size on a check {kinds} alone, no method proving "
           f"{'it' if rest == 1 else 'them'} there)")


def _power_of_ten(p: float) -> str:
    """A small probability as m·10⁻ᵏ (one decimal of the mantissa), in Unicode."""
    mant, exp = f"{p:.1e}".split("e")
    return f"{mant}·10{str(int(exp)).translate(str.maketrans('-0123456789', '⁻⁰¹²³⁴⁵⁶⁷⁸⁹'))}"


def _shadowing_words(claims: list[ClaimResults]) -> str:
    """The headline's sentence on the claims of claims files that have catalog claims' ids ("" without one): what
    their verdicts are about, so that none is read as a verdict on the paper's statement of that id."""
    shadows = [c for c in claims if c.shadows]
    if not shadows:
        return ""
    one = len(shadows) == 1
    ids = ", ".join(c.id for c in shadows[:5]) + (f" and {len(shadows) - 5} more" if len(shadows) > 5 else "")
    return (f" {len(shadows)} of the claims verified ({ids}) {'is a claim' if one else 'are claims'} of a claims file "
            f"with the id of a catalog claim, which {'it' if one else 'they'} replaced in this run: "
            f"{'its verdicts are' if one else 'their verdicts are'} about the file's "
            f"{'statement' if one else 'statements'}, not the paper's (see the section of "
            f"{'its' if one else 'their'} claims file).")


def _slips_words(errata: list[ClaimResults]) -> str:
    """The slips of the paper that the errata's texts report in passing and that make no statement fail, as a
    sentence after the headline's count of errors ("" when there is none)."""
    slips = [(c, s) for c in errata for s in c.slips]
    if not slips:
        return ""
    one = len(slips) == 1
    return (f" Besides these failures, {len(slips)} {'slip' if one else 'slips'} of the paper that "
            f"{'makes' if one else 'make'} no statement fail {'is' if one else 'are'} reported in passing: "
            + "; ".join(f"{s} (see {c.id})" for c, s in slips) + ".")


#: the catalog's sections as the paper numbers them (its appendices are §9 and §10)
_PAPER_SECTION = {"A1": "9", "A2": "10"}

TYPO_INTRO = ("Slips of the paper in passages whose mathematics holds: none makes a statement fail, and none is "
              "counted among the errata above.  Each is given with its place (the section, the paper's printed "
              "numbers, the line of the paper's LaTeX source), what is printed, what is meant, and the evidence "
              "from the paper itself.  A slip marked probable has a clear intended reading that the paper does not "
              "force; the claims named after a slip compute the intended reading.")


def typographical_slips(meta: dict[str, Any]) -> list[Any]:
    """The catalog's list of typographical slips (:mod:`stiefelsym.proofs.slips`) for a report of a run of the
    whole catalog; none for a report of some claims or of a claims file."""
    if meta.get("claims_files") or not meta.get("whole_catalog"):
        return []
    from stiefelsym.proofs.slips import SLIPS
    return list(SLIPS)


SPELLING_INTRO = ("Slips of spelling and punctuation, without mathematical content.  Each is given with its place "
                  "(the section or environment, the line of the paper's LaTeX source), the source's text as it "
                  "stands there and the text meant, in the same form.")


def spelling_slips(meta: dict[str, Any]) -> list[Any]:
    """The catalog's list of the paper's slips of spelling and punctuation (:mod:`stiefelsym.proofs.slips`), for
    the reports that list its typographical slips (:func:`typographical_slips`)."""
    if meta.get("claims_files") or not meta.get("whole_catalog"):
        return []
    from stiefelsym.proofs.slips import SPELLING
    return list(SPELLING)


def _typo_words(n: int, spelling: int = 0) -> str:
    """The headline's sentence on the lists of typographical slips and of slips of spelling and punctuation
    ("" without either)."""
    typo = f"the section Typographical slips lists {n} more slips, in passages whose mathematics holds" if n else ""
    spell = (f"the section Spelling and punctuation lists {spelling} "
             f"{'slip' if spelling == 1 else 'slips'} without mathematical content" if spelling else "")
    words = "; ".join(x for x in (typo, spell) if x)
    return f" {words[:1].upper()}{words[1:]}." if words else ""


def _slip_place(slip: Any) -> str:
    """Where a slip is, in plain words: its place, then the section (where the place does not name it) and the
    line(s) of the source, "The proof of Lemma 6.2 (§6, source line 1355)"."""
    lines = f"source line{'s' if any(c in slip.lines for c in ',–') else ''} {slip.lines}"
    if not slip.section:
        where = f"({lines})"
    else:
        sec = _PAPER_SECTION.get(slip.section, slip.section)
        where = f"({lines})" if f"§{sec}" in slip.where else f"(§{sec}, {lines})"
    return f"{slip.where[:1].upper()}{slip.where[1:]} {where}"


def _slip_parts(slip: Any) -> tuple[str, str]:
    """(place, the rest) of one slip in plain words (scripts in ASCII, as the catalog's words are written):
    where it is, then what is printed, what is meant, the evidence, and whether it is probable and which
    claims compute the intended reading."""
    def sentence(text: str) -> str:
        return text if text.endswith((".", ".”")) else text + "."
    rest = (f"Printed: {sentence(slip.printed)}  Meant: {sentence(slip.meant)}  Evidence: {slip.why}"
            + ("  Probable." if slip.probable else "")
            + (f"  The intended reading is computed by {', '.join(slip.claims)}." if slip.claims else ""))
    return _slip_place(slip), rest


def _md_typo_section(slips: list[Any]) -> list[str]:
    if not slips:
        return []
    out = ["## Typographical slips", "", _md_escape(TYPO_INTRO), ""]
    for slip in slips:
        place, rest = _slip_parts(slip)
        out.append(f"- **{_md_escape(unicode_words(place))}.** {_md_escape(unicode_words(rest))}")
    return out + [""]


def _tex_typo_section(slips: list[Any]) -> list[str]:
    if not slips:
        return []
    out = _toc_section("Typographical slips") + [tex_escape(TYPO_INTRO), ""]
    items = []
    for slip in slips:
        place, rest = _slip_parts(slip)
        items.append(r"\textbf{" + tex_words(place) + ".} " + tex_words(rest))
    return out + _tex_items(items)


def _md_spelling_section(slips: list[Any]) -> list[str]:
    if not slips:
        return []
    out = ["## Spelling and punctuation", "", _md_escape(SPELLING_INTRO), ""]
    for slip in slips:
        note = f": {_md_escape(unicode_words(slip.note))}" if slip.note else "."
        out.append(f"- **{_md_escape(unicode_words(_slip_place(slip)))}.** Printed {_md_code(slip.printed)}, "
                   f"meant {_md_code(slip.meant)}{note}")
    return out + [""]


def _tex_spelling_section(slips: list[Any]) -> list[str]:
    if not slips:
        return []
    out = _toc_section("Spelling and punctuation") + [tex_escape(SPELLING_INTRO), ""]
    items = []
    for slip in slips:
        note = f": {tex_words(slip.note)}" if slip.note else "."
        items.append(r"\textbf{" + tex_words(_slip_place(slip)) + ".} Printed " + _tt_words(slip.printed)
                     + ", meant " + _tt_words(slip.meant) + note)
    return out + _tex_items(items)


def _tt_words(text: str) -> str:
    """Monospace words (:func:`_tt`) that may break after the hyphen inside a word too ("Semonov-Tian-Shanski": a
    monospace font hyphenates nothing)."""
    return re.sub(r"(?<=[A-Za-z])-(?=[A-Za-z])", r"-\\allowbreak{}", _tt(text))


def _corrections_proved_words(corrected: list[ClaimResults], errata: Sequence[ClaimResults]) -> str:
    """How many distinct corrections were proved for every n and r: the statements of one group of
    :func:`shared_misprints` (of ``errata``: the paper's catalog alone) are repaired by one correction, counted
    once, and the statements they repair are then said too."""
    groups = [g for g in shared_misprints(errata) if any(c in corrected for c in g)]
    distinct = len(corrected) - sum(sum(c in corrected for c in g) - 1 for g in groups)
    words = f"{distinct} {'correction' if distinct == 1 else 'corrections'}"
    if distinct == len(corrected):
        return f"{words} proved for every n and r"
    return (f"{distinct} distinct corrections proved for every n and r, which repair {len(corrected)} of the "
            "statements that fail")


#: how a statement failed, in the headline's words (see :func:`_failure_kind`)
FAILURE_KINDS = {"point": "with an exact witness point (a nonzero residual there)",
                 "number": "with a number computed exactly against the printed one (a size, dimension, rank or count, "
                           "or a truth value coded 1/0)",
                 "identically": "said not to vanish and proved to vanish identically",
                 "points": "said not to vanish and found zero at every random point drawn",
                 "bare": "with no witness point"}


def _failure_kind(c: ClaimResults) -> str:
    """``point``: some failing run has an exact witness point (its nonzero residual); ``number``: a rank or count
    computed exactly against the printed one (a misprinted size or dimension reads so); a statement that something
    does not vanish was refuted by the exact method (``identically``) or only at random points (``points``); else
    ``bare``."""
    if any(witness_lines(r.witness) for r in c.failures):
        return "point"
    if any(any(ch.status in DIMENSION_STATUSES for ch in r.checks) for r in c.failures):
        return "number"
    if c.failures[0].kind == "not":
        return "identically" if any(r.method == "exact" for r in c.failures) else "points"
    return "bare"


def _kind_words(kind: str, claims: list[ClaimResults]) -> str:
    """The headline's words for the failures of one kind; a statement said not to vanish says where it vanishes
    (the sizes' rule, "where r = 1 or r = n", when the claims of that kind share one), not "at some size"."""
    words = FAILURE_KINDS[kind]
    if kind in ("identically", "points"):
        rules = {sizerules.rule(f["fails"], f["holds"]) or "" for f in map(_erratum_facts, claims)}
        words += f" where {rules.pop()}" if len(rules) == 1 and "" not in rules else " at some sizes"
    return words


#: the natures of the places of the paper the errata fail through (:data:`stiefelsym.claims.NATURES`), in the
#: headline's words: (one, several, what it is), each said with its count
NATURE_WORDS = {
    "formula": ("misprint in a printed formula", "misprints in a printed formula",
                "a sign, an inverse, a letter or a term"),
    "size": ("misprinted size or index range", "misprinted sizes or index ranges", "Iₙ for I₂ᵣ, GL(n) for GL(r)"),
    "range": ("statement that fails at some of the sizes it is made for",
              "statements that fail at some of the sizes they are made for",
              "a bound on n and r, or exceptional sizes, missed"),
    "statement": ("wrong statement", "wrong statements", "a condition or an identification false as made"),
    "literal": ("statement that fails only when read literally", "statements that fail only when read literally",
                "where a hypothesis is tacit or a formula schematic"),
}


def _nature_words(errata: list[ClaimResults], shared: list[list[ClaimResults]]) -> str:
    """How many places of the paper of each nature the errata fail through (a group of :func:`shared_misprints`
    is one place), "8 misprints in a printed formula (a sign, …), 7 misprinted sizes or index ranges (…), …"; ""
    unless every erratum says its nature (a claims file's need not)."""
    if not errata or any(c.nature not in NATURE_WORDS for c in errata):
        return ""
    places = Counter(c.nature for c in errata)
    for g in shared:
        places[g[0].nature] -= len(g) - 1
    words = [f"{places[k]} {one if places[k] == 1 else several} ({what})"
             for k, (one, several, what) in NATURE_WORDS.items() if places[k]]
    return ", ".join(words[:-1]) + " and " + words[-1] if len(words) > 1 else words[0]


def _nature_tag(c: ClaimResults) -> str:
    """What an erratum in the list after the headline fails through, as the headline counts it ("; nature: a
    misprinted size or index range"); "" where the catalog says nothing (a claims file's claim)."""
    return f"; nature: a {NATURE_WORDS[c.nature][0]}" if c.nature in NATURE_WORDS else ""


def _misprint_words(errata: list[ClaimResults]) -> str:
    """How many places of the paper the failures come from, of each nature (:func:`_nature_words`, as the catalog
    declares it of each erratum), where some statements are repaired by one correction.  Without the natures, a
    place is what fails as printed there, whatever its nature (a false statement, a misprinted size or index, or a
    statement taken literally where a hypothesis is tacit or a formula schematic)."""
    shared = shared_misprints(errata)
    kinds = _nature_words(errata, shared)
    if not shared:
        if not kinds:
            return ""
        return f" (through {kinds})" if len(errata) == 1 else f" (each through a place of the paper of its own: {kinds})"
    distinct = len(errata) - sum(len(g) - 1 for g in shared)
    names = [", ".join(c.id for c in g[:-1]) + f" and {g[-1].id}" for g in shared]
    what = (f": {kinds}; " if kinds else ", each a false statement, a misprinted size or index, or a statement taken "
            "literally where a hypothesis is tacit or a formula schematic: ")
    return (f" (from {distinct} distinct places of the paper{what}{names[0]} fail through "
            "one place, repaired by one correction"
            + "".join(f"{'; and so do' if i == len(names) - 1 else '; so do'} {x}" for i, x in enumerate(names[1:], 1))
            + ")")


def _errata_words(errata: list[ClaimResults]) -> str:
    """What the headline says of the failures: how many have an exact witness point, how many a number computed
    against the printed one, and how many of those with a registered correction have one verified (each said
    only as far as the records show it)."""
    if not errata:
        return ""
    by_kind: dict[str, list[ClaimResults]] = {}
    for c in errata:
        by_kind.setdefault(_failure_kind(c), []).append(c)
    corrected = [c for c in errata if c.variants]
    verified = sum(bool(_erratum_facts(c)["verified"]) for c in corrected)
    each = "it is" if len(errata) == 1 else "each is"
    if set(by_kind) <= {"point", "number"} and len(by_kind) == 1:
        words = f": {each} an erratum {FAILURE_KINDS[next(iter(by_kind))]}"
    else:
        words = ": " + ", ".join(f"{len(by_kind[k])} {_kind_words(k, by_kind[k])}" for k in FAILURE_KINDS
                                 if k in by_kind)
    if corrected and verified == len(corrected):
        words += (", and where a correction is registered"
                  + (f" ({len(corrected)} of the {len(errata)})" if len(corrected) < len(errata) else "")
                  + " it was verified at every size computed")
    elif corrected:
        words += (f"; of the {len(corrected)} with a registered correction, {verified} "
                  f"{'has' if verified == 1 else 'have'} one verified at every size computed")
    return words


def _placed(c: ClaimResults, labelled: str, words: Callable[[str], str]) -> str:
    """An erratum in the list after the headline: its labels, or, where the misprint sits beside them, "in <place>
    (involves: <labels>)" (``labelled``: the labels as the document sets them; ``words`` sets the place)."""
    if not c.place:
        return labelled
    return f"in {words(c.place)}" + (f" (involves: {labelled})" if labelled else "")


def _listed_correction(c: ClaimResults, words: Callable[[str], str],
                       errata: Sequence[ClaimResults] = ()) -> str:
    """The correction named beside an erratum in the list after the headline: a verified one only; an erratum
    repaired by the same correction as one listed before it says so (one misprint, see :func:`shared_misprints`)."""
    verified = _erratum_facts(c)["verified"]
    if verified:
        first = next((g[0] for g in shared_misprints(errata) if c in g[1:]), None)
        same = f" (the same place of the paper as {first.id})" if first is not None else ""
        return "; correction: " + words(verified[0]) + same
    return "; no registered correction verified" if c.variants else ""


def shared_misprints(errata: Sequence[ClaimResults]) -> list[list[ClaimResults]]:
    """The errata of the paper's catalog that declare one place of their misprint and are repaired there by one and
    the same verified correction (the same words, and the same change of the formula in the graphs), in groups of
    two or more, in the order of the list: statements of their own (a theorem and a sentence that extends it) that
    fail through one misprint.  Only for a report of the catalog alone (the callers' rule): a claims file's claim is
    never counted with the paper's.  The same correction of two formulas (Iₙ for I₂ᵣ in two displays) is two
    misprints: their places differ."""
    groups: dict[tuple, list[ClaimResults]] = {}
    for c in errata:
        verified = tuple(_erratum_facts(c)["verified"])
        if not verified or not c.place:
            continue
        changes = tuple(sorted({(ch.get("old", ""), ch.get("new", "")) for v in verified for ch in c.change_of(v)}))
        groups.setdefault((c.place, verified, changes), []).append(c)
    return [g for g in groups.values() if len(g) > 1]


#: the longest line written to a LaTeX report (TeX reads a line into a buffer of its own: Debian's texlive has
#: buf_size 200000, and a derivation's source printed whole in one \texttt once made a line of 211,394 characters)
TEX_LINE_MAX = 2000


def short_lines(tex: str, limit: int = TEX_LINE_MAX) -> str:
    """``tex`` with every line longer than ``limit`` broken at spaces, so that the document typesets the same:
    TeX drops the spaces that end an input line and those that begin one, and reads the end of a line as one
    space, so a break is made only between two pieces of text (never inside a run of blanks, which would leave a
    line of blanks, an empty line: a new paragraph), and not after a backslash (a control space).  A line of
    blanks alone is left empty (TeX reads it so), and a line that holds a comment (an unescaped %) is left
    whole."""
    out = []
    for line in tex.split("\n"):
        if len(line) <= limit or _has_comment(line):
            out.append(line)
            continue
        if not line.strip(" "):
            out.append("")
            continue
        while len(line) > limit:
            cut = _break_at(line, limit)
            if cut is None:
                break
            out.append(line[:cut])
            line = line[cut:].lstrip(" ")
        if line:
            out.append(line)
    return "\n".join(out)


def _break_at(line: str, limit: int) -> int | None:
    """Where to end the first piece of ``line``: at the start of a run of blanks that has text before it (not a
    backslash that would make its first blank a control space) and text after it, as late as possible within
    ``limit``, else the first such place beyond it; None when there is none."""
    def ok(i: int) -> bool:
        if i <= 0 or line[i - 1] == " " or not line[i:].strip(" "):
            return False
        k = i
        while k > 0 and line[k - 1] == "\\":
            k -= 1
        return (i - k) % 2 == 0
    i = line.rfind(" ", 0, limit)
    while i > 0:
        while i > 0 and line[i - 1] == " ":
            i -= 1
        if ok(i):
            return i
        i = line.rfind(" ", 0, i)
    i = line.find(" ", limit)
    while i > 0:
        if ok(i):
            return i
        i = line.find(" ", i + 1)
    return None


def _has_comment(line: str) -> bool:
    """Whether a line of TeX holds a % that is not escaped (preceded by an odd number of backslashes)."""
    i = line.find("%")
    while i >= 0:
        k = i
        while k > 0 and line[k - 1] == "\\":
            k -= 1
        if (i - k) % 2 == 0:
            return True
        i = line.find("%", i + 1)
    return False


#: the first words of the per-run document, in place of the summary it would repeat ({what}: the
#: paper's errata, or a claims file's statements that fail)
RUNS_PREFACE = ("This document is the companion of verification.tex, which summarizes the verdicts and lists "
                "{what} with their corrections.  Here the errata come first again, each with more of its failing "
                "runs; then every run follows, claim by claim: its verdict, the reductions its proof used (the "
                "chart of T*V, an equivariance, the dimension-free proof specialised to a size), its residual and "
                "its certificate, or its witness and the command that reruns it.")


def render_latex(results: Sequence[Result], meta: dict[str, Any] | None = None, mutation: Any = None,
                 detail: bool = False) -> str:
    """A complete ``article`` document (pdflatex, Debian's texlive-latex-base/recommended).

    Without ``detail`` it is what a referee reads: the headline, the errata right after the summary,
    and per claim its statement and verdicts in a few lines.  With ``detail`` (the per-run
    document) every run, reduction, derivation and certificate summary follows, after a preface that
    points to the referee's document instead of repeating its summary.  With ``mutation``
    (the parsed ``mutation.json``) a section "Mutation analysis" at the end."""
    meta = meta or {}
    results = readable_results(results)
    claims = group_by_claim(results)
    unexpected = sum(not r.expected for r in results)
    text, errata = headline(claims, paper=not meta.get("claims_files"))
    # the list of typographical slips is the referee's document's (its companion lists runs)
    slips = [] if detail else typographical_slips(meta)
    spelling = [] if detail else spelling_slips(meta)
    text += _typo_words(len(slips), len(spelling))
    title = meta.get("title") or DEFAULT_TITLE
    out = [TEX_PREAMBLE,
           r"\title{" + tex_escape(title + (": every run" if detail else "")) + "}",
           r"\author{Generated by \texttt{stiefelsym}}",
           r"\date{" + tex_escape(meta.get("date") or "") + "}",
           r"\begin{document}", r"\maketitle", "",
           # the per-run document is the referee's document's companion: its summary is not repeated
           tex_escape(RUNS_PREFACE.format(what="the statements that fail" if meta.get("claims_files")
                                          else "the errata of the paper") if detail else text), "",
           tex_escape(f"{len(results)} runs; ")
           + (("every verdict is the one the catalog expects (the errata are expected to fail as printed)."
               if not meta.get("claims_files") else "every verdict is the one its claim expects.")
              if not unexpected else f"\\textbf{{{unexpected} verdicts not as expected.}}"), ""]
    if errata and not detail:
        out += [tex_escape("Fails as printed:")]
        out += _tex_items([r"\texttt{" + tex_escape(c.id) + "}" + tex_escape(_shadow_tag(c)) + " "
                           + _placed(c, tex_labels(c.paper, c.unlabelled), tex_words)
                           + _listed_correction(c, tex_words, errata if not meta.get("claims_files") else ())
                           + (tex_words(_nature_tag(c)) if not meta.get("claims_files") else "")
                           for c in errata])
    if not detail:
        out += [tex_escape("Every run, with the reductions its proof used (the chart of T*V, an equivariance, "
                           "the dimension-free proof specialised to a size), its residual and its certificate, "
                           "is in the companion document verification-runs.tex and in results.json."), ""]
    out += [r"\tableofcontents", ""]

    # the vocabulary before its first use: the errata speak of verdicts, methods and the bound p
    out += _toc_section("What the verdicts mean") + [r"\begin{description}"]
    out += [f"\\item[{v}] {tex_escape(VERDICT_MEANING[v])}" for v in VERDICTS]
    out += [r"\end{description}",
            r"\paragraph{The methods.} " + tex_escape(METHODS_INTRO), r"\begin{description}"]
    out += [f"\\item[{m}] {tex_escape(t)}" for m, t in METHOD_MEANING.items()]
    out += [r"\end{description}",
            r"\paragraph{The bound $p$.} " + tex_escape(BOUND_EXPLANATION),
            r"\paragraph{Graphs and digests.} " + tex_escape(GRAPH_EXPLANATION),
            r"\paragraph{Charts, reductions, certificates.} " + tex_escape(REDUCTIONS_EXPLANATION),
            r"\paragraph{References to the paper.} " + tex_escape(REFERENCES_EXPLANATION),
            *([r"\paragraph{What a claim covers.} " + tex_escape(SCOPE_EXPLANATION)] if not meta.get("claims_files") else []),
            r"\paragraph{Expected verdicts.} " + tex_escape(EXPECTED_EXPLANATION), ""]

    out += _toc_section("Errata")
    # the referee's document names two more failing runs; the per-run one eight (all are in results.json)
    out += _errata_body(claims, tex_escape, lambda c: _tex_erratum(c, MAX_ERRATUM_RERUNS if detail else 2),
                        lambda c: [_tex_claim_heading(c)] + _tex_corrections(c))
    out += _tex_typo_section(slips)
    out += _tex_spelling_section(spelling)

    out += _tex_claim_table(claims) if detail else _tex_section_table(claims, meta)

    for sec, cs in group_by_section(claims):
        out += _toc_section(tex_escape(_section_heading(sec, meta)))
        # the referee's document sets the claims a size smaller: the statements are what is read
        out += [] if detail else [r"{\small"]
        for c in cs:
            out += _tex_claim(c) if detail else _tex_claim_brief(c)
        out += [] if detail else ["}", ""]

    out += _toc_section("How to reproduce")
    out += [r"{\raggedright " + _tt(meta.get("command") or "stiefelsym verify") + r"\par}", ""]
    out += [tex_escape(f) for f in _run_facts(meta)] + [""]
    if mutation:
        out += _tex_mutation_section(_mutation_data(mutation))
    return short_lines("\n".join(out + [r"\end{document}", ""]))


def _tex_claim_table(claims: list[ClaimResults]) -> list[str]:
    """The per-run document's summary: per claim as printed, the verdict for all n, r and the
    runs at fixed sizes by verdict."""
    present, rows = _summary_rows(claims)
    out = _toc_section("Summary")
    out += [tex_escape("For each claim as printed: the verdict of the dimension-free method (all n, r at "
                       "once), then the runs at fixed sizes (n, r) by verdict."), "",
            r"{\small\setlength{\tabcolsep}{3pt}",
            r"\begin{longtable}{@{}P{3.6cm}P{3.0cm}P{0.5cm}P{1.6cm}" + "r" * (len(present) - 1) + "P{1.6cm}@{}}",
            r"\toprule",
            " & ".join(["claim", "paper", r"\ensuremath{\S}"]
                       + [r"\rotatebox{90}{" + v + "}" for v in present] + ["status"]) + r"\\",
            r"\midrule", r"\endhead"]
    for c, counts, status in rows:
        out.append(" & ".join([r"\texttt{" + tex_escape(c.id).replace("-", r"-\allowbreak{}") + "}",
                               tex_labels(c.paper, c.unlabelled),
                               tex_escape("--" if c.shadows else c.section or "--")]
                              + [tex_escape(str(k or "")) for k in counts]
                              + [tex_escape(status) if status == "as expected"
                                 else rf"\textbf{{{tex_escape(status)}}}"])
                   + r"\\")
    return out + [r"\bottomrule", r"\end{longtable}", "}", ""]


def holds_at_every_size(c: ClaimResults) -> bool:
    """The claim as printed holds at every size it was computed at: proved for every size at once, or
    passed (proved or checked) by some method at each computed size; a size that no method decided
    (only undecided or inconclusive runs) is not counted as holding."""
    if c.failures:
        return False
    if any(r.n is None and r.verdict == "proved" for r in c.printed):
        return True
    sizes = {(r.n, r.r) for r in c.printed if r.n is not None}
    return bool(sizes) and sizes <= {(r.n, r.r) for r in c.printed if r.n is not None and r.verdict in PASSING}


def proved_at_every_size(c: ClaimResults) -> bool:
    """The claim as printed is proved at every size it was computed at: proved for every size at once, or
    proved by some method at each computed size (a size passed only by a check at random points, or
    numerically, is not)."""
    if c.failures:
        return False
    if any(r.n is None and r.verdict == "proved" for r in c.printed):
        return True
    sizes = {(r.n, r.r) for r in c.printed if r.n is not None}
    return bool(sizes) and sizes <= {(r.n, r.r) for r in c.printed if r.n is not None and r.verdict == "proved"}


#: the columns of the summary by section, in order (Markdown headings; the LaTeX ones are SECTION_TEX_HEADINGS)
SECTION_COLUMNS = ("claims", "proved for all n, r", "proved for every n at one r", "hold at every size",
                   "proved at every size", "fail as printed", "unexpected")
SECTION_TEX_HEADINGS = ("claims", r"all $n,r$", r"one $r$", "hold", "proved", "fail", "unexp.")


def section_counts(cs: list[ClaimResults]) -> dict[str, int]:
    """Per section: its claims; those proved dimension-free as printed for every n and r, and those proved
    for every n at the one r (or the r = 1 and r = n) they are stated for; those that hold as printed at
    every computed size, and those of them proved at every computed size; those that fail as printed; and
    those with a verdict not expected."""
    scopes = [next((free_scope(r) for r in c.printed if r.n is None and r.verdict == "proved"), None) for c in cs]
    fails = sum(bool(c.failures) for c in cs)
    counts = (len(cs), scopes.count("all n, r"), sum(s not in (None, "all n, r") for s in scopes),
              sum(map(holds_at_every_size, cs)), sum(map(proved_at_every_size, cs)), fails,
              sum(bool(c.unexpected) for c in cs))
    return dict(zip(SECTION_COLUMNS, counts))


def _tex_section_table(claims: list[ClaimResults], meta: dict[str, Any]) -> list[str]:
    """The referee's summary: one row per section of the paper."""
    out = _toc_section("Summary")
    out += [tex_escape(SECTION_TABLE_INTRO + "  Each claim follows, by section."), "",
            r"\begin{center}\small", r"\begin{tabular}{@{}P{5.6cm}rrrrrrr@{}}", r"\toprule",
            "section & " + " & ".join(SECTION_TEX_HEADINGS) + r"\\", r"\midrule"]
    total: Counter = Counter()
    for sec, cs in group_by_section(claims):
        k = section_counts(cs)
        total.update(k)
        out.append(" & ".join([tex_escape(_section_heading(sec, meta))] + [str(v) for v in k.values()]) + r"\\")
    out += [r"\midrule", " & ".join(["total"] + [str(total[key]) for key in section_counts([])]) + r"\\",
            r"\bottomrule", r"\end{tabular}", r"\end{center}", ""]
    return out


def _tex_traced(c: ClaimResults) -> list[str]:
    """A claims file's claim's outputs as traced, in LaTeX: the statement that was verified, which a reader
    compares with the file's words (a catalog claim's are in verification.md, beside the paper's display)."""
    where, traced, graphs = c.traced()
    if not (traced and c.own):
        return []
    return [tex_escape(traced_intro(where, graphs, c.expect, c.traced_sizes())) + ":"] + _tex_items(
        [(tex_escape(f"{name}: ") if name else "")
         + (_tex_inline(tex, always=True) if math_ok(tex) and tex.isascii() and len(text) <= TEX_TRACED_CHARS
            else tex_escape(text).replace(")", r")\allowbreak{}")) for name, text, tex in traced])


#: a formula as traced longer than this (characters of its Unicode text) is printed as that text in the LaTeX
#: reports, which breaks across lines (its mathematics, set in one box, would be shrunk below legibility)
TEX_TRACED_CHARS = 90


def _tex_claim_brief(c: ClaimResults) -> list[str]:
    """A claim in a few lines: its statement, the verdict for all n, r, and its sizes by method."""
    out = [_tex_claim_heading(c)]
    if c.title:
        out += [tex_words(c.title), ""]
    if c.statement.strip():
        out.append(tex_display(c.statement))
    out += _tex_traced(c)
    free = next((r for r in c.printed if r.n is None), None)
    lines = []
    if free is not None:
        assumes = free_assumptions(free)
        lines.append(f"{free_scope(free)} (dimension-free): proved"
                     + (f", assuming {'; '.join(assumes)}" if assumes else "") if free.verdict == "proved" else
                     f"all n, r (dimension-free): {free.verdict} ({_brief_reason(free.message)})")
    _, phrases = correction_summary([r for r in c.printed if r.n is not None], planned_sizes(c))
    lines += phrases
    if c.failures:
        lines.append("fails as printed: see the Errata")
    out += [r"\noindent\textit{Verdict:} " + tex_words("; ".join(lines) + "."), ""]
    return out


def _brief_reason(message: str | None) -> str:
    """The first clause of a reason, for the referee's document (the whole is in the per-run one):
    "needs coordinates (fixed n, r): a rank", "4 residual entries have a nonzero normal form"."""
    text = (message or "").split(" (e.g.")[0].split("; ")[0]
    head, sep, rest = text.partition(": ")
    text = head + sep + rest.split(" (")[0] if sep else text
    # in words a mathematician reads: what the statement needs, what the rewriting left
    text = text.replace("needs coordinates (fixed n, r): ", "needs fixed n, r: ")
    text = re.sub(r"^(\d+) residual entr(?:y has|ies have) a nonzero normal form$",
                  lambda m: f"{m.group(1)} residual entr{'y does' if m.group(1) == '1' else 'ies do'} not reduce to 0 "
                            "by the rewriting rules", text)
    return short(text, 90)


def _tex_claim_heading(c: ClaimResults) -> str:
    heading = r"\subsection*{\texttt{" + tex_escape(c.id) + "} " + _placed(c, tex_labels(c.paper, c.unlabelled), tex_words) + "}"
    # a claims file's claim with a catalog claim's id says whose it is, wherever its heading stands
    return heading + ("\n" + r"\textbf{" + tex_escape(shadow_words(c)) + "}\n" if c.shadows else "")


def _tex_claim(c: ClaimResults) -> list[str]:
    out = [_tex_claim_heading(c)]
    if c.title:
        out += [tex_words(c.title), ""]
    if c.statement.strip():
        out.append(tex_display(c.statement))
    out += [tex_escape(f"Kind: {c.kind}, {kind_words(c)}."), ""]
    if c.printed:
        out += _tex_results(c.printed)
    dims = grouped_dimension_checks(c)
    if dims:
        out += [tex_escape("Rank and count statements (at each size, from the most rigorous method that ran; the "
                           "sizes at which a check says the same thing share an item):")]
        out += _tex_items([tex_escape(f"{name}, {size} {m}: ")
                           + (st if st == "as printed" else rf"\textbf{{{st}}}")
                           + (". " + tex_words(engine_words(short(detail, 400))) if detail else "")
                           for name, size, m, st, detail in dims])
    how = c.how_obtained()
    if how:
        out += ["How the verdicts were obtained:"]
        out += _tex_items([tex_words(f"{m}: {engine_words(text)}") for m, text in how])
    out += _tex_traced(c)
    notes = [tex_words(f"{r.size} {r.method}: {engine_words(short(r.message, 300))}") for r in c.notes()]
    if notes:
        out += ["Notes:"] + _tex_items(notes)
    out += _tex_derivations(c)
    if c.failures:
        out += ["Fails as printed: see the Errata section.", ""]
    elif c.variants:
        out += [tex_escape(f"{len(c.variants)} candidate correction(s) also checked: "
                           "see the Errata section."), ""]
    return out


def free_assumptions(r: Result) -> list[str]:
    """What a dimension-free proof assumes beyond the constraints (the metric realization: A positive
    definite, and the flow's multipliers the unique solutions of their Sylvester equations), in words:
    the engine's names of the multipliers (``Lambda:1``) and of their relations (``rho:Lambda:1``) as Λ."""
    data = r.certificate_data
    if r.verdict != "proved" or not isinstance(data, dict) or not isinstance(data.get("summary"), dict):
        return []
    assumes = [str(a) for a in data["summary"].get("assumes") or ()]
    letters = sorted(set(re.findall(r"(?<!rho:)Lambda:(\d+)", " ".join(assumes))), key=int)
    name = {k: "Λ" if len(letters) == 1 else "Λ" + k.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
            for k in letters}
    out = []
    for a in assumes:
        a = re.sub(r"rho:Lambda:(\d+) = 0", "its Sylvester equation", a)
        a = re.sub(r"Lambda:(\d+)", lambda m: name.get(m.group(1), "Λ"), a)
        a = a.replace("A^-1", "A⁻¹").replace("I_r", "Iᵣ").replace("I_n", "Iₙ").replace("(keeps: ", "(to keep ")
        out.append(unicode_name(a))
    return out


#: the engine's letter names in the relations of a certificate: (pattern, the paper's notation), in this order
_LETTER_PARTS = ((r"inv$", "⁻¹"), (r"t$", "ᵀ"), (r"d$", "\u0307"))
_LETTER_SCRIPTS = str.maketrans("0123456789r", "₀₁₂₃₄₅₆₇₈₉ᵣ")
_SIZE_IDENTITY = {"n": "Iₙ", "r": "Iᵣ", "1": "1", "r-1": "Iᵣ₋₁"}


def _letter_words(name: str) -> str:
    """An engine letter in the paper's notation: Xt as Xᵀ, Ainv as A⁻¹, Udt as U̇ᵀ, E1 as E₁, Ert as Eᵣᵀ."""
    tail = ""
    changed = True
    while changed:
        changed = False
        for pattern, mark in _LETTER_PARTS:
            m = re.search(pattern, name)
            if m and m.start() > 0 and (mark != "\u0307" or re.fullmatch(r"D?[A-Z]", name[:m.start()])):
                name, tail = name[:m.start()], mark + tail
                changed = True
                break
    if re.fullmatch(r"E(\d|r)", name):
        name = "E" + name[1:].translate(_LETTER_SCRIPTS)
    return name + tail


def hypothesis_words(name: str) -> str:
    """A relation of the ideal of a dimension-free certificate as the paper writes it, from the name the engine and
    the results file give it: "XtP+PtX" as "XᵀP + PᵀX = 0", "XtX" as "XᵀX = Iᵣ", "UtV-VtU" as "UᵀV = VᵀU",
    "res_left:R[lambda]" as "(λIₙ − A)(λIₙ − A)⁻¹ = Iₙ", "rho:Lambda:1" as "the Sylvester equation of Λ"; a name of no
    fixed relation as it is."""
    from stiefelsym.certificate_check import HYPOTHESES
    kind, _, arg = name.partition(":")
    m = re.fullmatch(r"R\[(-?)(\w+)\]", arg)
    if kind in ("res_left", "res_right") and m:
        mu = ("−" if m.group(1) else "") + greek_words(m.group(2))
        shifted = f"({mu}Iₙ − A)"
        pair = f"{shifted}{shifted}⁻¹" if kind == "res_left" else f"{shifted}⁻¹{shifted}"
        return f"{pair} = Iₙ"
    sylvester = re.fullmatch(r"(\w+):\d+", arg)
    if kind == "rho" and sylvester:         # the relation of a multiplier that solves a Sylvester equation
        return f"the Sylvester equation of {greek_words(sylvester.group(1))}"
    if name not in HYPOTHESES:
        return name
    rows, _cols, terms = HYPOTHESES[name]

    def side(ts: list) -> str:
        words = ["".join(map(_letter_words, w)) or _SIZE_IDENTITY.get(rows, "I") for _, w in ts]
        return " + ".join(words) if words else "0"
    plus = [t for t in terms if int(t[0]) > 0]
    minus = [t for t in terms if int(t[0]) < 0]
    return f"{side(plus)} = {side(minus)}"


_HYPOTHESES_LIST = re.compile(r"(\bhypotheses )([^();]*(?:\[[^\]]*\][^();]*)*)(?=[);])")


def certificate_words(text: str) -> str:
    """A record's certificate with the relations it names in the paper's notation (:func:`hypothesis_words`):
    "26 terms in the hypotheses XtP+PtX, XtX" as "26 terms in the hypotheses XᵀP + PᵀX = 0, XᵀX = Iᵣ"."""
    return _HYPOTHESES_LIST.sub(lambda m: m.group(1) + ", ".join(hypothesis_words(h.strip())
                                                                 for h in m.group(2).split(", ")), text or "")


def certificate_summary(r: Result) -> str:
    """One line on a dimension-free proof's cofactor certificate (its terms are in results.json)."""
    data = r.certificate_data
    if r.verdict != "proved" or not isinstance(data, dict) or "summary" not in data:
        return ""
    sm = data["summary"]
    certs = [c.get("certificate", {}) for c in data.get("cases", ())] or [data]    # (a certificate of cases: each)
    per = [len(e.get("terms", ())) for d in certs for e in d.get("entries", ())]
    entries = f"{sm['entries']} residual entr{'y' if sm['entries'] == 1 else 'ies'}"
    if data.get("cases"):   # a claim stated at a union of one-r families: one certificate per family
        entries += " in " + " and ".join(f"the case r = {c['sizes']['r']} (every n >= {c['sizes']['n_min']})"
                                         for c in data["cases"])
    checked = "re-checked by an independent checker (a small separate program that re-expands it)"
    assumes = free_assumptions(r)
    if assumes:
        checked += f"; it assumes (the {sm.get('realization', 'metric')} realization): {'; '.join(assumes)}"
    if not sm["terms"]:
        verb = "vanishes" if sm["entries"] == 1 else "vanish"
        return (f"Cofactor certificate ({_method_name(r.method)}): empty, the {entries} already {verb} in the free algebra "
                f"as built; {checked}")
    sizes = ", ".join(map(str, per[:12])) + (", ..." if len(per) > 12 else "")
    return (f"Cofactor certificate ({_method_name(r.method)}): {sm['terms']} terms over {entries} (per entry: {sizes}), "
            f"in {len(sm['hypotheses'])} relation{'' if len(sm['hypotheses']) == 1 else 's'} of the ideal "
            f"({', '.join(map(hypothesis_words, sm['hypotheses']))}); {checked}; the terms are in the results file "
            "(results.json, which names these relations by the engine's names)")


def certificate_summaries(records: list[Result]) -> dict[str, str]:
    """{summary: its line} per distinct certificate of the records (:func:`certificate_summary`), in order: the
    records at sizes that carry one (proofs on a family r = k, one certificate for every n) are named after it."""
    lines: dict[str, list[str]] = {}
    for r in records:
        line = certificate_summary(r)
        if line:
            lines.setdefault(line, [])
            if r.n is not None:
                lines[line].append(f"({r.n},{r.r})")
    return {line: line + (f" (the records at {', '.join(sizes)})" if sizes else "") for line, sizes in lines.items()}


def _tex_derivations(c: ClaimResults) -> list[str]:
    """The dimension-free proofs: residual, rules applied, normal form, certificate size."""
    out = []
    grouped = certificate_summaries(c.printed)
    for r in c.printed:
        cert = certificate_summary(r)
        if cert and not r.derivation and cert in grouped:
            out += [tex_words(grouped.pop(cert) + "."), ""]      # (once for the records that carry it)
        if not r.derivation or r.verdict != "proved":
            continue
        out.append(r"\subsubsection*{" + tex_escape(f"Dimension-free proof ({r.method})") + "}")
        if cert:
            out.append(tex_words(cert + "."))
        for chunk in r.derivation[:MAX_DERIVATIONS]:
            # a derivation that is not balanced LaTeX is shown as its source, ragged right (a space of the typewriter
            # font does not stretch: justified, its lines were overfull or underfull)
            out.append(_fit_derivation(chunk) if tex_balanced(chunk)
                       else r"{\raggedright\texttt{" + tt_escape(chunk) + r"}\par}")
        if len(r.derivation) > MAX_DERIVATIONS:
            out.append(tex_escape(f"… and {len(r.derivation) - MAX_DERIVATIONS} more entries "
                                  "(in full in results.json)."))
        out.append("")
    return out


#: a derivation longer than this (characters of LaTeX) is summarized by its size (it is in results.json)
DERIVATION_CHARS = 2500
_DISPLAY = re.compile(r"\\\[(.*?)\\\]", re.S)


def _fit_derivation(chunk: str) -> str:
    """A derivation of a free proof for the page: each display shrunk to the line's width when wider,
    and a display too long to read at any size summarized by its length."""
    def fit(m: re.Match) -> str:
        body = m.group(1)
        if len(body) > DERIVATION_CHARS:
            return ("\n" + tex_escape(f"(a display of {len(body)} characters of LaTeX: in results.json, "
                                       "the record's derivation)") + "\n")
        return (r"\begin{center}\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{$\displaystyle "
                + body + r"$}\end{center}")
    return _DISPLAY.sub(fit, chunk)


def _tex_erratum(c: ClaimResults, reruns: int = MAX_ERRATUM_RERUNS) -> list[str]:
    facts = _erratum_facts(c)
    out = [_tex_claim_heading(c)]
    out += [r"\textbf{" + _note_heading(c) + "} "
            + _erratum_note(c, facts, tex_escape, lambda v: _tex_with_change(c, v, note=True), tex_words), ""]
    if c.statement.strip():
        out += [statement_heading(c, tex_words).replace("“", "``").replace("”", "''") + r"\nopagebreak",
                tex_display(c.statement)]
    w = _witness_run(c)
    out += [tex_escape("Failing runs: " + ", ".join(f"{r.size} {r.method}" for r in c.failures) + "."), ""]
    if w.erratum:
        out += ["What is wrong: " + tex_words(greek_words(w.erratum)), ""]
    out += _tex_small_witness(c)
    if small_witness_of(c) is not None and "point" in (w.witness or {}):
        out += [tex_escape(f"The seeded run that found the failure: size {w.size}, method {w.method}"
                           + (f", seed {w.seed}" if w.seed is not None else "") + "; rerun: ")
                + _tt(w.rerun or "") + ".", ""]
        return _tex_erratum_tail(c, facts, w, out, reruns)
    out += [tex_escape(_witness_heading(w))]
    items = [tex_escape(k) + ": " + _tt(v) for k, v in witness_lines(w.witness)]
    if not items:
        items = [tex_escape(f"({no_point_text(w)})")]
    if w.residual:
        items.append("residual: " + _tt(short(w.residual, WITNESS_WIDTH)))
    items += [tex_words(check_line(ch)) for ch in w.checks if ch.status != "zero"][:10]
    if w.message:
        items.append(tex_escape(w.message))
    if w.rerun:
        items.append("rerun: " + _tt(w.rerun))
    out += _tex_items(items)
    return _tex_erratum_tail(c, facts, w, out, reruns)


def _tex_erratum_tail(c: ClaimResults, facts: dict[str, Any], w: Result, out: list[str],
                      reruns: int = MAX_ERRATUM_RERUNS) -> list[str]:
    others = grouped_reruns([x for x in facts["reruns"] if x != w.rerun])
    if others:
        shown = _shown(others, reruns)
        more = [f"… and {len(others) - shown} more (in results.json)"] if len(others) > shown else []
        out += ["Every other failure, reproducible with:"] + _tex_items(
            [_tt(x) for x in others[:shown]] + [tex_escape(m) for m in more], ragged=True)
    # the verified corrections are in the note for the authors and in the list of candidates below: not
    # a third time here
    return out + _tex_corrections(c)


def _corrections_rule(planned: Sequence[tuple[int, int]]) -> str:
    """Where the claim as printed was run, and so where a correction must pass."""
    if len(planned) == 1:
        return (f"the claim as printed was run at the one size {format_sizes(planned)}; a correction is "
                "verified only if it passes there.")
    return (f"the claim as printed was run at {len(planned)} sizes {format_sizes(planned)}; a correction is "
            "verified only if it passes at every one of them and fails nowhere.")


def _tex_corrections(c: ClaimResults) -> list[str]:
    if not c.variants:
        return ["No candidate correction was checked.", ""]
    planned = planned_sizes(c)
    items = []
    for var, rs in c.variants.items():
        status, phrases = correction_summary(rs, planned)
        label = tex_escape(_status_label(status, rs))
        items.append(_tex_with_change(c, var) + " --- " + (r"\textbf{" + label + "}" if status == "verified" else label)
                     + tex_escape(" (" + "; ".join(phrases) + ")."))
    intro = "Candidate corrections:"
    if planned:
        intro += tex_escape(" " + _corrections_rule(planned))
    return [intro] + _tex_items(items)


# --------------------------------------------------------------------------- mutation analysis

#: the words of the mutation analysis, defined once before it uses them
MUTATION_TERMS = [
    "Terms used below:", "",
    "- **mutant**: the claim's source corrupted in one small place (one of the corruptions listed below); a mutant "
    "is meant to be a false statement, which every method should notice.",
    "- **refuted**: a method refutes a mutant when it fails it (with a witness) or gives error at some size where "
    "the claim as printed passes.",
    "- **equivalent**: a mutant that every method passes at every size run: the corruption left a true statement (at "
    "those sizes), which tests no method.",
    "- **survivor** (of a method): a mutant the method passes at a size where another method refutes it, or, for the "
    "dimension-free method, a mutant it proves that is not equivalent; a survivor is a soundness or sensitivity "
    "problem of that method.",
    "- **unresolved**: a mutant that no method refutes, that some method leaves undecided (inconclusive or "
    "undecided) and another passes.",
    "- **missed**: a mutant a method passes at every size it ran, where another method refuted it at a size this one "
    "did not run.",
]

MUTATION_EXPLANATION = (
    "Each claim's source is corrupted in one small place (a mutant): the sign of a term flipped, "
    "the operands of a product or commutator swapped, a factor transposed, a term dropped, a "
    "scene letter replaced by another of the same kind, a rational coefficient changed.  Every "
    "mutant runs with every method at a few sizes, and with the dimension-free method; the claim "
    "as printed runs too, and a (size, method) where it does not pass is not counted.  A method "
    "refutes a mutant when, at some counted size, it fails (refuted with a witness) or gives error (for "
    "instance ill-typed: the engine refused the expression); it leaves it undecided when it does not pass it "
    "and does not refute it anywhere (inconclusive or undecided: no verdict, neither a refutation nor a pass).  "
    "A mutant that passes everywhere is "
    "equivalent: a true statement at the sizes run.  A method survives a mutant when it passes it at a size where "
    "another method refutes it; the dimension-free method survives a mutant when it proves one that "
    "is not equivalent.  Survivors are soundness or sensitivity problems.  A mutant that no method refutes, "
    "that some method leaves undecided and that another passes is unresolved in the row of the method that "
    "passes it.  A method missed a mutant that it passed at every size it ran, where another method refuted it "
    "at a size this one did not run (the symbolic method stops at smaller sizes than the point methods).  "
    "refuted % = refuted / (mutants - equivalent); not passed % = (refuted + undecided) / "
    "(mutants - equivalent).  The dimension-free method proves or leaves undecided, it never refutes: its "
    "refuted mutants are those it refused (error), and its not passed % is the share it did not prove.  Unless the command says --fresh-points, the point methods (rational, "
    "modular, float) evaluate a mutant at the random points of the claim as printed and recompute "
    "only the subexpressions of its formula that the change reaches (parameters the printed claim never drew "
    "are drawn afresh), and the symbolic method has 15 s per run of a mutant and at most 3 x 10^7 term products "
    "per symbolic product (a count: a run stops at the same step on every machine), and, at a size where the "
    "rational or modular method has refuted it already with an exact witness (there a symbolic run can only "
    "err by proving it), at most 10^7 (a run stopped there is inconclusive: it does not test the symbolic method "
    "on that mutant at that size); the point methods' verdicts are those of fresh points, which the tests check.")
MUTATION_COLUMNS = ("mutants", "refuted", "fails", "error", "undecided", "survived", "equivalent",
                    "unresolved", "missed", "refuted %", "not passed %")


def _mutation_data(mutation: Any) -> dict[str, Any]:
    """The parsed mutation.json (a MutationReport is accepted and turned into its record)."""
    if hasattr(mutation, "to_json"):
        mutation = mutation.to_json()
    return mutation or {}


def refuted(row: dict[str, Any]) -> int:
    """The mutants a method refuted (fails, or error: refused), of a row of the mutation table."""
    return row.get("fails", 0) + row.get("error", 0)


def kill_rate(row: dict[str, Any], decisive: bool = True) -> str:
    """refuted / (mutants - equivalent) (``decisive``), or (refuted + undecided) / (mutants - equivalent),
    the share not passed; "–" when nothing could be refuted.  A rate is never rounded up to 100%."""
    denom = row.get("total", 0) - row.get("equivalent", 0)
    if denom <= 0 or row.get("baseline_passes") is False:
        return "–"
    part = refuted(row) if decisive else row.get("killed", 0)
    if part == denom:
        return "100%"
    return f"{min(99.9, 100 * part / denom):.1f}%"


def _mutation_cells(row: dict[str, Any]) -> list[str]:
    other = row.get("inconclusive", 0) + row.get("undecided", 0)
    vals = [row.get("total", 0), refuted(row), row.get("fails", 0), row.get("error", 0), other,
            row.get("survived", 0), row.get("equivalent", 0), row.get("unresolved", 0), row.get("missed", 0)]
    return [str(v) for v in vals] + [kill_rate(row), kill_rate(row, decisive=False)]


def _mutants(data: dict[str, Any], classification: str | None = None, survivors: bool = False) -> list[dict]:
    out = []
    for c in data.get("claims", []):
        for o in c.get("mutants", []):
            if survivors and o.get("survived"):
                out.append(o)
            elif classification is not None and o.get("classification") == classification:
                out.append(o)
    return out


def _mutant_verdicts(o: dict[str, Any]) -> str:
    per: dict[str, list[str]] = {}
    for c in o.get("cells", []):
        size = "" if c.get("n") is None else f" ({c['n']},{c['r']})"
        per.setdefault(c["method"], []).append(f"{c['verdict']}{size}")
    return "; ".join(f"{m}: {', '.join(v)}" for m, v in per.items())


def _mutant_label(o: dict[str, Any]) -> str:
    return f"{o.get('claim')}#{o.get('index')}"


def render_mutation_summary(mutation: Any) -> str:
    """The table of refuted and undecided mutants for the terminal (totals per method, then per claim and method)."""
    data = _mutation_data(mutation)
    rows = [dict(r, claim="all claims") for r in data.get("totals", [])] + list(data.get("table", []))
    if not rows:
        return "mutation: nothing was run\n"
    head = ["claim", "method"] + list(MUTATION_COLUMNS)
    body = [[r.get("claim", ""), r.get("method", "")] + _mutation_cells(r) for r in rows]
    widths = [max(len(str(x)) for x in col) for col in zip(head, *body)]
    fmt = lambda cells: "  " + "  ".join(str(c).ljust(w) if i < 2 else str(c).rjust(w)
                                         for i, (c, w) in enumerate(zip(cells, widths)))
    surv = _mutants(data, survivors=True)
    lines = [f"mutation: {sum(len(c.get('mutants', [])) for c in data.get('claims', []))} mutants of "
             f"{len(data.get('claims', []))} claims; {len(surv)} survivor{'s' * (len(surv) != 1)}, "
             f"{len(_mutants(data, 'equivalent'))} equivalent"] + _mutation_made_on(data) \
        + [fmt(head)] + [fmt(b) for b in body]
    if surv:
        lines.append("survivors (a method passed a mutant another method refuted, or free proved it):")
        for o in surv:
            change = change_text(o.get("notation"))
            lines.append(f"  {_mutant_label(o)} survived {', '.join(o['survived'])}: "
                         + (f"{change} (source: {o.get('description')})" if change else f"{o.get('description')}"))
            lines.append(f"    {_mutant_verdicts(o)}")
    return "\n".join(lines) + "\n"


def _mutation_made_on(data: dict[str, Any]) -> list[str]:
    """What the mutants were made on, per claim (a line only when some claim was mutated on graphs, or fell
    back to its source)."""
    made = [c for c in data.get("claims", []) if c.get("on")]
    if not any(c["on"] != "source" or c.get("fallback") for c in made):
        return []
    counts: dict[str, int] = {}
    for c in made:
        counts[c["on"]] = counts.get(c["on"], 0) + 1
    fell = sum(1 for c in made if c.get("fallback"))
    return ["mutants made on: " + ", ".join(f"{k}: {v} claim{'s' * (v != 1)}" for k, v in counts.items())
            + (f" ({fell} fell back from graphs to the source)" if fell else "")]


def _md_mutation_tables(data: dict[str, Any]) -> list[str]:
    head = list(MUTATION_COLUMNS)
    out = ["Per method, over all claims:", ""]
    out += _md_table(["method"] + head, [[r["method"]] + _mutation_cells(r) for r in data.get("totals", [])],
                     "l" + "r" * len(head))
    out += ["Per claim and method (the verdicts of the claim as printed in the third column):", ""]
    out += _md_table(["claim", "method", "as printed"] + head,
                     [[f"`{r['claim']}`", r["method"], _md_cell(r.get("baseline") or "–")] + _mutation_cells(r)
                      for r in data.get("table", [])], "lll" + "r" * len(head))
    return out


def _md_described(text: str) -> str:
    """A mutant's description: `code` spans kept as code, the words between them escaped."""
    parts = str(text).split("`")
    if len(parts) % 2 == 0:   # unbalanced backticks: all text
        return _md_escape(text)
    return "".join(_md_code(p) if i % 2 else _md_escape(p) for i, p in enumerate(parts))


def _md_change(changes: Sequence[dict[str, str]] | None) -> str:
    return _md_escape(change_text(changes)).replace("[", r"\[").replace("]", r"\]")


def _tex_change(changes: Sequence[dict[str, str]] | None) -> str:
    """The change in LaTeX: the place in text, old → new in math (Unicode escaped where the LaTeX of
    an expression is not safe in math mode)."""
    if not changes:
        return ""
    if not changes[0].get("where") and not changes[0].get("old"):
        return tex_escape("no change in the formula")
    parts = []
    for c in changes:
        if c.get("more"):
            parts.append(tex_escape(f"and {c['more']} more change{'s' * (c['more'] != 1)}"))
            continue
        old, new = c.get("old_tex", ""), c.get("new_tex", "")
        math = (f"{_tex_inline(old)} $\\to$ {_tex_inline(new)}"
                if old and new and all(math_ok(t) and t.isascii() for t in (old, new))
                else tex_escape(f"{c.get('old', '')} → {c.get('new', '')}"))
        parts.append(tex_words(f"in {unicode_name(c.get('where', ''))}: ") + math)
    return "; ".join(parts)


def _tex_inline(math: str, always: bool = False) -> str:
    r"""Inline mathematics; one with ``\left … \right`` (which TeX cannot break across lines), or any with
    ``always`` (a formula read back from a graph, whose subscripts and arguments TeX cannot break either), is
    shrunk to 0.9 of the line's width when it is wider, never an overfull line, and may begin a line with
    the line before it filled out (the glue ``\hfil``, cancelled by ``\hfilneg`` when no break is made)."""
    if "\\left" not in math and not always:
        return f"${math}$"
    # at most 0.9 of the line: the punctuation that follows it stays on its line
    return (r"\nobreak\hfil\penalty0\hfilneg\relax\resizebox{\ifdim\width>0.9\linewidth 0.9\linewidth\else\width\fi}{!}{$"
            + math + "$}")


def _md_mutant_text(o: dict[str, Any]) -> str:
    """The paper's notation first (where the mutant traces), the source edit after it."""
    change = _md_change(o.get("notation"))
    source = _md_described(o.get("description", ""))
    return f"{change} (source: {source})" if change else source


def _tex_mutant_text(o: dict[str, Any]) -> str:
    change = _tex_change(o.get("notation"))
    source = tex_escape(o.get("description", ""))
    return f"{change} {{\\small (source: {source})}}" if change else source


def _md_mutant_item(o: dict[str, Any], verdicts: bool = True) -> str:
    text = f"- `{_mutant_label(o)}` {_md_mutant_text(o)}"
    if o.get("survived"):
        text += f": **survived {', '.join(o['survived'])}**"
    if verdicts:
        text += f" ({_md_escape(_mutant_verdicts(o))})"
    return text


def _md_mutation_body(data: dict[str, Any], full: bool) -> list[str]:
    out = _md_mutation_tables(data)
    surv = _mutants(data, survivors=True)
    if surv:
        out += [f"**{len(surv)} survivor{'s' * (len(surv) != 1)}**: a method passed a mutant that another "
                "method refuted at the same size, or the dimension-free method proved a mutant that is not "
                "equivalent.", ""]
        out += [_md_mutant_item(o) for o in surv] + [""]
        if full:
            for o in surv:
                msgs = [c for c in o.get("cells", []) if c.get("message") and c["verdict"] in ("fails", "error")]
                if msgs:
                    c = msgs[0]
                    size = "all n, r" if c.get("n") is None else f"({c['n']},{c['r']})"
                    out += [f"  - `{_mutant_label(o)}` {size} {c['method']} {c['verdict']}: "
                            f"{_md_cell(short(c['message'], 200))}"]
            out.append("")
    else:
        out += ["No survivor: no method passed a mutant at a size where another method refuted it, and the "
                "dimension-free method proved no mutant that is not equivalent.", ""]
    equiv = _mutants(data, "equivalent")
    unresolved = _mutants(data, "unresolved")
    if full or len(equiv) <= 30:
        out += [f"Equivalent mutants ({len(equiv)}): passed by every method at every size run (where the "
                "printed claim passes), so true statements at those sizes.", ""]
        out += [_md_mutant_item(o, verdicts=False) for o in equiv] + [""] if equiv else []
    else:
        out += [f"{len(equiv)} equivalent mutants (true statements), listed in `mutation.md`.", ""]
    if unresolved:
        out += [f"Unresolved mutants ({len(unresolved)}): refuted by no method, left undecided (inconclusive or "
                "undecided) by some method and passed by another.", ""]
        out += [_md_mutant_item(o) for o in unresolved] + [""]
    made_on = _mutation_made_on(data)
    if made_on:
        out += [_md_escape(made_on[0][0].upper() + made_on[0][1:]) + ".", ""]
        fell = [c for c in data.get("claims", []) if c.get("fallback")]
        if fell:
            out += ["Claims mutated on their source because their graphs could not be:", ""]
            out += [f"- `{c['claim']}`: {_md_escape(c['fallback'])}" for c in fell] + [""]
    widened = [c for c in data.get("claims", []) if c.get("sites") and c["sites"] != "the claim's function"]
    if widened:
        out += ["Claims whose own function offers no change of its formulas, mutated at the sites of the functions "
                "it calls as well:", ""]
        out += [f"- `{c['claim']}`: {_md_escape(c['sites'])}" for c in widened] + [""]
    skipped = [c for c in data.get("claims", []) if c.get("skipped")]
    if skipped:
        out += ["Claims not mutated:", ""]
        out += [f"- `{c['claim']}`: {_md_escape(c['skipped'])}" for c in skipped] + [""]
    return out


def _mutation_facts(data: dict[str, Any]) -> list[str]:
    """Plain-text sentences on the run (the command is rendered apart, as code)."""
    meta = data.get("meta") or {}
    run = [f"seed {meta['seed']}" if meta.get("seed") is not None else "",
           f"at commit {meta['commit']}" if meta.get("commit") else ""]     # no date, no duration: no drift
    return ["Run with " + ", ".join(x for x in run if x) + "."] if any(run) else []


def _md_mutation_facts(data: dict[str, Any]) -> list[str]:
    command = (data.get("meta") or {}).get("command")
    return ([f"Command: {_md_code(command)}."] if command else []) + \
        [_md_escape(f) for f in _mutation_facts(data)]


def render_mutation_markdown(mutation: Any) -> str:
    """``mutation.md``: the tables of refuted and undecided mutants, the survivors, the equivalent mutants (all of them)."""
    data = _mutation_data(mutation)
    meta = data.get("meta") or {}
    out = ["# Mutation analysis", "",
           "Generated by `stiefelsym mutate` from `mutation.json`; do not edit by hand.", ""]
    facts = _md_mutation_facts(data)
    out += facts + ([""] if facts else [])
    out += MUTATION_TERMS + [""]
    out += [_md_escape(MUTATION_EXPLANATION), ""]
    ops = meta.get("operators") or []
    if ops:
        out += ["The corruptions:", ""] + [f"- {o['name']}: {_md_escape(o['description'])}" for o in ops] + [""]
    swaps = meta.get("letter_swaps") or {}
    if swaps:
        seen: dict[frozenset, str] = {}
        for a, bs in swaps.items():
            for b in bs:   # a two-way swap once, in the order of the table
                seen.setdefault(frozenset((a, b)), f"{a} ↔ {b}" if a in swaps.get(b, ()) else f"{a} → {b}")
        pairs = list(seen.values())
        out += ["Letter swaps (scene attributes, local names bound to them, and flow[\"...\"] keys): "
                + ", ".join(_md_code(p) for p in pairs) + ".", ""]
    groups: dict[tuple, list[str]] = {}
    for c in data.get("claims", []):
        if not c.get("skipped"):
            groups.setdefault(tuple(tuple(x) for x in c.get("sizes", [])), []).append(c["claim"])
    if groups:
        out += ["Sizes (where the printed claim is stated and expected to hold):", ""]
        out += [f"- {format_sizes(sz, 6) or 'none'}: " + (f"every claim ({len(ids)})" if len(groups) == 1
                                                         else ", ".join(f"`{i}`" for i in ids))
                for sz, ids in groups.items()] + [""]
    return "\n".join(out + _md_mutation_body(data, full=True)).rstrip() + "\n"


def _md_mutation_section(data: dict[str, Any]) -> list[str]:
    """The appendix's section on the mutation analysis: its summary (the totals per method, the survivors, how
    many mutants are equivalent or unresolved), the rest being in ``mutation.md``, which it does not repeat."""
    claims = data.get("claims", [])
    mutated = [c for c in claims if not c.get("skipped")]
    count = sum(len(c.get("mutants", [])) for c in claims)
    surv = _mutants(data, survivors=True)
    # every class of mutant, so that the counts add up to the mutants (a class with none left out, survivors kept)
    classes = [(len(_mutants(data, "killed")), "refuted"), (len(_mutants(data, "equivalent")), "equivalent"),
               (len(_mutants(data, "unresolved")), "unresolved"),
               (len(_mutants(data, "unexercised")), "run at no size where the claim as printed passes")]
    counts = ", ".join(f"{k:,} {what}" for k, what in classes if k)
    out = ["## Mutation analysis", "",
           "From `mutation.json` (`stiefelsym mutate`).  This section is its summary; `mutation.md` has the whole "
           "analysis: the corruptions, the verdicts per claim and method, and every mutant that is not refuted."]
    out += _md_mutation_facts(data) + [""]
    out += [_md_escape(MUTATION_EXPLANATION), ""]
    skipped = len(claims) - len(mutated)
    out += [f"{count:,} mutant{'s' * (count != 1)} of {len(mutated)} claim{'s' * (len(mutated) != 1)}"
            + (f" ({skipped} more claim{'s' * (skipped != 1)} not mutated, each with its reason in `mutation.md`)"
               if skipped else "") + f": {counts}; {len(surv)} survivor{'s' * (len(surv) != 1)}.", ""]
    head = list(MUTATION_COLUMNS)
    out += ["Per method, over all claims:", ""]
    out += _md_table(["method"] + head, [[r["method"]] + _mutation_cells(r) for r in data.get("totals", [])],
                     "l" + "r" * len(head))
    if surv:
        out += [f"**{len(surv)} survivor{'s' * (len(surv) != 1)}**: a method passed a mutant that another "
                "method refuted at the same size, or the dimension-free method proved a mutant that is not "
                "equivalent.", ""]
        out += [_md_mutant_item(o) for o in surv] + [""]
    else:
        out += ["No survivor: no method passed a mutant at a size where another method refuted it, and the "
                "dimension-free method proved no mutant that is not equivalent.", ""]
    return out


def _tex_mutation_section(data: dict[str, Any]) -> list[str]:
    head = list(MUTATION_COLUMNS)
    out = [r"\section*{Mutation analysis}",
           tex_escape("From mutation.json (stiefelsym mutate; in full in mutation.md). ")
           + (("Command: " + _tt((data.get("meta") or {})["command"]) + ". ")
              if (data.get("meta") or {}).get("command") else "")
           + " ".join(tex_escape(f) for f in _mutation_facts(data)), "",
           tex_escape(MUTATION_EXPLANATION), "",
           r"{\small\setlength{\tabcolsep}{3pt}",
           r"\begin{longtable}{@{}P{4.2cm}l" + "r" * len(head) + "@{}}", r"\toprule",
           " & ".join(["claim", "method"] + [r"\rotatebox{90}{" + tex_escape(h) + "}" for h in head]) + r"\\",
           r"\midrule", r"\endhead"]
    rows = [dict(r, claim="all claims") for r in data.get("totals", [])] + list(data.get("table", []))
    for i, r in enumerate(rows):
        name = (r"\textit{all claims}" if r["claim"] == "all claims"
                else r"\texttt{" + tex_escape(r["claim"]).replace("-", r"-\allowbreak{}") + "}")
        out.append(" & ".join([name, tex_escape(r["method"])] + [tex_escape(x) for x in _mutation_cells(r)]) + r"\\")
        if r["claim"] == "all claims" and (i + 1 == len(rows) or rows[i + 1]["claim"] != "all claims"):
            out.append(r"\midrule")
    out += [r"\bottomrule", r"\end{longtable}", "}", ""]
    surv = _mutants(data, survivors=True)
    if surv:
        out.append(tex_escape(f"{len(surv)} survivors: a method passed a mutant that another method refuted "
                              "at the same size, or the dimension-free method proved a mutant that is not "
                              "equivalent."))
        out += _tex_items([r"\texttt{" + tex_escape(_mutant_label(o)) + "} " + _tex_mutant_text(o)
                           + r": \textbf{survived " + tex_escape(", ".join(o["survived"])) + "} ("
                           + tex_escape(short(_mutant_verdicts(o), 300)) + ")" for o in surv])
    else:
        out.append("No survivor.")
    equiv = _mutants(data, "equivalent")
    out += ["", tex_escape(f"{len(equiv)} equivalent mutants (true statements)" + (":" if equiv else "."))]
    out += _tex_items([r"\texttt{" + tex_escape(_mutant_label(o)) + "} " + _tex_mutant_text(o)
                       for o in equiv[:40]])
    if len(equiv) > 40:
        out.append(tex_escape(f"… and {len(equiv) - 40} more (in mutation.md)."))
    return out + [""]
