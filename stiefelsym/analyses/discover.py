"""Discovery: the exact space of conserved quantities of a flow in a space of trace polynomials.

A mathematician who asks "which functions of this shape are integrals of this flow?"
asks a linear question.  The ansatz is a list of trace monomials F₁, …, F_N in the
letters X, Xᵀ, P, Pᵀ, A (closed words, one per class under rotation and transposition,
and products of two of them) with unknown coefficients c; the flow's derivative of
Σ cᵢFᵢ is linear in c.  So:

1. the claim ``{Fᵢ, dFᵢ/dt}`` is traced once (:mod:`stiefelsym.ir`) and its graph
   evaluated at K > N random points of T*V over a prime field p ≈ 2⁶¹;
2. the null spaces of the two K × N systems give V₁ = {c : d(ΣcᵢFᵢ)/dt = 0} and
   V₀ = {c : ΣcᵢFᵢ constant on T*V} (V₀ ⊆ V₁: what is constant on T*V is conserved
   for a trivial reason);
3. a basis of V₁ modulo V₀ is put in reduced echelon form and its coefficients are
   reconstructed as rationals (they must be: the flow and the ansatz are rational);
4. every basis element is then a claim of its own, verified by the usual methods at
   the sizes asked for, and by the dimension-free method for all n, r.

The number dim V₁ − dim V₀ is reported per size; a false pass of step 1–2 is caught by
step 4 (no element is reported without its verdicts).
"""
from __future__ import annotations

import itertools
import math
import random
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Sequence

from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.ir import block

#: the letters: (name, rows, columns, transpose, LaTeX)
LETTERS = {"X": ("n", "r", "Xt", "X"), "Xt": ("r", "n", "X", "X^T"), "P": ("n", "r", "Pt", "P"),
           "Pt": ("r", "n", "P", "P^T"), "A": ("n", "n", "A", "A")}

PRIME = 2**61 - 1
#: the primes a search tries in turn: the next one where a constant of the flow (or of the ansatz) is 0 or has no
#: inverse modulo the one before, or where the space found there is refuted by verification (a constant of the
#: flow divisible by that prime makes the flow vanish there, and every monomial looks conserved)
PRIMES = (PRIME, 2**62 - 57, 2**60 - 93)


def _prime_text(p: int) -> str:
    for e in (60, 61, 62):
        if 0 <= 2**e - p < 2**e // 2:
            return f"2^{e} - {2**e - p}"
    return str(p)


def _canonical(word: tuple[str, ...]) -> tuple[str, ...]:
    """The representative of tr(word) under rotation and transposition (tr w = tr wᵀ)."""
    t = tuple(LETTERS[x][2] for x in reversed(word))
    return min(w[i:] + w[:i] for w in (word, t) for i in range(len(w)))


def closed_words(degree: int, max_a: int = 1) -> list[tuple[str, ...]]:
    """The closed words in X, Xᵀ, P, Pᵀ (and at most ``max_a`` letters A) of 1..degree letters X, P,
    one per class of tr under rotation and transposition, leaving out those that contain XᵀX
    (cyclically): on T*V they are shorter words."""
    out = set()
    for length in range(1, degree + max_a + 1):
        for word in itertools.product(LETTERS, repeat=length):
            if not 1 <= sum(x != "A" for x in word) <= degree or word.count("A") > max_a:
                continue
            if any(LETTERS[a][1] != LETTERS[b][0] for a, b in zip(word, word[1:])):
                continue
            if LETTERS[word[-1]][1] != LETTERS[word[0]][0]:
                continue
            if any(a == "Xt" and b == "X" for a, b in zip(word, word[1:] + word[:1])):
                continue        # XᵀX = I_r on T*V: the word reduces to a shorter one
            out.add(_canonical(word))
    return sorted(out, key=lambda w: (len(w), w))


@dataclass(frozen=True)
class Monomial:
    """A product of traces of closed words."""

    words: tuple[tuple[str, ...], ...]

    @property
    def degree(self) -> int:
        return sum(sum(x != "A" for x in w) for w in self.words)

    def latex(self) -> str:
        return "".join(r"\operatorname{tr}(" + " ".join(LETTERS[x][3] for x in w) + ")" for w in self.words)

    def text(self) -> str:
        names = {"X": "X", "Xt": "Xᵀ", "P": "P", "Pt": "Pᵀ", "A": "A"}
        return "·".join("tr(" + "".join(names[x] for x in w) + ")" for w in self.words)

    def __call__(self, s: Any) -> Any:
        acc = None
        for w in self.words:
            M = None
            for x in w:
                L = {"X": s.X, "Xt": s.X.T, "P": s.P, "Pt": s.P.T, "A": s.A}[x]
                M = L if M is None else M @ L
            t = s.tr(M)
            acc = t if acc is None else acc * t
        return acc


def ansatz(degree: int, max_a: int = 1, products: bool = True) -> list[Monomial]:
    """The trace monomials of degree <= ``degree`` (in X, P; at most ``max_a`` letters A per trace):
    single traces, and products of two when ``products``."""
    words = closed_words(degree, max_a)
    out = [Monomial((w,)) for w in words]
    if products:
        for a, b in itertools.combinations_with_replacement(words, 2):
            m = Monomial((a, b))
            if m.degree <= degree and sum(w.count("A") for w in m.words) <= max_a:
                out.append(m)
    # the most composite first: the echelon forms below put their pivots there, so that each integral
    # is written with the simplest monomials
    return sorted(out, key=lambda m: (-len(m.words), -m.degree, m.words))


def _rational(a: int, p: int) -> Fraction | None:
    """The rational u/v with |u|, v < sqrt(p/2) congruent to a mod p (None if there is none); p may be any
    modulus (a product of primes, :class:`_Lift`)."""
    bound = math.isqrt(p // 2)
    r0, r1, t0, t1 = p, a % p, 0, 1
    while r1 > bound:
        q = r0 // r1
        r0, r1, t0, t1 = r1, r0 - q * r1, t1, t0 - q * t1
    if t1 == 0 or abs(t1) > bound:
        return None
    return Fraction(r1, t1)


#: at most this many primes for one reconstruction (a coefficient of height up to about 2^(61·LIFT_PRIMES/2))
LIFT_PRIMES = 8


def lift_primes() -> list[int]:
    """The primes a search solves modulo, in turn: :data:`PRIMES`, then the primes below 2^61 − 1 downwards."""
    import flint
    out, q = list(PRIMES), PRIME - 2
    while len(out) < LIFT_PRIMES:
        if flint.fmpz(q).is_prime():
            out.append(q)
        q -= 2
    return out


class _Lift:
    """Integer vectors known modulo a growing product of primes (Chinese remainders), reconstructed as rationals.

    A linear search solves its system modulo one prime at a time and puts each solution into a canonical form
    (reduced echelon rows), which modulo every prime but finitely many is the reduction of the one rational
    solution.  The residues of the primes whose echelon shape (``key``: ranks and pivots) agrees are combined;
    the reconstruction is accepted only when two successive moduli give the same rationals (a single prime may
    reconstruct a wrong fraction of small height where the true coefficient is beyond its reach), and a prime of
    another shape starts afresh."""

    def __init__(self) -> None:
        self.key: Any = None
        self.m = 1
        self.vals: list[int] = []
        self.last: list[Fraction] | None = None
        #: reconstructions that verification refuted: the residues stay (they are right; the modulus was too
        #: small), and the answer must be another reconstruction, agreed on by two further moduli
        self.refuted: list[list[Fraction]] = []

    def refute(self) -> None:
        if self.last is not None:
            self.refuted.append(self.last)
        self.last = None

    def add(self, key: Any, vals: Sequence[int], prime: int) -> list[Fraction] | None:
        if key != self.key or len(vals) != len(self.vals):
            self.key, self.m, self.vals, self.last = key, 1, [0] * len(vals), None
            self.refuted = []
        inv = pow(self.m % prime, -1, prime)
        self.vals = [a + self.m * (((b - a) * inv) % prime) for a, b in zip(self.vals, vals)]
        self.m *= prime
        got = [_rational(x, self.m) if x else Fraction(0) for x in self.vals]
        rec = None if any(q is None for q in got) else [q for q in got if q is not None]
        stable = rec is not None and rec == self.last and rec not in self.refuted
        self.last = rec
        return rec if stable else None


@dataclass
class Integral:
    """One conserved quantity found: its coefficients on the ansatz and its verdicts."""

    terms: list[tuple[Fraction, Monomial]]
    verdicts: dict[str, str] = field(default_factory=dict)

    def text(self) -> str:
        out = []
        for c, m in self.terms:
            sign = "−" if c < 0 else "+"
            a = abs(c)
            coef = "" if a == 1 else f"{a}·"
            out.append(f"{sign} {coef}{m.text()}")
        s = " ".join(out)
        return s[2:] if s.startswith("+ ") else "−" + s[2:]

    def latex(self) -> str:
        out = []
        for c, m in self.terms:
            a = abs(c)
            coef = "" if a == 1 else (rf"\tfrac{{{a.numerator}}}{{{a.denominator}}}" if a.denominator != 1 else str(a))
            out.append(("-" if c < 0 else "+") + coef + m.latex())
        s = "".join(out)
        return s[1:] if s.startswith("+") else s

    def function(self) -> Callable[[Any], Any]:
        terms = list(self.terms)

        def F(s):
            acc = None
            for c, m in terms:
                v = m(s) * s.q(c.numerator, c.denominator)
                acc = v if acc is None else acc + v
            return acc
        return F

    @property
    def verified(self) -> bool:
        return bool(self.verdicts) and all(v in ("proved", "checked", "numeric") for v in self.verdicts.values())


@dataclass
class Discovery:
    """The space of conserved quantities of ``flow`` in the ansatz, at one size."""

    flow: str
    size: Size
    ansatz: list[Monomial]
    conserved_dim: int          # dim V1
    constant_dim: int           # dim V0 (constant on T*V)
    integrals: list[Integral]
    points: int
    seed: int
    prime: int = PRIME
    #: what went wrong at the primes tried before (and at this one, when every prime was tried)
    caveats: list[str] = field(default_factory=list)
    #: the space found is the flow's as far as verification can tell: every element was reconstructed and none
    #: was refuted (False: every prime was tried, and this is the last space found)
    certified: bool = True

    def lines(self) -> list[str]:
        n, r = self.size.n, self.size.r
        out = [f"flow {self.flow}, (n, r) = ({n}, {r}): ansatz of {len(self.ansatz)} trace monomials "
               f"(degree <= {max(m.degree for m in self.ansatz)}); {self.points} points of "
               f"GF({_prime_text(self.prime)}), seed {self.seed}"]
        out += [f"  note: {c}" for c in self.caveats]
        out += [f"  conserved: dim {self.conserved_dim}; constant on T*V: dim {self.constant_dim}; "
                f"independent integrals modulo constants: {len(self.integrals)}"
                + ("" if self.certified else "  (NOT the flow's: see the note above)")]
        for k, I in enumerate(self.integrals, 1):
            v = ", ".join(f"{m} {x}" for m, x in I.verdicts.items())
            out.append(f"  I{k} = {I.text()}    [{v}]")
        return out


def _nullspace(rows: list[list[int]], N: int, p: int) -> list[list[int]]:
    """A basis of {c : rows · c = 0} over GF(p), as the rows of a reduced echelon matrix."""
    import flint
    if not rows:
        return [[int(i == j) for j in range(N)] for i in range(N)]
    X, nullity = flint.nmod_mat(rows, p).nullspace()
    basis = [[int(X[i, j]) for i in range(N)] for j in range(nullity)]
    if not basis:
        return []
    R = flint.nmod_mat(basis, p).rref()[0]
    return [[int(R[i, j]) for j in range(N)] for i in range(nullity)]


def _quotient(V1: list[list[int]], V0: list[list[int]], p: int) -> list[list[int]]:
    """A basis of span(V1) modulo span(V0) (V0 in reduced echelon form): each row of V1 with the
    pivot columns of V0 eliminated, the result in reduced echelon form."""
    import flint
    pivots = [(row.index(next(x for x in row if x)), row) for row in V0]
    reduced = []
    for v in V1:
        v = list(v)
        for j, row in pivots:
            if v[j]:
                c = v[j]
                v = [(x - c * y) % p for x, y in zip(v, row)]
        if any(v):
            reduced.append(v)
    if not reduced:
        return []
    R = flint.nmod_mat(reduced, p).rref()
    M, rank = R
    return [[int(M[i, j]) for j in range(len(V1[0]))] for i in range(rank)]


def evaluate_derived(g: Any, scene: Any) -> Any:
    """A probe's graph evaluated as the methods evaluate a claim's: its derivatives along flows, gradients,
    flows and brackets rewritten into graph nodes where the scene lets them (:mod:`stiefelsym.ir.derivative`;
    the rest computed by the scene), on ``scene``."""
    from stiefelsym.ir.derivative import derivatives, scene_flows
    from stiefelsym.ir.evaluate import evaluate
    return evaluate(derivatives(g, scene_flows(scene)), scene)


def conserved(flow: Callable[[Any], Any], size: Size, degree: int = 4, *, max_a: int = 1,
              products: bool = True, seed: int = 0, name: str = "", verify: Sequence[str] = ("auto", "free"),
              terms: Sequence[Monomial] | None = None, realization: str = "standard") -> Discovery:
    """The conserved quantities of ``flow`` (a function of the scene giving the tangent vector
    {"X": Ẋ, "P": Ṗ}) among the trace monomials of degree <= ``degree``, at ``size``; each basis
    element verified by the methods ``verify`` (the dimension-free one for all n, r)."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.scene import REALIZATIONS

    mons = list(terms) if terms is not None else ansatz(degree, max_a, products)
    N = len(mons)

    def probe(s):
        tangent = flow(s)
        out = {}
        for i, m in enumerate(mons):
            out[f"F{i}"] = m(s)
            out[f"dF{i}"] = s.d(m, tangent)
        return out
    cons = REALIZATIONS[realization]
    g = compile_claim(probe, size.n, size.r, (cons.name, cons.build))
    K = N + 8
    caveats: list[str] = []
    last: Discovery | None = None
    for prime in PRIMES:
        found = _conserved_mod(g, size, N, K, prime, seed, name, realization)
        if isinstance(found, str):
            caveats.append(found)
            continue
        V0, V1, kept = found
        integrals = []
        for v in kept:
            coeffs = [_rational(x, prime) if x else Fraction(0) for x in v]
            if any(c is None for c in coeffs):
                continue
            integrals.append(Integral([(c, m) for c, m in zip(coeffs, mons) if c]))
        _verify_integrals(integrals, flow, size, name, realization, verify, seed)
        refuted = [k for k, I in enumerate(integrals, 1) if "fails" in I.verdicts.values()]
        lost = len(kept) - len(integrals)
        last = Discovery(name or getattr(flow, "__name__", "flow"), size, mons, len(V1), len(V0), integrals, K,
                         seed, prime, caveats)
        if not refuted and not lost:
            return last
        caveats.append(
            f"modulo p = {_prime_text(prime)} the space found is not the flow's: "
            + (f"{', '.join(f'I{k}' for k in refuted)} {'fails' if len(refuted) == 1 else 'fail'} verification"
               if refuted else "")
            + ("; " if refuted and lost else "")
            + (f"{lost} of its {len(kept)} elements have no rational coefficients of small height" if lost else "")
            + " (a constant of the flow may be divisible by p)")
    if last is not None:
        last.certified = False      # every prime tried: the last space found, with what is wrong with it
        return last
    raise ValueError("the flow cannot be evaluated modulo any of the primes "
                     + ", ".join(_prime_text(p) for p in PRIMES) + ": " + "; ".join(caveats))


def _conserved_mod(g: Any, size: Size, N: int, K: int, prime: int, seed: int, name: str,
                   realization: str) -> tuple[list, list, list] | str:
    """The spaces V0 (constant on T*V), V1 (conserved) and V1 modulo V0 over GF(prime), from K + 1 random points;
    a sentence instead where the graph cannot be evaluated modulo ``prime`` (a constant 0 or not invertible
    there)."""
    from stiefelsym.backends.fields import DegenerateError, ModularField
    from stiefelsym.scene import Scene
    rng = random.Random(f"{seed}|discover|{name}|{size.n}|{size.r}" + (f"|{prime}" if prime != PRIME else ""))
    values, derivs = [], []
    try:
        for k in range(K + 1):
            scene = Scene(size.n, size.r, ModularField(prime), chart="cayley", rng=rng,
                          component=k % 2 if size.r == size.n else 0, realization=realization)
            out = evaluate_derived(g, scene)
            values.append([int(out[f"F{i}"]) for i in range(N)])
            derivs.append([int(out[f"dF{i}"]) for i in range(N)])
    except (DegenerateError, ZeroDivisionError) as exc:
        return f"modulo p = {_prime_text(prime)} the flow cannot be evaluated ({exc})"
    base = values[0]
    V0 = _nullspace([[(v - b) % prime for v, b in zip(row, base)] for row in values[1:]], N, prime)
    V1 = _nullspace(derivs[1:], N, prime)
    return V0, V1, _quotient(V1, V0, prime)


def _verify_integrals(integrals: list[Integral], flow: Callable[[Any], Any], size: Size, name: str,
                      realization: str, verify: Sequence[str], seed: int) -> None:
    """Each integral's verdicts (dI/dt = 0 along the flow) by the methods ``verify``, in its ``verdicts``."""
    from stiefelsym.run.runner import run_one
    for k, I in enumerate(integrals, 1):
        F = I.function()
        tangent_of = flow

        def check(s, F=F):
            return {"dI/dt": s.d(F, tangent_of(s))}
        check.__doc__ = f"d/dt ({I.text()}) = 0 along {name or 'the flow'}."
        claim = Claim(id=f"discovered-{k}", paper=("discover",), kind="id", section="discover", func=check,
                      sizes=admissible(max(size.n, 1)), realization=realization)
        for m in verify:
            res = run_one(claim, None if m == "free" else size, m, seed)
            I.verdicts[m if m != "free" else "free (all n, r)"] = res.verdict


def hamiltonian_flow(H: Callable[[Any], Any]) -> Callable[[Any], Any]:
    """The tangent vector of the Dirac flow of a Hamiltonian H, as a function of the scene."""
    def flow(s):
        return s.dirac_flow(H).tangent()
    flow.__name__ = f"dirac_flow({getattr(H, '__name__', 'H')})"
    return flow


#: the catalog's Lax matrices by the paper's label: (module, function)
LAX = {"LA2": ("sec5_neumann", "L_neum")}

#: the catalog's flows by name: (module of the catalog, function, how to make the tangent, reference)
FLOWS = {
    "neumann-normal": ("sec5_neumann", "flow_N0", "tangent", "(N0_XP2): the Neumann flow of the normal metric"),
    "neumann-euclidean": ("sec5_neumann", "flow_NE", "tangent", "(NE_XP): the Neumann flow of the Euclidean metric"),
    "geodesic-normal": ("sec3_geodesic_flows", "H_normal", "hamiltonian", "the geodesic flow of the normal metric"),
    "geodesic-euclidean": ("sec3_geodesic_flows", "H_euclidean", "hamiltonian",
                           "the geodesic flow of the Euclidean metric"),
}


def _catalog_module(name: str) -> Any:
    import importlib
    for pkg in ("stiefelsym.proofs", "proofs"):
        try:
            return importlib.import_module(f"{pkg}.{name}")
        except ImportError:
            continue
    raise ImportError(f"the catalog module {name!r} is not available")


def resolve_function(spec: str, table: dict[str, tuple[str, str]],
                     sizes: Sequence[Size] = ()) -> Callable[[Any], Any]:
    """A matrix-valued function of the scene by catalog name, ``module:function`` or ``file.py:function`` (a user's:
    traced in the claims files' sandbox at ``sizes``, see :func:`confined_function`)."""
    if spec in table:
        mod, fn = table[spec]
        return getattr(_catalog_module(mod), fn)
    parts = spec.split(":")
    if len(parts) == 2 and all(parts):
        return confined_function(parts[0], parts[1], "matrix", sizes)
    raise ValueError(f"unknown function {spec!r}: a catalog name ({', '.join(table)}), module:function or "
                     "file.py:function")


def load_object(mod: str, name: str) -> Any:
    """The object ``name`` of a module (dotted name) or of a file ``something.py``, imported in this process: for
    the Python API (a library user's own code runs where they call it), never for a command's verdicts."""
    import importlib
    try:
        if mod.endswith(".py"):
            import importlib.util
            mspec = importlib.util.spec_from_file_location(f"_discover_{abs(hash(mod))}", mod)
            if mspec is None or mspec.loader is None:
                raise ImportError(f"no such file: {mod}")
            module = importlib.util.module_from_spec(mspec)
            mspec.loader.exec_module(module)
        else:
            module = importlib.import_module(mod)
        return getattr(module, name)
    except (ImportError, AttributeError, OSError, SyntaxError) as exc:
        raise ValueError(f"cannot load {mod}:{name}: {exc}") from None


#: the claim a user's function is wrapped in, to be traced in the claims files' sandbox (confined_function)
CONFINED_CLAIM = "discover-user-function"
#: what the wrapping claim returns of the user's function, by the kind of function
_CONFINED_BODY = {
    "tangent": 't = _f(s)\n    return {"X": t["X"], "P": t["P"]}',
    "hamiltonian": 'return {"H": _f(s)}',
    "matrix": 'return {"L": _f(s)}',
}


def confined_function(mod: str, name: str, how: str, sizes: Sequence[Size] = ()) -> Callable[[Any], Any]:
    """A user's function of the scene (``how``: "tangent" {"X": Ẋ, "P": Ṗ}, "hamiltonian" a number, "matrix" a
    matrix), from ``file.py`` or a module, as the discover command uses it: the file is imported and the function
    traced in the claims files' sandbox (:func:`stiefelsym.run.userfile.load_claims_isolated`; a generated claims
    file wraps it in one claim), at ``sizes`` and with symbolic sizes, and what comes back is its graphs, replayed
    on the engine's tracer.  No code of the user's runs in this process, which gives the verdicts: a file that
    patched the engine here would steer them."""
    import tempfile
    from pathlib import Path
    from stiefelsym.claims import CatalogError
    from stiefelsym.run.userfile import load_claims_isolated
    needed = sorted({(z.n, z.r) for z in sizes}) or [(4, 2)]
    if not name.isidentifier():
        raise ValueError(f"cannot load {mod}:{name}: {name!r} is not a name")
    if mod.endswith(".py"):
        path = Path(mod).resolve()
        if not path.is_file():
            raise ValueError(f"cannot load {mod}:{name}: no such file")
        load = (f"_spec = importlib.util.spec_from_file_location('_stiefelsym_discover_user', {str(path)!r})\n"
                "_m = importlib.util.module_from_spec(_spec)\n_spec.loader.exec_module(_m)\n")
    elif all(part.isidentifier() for part in mod.split(".")):
        load = f"_m = importlib.import_module({mod!r})\n"
    else:
        raise ValueError(f"cannot load {mod}:{name}: neither a file.py nor a dotted module name")
    # (only names checked above and repr() of the rest go into the source: a quote or a newline in a file name
    # is not code)
    source = (f'"""A {how} function of one\'s own, wrapped by stiefelsym discover to be traced in the sandbox."""\n'
              "import importlib\nimport importlib.util\n\nfrom stiefelsym import admissible, claim\n\n"
              + load + f"_f = getattr(_m, {name!r})\n_SIZES = {needed!r}\n\n\n"
              f"@claim({CONFINED_CLAIM!r}, paper=('discover',), kind='id', sizes=admissible("
              f"n_max={max(n for n, _ in needed)}, where=lambda n, r: (n, r) in _SIZES))\n"
              f'def user_function(s):\n    """The {how} function {name}."""\n    {_CONFINED_BODY[how]}\n')
    # the wrapper lies where the user's code does (the file's folder, or the current one for a module), for a
    # while: the sandbox shows the interpreter the claims file's folder, and the file imports what lies beside it
    folder = path.parent if mod.endswith(".py") else Path.cwd()
    try:
        handle = tempfile.NamedTemporaryFile("w", encoding="utf-8", suffix=".py", prefix=".stiefelsym-discover-",
                                             dir=folder, delete=False)
    except OSError as exc:
        raise ValueError(f"cannot load {mod}:{name}: discover writes a claims file wrapping it beside it, in "
                         f"{folder}, for a moment ({exc.strerror})") from None
    wrapper = Path(handle.name)
    try:
        with handle:
            handle.write(source)
        registry = load_claims_isolated(wrapper, needed)
    except CatalogError as exc:
        said = str(exc).removeprefix(f"{wrapper}: ").replace(str(wrapper), f"{mod}:{name}")
        raise ValueError(f"cannot load {mod}:{name}: {said}") from None
    finally:
        wrapper.unlink(missing_ok=True)
    traced = registry.get(CONFINED_CLAIM).func
    if how == "tangent":
        def function(s: Any) -> Any:
            out = traced(s)
            return {"X": out["X"], "P": out["P"]}
    else:
        key = "H" if how == "hamiltonian" else "L"

        def function(s: Any) -> Any:
            return traced(s)[key]
    function.__name__ = name
    return hamiltonian_flow(function) if how == "hamiltonian" else function


def resolve_flow(spec: str, sizes: Sequence[Size] = ()) -> tuple[Callable[[Any], Any], str]:
    """A flow by catalog name, by ``module:function`` or ``file.py:function`` (a function of the scene
    giving {"X": Ẋ, "P": Ṗ}), or by ``hamiltonian:module:function`` (the Dirac flow of a Hamiltonian); a
    user's function is traced in the claims files' sandbox at ``sizes`` (:func:`confined_function`)."""
    if spec in FLOWS:
        mod, fn, how, text = FLOWS[spec]
        f = getattr(_catalog_module(mod), fn)
        return (hamiltonian_flow(f) if how == "hamiltonian" else f), text
    parts = spec.split(":")
    if len(parts) in (2, 3) and all(parts):
        how = parts[0] if len(parts) == 3 else "tangent"
        if how not in ("tangent", "hamiltonian"):
            raise ValueError(f"unknown kind of flow {how!r} (tangent or hamiltonian)")
        return confined_function(parts[-2], parts[-1], how, sizes), spec
    raise ValueError(f"unknown flow {spec!r}: a catalog flow ({', '.join(FLOWS)}), module:function or "
                     "hamiltonian:module:function")


# ---------------------------------------------------------------------------------------------
# affine spaces: Σ cⱼ Tⱼ = R identically on T*V (Lax partners, corrections of printed formulas)

def open_words(degree: int, rows: str = "n", cols: str = "n", max_a: int = 1) -> list[tuple[str, ...]]:
    """The words in X, Xᵀ, P, Pᵀ, A from ℝ^cols to ℝ^rows (a matrix rows × cols) with at most ``degree``
    letters X, P and ``max_a`` letters A, none containing XᵀX (the empty word: the identity)."""
    out = [()] if rows == cols else []
    for length in range(1, degree + max_a + 1):
        for word in itertools.product(LETTERS, repeat=length):
            if sum(x != "A" for x in word) > degree or word.count("A") > max_a:
                continue
            if LETTERS[word[0]][0] != rows or LETTERS[word[-1]][1] != cols:
                continue
            if any(LETTERS[a][1] != LETTERS[b][0] for a, b in zip(word, word[1:])):
                continue
            if any(a == "Xt" and b == "X" for a, b in zip(word, word[1:])):
                continue
            out.append(word)
    return out


def word_matrix(s: Any, word: tuple[str, ...], rows: str = "n") -> Any:
    if not word:
        return s.In if rows == "n" else s.Ir
    M = None
    for x in word:
        L = {"X": s.X, "Xt": s.X.T, "P": s.P, "Pt": s.P.T, "A": s.A}[x]
        M = L if M is None else M @ L
    return M


def word_text(word: tuple[str, ...], rows: str = "n") -> str:
    names = {"X": "X", "Xt": "Xᵀ", "P": "P", "Pt": "Pᵀ", "A": "A"}
    return "".join(names[x] for x in word) or f"I_{rows}"


class _Answer:
    """What a linear search answers where it gives no formula (the fields of :class:`AffineSpace` and
    :class:`CorrectionSpace`): the space is empty, certified, only where the sampled system is inconsistent
    modulo EMPTY_PRIMES primes and consistent modulo none."""

    particular: list[Fraction] | None
    empty_primes: list[int]
    consistent: int

    @property
    def certified_empty(self) -> bool:
        return self.particular is None and not self.consistent and len(self.empty_primes) >= EMPTY_PRIMES


@dataclass
class AffineSpace(_Answer):
    """The solutions c of Σ cⱼ Tⱼ = R found at random points: a particular solution (None: there is none, certified
    by ranks modulo EMPTY_PRIMES primes, or none was found: see :func:`no_formula_text`) and a basis of the
    homogeneous solutions."""

    names: list[str]
    particular: list[Fraction] | None
    basis: list[list[Fraction]]
    equations: int
    rank: int
    rank_augmented: int
    prime: int = PRIME
    #: where no formula is given: the primes modulo which the sampled system is inconsistent (the space is certified
    #: empty of formulas whose denominators are prime to them when it is so modulo EMPTY_PRIMES primes and consistent
    #: modulo none), those modulo which it is consistent, and the reconstructions verification refuted
    empty_primes: list[int] = field(default_factory=list)
    consistent: int = 0
    refuted: int = 0

    def certificate(self) -> str:
        if self.particular is None:
            return no_formula_text(len(self.names), self.equations, self.rank, self.rank_augmented,
                                   self.empty_primes, self.consistent, self.refuted)
        return (f"a {len(self.basis)}-dimensional affine space of solutions in the {len(self.names)}-term space "
                f"(rank {self.rank} of {len(self.names)})")

    def text(self, c: Sequence[Fraction] | None = None) -> str:
        c = self.particular if c is None else c
        if c is None:
            return "(none)"
        out = []
        for x, name in zip(c, self.names):
            if x:
                a = abs(x)
                out.append(f"{'−' if x < 0 else '+'} {'' if a == 1 else f'{a}·'}{name}")
        s = " ".join(out) or "0"
        return s[2:] if s.startswith("+ ") else "−" + s[2:] if s.startswith("− ") else s


#: a space of formulas is certified empty where its sampled system is inconsistent modulo this many primes and
#: consistent modulo none (a rational solution whose denominators are prime to p solves it modulo p: one prime that
#: divides a denominator of every solution is not enough)
EMPTY_PRIMES = 2


def no_formula_text(N: int, equations: int, rank: int, rank_aug: int, empty_primes: Sequence[int], consistent: int,
                    refuted: int) -> str:
    """Why a search gives no formula: a certificate of emptiness, or what stopped it (never "no formula holds"
    without the certificate)."""
    primes = " and ".join(_prime_text(p) for p in empty_primes)
    if not consistent and len(empty_primes) >= EMPTY_PRIMES:
        return (f"no formula in this {N}-term space holds with coefficients whose denominators are prime to {primes}: "
                f"the {equations} x {N} sampled system is inconsistent modulo each (rank {rank}, its augmented "
                f"matrix rank {rank_aug})")
    out = [f"no formula is given, and none is excluded: the {equations} x {N} sampled system is consistent modulo "
           f"{consistent} of the primes tried"]
    if refuted:
        out.append(f"{refuted} reconstruction{'s' if refuted != 1 else ''} of its solutions "
                   f"{'were' if refuted != 1 else 'was'} refuted by verification")
    elif consistent:
        out.append("its solutions have no rational reconstruction from those primes")
    if empty_primes:
        out.append(f"it is inconsistent modulo {primes} (a prime that divides a denominator of every solution, or "
                   "there is none)")
    return "; ".join(out)


def solve_affine(terms: Sequence[tuple[str, Callable[[Any], Any]]], target: Callable[[Any], Any], size: Size,
                 *, seed: int = 0, points: int | None = None, realization: str = "standard",
                 accept: Callable[[list[Fraction], list[list[Fraction]]], bool] | None = None) -> AffineSpace:
    """Every c with Σ cⱼ Tⱼ(s) = R(s) at random points of T*V over GF(p), one prime after another (the next
    where a constant is 0 or has no inverse mod p) (matrices: entry by entry), with rational coefficients
    reconstructed from the residues of several primes (:class:`_Lift`).  ``accept`` (particular, directions)
    verifies a reconstruction: one it refutes is dropped and the search goes on with the primes that follow (a
    reconstruction that two moduli agree on can still be wrong).  The space is said to be empty only where the
    system is inconsistent modulo EMPTY_PRIMES primes and consistent modulo none."""
    import flint
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.backends.fields import DegenerateError, ModularField
    from stiefelsym.scene import REALIZATIONS, Scene

    N = len(terms)

    def probe(s):
        out = {f"T{j}": f(s) for j, (_, f) in enumerate(terms)}
        out["R"] = target(s)
        return out
    cons = REALIZATIONS[realization]
    g = compile_claim(probe, size.n, size.r, (cons.name, cons.build))
    names = [name for name, _ in terms]
    failed: list[str] = []
    lift = _Lift()
    tried = consistent = refuted = 0
    empty: list[int] = []
    rows: list[list[int]] = []
    rank = rank_aug = 0
    for prime in lift_primes():
        rng = random.Random(f"{seed}|affine|{size.n}|{size.r}|{N}" + (f"|{prime}" if prime != PRIME else ""))
        rows = []
        try:
            for k in range(points or max(4, N // max(1, size.n * size.n) + 4)):
                scene = Scene(size.n, size.r, ModularField(prime), chart="cayley", rng=rng,
                              component=k % 2 if size.r == size.n else 0, realization=realization)
                out = evaluate_derived(g, scene)
                cols = [_entries_mod(out[f"T{j}"]) for j in range(N)] + [_entries_mod(out["R"])]
                # the target first: the reduced echelon form of the solutions then has one row with t = 1
                # (the particular solution) and the others with t = 0 (the homogeneous ones)
                for e in range(len(cols[-1])):
                    rows.append([(-cols[-1][e]) % prime] + [c[e] for c in cols[:-1]])
        except (DegenerateError, ZeroDivisionError) as exc:
            failed.append(f"modulo p = {_prime_text(prime)}: {exc}")
            continue
        tried += 1
        rank_aug = flint.nmod_mat(rows, prime).rank()
        rank = flint.nmod_mat([r[1:] for r in rows], prime).rank() if N else 0
        if rank != rank_aug:
            empty.append(prime)
            if not consistent and len(empty) >= EMPTY_PRIMES:
                return AffineSpace(names, None, [], len(rows), rank, rank_aug, prime, empty_primes=empty)
            continue
        consistent += 1
        vecs = _nullspace(rows, N + 1, prime)
        if not vecs or not vecs[0][0]:
            # no solution with t = 1 modulo this prime although the ranks agree: cannot happen over a field
            # (rank = augmented rank), but a prime is never trusted with a certificate it does not give
            continue
        key = (rank, tuple(next(j for j, x in enumerate(v) if x) for v in vecs))
        rec = lift.add(key, [x for v in vecs for x in v[1:]], prime)
        if rec is not None:
            chunks = [rec[i * N:(i + 1) * N] for i in range(len(vecs))]
            if accept is None or accept(chunks[0], chunks[1:]):
                return AffineSpace(names, chunks[0], chunks[1:], len(rows), rank, rank_aug, prime)
            refuted += 1
            lift.refute()           # refuted: more primes, and another reconstruction
    if not tried:
        raise ValueError("the terms cannot be evaluated modulo any of the primes tried: " + "; ".join(failed))
    return AffineSpace(names, None, [], len(rows), rank, rank_aug, PRIME, empty_primes=empty, consistent=consistent,
                       refuted=refuted)


def _entries_mod(v: Any) -> list[int]:
    if hasattr(v, "_view"):
        return [int(x) for x in v._view().flat]
    return [int(v)]


def lax_partner(L: Callable[[Any], Any], flow: Callable[[Any], Any], size: Size, *, degree: int = 2,
                lam_powers: int = 2, max_a: int = 1, seed: int = 0,
                verify: Sequence[str] = ("auto", "free")) -> tuple[AffineSpace, dict[str, str]]:
    """Every A(λ) = Σ cⱼ λᵏ Wⱼ (words Wⱼ : ℝⁿ → ℝⁿ of degree <= ``degree``, k < ``lam_powers``) with
    dL/dt = [A, L] along ``flow``; the particular solution found is verified by ``verify``."""
    from stiefelsym.backends.matrix import comm as _comm
    from stiefelsym.run.runner import run_one
    words = open_words(degree, "n", "n", max_a)
    shapes = [(k, w) for k in range(lam_powers) for w in words]

    def partner(s, coeffs):
        acc = None
        for c, (k, w) in coeffs:
            W = word_matrix(s, w)
            W = W * (s.lam ** k) if k else W
            W = W * s.q(c.numerator, c.denominator) if c != 1 else W
            acc = W if acc is None else acc + W
        return acc

    terms = [((("" if k == 0 else "λ·" if k == 1 else f"λ^{k}·") + word_text(w)),
              lambda s, k=k, w=w: _comm(partner(s, [(Fraction(1), (k, w))]), L(s))) for k, w in shapes]
    verdicts: dict[str, str] = {}

    def accept(particular: list[Fraction], basis: list[list[Fraction]]) -> bool:
        # the particular solution and the particular one plus each direction of the space: every formula the
        # search prints is verified (a verdict per method: the first that is not a pass, else the pass); a
        # reconstruction with a formula that fails is not the answer
        candidates = [particular] + [[a + b for a, b in zip(particular, h)] for h in basis]
        found: dict[str, list[str]] = {}
        for c in candidates:
            coeffs = [(x, kw) for x, kw in zip(c, shapes) if x]

            def check(s, coeffs=coeffs):
                A = partner(s, coeffs) if coeffs else s.zeros(s.n, s.n, ("n", "n"))
                return {"dL/dt - [A, L]": s.d(L, flow(s)) - _comm(A, L(s))}
            claim = Claim(id="discovered-lax-partner", paper=("discover",), kind="lax", section="discover",
                          func=check, sizes=admissible(max(size.n, 1)))
            for m in verify:
                res = run_one(claim, None if m == "free" else size, m, seed)
                found.setdefault(m if m != "free" else "free (all n, r)", []).append(res.verdict)
        verdicts.clear()
        verdicts.update({m: next((v for v in vs if v not in ("proved", "checked")), vs[0]) for m, vs in found.items()})
        return "fails" not in verdicts.values()
    space = solve_affine(terms, lambda s: s.d(L, flow(s)), size, seed=seed, accept=accept)
    if space.particular is None:
        verdicts.clear()            # the verdicts of a refuted reconstruction are not those of an answer
    return space, verdicts


# ---------------------------------------------------------------------------------------------
# corrections: the formulas of the printed shape that hold, as an exact affine space

@dataclass(frozen=True)
class Term:
    """One term of a correction ansatz: its value at a point (a function of the scene and of the point),
    its name in the paper's notation, and the block of the slot it fills (None: the slot is one block)."""

    text: str
    latex: str
    value: Callable[[Any, Any], Any]
    block: tuple[int, int] | None = None

    @property
    def key(self) -> str:
        """The term's name, with its block when the slot is a block matrix."""
        return self.text if self.block is None else f"{self.text} in block ({self.block[0] + 1},{self.block[1] + 1})"


@dataclass
class CorrectionAnsatz:
    """The space searched for a correction of one printed formula of a claim.

    ``residual(s, slot)`` is the claim's residual (a matrix, or a dict of them) with the formula under
    correction given by ``slot``, a function of (scene, point) as ``Term.value``; it must be affine in the
    slot.  ``terms`` are listed most natural first (the printed shape before the rest): the solution is
    written, modulo the homogeneous solutions, with the most natural terms.  ``printed`` and
    ``registered`` are the coefficients (by term text) of the printed formula and of the registered
    correction, when they lie in the ansatz."""

    claim: str
    label: str
    slot: str
    slot_latex: str
    terms: list[Term]
    residual: Callable[[Any, Callable[[Any, Any], Any]], Any]
    point: Callable[[Any], Any]
    description: str
    description_latex: str
    printed: dict[str, Fraction] | None = None
    registered: dict[str, Fraction] | None = None
    size: Size = field(default_factory=lambda: Size(3, 2))
    realization: str = "standard"
    blocks: tuple[int, int] = (1, 1)
    #: whether the dimension-free method applies (the claim lives on T*V itself)
    free: bool = False
    #: what ``registered`` is
    registered_name: str = "the registered correction"
    #: the sizes besides the search's at which each solution is verified
    verify_sizes: tuple[Size, ...] = ()

    def vector(self, coeffs: dict[str, Fraction]) -> list[Fraction]:
        names = [t.key for t in self.terms]
        unknown = set(coeffs) - set(names)
        if unknown:
            raise KeyError(f"not terms of the ansatz of {self.claim}: {sorted(unknown)}")
        return [Fraction(coeffs.get(x, 0)) for x in names]


def combination(terms: Sequence[Term], coeffs: Sequence[Fraction]) -> Callable[[Any, Any], Any]:
    """Σ cⱼ Tⱼ as a function of (scene, point); the empty sum is 0 · T₁ (a zero of the slot's shape)."""
    pairs = [(c, t) for c, t in zip(coeffs, terms) if c]

    def slot(s, w):
        if not pairs:
            return terms[0].value(s, w) * s.q(0)
        acc = None
        for c, t in pairs:
            v = t.value(s, w)
            v = v if c == 1 else v * s.q(c.numerator, c.denominator)
            acc = v if acc is None else acc + v
        return acc
    return slot


def _flat(v: Any) -> list[Any]:
    """The matrices of a residual (a matrix, a scalar, or a dict/list of them) in a fixed order."""
    if isinstance(v, dict):
        return [x for k in v for x in _flat(v[k])]
    if isinstance(v, (list, tuple)):
        return [x for e in v for x in _flat(e)]
    return [v]


@dataclass
class CorrectionSpace(_Answer):
    """The solutions of one correction ansatz at one size: an affine space modulo the combinations that
    vanish identically on the phase space (certified empty when the sampled system is inconsistent)."""

    ansatz: CorrectionAnsatz
    size: Size
    particular: list[Fraction] | None
    basis: list[list[Fraction]]
    zero_dim: int
    equations: int
    rank: int
    rank_augmented: int
    seed: int
    seconds: float = 0.0
    verdicts: dict[str, str] = field(default_factory=dict)
    contains_registered: bool | None = None
    contains_printed: bool | None = None
    #: the prime of the ranks quoted
    prime: int = PRIME
    #: where no formula is given: as in :class:`AffineSpace`
    empty_primes: list[int] = field(default_factory=list)
    consistent: int = 0
    refuted: int = 0

    @property
    def N(self) -> int:
        return len(self.ansatz.terms)

    @property
    def empty(self) -> bool:
        return self.certified_empty

    @property
    def dimension(self) -> int | None:
        """The dimension of the affine space of solutions (modulo what vanishes on the phase space)."""
        return None if self.particular is None else len(self.basis)

    @property
    def verified(self) -> bool:
        return bool(self.verdicts) and all(v in ("proved", "checked") for v in self.verdicts.values())

    def certificate(self) -> str:
        if self.particular is None:
            return no_formula_text(self.N, self.equations, self.rank, self.rank_augmented, self.empty_primes,
                                   self.consistent, self.refuted)
        what = ("exactly one formula holds" if not self.basis else
                f"a {len(self.basis)}-dimensional affine space of formulas holds")
        return (f"{what} in this {self.N}-term space, modulo the {self.zero_dim} independent combinations that "
                f"vanish on the phase space (the {self.equations} x {self.N} system has rank {self.rank})")

    def text(self, c: Sequence[Fraction] | None = None) -> str:
        """Σ cⱼ Tⱼ in the paper's notation, block by block when the slot is a block matrix."""
        c = self.particular if c is None else c
        if c is None:
            return "(none)"
        return _render(self.ansatz, c, latex=False)

    def latex(self, c: Sequence[Fraction] | None = None) -> str:
        c = self.particular if c is None else c
        if c is None:
            return r"\text{(none)}"
        return _render(self.ansatz, c, latex=True)

    def lines(self) -> list[str]:
        a, z = self.ansatz, self.size
        out = [f"{a.claim} {a.label}, (n, r) = ({z.n}, {z.r}): {a.slot} in the {self.N}-term space {a.description}",
               f"  {self.certificate()}"]
        if self.particular is not None:
            v = ", ".join(f"{m} {x}" for m, x in self.verdicts.items())
            out.append(f"  {a.slot} = {self.text()}" + (f"    [{v}]" if v else ""))
            for b in self.basis:
                out.append(f"  + any multiple of {self.text(b)}")
        if self.contains_printed is not None:
            out.append(f"  the printed formula {'holds' if self.contains_printed else 'is not in the space'}")
        if self.contains_registered is not None:
            out.append(f"  {a.registered_name} {'is in the space' if self.contains_registered else 'is NOT in the space'}")
        out.append(f"  searched and verified in {self.seconds:.2f} s (seed {self.seed})")
        return out


def _sum_text(parts: list[tuple[Fraction, Term]], latex: bool) -> str:
    out = []
    for x, t in parts:
        a = abs(x)
        if latex:
            coef = "" if a == 1 else (rf"\tfrac{{{a.numerator}}}{{{a.denominator}}}" if a.denominator != 1 else str(a))
            out.append(("-" if x < 0 else "+") + coef + t.latex)
        else:
            out.append(f"{'−' if x < 0 else '+'} {'' if a == 1 else f'{a}·'}{t.text}")
    if not out:
        return "0"
    s = ("" if latex else " ").join(out)
    if latex:
        return s[1:] if s.startswith("+") else s
    return s[2:] if s.startswith("+ ") else "−" + s[2:]


def _render(a: CorrectionAnsatz, c: Sequence[Fraction], latex: bool) -> str:
    parts = [(x, t) for x, t in zip(c, a.terms) if x]
    if a.blocks == (1, 1):
        return _sum_text([(x, t) for x, t in parts], latex)
    rows, cols = a.blocks
    grid = [[_sum_text([(x, t) for x, t in parts if t.block == (i, j)], latex) for j in range(cols)]
            for i in range(rows)]
    if latex:
        return r"\begin{pmatrix}" + r"\\".join("&".join(row) for row in grid) + r"\end{pmatrix}"
    return "[" + "; ".join(", ".join(row) for row in grid) + "]"


def _in_span(v: Sequence[Fraction], basis: Sequence[Sequence[Fraction]]) -> bool:
    """Whether v lies in the span of ``basis`` (exact rational ranks)."""
    import flint
    if not any(v):
        return True
    if not basis:
        return False
    B = flint.fmpq_mat([[flint.fmpq(x.numerator, x.denominator) for x in b] for b in basis])
    Bv = flint.fmpq_mat([[flint.fmpq(x.numerator, x.denominator) for x in b] for b in list(basis) + [list(v)]])
    return Bv.rank() == B.rank()


def _reduce(v: list[int], echelon: list[list[int]], p: int) -> list[int]:
    """v with the pivot columns of the reduced echelon rows ``echelon`` eliminated (mod p)."""
    v = list(v)
    for row in echelon:
        j = next(k for k, x in enumerate(row) if x)
        if v[j]:
            c = v[j]
            v = [(x - c * y) % p for x, y in zip(v, row)]
    return v


def _rref(rows: list[list[int]], N: int, p: int) -> list[list[int]]:
    import flint
    if not rows:
        return []
    R, rank = flint.nmod_mat(rows, p).rref()
    return [[int(R[i, j]) for j in range(N)] for i in range(rank)]


def _correction_mod(g: Any, ansatz: CorrectionAnsatz, size: Size, N: int, order: list[int], prime: int, seed: int,
                    points: int | None) -> tuple[int, int, int, list, list | None, list] | None:
    """A correction search modulo one prime: the ranks of the sampled system and of its augmented matrix, the
    number of equations, the reduced echelon bases of the combinations that vanish on the phase space (Z) and of
    the homogeneous solutions modulo them (H), and the particular solution reduced modulo both (None where
    there is none); None where the graph cannot be evaluated modulo ``prime``."""
    import flint
    from stiefelsym.backends.fields import DegenerateError, ModularField
    from stiefelsym.scene import Scene
    rng = random.Random(f"{seed}|correct|{ansatz.claim}|{size.n}|{size.r}|{N}" + (f"|{prime}" if prime != PRIME else ""))
    slot_rows: list[list[int]] = []
    rows: list[list[int]] = []
    k, stable, last = 0, 0, (-1, -1)
    # sample until the ranks of both systems stop growing (two more points change neither)
    try:
        while True:
            scene = Scene(size.n, size.r, ModularField(prime), chart="cayley", rng=rng,
                          component=k % 2 if size.r == size.n else 0, realization=ansatz.realization)
            out = evaluate_derived(g, scene)
            k += 1
            S = [_entries_mod(out[f"S{j}"]) for j in order]
            slot_rows += [[c[e] for c in S] for e in range(len(S[0]))]
            keys = sorted((x for x in out if x.startswith("R|")), key=lambda x: int(x[2:]))
            R0 = [e for x in keys for e in _entries_mod(out[x])]
            cols = [[(a - b) % prime for a, b in zip((e for x in keys for e in _entries_mod(out[f"R{j}|{x[2:]}"])), R0)]
                    for j in order]
            # Σ cⱼ (Rⱼ − R₀) = −R₀: a null vector (c, t) of [Rⱼ − R₀ | R₀] with t ≠ 0 gives c / t
            rows += [[c[e] for c in cols] + [R0[e]] for e in range(len(R0))]
            if len(rows) >= N + 8 and len(slot_rows) >= N + 8:
                ranks = (flint.nmod_mat(rows, prime).rank(), flint.nmod_mat(slot_rows, prime).rank())
                stable = stable + 1 if ranks == last else 0
                last = ranks
                if stable >= 2 and k >= (points or 3):
                    break
    except (DegenerateError, ZeroDivisionError):
        return None
    rank_aug = flint.nmod_mat(rows, prime).rank()
    rank = flint.nmod_mat([r[:-1] for r in rows], prime).rank()
    Z = _rref(_nullspace(slot_rows, N, prime), N, prime)
    if rank != rank_aug:
        return rank, rank_aug, len(rows), Z, None, []
    full = _nullspace(rows, N + 1, prime)
    part = next((v for v in full if v[-1]), None)
    homogeneous = [v[:-1] for v in full if not v[-1]]
    H = _quotient(homogeneous, Z, prime) if homogeneous else []
    if part is None:
        return rank, rank_aug, len(rows), Z, None, H
    inv = pow(part[-1], prime - 2, prime)
    p0 = _reduce([x * inv % prime for x in part[:-1]], _rref(H + Z, N, prime), prime)
    return rank, rank_aug, len(rows), Z, p0, H


def correction_space(ansatz: CorrectionAnsatz, size: Size | None = None, *, seed: int = 0,
                     verify: Sequence[str] = ("auto",), points: int | None = None) -> CorrectionSpace:
    """Every formula Σ cⱼ Tⱼ of the ansatz that makes the claim's residual vanish on the phase space:
    the residual of each term is sampled at random points over GF(p) (:func:`solve_affine`), the affine system solved,
    the combinations that vanish on the phase space quotiented out, the coefficients reconstructed as
    rationals, and the solution (and each direction of the space) verified by ``verify`` with the
    catalog's claim.  An inconsistent sampled system certifies that the space is empty."""
    import time

    from stiefelsym.claims import load_catalog
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.run.runner import run_one
    from stiefelsym.scene import REALIZATIONS

    t0 = time.perf_counter()
    size = size or ansatz.size
    terms, N = ansatz.terms, len(ansatz.terms)
    # the least natural terms first, so that the reduced echelon forms put their pivots there
    order = list(reversed(range(N)))

    def probe(s):
        w = ansatz.point(s)
        out = {}
        for j, t in enumerate(terms):
            out[f"S{j}"] = t.value(s, w)
        zero = combination(terms, [Fraction(0)] * N)
        for e, v in enumerate(_flat(ansatz.residual(s, zero))):
            out[f"R|{e}"] = v
        for j, t in enumerate(terms):
            for e, v in enumerate(_flat(ansatz.residual(s, t.value))):
                out[f"R{j}|{e}"] = v
        return out
    cons = REALIZATIONS[ansatz.realization]
    g = compile_claim(probe, size.n, size.r, (cons.name, cons.build))

    def unorder(v: Sequence[Any]) -> list[Any]:
        out = [None] * N
        for pos, j in enumerate(order):
            out[j] = v[pos]
        return out

    try:
        claim = load_catalog().get(ansatz.claim)
    except KeyError:        # a search of one's own: its residual is the whole claim
        claim = Claim(id=ansatz.claim, paper=("discover",), kind="id", section="discover",
                      func=lambda s: {}, sizes=admissible(max(size.n, 1)), realization=ansatz.realization)
    at = [size] + [z for z in ansatz.verify_sizes if z != size]

    def verified(particular: list[Fraction], basis: list[list[Fraction]], zeros: list[list[Fraction]]) -> dict:
        """The verdicts of the particular formula and of it plus each direction, per method (the first that is
        not a pass, else the pass), and of each combination said to vanish on the phase space (by the first
        method at the search's size): every element the answer rests on is verified."""
        checks = [particular] + [[a + b for a, b in zip(particular, h)] for h in basis]
        out: dict[str, str] = {}
        for m in verify:
            if m == "free" and not ansatz.free:
                continue
            verdicts = []
            for c in checks:
                slot = combination(terms, c)

                def func(s, slot=slot):
                    r = ansatz.residual(s, slot)
                    return r if isinstance(r, dict) else {f"{ansatz.label} corrected": r}
                for z in ([None] if m == "free" else at):
                    verdicts.append(run_one(claim, z, m, seed, func=func).verdict)
            key = "free (all n, r)" if m == "free" else (
                m if len(at) == 1 else f"{m} at " + ", ".join(f"({z.n},{z.r})" for z in at))
            out[key] = next((v for v in verdicts if v not in ("proved", "checked")), verdicts[0])
        first = next((m for m in verify if m != "free"), "modular")
        for z0 in zeros:
            slot = combination(terms, z0)

            def vanishes(s, slot=slot):
                return {f"the combination, entry {i + 1}": v for i, v in enumerate(_flat(slot(s, ansatz.point(s))))}
            v = run_one(claim, size, first, seed, func=vanishes).verdict
            if v not in ("proved", "checked"):
                # refuted ("fails"), or not shown to vanish: containment is not read from it
                out["a combination said to vanish on the phase space"] = v
                break
        return out

    space = CorrectionSpace(ansatz, size, None, [], 0, 0, 0, 0, seed)
    lift = _Lift()
    zero_basis: list[list[Fraction]] = []
    tried = 0
    for prime in lift_primes():
        found = _correction_mod(g, ansatz, size, N, order, prime, seed, points)
        if found is None:
            continue            # a constant of the ansatz is 0 or has no inverse modulo this prime
        tried += 1
        rank, rank_aug, equations, Z, p0, H = found
        space.zero_dim, space.equations, space.rank, space.rank_augmented = len(Z), equations, rank, rank_aug
        space.prime = prime
        if rank != rank_aug:
            space.empty_primes.append(prime)
            if space.certified_empty:
                break            # certified empty: the sampled system is inconsistent modulo enough primes
            continue
        space.consistent += 1
        if p0 is None:
            continue
        shape = (rank, tuple(next(j for j, x in enumerate(v) if x) for v in H + Z), len(H), len(Z))
        rec = lift.add(shape, p0 + [x for v in H + Z for x in v], prime)
        if rec is None:
            continue
        chunks = [rec[i * N:(i + 1) * N] for i in range(1 + len(H) + len(Z))]
        particular, basis = unorder(chunks[0]), [unorder(b) for b in chunks[1:1 + len(H)]]
        zeros = [unorder(z) for z in chunks[1 + len(H):]]
        verdicts = verified(particular, basis, zeros)
        if "fails" in verdicts.values():
            space.refuted += 1
            lift.refute()        # a reconstruction two moduli agreed on, refuted: more primes, another reconstruction
            continue
        space.particular, space.basis, space.verdicts, zero_basis = particular, basis, verdicts, zeros
        break
    if not tried:
        raise ValueError(f"{ansatz.claim}: the ansatz cannot be evaluated modulo any of the primes tried")
    if space.particular is not None and "a combination said to vanish on the phase space" not in space.verdicts:
        # every element of the span is verified: a formula in it holds; the ranks give the span's dimension
        span = space.basis + zero_basis
        for name, coeffs in (("registered", ansatz.registered), ("printed", ansatz.printed)):
            if coeffs is not None:
                d = [a - b for a, b in zip(ansatz.vector(coeffs), space.particular)]
                setattr(space, f"contains_{name}", _in_span(d, span))
    elif space.certified_empty:
        if ansatz.printed is not None:
            space.contains_printed = False
        if ansatz.registered is not None:
            space.contains_registered = False
    space.seconds = time.perf_counter() - t0
    return space


@dataclass(frozen=True)
class Factor:
    """A factor of a sandwich UᵀMV: its text, its LaTeX and its value (a function of (scene, point) for
    the outer factors, of the scene for the middle one); a middle factor may carry a scalar prefix."""

    text: str
    latex: str
    value: Callable[..., Any]
    prefix: str = ""
    prefix_latex: str = ""


def sandwich_terms(left: Sequence[Factor], right: Sequence[Factor], middles: Sequence[Factor],
                   blocks: Sequence[tuple[int, int]], grid: tuple[int, int], zero: Callable[[Any], Any],
                   preferred: Callable[[tuple[int, int], Factor, Factor, Factor], int] | None = None,
                   extra: Sequence[tuple[Factor, tuple[int, int]]] = (),
                   identities: dict[str, tuple[str, str]] | None = None) -> list[Term]:
    """The terms (prefix)·U M V placed in one block of a ``grid`` of blocks (``zero(s)`` elsewhere), for
    every block of ``blocks``, U in ``left``, V in ``right`` and M in ``middles``, and the ``extra``
    single-block terms; sorted by ``preferred`` (smaller first), then in the order given.  ``identities``
    renames a word that is simpler on the phase space (its text -> the simpler text and LaTeX)."""
    rows, cols = grid

    def placed(pos, f):
        def value(s, w):
            Z = zero(s)
            return block([[f(s, w) if (i, j) == pos else Z for j in range(cols)] for i in range(rows)])
        return value
    out = []
    for pos in blocks:
        for U in left:
            for V in right:
                for M in middles:
                    word = f"{U.text}{M.text}{V.text}"
                    simple = (identities or {}).get(word)
                    text = M.prefix + (simple[0] if simple else word)
                    latex = M.prefix_latex + (simple[1] if simple else f"{U.latex}{M.latex}{V.latex}")
                    f = (lambda s, w, U=U, V=V, M=M: U.value(s, w) @ M.value(s) @ V.value(s, w))
                    key = preferred(pos, U, M, V) if preferred else 0
                    out.append((key, Term(text, latex, placed(pos, f), pos)))
    for F, pos in extra:
        out.append((-1, Term(F.text, F.latex, placed(pos, F.value), pos)))
    return [t for _, (_, t) in sorted(enumerate(out), key=lambda e: (e[1][0], e[0]))]
