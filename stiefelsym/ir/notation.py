"""The paper's notation for a graph's nodes, and the smallest change between two graphs.

A node of a graph (:mod:`.graph`) is read back as mathematics: the scene's
letters (X, P, A, Φ, Ψ, λ, κ, ξ, η, Y, Q...), transposes Xᵀ, products by
juxtaposition, sums with signs, rational coefficients as fractions, tr(…),
⟨a, b⟩ = −½ tr(ab), inverses (…)⁻¹, the resolvent (λIₙ − A)⁻¹ (the scene's
``resolvent(μ)`` is (μIₙ − A)⁻¹), commutators [a, b] (a sum ab − ba), block
matrices, entries, d/dt along a flow (a dot on a letter), gradients and
Poisson brackets.  An op or a scene method with no notation of its own is
written as a function call.  Each node becomes an :class:`Expr` first (sums and
products flattened, signs and coefficients collected), which is printed in
Unicode (for Markdown and the terminal) or LaTeX (math mode); a subexpression
above a size cap is cut short with an ellipsis.

:func:`diff` compares two graphs of one claim at one size (the claim as printed
and a mutant or a correction of it): per output, the topmost changed
subexpressions under an unchanged context, each with the expression it
replaced at the same place, and the block of a block matrix it sits in.
Nothing here evaluates anything; the graphs are read as data.
"""
from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Sequence

from stiefelsym.ir.graph import Graph, Named, Ref, Size, node_keys

_SUPERSCRIPT_DIGITS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def power_of_ten(p: float) -> str:
    """A bound (a false-pass probability, its target) as the reports print one: m·10⁻ᵏ with one decimal of the
    mantissa, 10⁻ᵏ where the mantissa is 1 (the target 10⁻³⁰), the number itself where it is not small (0, 0.5,
    1.0: a bound of at least 0.1 is no power of ten to a reader)."""
    if not 0 < p < 0.1:
        return f"{p:g}"
    mant, exp = f"{p:.1e}".split("e")
    power = "10" + str(int(exp)).translate(_SUPERSCRIPT_DIGITS)
    return power if mant == "1.0" else f"{mant}·{power}"


#: at most this many letters and numbers of an expression are printed (beyond: an ellipsis)
CAP = 40
#: a node with several changes below it and at most this many letters is reported as a whole
SMALL = 10

#: at most this many changes are listed (then: "and k more changes")
MAX_CHANGES = 4
#: sums and products are flattened up to this many terms or factors (beyond, a part stays one term)
FLAT_MAX = 256
#: at most this many blocks are named where one change is made in several
MAX_BLOCKS = 4

SUM, PROD, ATOM = 1, 2, 3

# ---------------------------------------------------------------------------------------------
# expressions


@dataclass(frozen=True, eq=False)
class Expr:
    """A node of the notation: its kind, its own data, its parts, its number of letters and a digest
    of the whole (equal digests: the same mathematics as printed)."""

    kind: str
    data: tuple
    kids: tuple
    size: int
    key: bytes


def _mk(kind: str, data: tuple = (), kids: Sequence[Expr] = ()) -> Expr:
    kids = tuple(kids)
    h = hashlib.blake2b(digest_size=16)
    h.update(f"{kind}|{data!r}|".encode())
    for k in kids:
        h.update(k.key)
    size = 1 if not kids else sum(k.size for k in kids)
    return Expr(kind, data, kids, size, h.digest())


def atom(u: str, tex: str | None = None) -> Expr:
    return _mk("atom", (u, u if tex is None else tex))


def num(q: Any) -> Expr:
    return _mk("num", (Fraction(q),))


ZERO = num(0)


def post(op: str, base: Expr) -> Expr:
    """A postfix: ``T`` (transpose), ``inv``, ``pow:k``, ``bar`` (complex conjugate); (M⁻¹)⁻¹ = M,
    (Mᵀ)ᵀ = M and the conjugate of a conjugate are written as M."""
    if op in ("T", "inv", "bar") and base.kind == "post" and base.data == (op,):
        return base.kids[0]
    return _mk("post", (op,), (base,))


def func(u: str, args: Sequence[Expr], tex: str | None = None) -> Expr:
    return _mk("func", (u, tex if tex is not None else r"\mathrm{" + _tex_word(u) + "}"), args)


def bracket(kind: str, a: Expr, b: Expr) -> Expr:
    """``comm`` [a, b], ``killing`` ⟨a, b⟩, ``poisson`` {a, b}, ``canonical`` {a, b}₀."""
    return _mk("bracket", (kind,), (a, b))


def _split(x: Expr) -> tuple[int, Fraction, tuple]:
    """x as sign · coefficient · factors."""
    if x.kind == "prod":
        return x.data[0], x.data[1], x.kids
    if x.kind == "num":
        v = x.data[0]
        return (-1 if v < 0 else 1), abs(v), ()
    return 1, Fraction(1), (x,)


def prod(*xs: Expr) -> Expr:
    """The product of xs (flattened; signs and rational coefficients collected in front)."""
    sign, coeff, factors = 1, Fraction(1), []  # type: tuple[int, Fraction, list[Expr]]
    for x in xs:
        s, c, f = _split(x)
        if len(factors) + len(f) > FLAT_MAX:          # a shared product is not copied without end
            s, c, f = 1, Fraction(1), (x,)
        sign, coeff = sign * s, coeff * c
        factors += f
    if coeff == 0:
        return ZERO
    if not factors:
        return num(sign * coeff)
    if sign == 1 and coeff == 1 and len(factors) == 1:
        return factors[0]
    return _mk("prod", (sign, coeff), factors)


def neg(x: Expr) -> Expr:
    if x.kind == "sum":
        return _mk("sum", (tuple(-s for s in x.data[0]),), x.kids)
    return prod(num(-1), x)


def add(*terms: tuple[int, Expr]) -> Expr:
    """The sum of signed terms (flattened; a term's own sign taken into its sign)."""
    signs: list[int] = []
    kids: list[Expr] = []
    terms = tuple((s, t) for s, t in terms if not (t.kind == "num" and t.data[0] == 0)) or ((1, ZERO),)  # 0+x=x
    for s, t in terms:
        if t.kind == "sum" and len(kids) + len(t.kids) <= FLAT_MAX:   # (a shared sum: not copied without end)
            signs += [s * u for u in t.data[0]]
            kids += t.kids
            continue
        if t.kind == "prod" and t.data[0] == -1:
            s, t = -s, _mk("prod", (1, t.data[1]), t.kids) if (t.data[1] != 1 or len(t.kids) > 1) else t.kids[0]
        elif t.kind == "num" and t.data[0] < 0:
            s, t = -s, num(-t.data[0])
        signs.append(s)
        kids.append(t)
    # A − A = 0: a letter and its negative cancel (a zero block written so); larger terms stay, so that a
    # change that makes two terms cancel reads as the change of one of them
    # (in one pass: each letter cancels the first later one of the other sign not already cancelled, the pairs
    # the quadratic search from the left made; the letters of one key left waiting all have one sign)
    waiting: dict[bytes, list[int]] = {}
    gone: set[int] = set()
    for i, k in enumerate(kids):
        if k.kind != "atom":
            continue
        queue = waiting.setdefault(k.key, [])
        if queue and signs[queue[0]] == -signs[i]:
            gone.add(queue.pop(0))
            gone.add(i)
        else:
            queue.append(i)
    if gone:
        signs = [u for i, u in enumerate(signs) if i not in gone]
        kids = [k for i, k in enumerate(kids) if i not in gone]
    # the numbers of a sum are one number, in the place of the first (½ + κ at κ = −½ reads 0, not ½ − ½)
    at = [i for i, k in enumerate(kids) if k.kind == "num"]
    if len(at) > 1:
        total = sum((signs[i] * kids[i].data[0] for i in at), Fraction(0))
        keep = [i for i in range(len(kids)) if i not in at[1:]]
        signs[at[0]], kids[at[0]] = (-1, num(-total)) if total < 0 else (1, num(total))
        pairs = [(signs[i], kids[i]) for i in keep if not (i == at[0] and total == 0)]
        signs, kids = [u for u, _ in pairs], [k for _, k in pairs]
    if not kids:
        return ZERO
    if len(kids) == 1 and signs[0] == 1:
        return kids[0]
    return _mk("sum", (tuple(signs),), kids)


def signed(s: int, t: Expr) -> Expr:
    return t if s == 1 else neg(t)


# ---------------------------------------------------------------------------------------------
# the scene's letters

#: scene attribute -> (Unicode, LaTeX)
LETTERS: dict[str, tuple[str, str]] = {
    "X": ("X", "X"), "P": ("P", "P"), "A": ("A", "A"), "Ainv": ("A⁻¹", "A^{-1}"), "Phi": ("Φ", r"\Phi"),
    "Psi": ("Ψ", r"\Psi"), "In": ("Iₙ", "I_n"), "Ir": ("Iᵣ", "I_r"), "xi": ("ξ", r"\xi"),
    "zeta": ("ζ", r"\zeta"), "eta": ("η", r"\eta"), "theta": ("θ", r"\theta"), "Y": ("Y", "Y"),
    "Q": ("Q", "Q"), "Zc": ("Z", "Z"), "Zc_dot": ("Ż", r"\dot Z"), "DX": ("δX", r"\delta X"),
    "DY": ("δY", r"\delta Y"), "DXdot": ("δẊ", r"\delta\dot X"), "DYdot": ("δẎ", r"\delta\dot Y"),
    "lam": ("λ", r"\lambda"), "kappa": ("κ", r"\kappa"), "eps": ("ε", r"\varepsilon"),
    # the components of a flow
    "Xdot": ("Ẋ", r"\dot X"), "Pdot": ("Ṗ", r"\dot P"),
}
#: names a claim gives its own parameters (s.scalar, s.generic), when they are Greek
GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "mu": "μ", "nu": "ν", "rho": "ρ", "sigma": "σ",
         "tau": "τ", "omega": "ω", "lam": "λ", "kappa": "κ", "eps": "ε", "xi": "ξ", "eta": "η", "zeta": "ζ",
         "theta": "θ", "phi": "φ", "psi": "ψ", "chi": "χ", "Omega": "Ω", "Lambda": "Λ", "Pi": "Π", "Sigma": "Σ",
         "AA": "𝔸", "BB": "𝔹"}
_GREEK_TEX = {"α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "μ": r"\mu", "ν": r"\nu",
              "ρ": r"\rho", "σ": r"\sigma", "τ": r"\tau", "ω": r"\omega", "λ": r"\lambda", "κ": r"\kappa",
              "ε": r"\varepsilon", "ξ": r"\xi", "η": r"\eta", "ζ": r"\zeta", "θ": r"\theta", "φ": r"\varphi",
              "ψ": r"\psi", "χ": r"\chi", "Ω": r"\Omega", "Λ": r"\Lambda", "Π": r"\Pi", "Σ": r"\Sigma",
              "𝔸": r"\mathbb{A}", "𝔹": r"\mathbb{B}"}
_SUB_DIGITS = str.maketrans("0123456789+-nr", "₀₁₂₃₄₅₆₇₈₉₊₋ₙᵣ")
_SUP_DIGITS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
_VULGAR = {Fraction(1, 2): "½", Fraction(1, 3): "⅓", Fraction(2, 3): "⅔", Fraction(1, 4): "¼",
           Fraction(3, 4): "¾", Fraction(1, 8): "⅛"}


def _prim_letter(name: str, args: list) -> tuple[str, str] | None:
    """The letter the appendix's constant matrices (:mod:`stiefelsym.twisted`) are written with: E₁ = the
    first basis vector of ℝʳ, Eᵣ, (E₁…Eᵣ₋₁), the block projectors Π₁ = diag(I_{r₁}, 0) and Π₂ = diag(0, I_{r₂}),
    the reflection S₁, the projector D onto an eigenspace of A, D_k, the kernel frame W and annihilator K, and the
    magnetic form's F = E₁∧E₂;
    None for another step (written as a function call) or arguments that are not small ints."""
    if not all(type(v) is int and 0 <= v < 1000 for v in args):
        return None
    sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
    if not args:
        return {"last_basis_vector": ("Eᵣ", "E_r"), "leading_basis_vectors": ("(E₁…Eᵣ₋₁)", r"(E_1\dots E_{r-1})"),
                "reflection": ("S₁", "S_1"), "eigenspace_projector": ("D", "D"), "kernel_frame": ("W", "W"),
                "kernel_annihilator": ("K", "K"), "magnetic_matrix": ("F", "F")}.get(name)
    if len(args) != 1:
        return None
    k = args[0]
    if name == "basis_vector":
        return f"E{str(k + 1).translate(sub)}", f"E_{{{k + 1}}}"
    if name == "block_projector" and k in (0, 1):
        return f"Π{str(k + 1).translate(sub)}", rf"\Pi_{{{k + 1}}}"
    if name == "first_basis_vectors":
        return f"(E₁…E{str(k).translate(sub)})", rf"(E_1\dots E_{{{k}}})"
    if name == "coordinate_projector":
        return f"D{str(k).translate(sub)}", f"D_{{{k}}}"
    return None


def _tex_word(s: str) -> str:
    return "".join("\\" + c if c in "_&%$#{}" else c for c in s)


def name_atom(name: str) -> Expr:
    """A parameter a claim named (s.scalar("mu"), s.generic("G", ...)): Greek where it spells a Greek
    letter, its own name otherwise."""
    u = GREEK.get(name, name)
    if u in _GREEK_TEX:
        return atom(u, _GREEK_TEX[u])
    m = re.fullmatch(r"([A-Za-z]+?)_?(\d+)", name)
    if m and (len(m.group(1)) == 1 or m.group(1) in GREEK):
        base = GREEK.get(m.group(1), m.group(1))
        return atom(base + m.group(2).translate(_SUB_DIGITS), _GREEK_TEX.get(base, base) + "_{" + m.group(2) + "}")
    if len(name) == 1:
        return atom(name, name)
    return atom(name, r"\mathrm{" + _tex_word(name) + "}")


#: the letters of the engine's own matrices (the point, A, the momenta, the second point, the scene's elements, the
#: multipliers, the appendix's constants, A's eigenvalues aᵢ, a function's arguments u): a claim's parameter named
#: by one of them, with or without digits (P21 would read as the entry P₂₁, I2 as the identity I₂), is quoted
_ENGINE_MATRIX_LETTERS = frozenset("XPAIEDSWKCFYQZauΦΨΛΠξζηθδds")
#: the engine's scalars: a claim's parameter named so is quoted; with digits (λ₁, κ₀) it is a letter of its own
_ENGINE_SCALAR_LETTERS = frozenset("λκε")
#: the names a claim's parameter prints plainly: one Latin letter, or a Greek letter's name, then digits (with an
#: underscore or not); AA and BB (𝔸, 𝔹).  Any other name (AX, tr, I_n, lam, a Greek capital chi) is quoted.
_PLAIN_NAME = re.compile(r"([A-Za-z]|[A-Za-z]{2,7})(_?\d+)?")


def _plain_text(name: str) -> str | None:
    """The plain text of a claim's parameter (:func:`param_atom`), or None when it must be quoted."""
    if name in ("AA", "BB"):
        return name_atom(name).data[0]
    m = _PLAIN_NAME.fullmatch(name)
    if not m:
        return None
    base, digits = m.group(1), m.group(2)
    letter = base if len(base) == 1 else GREEK.get(base)
    if letter is None or len(letter) != 1 or letter in _ENGINE_MATRIX_LETTERS or \
            (letter in _ENGINE_SCALAR_LETTERS and not digits):
        return None
    return name_atom(name).data[0]


def param_atom(name: str, quote: bool = False) -> Expr:
    """A parameter the claim named (s.scalar, s.generic, s.general_params, s.sym_operator), as :func:`name_atom`
    prints it when that text reads as nothing else (:func:`_plain_text`: G, B, V₁, μ, α, κ₀, 𝔸); otherwise, and
    with ``quote`` (another of the graph's names prints the same: G1 and G_1 both as G₁), quoted ‘name’ (in LaTeX in
    typewriter letters): a generic matrix named "X" is not the point X, "P21" not an entry of P, "I2" not an
    identity, "AX" not a product, "tr" not a trace, "Lambda" not a flow's multiplier, a Greek capital chi not X."""
    m = re.fullmatch(r"Inverse([XY])(\d+)", str(name))
    if m:       # the generic elements of an Inverse statement (a name no claim may take): x̃₁, ỹ₁
        letter = m.group(1).lower()
        return atom(letter + "\u0303" + m.group(2).translate(_SUB_DIGITS), rf"\tilde {letter}_{{{m.group(2)}}}")
    if not quote and type(name) is str and _plain_text(name) is not None:
        return name_atom(name)
    return _quoted(name)


def _quoted(name: Any) -> Expr:
    """A name printed quoted, ‘name’ (in LaTeX in typewriter letters, ASCII only), its control characters escaped."""
    text = "".join(c if c.isprintable() else f"\\x{ord(c):02x}" for c in str(name)[:40]) + "…" * (len(str(name)) > 40)
    safe = "".join(c if c.isascii() and (c.isalnum() or c in "_-") else f"u{ord(c):04x}" for c in str(name)[:40])
    return atom(f"‘{text}’", r"\mathtt{" + _tex_word(safe or "-") + "}")


def _size_text(m: Any) -> tuple[str, str]:
    if type(m) is Size:
        return m.text(), m.text()
    return str(m), str(m)


def identity(m: Any) -> Expr:
    u, tex = _size_text(m)
    sub = u.translate(_SUB_DIGITS) if all(c in "0123456789nr" for c in u) else "_" + u
    return atom("I" + sub, "I_{" + tex + "}")


# ---------------------------------------------------------------------------------------------
# graph -> expressions


#: the letters of the point and of what moves with it along a flow (read in a function's body from the claim's
#: own scene, they are constants there: X₀)
MOVING = frozenset({"X", "P", "Phi", "Psi", "Y", "Q", "Zc", "Zc_dot"})
#: the steps that make a Hamiltonian's flow (calls of the scene, and twisted.flow), and how the legend names them
FLOW_STEPS = {"dirac_flow": "the Dirac flow of", "canonical_flow": "the canonical flow of",
              "multiplier_flow": "the flow with multipliers of", "flow": "the flow (twisted form) of"}


def flow_nodes(g: Graph) -> list[int]:
    """The nodes of the Hamiltonians' flows the graph differentiates along, reads the velocities or the
    multipliers of, in the graph's order."""
    found = set()
    for op, a in zip(g.ops, g.args):
        ref = a[2][1] if op == "call" and a[1] == "d" and len(a[2]) > 1 else \
            a[0] if op == "attr" and a[1] in ("Xdot", "Pdot") else \
            a[0] if op == "item" and a[1] in ("Lambda", "Pi") else None
        if type(ref) is Ref and _flow_step(g, ref.i):
            found.add(ref.i)
    return sorted(found)


def _flow_step(g: Graph, i: int) -> str:
    """The flow step node i is ("" when it is none)."""
    op, a = g.ops[i], g.args[i]
    name = a[1] if op == "call" else a[0].qualname.rsplit(".", 1)[-1] if op == "prim" else ""
    return name if name in FLOW_STEPS else ""


#: the scene's steps that make a parameter the claim names
PARAMETER_STEPS = ("scalar", "generic", "general_params", "sym_operator")


class Reader:
    """The expressions of one graph's nodes (each node read once)."""

    def __init__(self, g: Graph, twin: "Reader | None" = None, outer: "Reader | None" = None,
                 own: int | None = None) -> None:
        self.g = g
        self.memo: dict[int, Expr] = {}
        #: the readers of the bodies of the graph's functions, one per function's own scene (made when one is read):
        #: there the point of every other scene (the claim's, or an enclosing function's) is a constant, X₀ (a
        #: function differentiated along a flow moves its own scene's point only)
        self.outer = outer
        self.own = own
        self._inner: dict[int, "Reader"] = {}
        # the flows the graph differentiates along (a Hamiltonian's flow, not a tangent given outright): with more
        # than one, each is tagged ⁽ᵏ⁾ on its derivatives, dotted letters and multipliers
        self.flows = outer.flows if outer is not None else flow_nodes(g)
        # the claim's parameters whose plain texts coincide (G1 and G_1 both G₁): each printed quoted
        texts: dict[str, set] = {}
        for op, a in zip(g.ops, g.args):
            if op == "call" and a[1] in PARAMETER_STEPS and a[2] and type(a[2][0]) is str:
                text = _plain_text(a[2][0])
                if text is not None:
                    texts.setdefault(text, set()).add(a[2][0])
        self.quote = {name for names in texts.values() if len(names) > 1 for name in names}
        # a graph read next to another (a mutant next to its claim): a node whose key the other graph
        # has is that graph's expression, read once
        self.twin = twin
        if twin is not None:
            self.keys = node_keys(g)
            self.twin_index = {k: i for i, k in enumerate(node_keys(twin.g))}

    def flow_tag(self, ref: Any) -> tuple[str, str] | None:
        """The tag (Unicode, LaTeX) of a flow node: "" for the graph's one flow, ⁽ᵏ⁾ among several; None for
        anything else (a tangent given outright, printed with its components)."""
        if type(ref) is not Ref or ref.i not in self.flows:
            return None
        if len(self.flows) == 1:
            return "", ""
        k = self.flows.index(ref.i) + 1
        return f"⁽{str(k).translate(_SUP_DIGITS)}⁾", f"^{{({k})}}"

    def inner(self, own: int) -> "Reader":
        """The reader of a function's body whose own scene is number ``own``."""
        top = self.outer or self
        if own not in top._inner:
            top._inner[own] = Reader(self.g, outer=top, own=own)
        return top._inner[own]

    def node(self, i: int) -> Expr:
        if i not in self.memo:
            # the nodes below i first, in order (their numbers are smaller): no deep recursion
            todo, stack = set(), [i]
            while stack:
                j = stack.pop()
                if j in todo or j in self.memo:
                    continue
                if self.twin is not None:
                    t = self.twin_index.get(self.keys[j])
                    if t is not None:
                        self.memo[j] = self.twin.node(t)
                        continue
                todo.add(j)
                stack.extend(self.g.refs(j))
            for j in sorted(todo):
                self.memo[j] = self._read(j)
        return self.memo[i]

    def arg(self, a: Any) -> Expr:
        t = type(a)
        if t is Ref:
            return self.node(a.i)
        if t is bool or a is None:
            return atom(repr(a), r"\mathrm{" + repr(a) + "}")
        if t is int or t is Fraction:
            return num(a)
        if t is str:
            return name_atom(a)
        if t is Size:
            return atom(a.text())
        if t is Named:
            short = a.qualname.rsplit(".", 1)[-1]
            if re.fullmatch(r"[A-Za-z][A-Za-z0-9]*_?[A-Za-z0-9_]*", short) and len(short) > 3:
                return atom(short, r"\mathrm{" + _tex_word(short) + "}")
            return _quoted(short)       # (a one-letter function name reads as a letter: quoted)
        if t is tuple:
            return _mk("tuple", (), [self.arg(x) for x in a])
        return atom(repr(a))

    def _is(self, a: Any, op: str, name: str | None = None) -> bool:
        if type(a) is not Ref:
            return False
        if self.g.ops[a.i] != op:
            return False
        return name is None or self.g.args[a.i][1] == name

    def _read(self, i: int) -> Expr:
        op, a = self.g.ops[i], self.g.args[i]
        x = self.arg
        if op == "scene":
            return atom("s")
        if op == "param":
            return atom("u" if a[1] == 1 else "u" + str(a[1]).translate(_SUB_DIGITS),
                        "u" if a[1] == 1 else f"u_{{{a[1]}}}")
        if op == "attr":
            obj, name = a[0], a[1]
            if name in ("Xdot", "Pdot"):
                # the velocity of a flow: its letter (tagged among several flows), the flow's own expression in its
                # key (two flows' velocities never cancel, and a change of the Hamiltonian is a change of Ẋ)
                tag = self.flow_tag(obj) or ("", "")
                return _mk("atom", (LETTERS[name][0] + tag[0], LETTERS[name][1] + tag[1], x(obj).key.hex()))
            if name in MOVING and self.own is not None and self._is(obj, "scene") and self.g.args[obj.i][0] != self.own:
                # another scene's point inside a function's body (the claim's, an enclosing function's): a constant
                # there, the point at t = 0
                return atom(LETTERS[name][0] + "₀", LETTERS[name][1] + "_0")
            if name in LETTERS and self._is(obj, "scene"):
                return atom(*LETTERS[name])
            if name == "a" and self._is(obj, "scene"):
                return atom("a", "a")
            if name in LETTERS:         # a letter of another point: Φ(at_point(…))
                return func(LETTERS[name][0], [x(obj)], LETTERS[name][1])
            return func(name, [x(obj)])
        if op == "call":
            return self._call(a[1], a[2], a[3])
        if op == "prim":
            short = a[0].qualname.rsplit(".", 1)[-1]
            vals = [v for v in a[1:] if not (self._is(v, "kw") or self._is(v, "scene"))]
            # a constant matrix of the appendix is the same letter on every scene (a point of the claim's own too)
            consts = [v for v in vals if not self._is(v, "prim") or
                      self.g.args[v.i][0].qualname.rsplit(".", 1)[-1] != "at_point"]
            letter = _prim_letter(short, consts) if len(consts) == len(a) - 2 else None
            if letter is not None:
                return atom(*letter)
            return func(short, [x(v) for v in vals] + self._kws(a[1:]))
        if op == "apply":
            return _mk("apply", (), [x(a[0])] + [x(v) for v in a[1:] if not self._is(v, "kw")] + self._kws(a[1:]))
        if op == "add":
            return add((1, x(a[0])), (1, x(a[1])))
        if op == "sub":
            p, q = a
            if self._is(p, "matmul") and self._is(q, "matmul") and self.g.args[p.i] == self.g.args[q.i][::-1]:
                return bracket("comm", x(self.g.args[p.i][0]), x(self.g.args[p.i][1]))
            return add((1, x(p)), (-1, x(q)))
        if op == "neg":
            v = a[0]
            if self._is(v, "call", "resolvent") and self._is(self.g.args[v.i][2][0], "neg"):
                # −((−μ)Iₙ − A)⁻¹ = (A + μIₙ)⁻¹
                mu = self.g.args[self.g.args[v.i][2][0].i][0]
                return post("inv", add((1, atom(*LETTERS["A"])), (1, prod(x(mu), atom(*LETTERS["In"])))))
            return neg(x(v))
        if op in ("mul", "matmul"):
            return prod(x(a[0]), x(a[1]))
        if op == "rmul":
            return prod(x(a[1]), x(a[0]))
        if op in ("div", "rdiv"):
            p, q = (a[0], a[1]) if op == "div" else (a[1], a[0])
            d, n_ = x(q), x(p)
            if op == "div" and self._is(p, "call", "resolvent") and d.kind == "atom" \
                    and x(self.g.args[p.i][2][0]).key == post("inv", d).key:
                # (λ⁻¹Iₙ − A)⁻¹/λ = (λ(λ⁻¹Iₙ − A))⁻¹ = (Iₙ − λA)⁻¹, as the paper prints it
                return post("inv", add((1, atom(*LETTERS["In"])), (-1, prod(d, atom(*LETTERS["A"])))))
            if d.kind == "num" and d.data[0] != 0:
                return prod(n_, num(1 / d.data[0]))
            if n_.kind == "num" and d.kind == "atom":        # c/λ = cλ⁻¹
                return prod(n_, post("inv", d))
            return _mk("frac", (), (n_, d))
        if op == "pow":
            return post(f"pow:{a[1]}", x(a[0]))
        if op == "T":
            return post("T", x(a[0]))
        if op == "inv":
            return post("inv", x(a[0]))
        if op == "trace":
            return func("tr", [x(a[0])])
        if op == "entry":
            return self._entry(x(a[0]), a[1], a[2])
        if op == "item":
            return self._item(a[0], a[1])
        if op == "block":
            rows, cols = a[0], a[1]
            return _mk("block", (rows, cols), [x(v) for v in a[2]])
        if op in ("list", "tuple"):
            return _mk("tuple", (), [x(v) for v in a])
        if op == "dict":
            return _mk("tuple", (), [_mk("named", (k,), (x(v),)) for k, v in zip(a[0], a[1])])
        if op == "fn":
            return self.inner(a[0]).arg(a[2])
        if op == "kw":
            return _mk("tuple", (), [_mk("named", (k,), (x(v),)) for k, v in a])
        if op == "rank":       # rank(M) = k (generically, or at every point)
            return _mk("equals", ("" if a[2] else "everywhere",), (func("rank", [x(a[0])]), x(a[1])))
        if op == "inverse":    # op(inv(y)) = y and inv(op(x)) = x for generic x, y of the spaces, everywhere
            return _mk("tuple", (), [_mk("equals", ("everywhere",), (x(u), x(v)))
                                     for us, vs in ((a[2], a[0]), (a[5], a[3])) for u, v in zip(us, vs)])
        if op == "right_inverse":    # op(inv(y)) = y for generic y of the target spaces, everywhere
            return _mk("tuple", (), [_mk("equals", ("everywhere",), (x(u), x(v))) for u, v in zip(a[2], a[0])])
        if op == "count":      # a number the claim computed = the printed number
            return _mk("equals", ("",), (x(a[0]), x(a[1])))
        if op == "const":
            return x(a[0])
        return func(op, [x(v) for v in a])

    def _kws(self, args: tuple) -> list[Expr]:
        out: list[Expr] = []
        for v in args:
            if self._is(v, "kw"):
                out += [_mk("named", (k,), (self.arg(w),)) for k, w in self.g.args[v.i]]
        return out

    def _entry(self, m: Expr, i: Any, j: Any) -> Expr:
        if type(i) is int and type(j) is int and i >= 0 and j >= 0:
            u = f"{i + 1}{j + 1}" if i < 9 and j < 9 else f"{i + 1},{j + 1}"
            return _mk("entry", (u.translate(_SUB_DIGITS), u), (m,))

        def part(p: Any) -> str:
            if type(p) is int:     # (a negative index counts from the end: X[-1, 0] is X_{end,1})
                return str(p + 1) if p >= 0 else f"end{p + 1:+d}".replace("+0", "")
            start, stop, step = p[1:]
            if start is None and stop is None and step is None:
                return ":"
            back = step is not None and step < 0        # (a negative step runs from the end down to the first)
            lo = ("end" if back else 1) if start is None else start + 1 if start >= 0 else \
                f"end{start + 1:+d}".replace("+0", "")
            # the last index reached: stop - 1 going up, stop + 1 going down (1-based: stop, stop + 2)
            hi = ((1 if back else "end") if stop is None else (stop + 2 if back else stop) if stop >= 0 else
                  f"end{stop + 2 if back else stop:+d}".replace("+0", ""))
            return f"{lo}..{hi}" + ("" if step in (None, 1) else f" step {step}")
        text = f"{part(i)}, {part(j)}"
        return _mk("slice", (text,), (m,))

    def _item(self, v: Any, key: Any) -> Expr:
        g = self.g
        if self._is(v, "call", "gradient") and key in (0, 1):
            body = self.arg(g.args[v.i][2][0])
            return _mk("partial", (("X", "P")[key],), (body,))
        if self._is(v, "call", "d"):
            f = g.args[v.i][2][0]
            if type(f) is Ref and g.ops[f.i] == "fn":
                body = g.args[f.i][2]
                data, kids = self.flow_tag(g.args[v.i][2][1]) or (), (self.arg(g.args[v.i][2][1]),)
                inner = self.inner(g.args[f.i][0])
                if type(body) is Ref and g.ops[body.i] in ("list", "tuple") and type(key) is int:
                    return _mk("deriv", data, (inner.arg(g.args[body.i][key]),) + kids)
                if type(body) is Ref and g.ops[body.i] == "dict" and key in g.args[body.i][0]:
                    return _mk("deriv", data, (inner.arg(g.args[body.i][1][g.args[body.i][0].index(key)]),) + kids)
        if type(key) is str and key in LETTERS and self._is(v, "param"):   # z["X"] of a point z: X
            return atom(*LETTERS[key])
        if type(key) is str and key in GREEK:      # a multiplier of a flow: Λ, Π (tagged among several flows)
            e = name_atom(key)
            tag = self.flow_tag(v) or ("", "")
            return _mk("atom", (e.data[0] + tag[0], e.data[1] + tag[1], self.arg(v).key.hex()))
        if self._is(v, "attr", "a") and type(key) is int:
            return atom("a" + str(key + 1).translate(_SUB_DIGITS), f"a_{{{key + 1}}}")
        return _mk("index", (str(key + 1) if type(key) is int else str(key),), (self.arg(v),))

    def _call(self, name: str, args: tuple, kw: tuple) -> Expr:
        x = self.arg
        A = atom(*LETTERS["A"])
        if name == "tr":
            return func("tr", [x(args[0])])
        if name == "killing":
            return bracket("killing", x(args[0]), x(args[1]))
        if name == "resolvent":
            return post("inv", add((1, prod(x(args[0]), atom(*LETTERS["In"]))), (-1, A)))
        if name == "q":
            return num(Fraction(args[0], args[1]))
        if name == "const":
            return num(args[0])
        if name in PARAMETER_STEPS:
            return param_atom(args[0], args[0] in self.quote)
        if name == "fresh":    # a fresh element, numbered by the engine: w̃ᵢ (no name of a claim's spells it)
            return atom("w\u0303" + str(args[0]).translate(_SUB_DIGITS), r"\tilde w_{" + str(args[0]) + "}")
        if name == "zeros":
            return atom("0")
        if name == "identity":
            return identity(args[0])
        if name == "scalar_matrix":
            return prod(x(args[0]), identity(args[1]))
        if name == "mat":
            rows = args[0]
            if type(rows) is Ref and self.g.ops[rows.i] == "list" and all(
                    type(r) is Ref and self.g.ops[r.i] == "list" for r in self.g.args[rows.i]):
                cells = [[x(c) for c in self.g.args[r.i]] for r in self.g.args[rows.i]]
                if cells and cells[0]:
                    return _mk("block", (len(cells), len(cells[0])), [c for row in cells for c in row])
            return func("mat", [x(rows)])
        if name == "conj":
            return post("bar", x(args[0]))
        if name == "d":        # along a flow (written d/dt), or along a tangent vector (written so)
            # along a Hamiltonian's flow: tagged, the flow named in the output's legend (a part of the expression
            # all the same, which a change of the Hamiltonian changes)
            return _mk("deriv", self.flow_tag(args[1]) or (), (x(args[0]), x(args[1])))
        if name == "gradient":
            return func("∇", [x(args[0])], r"\nabla")
        if name == "bracket":
            return bracket("poisson", x(args[0]), x(args[1]))
        if name == "canonical_bracket":
            return bracket("canonical", x(args[0]), x(args[1]))
        if name in ("dirac_flow", "multiplier_flow", "canonical_flow"):
            return func(name.replace("_", " "), [x(args[0])], r"\mathrm{" + name.replace("_", r"\ ") + "}")
        if name == "constraint_bracket_matrix":
            return atom("C", "C")
        return func(name, [x(v) for v in args] + self._kws(kw))


def reader(g: Graph) -> Reader:
    """The graph's reader, kept with the graph (a claim as printed is compared with all its mutants)."""
    r = g.cache.get("notation")
    if r is None:
        r = g.cache["notation"] = Reader(g)
    return r


# ---------------------------------------------------------------------------------------------
# printing


#: a rational with more digits than this (numerator and denominator together) is written by its magnitude
BIG_DIGITS = 30


def _big(q: Fraction, tex: bool) -> str:
    """A positive rational of many digits: 2ᵏ exactly where it is a power of 2 (2⁻¹⁵⁰⁰⁰), else its magnitude and
    digit count, "(≈3.5487·10⁻⁴⁵¹⁶, 1/4516 digits)" (its exact value is in the expression's key: two such
    constants never cancel, and results.json's digest names the graph)."""
    for a, b, sign in ((q.numerator, q.denominator, -1), (q.denominator, q.numerator, 1)):
        if a == 1 and b & (b - 1) == 0:
            k = sign * (b.bit_length() - 1)
            return f"2^{{{k}}}" if tex else "2" + str(k).translate(_SUP_DIGITS)
    dn, dd = len(str(q.numerator)), len(str(q.denominator))
    e = dn - dd
    m = q / Fraction(10) ** e
    if m < 1:
        e, m = e - 1, m * 10
    mant = f"{float(m):.4f}"
    if tex:
        return rf"(\approx {mant}\cdot 10^{{{e}}},\ \text{{{dn}/{dd} digits}})"
    return f"(≈{mant}·10{str(e).translate(_SUP_DIGITS)}, {dn}/{dd} digits)"


def _frac(q: Fraction, tex: bool) -> str:
    if len(str(q.numerator)) + len(str(q.denominator)) > BIG_DIGITS:
        return _big(q, tex)
    if q.denominator == 1:
        return str(q.numerator)
    if tex:
        return r"\tfrac{%d}{%d}" % (q.numerator, q.denominator)
    return _VULGAR.get(q, f"({q.numerator}/{q.denominator})")


def _nucleus(tex: str) -> str:
    """``tex`` as the nucleus of a subscript: in braces when it has scripts of its own (x_{[1]}_{[X]} is a
    double subscript, which TeX refuses; {x_{[1]}}_{[X]} is not)."""
    return "{" + tex + "}" if _scripted(tex) else tex


def _scripted(tex: str) -> bool:
    return "^" in tex or "_" in tex or tex.startswith(r"\dot") or tex.startswith(r"\overline")


class Printer:
    """Unicode (``tex=False``) or LaTeX math (``tex=True``) of expressions, at most ``cap`` letters each."""

    def __init__(self, tex: bool = False, cap: int = CAP) -> None:
        self.tex, self.cap = tex, cap
        self.dots = r"\dots" if tex else "…"

    def __call__(self, e: Expr) -> str:
        return self.show(e, self.cap)[0]

    def paren(self, text: str) -> str:
        return (r"\left(" + text + r"\right)") if self.tex and ("frac" in text or "pmatrix" in text) \
            else "(" + text + ")"

    def show(self, e: Expr, budget: int) -> tuple[str, int]:
        """(text, precedence)."""
        if e.size > budget and budget < 2:
            return self.dots, ATOM
        return getattr(self, "_" + e.kind)(e, budget)

    def sub(self, e: Expr, budget: int, prec: int) -> str:
        text, p = self.show(e, budget)
        return self.paren(text) if p < prec else text

    def _split_budget(self, kids: tuple, budget: int) -> list[int]:
        total = sum(k.size for k in kids)
        if total <= budget:
            return [k.size for k in kids]
        return [max(1, budget // len(kids))] * len(kids)

    # -- kinds ----------------------------------------------------------------------------------
    def _atom(self, e: Expr, budget: int) -> tuple[str, int]:
        return e.data[1 if self.tex else 0], ATOM

    def _num(self, e: Expr, budget: int) -> tuple[str, int]:
        v = e.data[0]
        if v < 0:
            return ("-" if self.tex else "−") + _frac(-v, self.tex), SUM
        return _frac(v, self.tex), (ATOM if v.denominator == 1 else PROD)

    def _sum(self, e: Expr, budget: int) -> tuple[str, int]:
        out: list[str] = []
        used = 0
        minus = "-" if self.tex else "−"
        for k, (s, t) in enumerate(zip(e.data[0], e.kids)):
            room = budget - used
            if t.size > room and (room < 3 or k > 0):
                out.append(f" {'+' if s > 0 else minus} {self.dots}" if out else self.dots)
                break
            text = self.sub(t, min(room, t.size) if t.size <= room else room, PROD)
            used += min(t.size, room)
            out.append((minus if s < 0 else "") + text if not out else f" {'+' if s > 0 else minus} {text}")
        return "".join(out), SUM

    def _prod(self, e: Expr, budget: int) -> tuple[str, int]:
        sign, coeff = e.data
        parts = []
        for k, b in zip(e.kids, self._split_budget(e.kids, budget)):
            parts.append(self.sub(k, b, ATOM))
        if self.tex:
            body = " ".join(parts)
        else:
            body = ""
            for p in parts:
                body += ("·" if body and body[-1].isdigit() and p[:1].isdigit() else "") + p
        c = "" if coeff == 1 else _frac(coeff, self.tex)
        if c and (self.tex or c[-1].isdigit() and body[:1].isdigit()):
            c += " " if self.tex else "·"
        return (("-" if self.tex else "−") if sign < 0 else "") + c + body, PROD

    def _post(self, e: Expr, budget: int) -> tuple[str, int]:
        op = e.data[0]
        base, p = self.show(e.kids[0], budget)
        if op == "bar":
            if self.tex:
                return r"\overline{" + base + "}", ATOM
            return (base + "\u0304" if p == ATOM and len(base) == 1 else "conj" + self.paren(base)), ATOM
        if p < ATOM or (not self.tex and e.kids[0].kind == "num"):
            base = self.paren(base)
        elif self.tex and _scripted(base):
            base = "{" + base + "}"
        if op == "T":
            return base + ("^T" if self.tex else "ᵀ"), ATOM
        if op == "inv":
            return base + ("^{-1}" if self.tex else "⁻¹"), ATOM
        k = op.split(":", 1)[1]
        return base + ("^{" + k + "}" if self.tex else k.translate(_SUP_DIGITS)), ATOM

    def _args(self, kids: tuple, budget: int) -> str:
        return ", ".join(self.show(k, b)[0] for k, b in zip(kids, self._split_budget(kids, budget)))

    def _func(self, e: Expr, budget: int) -> tuple[str, int]:
        name = e.data[1] if self.tex else e.data[0]
        return name + self.paren(self._args(e.kids, budget)), ATOM

    def _apply(self, e: Expr, budget: int) -> tuple[str, int]:
        b = self._split_budget(e.kids, budget)
        return self.sub(e.kids[0], b[0], ATOM) + self.paren(self._args(e.kids[1:], sum(b[1:]))), ATOM

    def _named(self, e: Expr, budget: int) -> tuple[str, int]:
        name = (r"\mathrm{" + _tex_word(e.data[0]) + "}") if self.tex else e.data[0]
        return f"{name} = {self.show(e.kids[0], budget)[0]}", SUM

    def _equals(self, e: Expr, budget: int) -> tuple[str, int]:
        b = self._split_budget(e.kids, budget)
        where = e.data[0] and ((r"\ \text{" + e.data[0] + "}") if self.tex else " " + e.data[0])
        return f"{self.show(e.kids[0], b[0])[0]} = {self.show(e.kids[1], b[1])[0]}{where}", SUM

    def _tuple(self, e: Expr, budget: int) -> tuple[str, int]:
        return self.paren(self._args(e.kids, budget)), ATOM

    def _bracket(self, e: Expr, budget: int) -> tuple[str, int]:
        kind = e.data[0]
        inner = self._args(e.kids, budget)
        if kind == "comm":
            return "[" + inner + "]", ATOM
        if kind == "killing":
            return (r"\langle " + inner + r"\rangle") if self.tex else "⟨" + inner + "⟩", ATOM
        close = "}" if kind == "poisson" else ("}_0" if self.tex else "}₀")
        return (r"\{" + inner + "\\" + close) if self.tex else "{" + inner + close, ATOM

    def _block(self, e: Expr, budget: int) -> tuple[str, int]:
        rows, cols = e.data
        if e.size > budget and budget < 2 * len(e.kids):     # too many blocks to show any: the shape
            return ((r"(%d \times %d\ \text{matrix})" % (rows, cols)) if self.tex
                    else f"({rows}×{cols} {BIG_MATRIX}"), ATOM
        cells = [self.show(k, b)[0] for k, b in zip(e.kids, self._split_budget(e.kids, budget))]
        grid = [cells[i * cols:(i + 1) * cols] for i in range(rows)]
        if self.tex:
            return r"\begin{pmatrix}" + r"\\ ".join(" & ".join(r) for r in grid) + r"\end{pmatrix}", ATOM
        return "(" + "; ".join(", ".join(r) for r in grid) + ")", ATOM

    def _entry(self, e: Expr, budget: int) -> tuple[str, int]:
        base, p = self.show(e.kids[0], budget)
        if p < ATOM or (e.kids[0].kind != "atom") or (self.tex and _scripted(base)):
            base = self.paren(base) if not (self.tex and p == ATOM and e.kids[0].kind == "atom") else "{" + base + "}"
        if self.tex:
            return base + "_{" + e.data[1] + "}", ATOM
        return base + e.data[0], ATOM

    def _slice(self, e: Expr, budget: int) -> tuple[str, int]:
        base = self.sub(e.kids[0], budget, ATOM)
        if self.tex:
            return _nucleus(base) + r"_{[" + e.data[0] + "]}", ATOM
        return base + "[" + e.data[0] + "]", ATOM

    def _index(self, e: Expr, budget: int) -> tuple[str, int]:
        base = self.sub(e.kids[0], budget, ATOM)
        return (_nucleus(base) + "_{[" + _tex_word(e.data[0]) + "]}") if self.tex else base + "[" + e.data[0] + "]", \
            ATOM

    def _frac(self, e: Expr, budget: int) -> tuple[str, int]:
        b = self._split_budget(e.kids, budget)
        if self.tex:
            return r"\frac{" + self.show(e.kids[0], b[0])[0] + "}{" + self.show(e.kids[1], b[1])[0] + "}", PROD
        return self.sub(e.kids[0], b[0], ATOM) + "/" + self.sub(e.kids[1], b[1], ATOM), PROD

    def _deriv(self, e: Expr, budget: int) -> tuple[str, int]:
        body, along = e.kids[0], e.kids[1] if len(e.kids) > 1 else None
        if along is not None and along.kind == "tuple":       # a tangent vector (Ẋ, Ṗ) = (U, V)
            b = self._split_budget(e.kids, budget)
            names = [k.data[0] for k in along.kids if k.kind == "named"]
            dots = [LETTERS.get(f"{nm}dot", (nm, nm))[1 if self.tex else 0] for nm in names]
            vals = [self.show(k.kids[0], max(1, b[1] // max(1, len(names))))[0] for k in along.kids if k.kind == "named"]
            text = self.show(body, b[0])[0]
            if self.tex:
                return (r"\frac{d}{dt}" + self.paren(text) + r"\ \text{along}\ (" + ", ".join(dots) + ") = ("
                        + ", ".join(vals) + ")"), SUM
            return f"d/dt{self.paren(text)} along ({', '.join(dots)}) = ({', '.join(vals)})", SUM
        text, p = self.show(body, budget)
        tag = (e.data[1] if self.tex else e.data[0]) if len(e.data) == 2 else ""
        if body.kind == "atom" and len(text) == 1 and text.isalpha() or (self.tex and body.kind == "atom"
                                                                         and not _scripted(text)):
            return ((r"\dot{" + text + "}") if self.tex else text + "\u0307") + tag, ATOM
        if body.kind != "block":
            text = self.paren(text)
        return (r"\frac{d}{dt}" if self.tex else "d/dt") + tag + text, ATOM

    def _partial(self, e: Expr, budget: int) -> tuple[str, int]:
        text, p = self.show(e.kids[0], budget)
        if self.tex:
            return r"\frac{\partial}{\partial " + e.data[0] + "}" + self.paren(text), ATOM
        return f"∂{self.paren(text) if p < ATOM else text}/∂{e.data[0]}", ATOM


def unicode(e: Expr, cap: int = CAP) -> str:
    """The expression in Unicode (at most ``cap`` letters; beyond, an ellipsis)."""
    return Printer(False, cap)(e)


def latex(e: Expr, cap: int = CAP) -> str:
    """The expression in LaTeX math mode."""
    return Printer(True, cap)(e)


def render(g: Graph, ref: Ref | int, tex: bool = False, cap: int = CAP) -> str:
    """Node ``ref`` of ``g`` in the paper's notation."""
    e = Reader(g).node(ref.i if isinstance(ref, Ref) else ref)
    return latex(e, cap) if tex else unicode(e, cap)


def outputs(g: Graph) -> list[tuple[str, Any]]:
    """The claim's named outputs (name, argument of the output dict)."""
    if g.output is None or g.ops[g.output.i] != "dict":
        return []
    names, vals = g.args[g.output.i]
    return list(zip(names, vals))


#: at most this many letters and numbers of each output are printed where a graph is shown as traced
TRACED_CAP = 60
#: a graph of more nodes than this is not read back where a record is made (about 70 µs a node): its text is
#: its size (:data:`NOT_READ_BACK`, :func:`stiefelsym.run.runner.traced_text`)
TRACED_NODES = 1500
#: the reader's length of a text printed whole (`stiefelsym show --full`): no sum, matrix or name is cut
FULL_CAP = 1 << 60


def traced_outputs(g: Graph, cap: int = TRACED_CAP) -> list[tuple[str, str, str]]:
    """Each output of the claim's graph as it was traced: (name, Unicode, LaTeX), in the claim's
    order; a claim that returns one value (no dict) has one output named "".  This is what every
    method evaluated, read back from the graph alone (never from the claim's code): a reader compares
    it with the statement, and ``stiefelsym check`` compares it with the graph it traces again.  A node
    with no notation of its own is written as a function call; one the reader cannot read at all is
    written "(no notation)"."""
    outs = outputs(g)
    if not outs and g.output is not None:
        outs = [("", g.output)]
    rd = Reader(g)
    uni, tex = Printer(False, cap), Printer(True, cap)
    out = []
    for name, ref in outs:
        try:
            e = rd.arg(ref)
            legend = _flow_legend(rd, ref, cap)
            out.append((str(name), uni(e) + legend[0], tex(e) + legend[1]))
        except Exception:  # noqa: BLE001 - a node without notation is named so, never an error of the run
            out.append((str(name), NO_NOTATION, r"\text{(no notation)}"))
    return out


def _flow_legend(rd: Reader, ref: Any, cap: int) -> tuple[str, str]:
    """The flows an output differentiates along, named after it (Unicode, LaTeX): " (along the Dirac flow of
    ½tr(PᵀP))", or with several flows each with its tag; ("", "") for an output that names none.  Without it the
    dotted letters and d/dt of two different Hamiltonians read the same."""
    g = rd.g
    if type(ref) is not Ref or not rd.flows:
        return "", ""
    seen, stack, used = set(), [ref.i], set()
    while stack:
        j = stack.pop()
        if j in seen:
            continue
        seen.add(j)
        if j in rd.flows:
            used.add(j)
        stack.extend(g.refs(j))
    if not used:
        return "", ""
    uni, tex = Printer(False, max(8, cap // 2)), Printer(True, max(8, cap // 2))
    parts_u, parts_t = [], []
    for j in sorted(used):
        step = _flow_step(g, j)
        fn = next((v for v in g.args[j][1:] + tuple(g.args[j][2] if g.ops[j] == "call" else ())
                   if type(v) is Ref and g.ops[v.i] == "fn"), None)
        h = rd.arg(fn) if fn is not None else None
        tag = rd.flow_tag(Ref(j)) or ("", "")
        words = FLOW_STEPS[step]
        parts_u.append(f"{tag[0] + ': ' if tag[0] else ''}{words} {uni(h) if h is not None else '…'}")
        parts_t.append((f"{tag[1]}\\text{{: }}" if tag[1] else "") + r"\text{" + words + " }"
                       + (tex(h) if h is not None else r"\dots"))
    lead = "along " if len(used) == 1 and not rd.flow_tag(Ref(min(used)))[0] else ""
    return (f" ({lead}{'; '.join(parts_u)})", r"\quad(" + (r"\text{along }" if lead else "")
            + r";\ ".join(parts_t) + ")")


NO_NOTATION = "(no notation)"
#: how the text of a graph too large to read back begins (:func:`stiefelsym.run.runner.traced_text`)
NOT_READ_BACK = "(a graph of"


# ---------------------------------------------------------------------------------------------
# the smallest change between two graphs


@dataclass(frozen=True)
class Change:
    """One change of a graph: where (the output, the block), what it was and what it became."""

    where: str
    old: str
    new: str
    old_tex: str
    new_tex: str
    #: not a change: the number of further changes left out
    more: int = 0

    def text(self) -> str:
        if self.more:
            return f"and {self.more} more change{'s' * (self.more != 1)}"
        return f"in {self.where}: {self.old} → {self.new}"

    def to_json(self) -> dict[str, Any]:
        d: dict[str, Any] = {"where": self.where, "old": self.old, "new": self.new, "old_tex": self.old_tex,
                             "new_tex": self.new_tex}
        if self.more:
            d["more"] = self.more
        return d


def _diff(a: Expr, b: Expr, ctx: tuple, deep: bool = False, memo: dict | None = None) -> list[tuple]:
    """The topmost changed subexpressions of a → b under an unchanged context: (ctx: the blocks on the
    way down, old, new, and the short product a changed letter sits in, or None).  A node whose parts
    changed in several ways is the change (a swap, a small node), unless ``deep``: then the parts'
    changes are listed (fewer when one change below repeats at many places)."""
    if memo is None:
        memo = {}
    k = (a.key, b.key)
    found = memo.get(k)
    if found is None:        # a shared part is compared once (the expressions are DAGs)
        found, seen = [], set()
        for o in _diff_at(a, b, deep, memo):       # the same change reached along two ways: once
            key = (o[0], o[1].key, o[2].key)
            if key not in seen:
                seen.add(key)
                found.append(o)
        memo[k] = found
    return [(ctx + o[0],) + o[1:] for o in found] if ctx else found


def _diff_at(a: Expr, b: Expr, deep: bool, memo: dict) -> list[tuple]:
    ctx: tuple = ()
    if a.key == b.key:
        return []
    out: list[tuple] = []
    if a.kind == b.kind == "equals" and a.data == b.data and a.kids[0].key == b.kids[0].key:
        # the printed number changed: "rank(M) = 6 → rank(M) = 8" (M cut short when it is large)
        left = a.kids[0] if a.kids[0].size <= SMALL else (
            func("rank", [atom("…", r"\dots")]) if a.kids[0].kind == "func" else atom("…", r"\dots"))
        return [(ctx, _mk("equals", a.data, (left, a.kids[1])), _mk("equals", b.data, (left, b.kids[1])), None)]
    if a.kind == b.kind and a.kind not in ("atom", "num") and len(a.kids) == len(b.kids):
        if a.data == b.data:
            changed = [i for i, (x, y) in enumerate(zip(a.kids, b.kids)) if x.key != y.key]
            per = [(i, _diff(a.kids[i], b.kids[i], _where(a, i), deep, memo)) for i in changed]
            out = [o for _, found in per for o in found]
            if a.kind == "post" and a.data == ("inv",) and len(out) == 1 and out[0][1:] == (a.kids[0], b.kids[0], None):
                return [(ctx, a, b, None)]     # an inverse whose whole argument changed: (Iₙ − λA)⁻¹ → (λIₙ − A)⁻¹
            kid = a.kids[changed[0]] if changed else a
            if (a.kind == "prod" and len(changed) == 1 and a.size <= SMALL and len(out) == 1
                    and out[0][1].kind == out[0][2].kind == "atom" and out[0][3] is None
                    and out[0][1].key in (kid.key, kid.kids[0].key if kid.kind == "post" else None)):
                return [out[0][:3] + ((a, b),)]       # a letter in a short product: QΠ → YΠ, not Q → Y
            if len({(o[1].key, o[2].key) for o in out}) <= 1:      # one change (perhaps repeated)
                # the same change made in several parts, where a part does not print the changed expression
                # as it is (one node read as XᵀP and, transposed, as PᵀX in XᵀP + PᵀX): the node is the
                # change if it is small, else each such part is changed whole, so that every place shows
                shown = (out[0][3] or out[0][1:])[0] if out else None
                hidden = {i for i in changed if len(changed) > 1 and shown is not None
                          and max(a.kids[i].size, b.kids[i].size) <= 3 * SMALL and not _shown_in(shown, [a.kids[i]])}
                if hidden and max(a.size, b.size) <= 3 * SMALL:
                    return [(ctx, a, b, None)]
                if hidden:
                    out = [o for i, found in per
                           for o in (found if i not in hidden else [(_where(a, i), a.kids[i], b.kids[i], None)])]
                return out
            # parts moved (operands swapped: a new part is an old part), or every part changed: the
            # node is the change
            old_parts = {k.key for k in a.kids}
            every = len(changed) == len(a.kids) and max(a.size, b.size) <= 3 * SMALL
            if not deep and len(changed) > 1 and (every or any(b.kids[i].key in old_parts for i in changed)):
                return [(ctx, a, b, None)]
        elif a.kind == "sum":
            for i, (s, t, x, y) in enumerate(zip(a.data[0], b.data[0], a.kids, b.kids)):
                if x.key != y.key or s != t:
                    if s == t:
                        out += _diff(x, y, (), deep, memo)
                    else:
                        out.append((ctx, signed(s, x), signed(t, y), None))
        elif a.kind == "prod" and all(x.key == y.key for x, y in zip(a.kids, b.kids)):
            return [(ctx, a, b, None)]
        else:
            return [(ctx, a, b, None)]
        if not deep and len({(o[1].key, o[2].key) for o in out}) > 1 and max(a.size, b.size) <= SMALL:
            return [(ctx, a, b, None)]
        return out
    ta, tb = _terms(a), _terms(b)
    if (a.kind == "sum" or b.kind == "sum") and len(ta) != len(tb):    # terms dropped or added
        longer, shorter = (ta, tb) if len(ta) > len(tb) else (tb, ta)
        extra, j = [], 0
        for s_, k in longer:             # the shorter sum's terms, in order, among the longer's
            if j < len(shorter) and (s_, k.key) == (shorter[j][0], shorter[j][1].key):
                j += 1
            else:
                extra.append((s_, k))
        if j == len(shorter):
            if max(a.size, b.size) <= SMALL:
                return [(ctx, a, b, None)]
            term = add(*extra)
            return [(ctx, term, ZERO, None) if longer is ta else (ctx, ZERO, term, None)]
    return [(ctx, a, b, None)]


def _shown_in(x: Expr, parts: Sequence[Expr]) -> bool:
    """Whether every part prints the expression x as x prints (a change of x is then seen at each place); a
    part the printer cuts short (…) is taken to show it."""
    pr = Printer(False, 4 * CAP)
    shown = pr(x)
    return all(shown in t or "…" in t for t in map(pr, parts))


def _terms(e: Expr) -> list[tuple[int, Expr]]:
    """e as signed terms (one term unless it is a sum)."""
    if e.kind == "sum":
        return list(zip(e.data[0], e.kids))
    if e.kind == "prod" and e.data[0] == -1:
        return [(-1, neg(e))]
    return [(1, e)]


def _where(e: Expr, i: int) -> tuple:
    if e.kind == "block" and e.data[0] * e.data[1] > 1:
        rows, cols = e.data
        return (f"({i // cols + 1},{i % cols + 1})",)
    return ()


def _place(name: str, blocks: list[tuple], of: str = "") -> str:
    """Where a change is: the check's name, and the blocks of a block matrix in it (``of``: that matrix, named
    when every block is one of its own, not one in a block of another)."""
    if not blocks or blocks == [()]:
        return name
    of = f" of {of}" if of and all(len(b) == 1 for b in blocks) else ""
    if len(blocks) == 1:
        return f"{name}, block {' in '.join(reversed(blocks[0]))}{of}"
    named = [' in '.join(reversed(b)) for b in blocks]
    if len(named) > MAX_BLOCKS:
        return f"{name}, blocks {', '.join(named[:MAX_BLOCKS - 1])} and {len(named) - MAX_BLOCKS + 1} more{of}"
    return f"{name}, blocks {', '.join(named)}{of}"


#: what a change says where a check was added or dropped, or where both sides print alike
NO_SUCH_CHECK, DROPPED, SAME_TEXT = "(no such check)", "(dropped)", "written the same, computed another way"
#: a matrix too big to show, as the printer writes it
BIG_MATRIX = "matrix)"


#: the largest expression (in nodes) whose change is read back literally (:func:`_read_literally`)
LITERAL_MAX = 400


def _read_literally(found: list[tuple], pairs: list[tuple[str, Expr, Expr]]) -> dict[tuple, str]:
    """Each output's change read back as a reader reads it: every place the old text is printed in the
    output becomes the new text.  Where an output has one change (outside blocks) and that reading does not
    give the new output, because the old text is also printed where nothing changed (XᵀP inside XᵀPλ beside a
    changed K = XᵀP), the places that do give it, by (output, old key, new key): "the 1st and 2nd of its 3
    places".  A change whose places cannot be read back so (a sign set into a sum) has none."""
    exprs = {name: (ea, eb) for name, ea, eb in pairs}
    whole = Printer(False, 10**9)
    out: dict[tuple, str] = {}
    for name, ctx, x, y, alt in found:
        ea, eb = exprs.get(name, (None, None))
        alone = sum(1 for f in found if f[0] == name) == 1
        if ea is not None and alone and ctx == () and max(ea.size, eb.size) <= LITERAL_MAX:
            u, v = (whole(e) for e in (alt if alt is not None else (x, y)))
            places = _places_changed(whole(ea), whole(eb), u, v)
            if places is not None:
                out[(name, x.key, y.key)] = places
    return out


def _ordinal(k: int) -> str:
    return f"{k}{'th' if 10 <= k % 100 <= 20 else {1: 'st', 2: 'nd', 3: 'rd'}.get(k % 10, 'th')}"


def _places_changed(old: str, new: str, u: str, v: str, most: int = 8) -> str | None:
    """None where replacing every printed u by v in ``old`` gives ``new`` (the change reads literally) or
    where no choice of the places of u does; else the places that do, in words ("the 1st and 3rd of its 4
    places"), the first such choice with the fewest places.  A sign flipped in a sum is read as its printed
    operator: λA → −λA turns "+ λA" into "− λA"."""
    if not u or u == v:
        return None
    readings = [(u, v)]
    if v.startswith("−") and not u.startswith("−"):
        readings.append(("+ " + u, "− " + v[1:]))
    if any(old.replace(a, b) == new for a, b in readings):
        return None
    for a, b in readings:
        found = _choose_places(old, new, a, b, most)
        if found is not None:
            return found
    return None


def _choose_places(old: str, new: str, u: str, v: str, most: int) -> str | None:
    at, i = [], old.find(u)
    while i >= 0:
        at.append(i)
        i = old.find(u, i + len(u))
    if not 1 < len(at) <= most:
        return None
    from itertools import combinations
    for k in range(1, len(at)):
        for chosen in combinations(range(len(at)), k):
            text, last = [], 0
            for j in chosen:
                text += [old[last:at[j]], v]
                last = at[j] + len(u)
            if "".join(text) + old[last:] == new:
                which = [_ordinal(j + 1) for j in chosen]
                listed = which[0] if k == 1 else ", ".join(which[:-1]) + " and " + which[-1]
                return f"the {listed} of its {len(at)} places"
    return None


def diff(old: Graph, new: Graph, cap: int = 24, blocks_of: str = "") -> list[Change]:
    """The changes from ``old`` (the claim as printed) to ``new`` (a mutant or a correction traced at
    the same size), per output: the topmost changed subexpressions under an unchanged context, each
    with the expression it replaced.  Equal changes at several places of one output are one change
    (with every block named, as blocks of the matrix ``blocks_of`` when a correction names it).  Empty when
    the graphs compute the same outputs."""
    ko, kn = node_keys(old), node_keys(new)
    ro = reader(old)
    rn = Reader(new, ro)
    po, pn = Printer(False, cap), Printer(True, cap)
    listed_old, out_new = outputs(old), dict(outputs(new))
    out_old = dict(listed_old)
    found: list[tuple] = []
    pairs: list[tuple[str, Expr, Expr]] = []
    same: list[tuple] = []
    names = [n for n, _ in listed_old] + [n for n in out_new if n not in out_old]
    for name in names:
        a = out_old.get(name)
        b = out_new.get(name)
        if type(a) is Ref and type(b) is Ref and ko[a.i] == kn[b.i]:
            continue
        ea = ro.arg(a) if name in out_old else atom(NO_SUCH_CHECK, rf"\text{{{NO_SUCH_CHECK}}}")
        eb = rn.arg(b) if name in out_new else atom(DROPPED, rf"\text{{{DROPPED}}}")
        if ea.key == eb.key:      # another computation of the same expression (e.g. (Mᵀ)ᵀ for M, or the
            # claim's functions numbered otherwise): said only when nothing else changed
            same.append((f"{name} ({SAME_TEXT})", (), ea, eb, None))
            continue
        pairs.append((name, ea, eb))
    memo: dict = {}
    shallow = [(name,) + o for name, ea, eb in pairs for o in _diff(ea, eb, (), False, memo)]
    distinct = lambda fs: len({(f[2].key, f[3].key) for f in fs})
    if distinct(shallow) > MAX_CHANGES:
        # many changes: perhaps one change below them, made at many places
        memo = {}
        deep = [(name,) + o for name, ea, eb in pairs for o in _diff(ea, eb, (), True, memo)]
        if distinct(deep) < distinct(shallow):
            shallow = deep
    found += shallow or same
    qualified = _read_literally(shallow, pairs)
    # one change per (old, new), with every output and block where it is made
    # (a changed letter is shown in its short product where that product is the same at every place)
    grouped: dict[tuple, dict[str, dict[tuple, None]]] = {}     # (ordered sets of places)
    contexts: dict[tuple, set] = {}
    for name, ctx, x, y, alt in found:
        grouped.setdefault((x.key, y.key), {}).setdefault(name, {})[ctx] = None
        contexts.setdefault((x.key, y.key), set()).add(None if alt is None else (alt[0].key, alt[1].key))
    changes, seen = [], set()
    for name, ctx, x, y, alt in found:
        k = (x.key, y.key)
        if k in seen:
            continue
        seen.add(k)
        if alt is not None and len(contexts[k]) == 1:
            x, y = alt
        texts = [_place(nm, list(blocks), blocks_of) for nm, blocks in grouped[k].items()]
        quals = [qualified.get((nm,) + k) for nm in grouped[k]]
        if len(set(quals)) > 1:
            # the places of the old text that changed differ between the outputs: each output says its own
            texts = [t + (f", at {q}" if q else "") for t, q in zip(texts, quals)]
        elif len(texts) > 2 and set(grouped[k]) == set(names) and all(list(b) == [()] for b in grouped[k].values()):
            texts = [f"every check ({len(texts)})"]
        where = ("; " if any(", block" in p or ", at the " in p for p in texts) else ", ").join(texts)
        if len(set(quals)) == 1 and quals[0]:
            where += f", at {quals[0]}"      # the same places in every output: said once
        wide = cap
        while po(x) == po(y) and x.key != y.key and wide < 2 * cap:   # cut short to the same text
            wide *= 4
            po, pn = Printer(False, wide), Printer(True, wide)
        changes.append(Change(where, po(x), po(y), pn(x), pn(y)))
        po, pn = Printer(False, cap), Printer(True, cap)
    if len(changes) > MAX_CHANGES:
        return changes[:MAX_CHANGES - 1] + [Change("", "", "", "", "", more=len(changes) - MAX_CHANGES + 1)]
    return changes


def describe(changes: Sequence[Change]) -> str:
    """The changes as one line ("no change" when there is none)."""
    return "; ".join(c.text() for c in changes) if changes else "no change"


def changes_text(changes: Sequence[dict[str, str]] | None) -> str:
    """Changes as :meth:`Change.to_json` gives them, in one line of Unicode ("" for none: the variant
    does not trace; "no change in the graph" for one empty change: the graphs agree)."""
    if not changes:
        return ""
    if not changes[0].get("where") and not changes[0].get("old"):
        return "no change in the graph"
    return "; ".join(f"and {c['more']} more change{'s' * (c['more'] != 1)}" if c.get("more")
                     else f"in {c.get('where', '')}: {c.get('old', '')} → {c.get('new', '')}" for c in changes)
