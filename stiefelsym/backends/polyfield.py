"""The exact method's whole-matrix backend: rational functions over flint's multivariate polynomials.

A matrix over :class:`SymbolicField` (below) is kept as a numpy array of flint
``fmpq_mpoly`` numerators over ONE common denominator, a product of powers of *atoms*: monic
irreducible polynomials registered once per field (flint factors every new divisor: a
determinant, λ − aᵢ, aᵢ, ...).  Because the atoms are irreducible, common denominators are
exact least common multiples without any gcd (the larger exponent of every atom), and a
numerator cancels against the denominator only by an atom dividing every entry, which is tested
after every product and inverse (one exact division per atom).

The zero test of a matrix is exact: every numerator is the zero polynomial.  Nothing is
"probably zero", and no SymPy is involved.  Scalars cross the boundary as symengine expressions
(the field's elements): traces and pairings are converted to symengine, symengine scalars that
multiply a matrix are converted to rational functions (memoized per field).  An entry flint
cannot represent (a non-integer power, a float, an infinity) sends that matrix to the generic
representation (:class:`ObjMat`: numpy arrays of symengine expressions, expanded entrywise,
exactly what :mod:`stiefelsym.backends.matrix` does without a backend).

flint contexts have a fixed number of variables while parameters appear on the fly: the ring
starts with 16 variables and doubles its context when it runs out, lifting every stored matrix
to the new context the next time it is used (by generator names, which never change).
"""
from __future__ import annotations

from collections import OrderedDict
from fractions import Fraction
from typing import Any

import math
import re
import os

import numpy as np

from stiefelsym._lazy import lazy
from stiefelsym.backends.fields import DegenerateError, Field, SymbolicBudget
from stiefelsym.backends.matrix import engine_number_type
from stiefelsym.backends.native import Backend
from stiefelsym.backends import ratmat
from stiefelsym.backends.denominators import NODEN, _merge_add, _merge_max, _minus  # noqa: F401 (ratmat's too)
from stiefelsym.backends.ratmat import RatMat

flint = lazy("flint", globals())
se = lazy("symengine", globals(), "se")

_INITIAL_VARS = 16
#: contexts of this many variables and more carry their polynomials to a wider context by text (PolyRing.lift)
_LIFT_BY_TEXT = 64
#: beyond this many parameters (a generic operator on so(n) brings n(n-1)/2 (n(n-1)/2 + 1)/2 of
#: them) a monomial costs a byte per parameter in flint: new matrices stay symengine expressions
#: (with the encoded form of :class:`_BigPoly`).  512 holds the generic operators on so(7) with a chart
#: at n = 7 (up to about 330 parameters in the catalog's runs at n <= 7): there a product of 5 x 7
#: matrices in flint's 512 variables took 0.3-1 s where symengine's expansion of the same entries took
#: 2-7 s (double-neumann-momentum at (7,5): 7.3 s -> 0.5 s of CPU); the context still grows from 16
#: variables (by 8 up to 64, by doubling beyond: :func:`_wider`), so a chart of few parameters never pays
#: for the wide exponent vectors
MAX_VARS = 512


class NotRational(TypeError):
    """A symbolic expression that is not a rational function with rational coefficients."""


#: flint's exception classes, imported on first use (flint loads lazily)
_FLINT_ERRORS: list = []


def _flint_errors() -> list:
    if not _FLINT_ERRORS:
        from flint.utils.flint_exceptions import DomainError, IncompatibleContextError
        _FLINT_ERRORS[:] = [DomainError, IncompatibleContextError]
    return _FLINT_ERRORS


def _domain_error():
    return (_FLINT_ERRORS or _flint_errors())[0]


def _incompatible_error():
    return (_FLINT_ERRORS or _flint_errors())[1]


def _divide_out(n, f, e: int) -> tuple:
    """(n / f^k, e − k) for the largest k ≤ e such that f^k divides n (exact divisions, each tried
    once: flint's failed division is the test)."""
    DomainError = _domain_error()
    while e > 0:
        try:
            n = n / f
        except DomainError:
            break
        e -= 1
    return n, e


_CONTEXTS: dict[int, tuple] = {}


def _context(cap: int) -> tuple:
    """The flint context with ``cap`` variables x0, x1, ..., its generators, 0 and 1 (shared)."""
    hit = _CONTEXTS.get(cap)
    if hit is None:
        ctx = flint.fmpq_mpoly_ctx.get(tuple(f"x{i}" for i in range(cap)), "degrevlex")
        hit = _CONTEXTS[cap] = (ctx, ctx.gens(), ctx.from_dict({}), ctx.constant(1))
    return hit


def _name_key(name: str) -> tuple:
    """A variable's name in natural order (A_1,2 before A_1,10; every part a (kind, value) pair, so that
    texts and numbers compare)."""
    return tuple((0, int(t)) if t.isdigit() else (1, t) for t in re.split(r"(\d+)", name) if t)


def _term_key(term: tuple) -> tuple:
    """Degree-lexicographic order of a monomial ((name, exponent), ...), highest first."""
    mono = term[0]
    return (-sum(e for _, e in mono), tuple((_name_key(nm), -e) for nm, e in mono))


def _wider(cap: int, need: int) -> int:
    """The width of a context of at least ``need`` variables grown from ``cap``: by 8 variables (a word of flint's
    exponent vectors at 8 bits an exponent) up to 64, by doubling beyond (where a polynomial takes milliseconds to
    carry to a wider context).  A product's cost follows the words of its monomials: a context of 64 variables
    for 37 parameters made the kernel product of pencil-rank-a1 at (6, 5) 1.4 times slower than one of 40."""
    while cap < need:
        cap = cap + 8 if cap < _LIFT_BY_TEXT else 2 * cap
    return cap


class PolyRing:
    """The variables, the flint context, the denominator atoms and the conversions of one field.

    ``width``: the number of variables the ring is expected to reach (another evaluation of the same graph
    reached it): the context starts wide enough for them (16, 24, ..., 64, 128, ... variables: _wider; at most MAX_VARS), so
    that the polynomials computed before the last of them is met are not carried to a wider context one
    by one (at 256 variables and more a polynomial of a few hundred terms takes milliseconds to carry).
    Which variable is which, and every value, are the same at every width."""

    def __init__(self, width: int = 0) -> None:
        self.syms: list = []               # symengine symbol of each variable index
        self.index: dict = {}              # symengine symbol -> variable index
        self.atoms: list = []              # monic irreducible polynomials (current context)
        self.atom_key: dict[str, int] = {}  # str(atom) -> atom id
        self._atom_se: dict[int, Any] = {}
        self._pow: dict[tuple[int, int], Any] = {}
        self._factor_memo: dict[str, tuple] = {}
        self.memo: dict = {}               # symengine expression -> (numerator, denominator)
        self.version = 0                   # bumped when the context grows
        self.ctx = None
        self._set_ctx(_wider(_INITIAL_VARS, min(width, MAX_VARS)))
        # parameters beyond MAX_VARS, in the encoded form of :class:`_BigPoly` (never ring variables)
        self.big: dict = {}                # symengine symbol -> index of the parameter
        self.big_syms: list = []
        self.big_memo: dict = {}           # symengine expression -> _BigPoly (or None: not representable)
        self._big = None                   # (key, shell bound S, context, generators)
        self._big_name_memo: dict = {}

    # -- context ------------------------------------------------------------------
    def _set_ctx(self, cap: int) -> None:
        old = self.ctx
        self.cap = cap
        self.ctx, self.gens, self.zero, self.one = _context(cap)
        if old is not None:
            self.version += 1
            self._big = None                   # the encoded form's context follows the ring's
            self.atoms = [p.project_to_context(self.ctx) for p in self.atoms]
            self._pow.clear()
            self._factor_memo.clear()
            self.memo.clear()

    def lift(self, p):
        """A polynomial of an older context in the current one.  flint composes with the generators through
        a dense matrix of (old variables) x (new variables) integers per term, so from 64 variables on the
        polynomial's text (the same names x0, x1, ... in both contexts) is parsed instead: linear in its
        length, 2-4 times faster there (a term of a 128-variable polynomial took 40 µs to project)."""
        if p.is_constant():
            # most polynomials carried are 0 or constants (entries of sparse matrices): 0.5 µs, not 20-40 µs
            return p.leading_coefficient() * self.one if p else self.zero
        if p.context().nvars() < _LIFT_BY_TEXT:
            return p.project_to_context(self.ctx)
        return flint.fmpq_mpoly(str(p), self.ctx)

    def var(self, sym) -> Any:
        i = self.index.get(sym)
        if i is None:
            if sym in self.big:
                raise NotRational("a parameter held in the encoded form of the parameters beyond the ring's")
            i = len(self.syms)
            if i >= MAX_VARS:
                raise NotRational(f"more than {MAX_VARS} parameters (flint's exponent vectors are dense)")
            if i >= self.cap:
                self._set_ctx(_wider(self.cap, i + 1))
            self.syms.append(sym)
            self.index[sym] = i
        return self.gens[i]

    def const(self, q) -> Any:
        if isinstance(q, int):
            return self.ctx.constant(q)
        return self.ctx.constant(flint.fmpq(q.numerator, q.denominator))

    # -- denominator atoms ------------------------------------------------------------
    def atom_pow(self, k: int, e: int):
        key = (k, e)
        p = self._pow.get(key)
        if p is None:
            p = self.atoms[k] ** e
            self._pow[key] = p
        return p

    def den_poly(self, d: tuple):
        out = self.one
        for k, e in d:
            out = out * self.atom_pow(k, e)
        return out

    def factor(self, p) -> tuple[Any, tuple]:
        """p = c * prod atom^e: the rational content c (a constant polynomial) and the atoms."""
        key = str(p)
        hit = self._factor_memo.get(key)
        if hit is not None:
            return hit
        c, facs = p.factor()
        den = {}
        for f, e in facs:
            if f.is_constant():
                c = c * f.leading_coefficient() ** e
                continue
            lc = f.leading_coefficient()
            if lc != 1:
                f = f / lc
                c = c * lc ** e
            fk = str(f)
            k = self.atom_key.get(fk)
            if k is None:
                k = len(self.atoms)
                self.atoms.append(f)
                self.atom_key[fk] = k
            den[k] = den.get(k, 0) + e
        out = (self.ctx.constant(c), tuple(sorted(den.items())))
        self._factor_memo[key] = out
        return out

    # -- scalar rational functions: (numerator, denominator atoms) ----------------------
    def rf_add(self, a, b):
        (n1, d1), (n2, d2) = a, b
        if d1 == d2:
            return (n1 + n2, d1)
        D = _merge_max(d1, d2)
        return (n1 * self.den_poly(_minus(D, d1)) + n2 * self.den_poly(_minus(D, d2)), D)

    def rf_sum(self, parts: list):
        """The sum of rational functions: the numerators over each denominator added pairwise in a
        balanced tree (a sum of k terms one by one costs O(k²) in sparse polynomial additions), then
        the groups over their common denominator (the result does not depend on the order)."""
        groups: dict = {}
        for n, d in parts:
            groups.setdefault(d, []).append(n)
        if len(groups) <= 2:
            acc = None
            for d, ns in groups.items():
                acc = (_balanced_sum(ns), d) if acc is None else self.rf_add(acc, (_balanced_sum(ns), d))
            return acc
        # over the common denominator D of every group at once: each group's numerator times its own cofactor
        # D/d, the products added in a balanced tree (the same numerator as adding the groups one by one, where
        # the growing sum is multiplied again by the cofactor of each group that brings a new atom)
        D = NODEN
        for d in groups:
            D = _merge_max(D, d)
        terms = []
        for d, ns in groups.items():
            n = _balanced_sum(ns)
            terms.append(n if d == D else n * self.den_poly(_minus(D, d)))
        return (_balanced_sum(terms), D)

    def rf_mul(self, a, b):
        """The product, divided by each atom of its denominator as often as the atom divides its numerator
        (exact divisions, :meth:`cancel`): the product a(λ)·e(λ) of a characteristic polynomial and a
        function with poles at its roots then stays a polynomial, instead of a fraction whose numerator
        grows with every later sum over other denominators (the coefficients of the spectral curve at
        λ, λ + 1, ...).  The divisions are done on the factors before their product (:meth:`cancel_product`).
        Counted against a :class:`term_cap` like a product of matrices."""
        if _TERM_CAP is not None:
            _spend(len(a[0]) * len(b[0]), "a product of rational functions")
        (n1, d1), (n2, d2) = a, b
        d = _merge_add(d1, d2)
        if not d or n1.is_zero() or n2.is_zero():
            return (n1 * n2, d)
        return self.cancel_product(n1, n2, d)

    def cancel_product(self, n1, n2, d: tuple) -> tuple:
        """(n1 n2 / d) reduced like :meth:`cancel` of the product, with the divisions done on the factors:
        an atom f is irreducible, so it divides n1 n2 exactly as often as it divides n1 plus as often as it
        divides n2; f is divided out of n1 as often as it divides it (up to its exponent in d), then out of
        n2 up to what is left.  The same numerator and atoms as the product's cancellation (a reduced form
        over given atoms is unique), with divisions of the smaller factors, and the product is taken of
        the quotients (gen-chasles2 at (3, 3): the products and failed divisions of 6 x 6 Laplace
        expansions over (a_i - λ))."""
        out = []
        for k, e in d:
            f = self.atoms[k]
            n1, e = _divide_out(n1, f, e)
            n2, e = _divide_out(n2, f, e)
            if e:
                out.append((k, e))
        return (n1 * n2, tuple(out))

    def rf_inv(self, a):
        n, d = a
        if n.is_zero():
            raise ZeroDivisionError("division by an identically zero expression")
        c, atoms = self.factor(n)
        return (self.den_poly(d) / c, atoms)

    def rf_reduce(self, a):
        n, d = a
        if not d:
            return a
        if n.is_zero():
            return (self.zero, NODEN)
        return self.cancel(n, d)

    def cancel(self, n, d: tuple, only=None) -> tuple:
        """(n', d'): n over the atoms d (with exponents), every atom (of ``only``, if given)
        divided out of n as often as it divides it (exact divisions)."""
        out = []
        for k, e in d:
            if only is None or k in only:
                n, e = _divide_out(n, self.atoms[k], e)
            if e:
                out.append((k, e))
        return (n, tuple(out))

    def from_se(self, x):
        """A symengine expression as a reduced rational function (memoized); a scalar of the backend
        (:class:`_RF`) of this ring as it is."""
        if type(x) is _RF:
            if x.R is self:
                return self.rf_reduce(x.rf())
            x = x.to_se()
        try:
            hit = self.memo.get(x)
        except TypeError:      # an unhashable object: not an expression of this field
            raise NotRational(f"not a symbolic expression: {type(x).__name__}") from None
        if hit is not None:
            return hit
        Incompatible = _incompatible_error()
        while True:
            v = self.version
            try:
                r = self._conv(x)
            except Incompatible:
                if v == self.version:
                    raise
                continue               # the context grew on the way: convert again in the new one
            if v == self.version:
                break
        r = self.rf_reduce(r)
        self.memo[x] = r
        return r

    def _conv(self, x):
        if not isinstance(x, se.Basic):
            if isinstance(x, int):
                return (self.ctx.constant(x), NODEN)
            if isinstance(x, Fraction):
                return (self.const(x), NODEN)
            raise NotRational(f"not a symbolic expression: {type(x).__name__}")
        if x.is_Symbol:
            return (self.var(x), NODEN)
        if x.is_Number:
            if x.is_Integer:
                return (self.ctx.constant(int(x)), NODEN)
            if x.is_Rational:
                return (self.ctx.constant(flint.fmpq(int(x.p), int(x.q))), NODEN)
            raise NotRational(f"not a rational number: {x}")
        memo = self.memo
        if x.is_Add:
            return self.rf_sum([memo.get(t) or self._conv(t) for t in x.args])
        if x.is_Mul:
            acc = None
            for t in x.args:
                r = memo.get(t) or self._conv(t)
                acc = r if acc is None else self.rf_mul(acc, r)
            return acc
        if x.is_Pow:
            b, e = x.args
            if not e.is_Integer:
                raise NotRational(f"a non-integer power: {x}")
            k = int(e)
            r = memo.get(b) or self._conv(b)
            if k < 0:
                try:
                    r = self.rf_inv(r)
                except ZeroDivisionError as exc:
                    raise NotRational(str(exc)) from None
                k = -k
            return (r[0] ** k, tuple((a, m * k) for a, m in r[1]))
        raise NotRational(f"not a rational function: {type(x).__name__}")

    # -- back to symengine ------------------------------------------------------------
    def poly_se(self, p):
        if p.is_zero():
            return se.Integer(0)
        syms = self.syms
        used = [i for i, d in enumerate(p.degrees()) if d]
        terms = []
        for exps, c in p.terms():
            cf = se.Integer(int(c.p)) if c.q == 1 else se.Rational(int(c.p), int(c.q))
            fs = [cf]
            for i in used:
                e = exps[i]
                if e:
                    fs.append(syms[i] if e == 1 else se.Pow(syms[i], int(e)))
            terms.append(se.Mul(*fs) if len(fs) > 1 else cf)
        return se.Add(*terms) if len(terms) > 1 else terms[0]

    def poly_text(self, p) -> str:
        """p as text in a canonical order (:meth:`_terms`): the same in every process and whatever the
        order in which the ring met its variables (a symengine expression's text orders its terms by
        hashes of the parameters, whose symbols are unique per process; flint's own order follows the
        variables' order of first use, which depends on what the process computed before)."""
        return self._terms_text(self._terms(p))

    def _terms(self, p, least: int | None = None) -> list:
        """The terms of p as (monomial, coefficient), a monomial a tuple of (name, exponent) in the
        natural order of the variables' names; the terms in degree-lexicographic order of the
        monomials, highest first (the order depends on the names only).

        ``least``: only the first ``least`` terms of that order (or all), without converting or sorting the
        others."""
        names = [str(x) for x in self.syms]
        # the variables in the natural order of their names, each with its rank there (equal names' keys,
        # equal ranks): a term's place in the order, (-degree, ((rank, -exponent), ...)), compares as
        # _term_key does, without a name's key per variable of every term
        keys = [_name_key(nm) for nm in names]
        order = sorted(range(len(names)), key=keys.__getitem__)
        rank = {}
        for i in order:
            rank.setdefault(keys[i], len(rank))
        ranks = [(i, rank[keys[i]]) for i in order]

        def term(exps, c) -> tuple:
            present = [(i, k, int(exps[i])) for i, k in ranks if exps[i]]
            return ((-sum(e for _, _, e in present), tuple((k, -e) for _, k, e in present)),
                    (tuple((names[i], e) for i, _, e in present), c))
        if least is not None and len(p) > least and len(rank) == len(names):
            # the printed order is flint's deglex with the variables in the order of their names: p is
            # carried there by flint (a renaming of its variables, in native code) and its first terms read
            return self._first_terms(p, least, [names[i] for i in order], order)
        out = [term(exps, c) for exps, c in p.terms()]
        out.sort(key=lambda t: t[0])
        return [t[1] for t in out]

    @staticmethod
    def _first_terms(p, least: int, ordered: list, order: list) -> list:
        """The first ``least`` terms of p in the printed order (:meth:`_terms`), ``ordered`` its variables'
        names in their natural order (distinct keys), ``order`` their places in p's context."""
        k = len(ordered)
        ctx = flint.fmpq_mpoly_ctx.get(tuple(f"v{j}" for j in range(k)), "deglex")
        gens = ctx.gens()
        place = {i: j for j, i in enumerate(order)}
        q = p.compose(*[gens[place.get(i, 0)] for i in range(p.context().nvars())], ctx=ctx)
        out = []
        for j in range(min(least, len(q))):
            exps = q.monomial(j)
            out.append((tuple((ordered[v], int(e)) for v, e in enumerate(exps) if e), q.coefficient(j)))
        return out

    @staticmethod
    def _terms_text(terms: list) -> str:
        if not terms:
            return "0"
        out = []
        for mono, c in terms:
            text = "*".join(name if e == 1 else f"{name}**{e}" for name, e in mono)
            neg = c < 0
            c = -c if neg else c
            if not text:
                t = str(c)
            elif c == 1:
                t = text
            else:
                t = f"{c}*{text}"
            out.append(("- " if neg else "+ ") + t if out else ("-" if neg else "") + t)
        return " ".join(out)

    def text(self, r, width: int | None = None, reduced: bool = False) -> str:
        """A rational function (numerator, denominator atoms) as text in a canonical order: the terms of
        each polynomial as :meth:`poly_text` orders them, each factor of the denominator with a positive
        leading coefficient in that order (its sign moved to the numerator), the factors sorted by text.

        ``width``: a text cut short is all that is wanted; the text returned is then a prefix of the whole
        text, of at least ``width`` characters (or the whole text): its numerator's first ``width`` terms
        only (each term is at least one character), whatever the size of the numerator.  ``reduced``: r is
        reduced already (:meth:`from_se`), and is not reduced again."""
        n, d = r if reduced else self.rf_reduce(r)
        num = self._terms(n, width)
        cut = len(num) < len(n)
        if not d:
            return self._terms_text(num)
        flip = False
        dens = []
        for k, e in d:
            terms = self._terms(self.atoms[k])
            if terms and terms[0][1] < 0:
                terms = [(m, -c) for m, c in terms]
                flip ^= e % 2 == 1
            dens.append((self._terms_text(terms), e))
        if flip:
            num = [(m, -c) for m, c in num]
        den = "*".join(f"({t})" + (f"**{e}" if e > 1 else "") for t, e in sorted(dens))
        text = self._terms_text(num)
        if cut:
            return f"({text}"     # a prefix of the whole text: the numerator goes on, then the denominator
        return f"({text})/({den})" if len(num) > 1 else f"{text}/({den})"

    def atom_se(self, k: int):
        s = self._atom_se.get(k)
        if s is None:
            s = self._atom_se[k] = self.poly_se(self.atoms[k])
        return s

    def to_se(self, r):
        """A rational function as a symengine expression (remembered for the way back)."""
        n, d = r
        out = self.poly_se(n)
        if d and not n.is_zero():
            den = [self.atom_se(k) if e == 1 else se.Pow(self.atom_se(k), e) for k, e in d]
            out = out / (se.Mul(*den) if len(den) > 1 else den[0])
        elif d:
            r = (n, NODEN)
        self.memo.setdefault(out, r)
        return out


    # -- parameters beyond the ring's: the encoded form (see _BigPoly) ----------------
    def big_ctx(self) -> tuple:
        """The context of the encoded form: the ring's variables x0.., then u0..u(S-1), v0..v(S-1)
        (S² >= the number of encoded parameters), as (key, S, context, generators); rebuilt when
        the ring or the number of encoded parameters grows (values are lifted by name)."""
        hit = self._big
        if hit is not None and len(self.big_syms) <= hit[1] * hit[1]:
            return hit
        from math import isqrt
        need = isqrt(max(len(self.big_syms) - 1, 0)) + 1
        S = max(need, 8, 2 * hit[1] if hit is not None else 0)
        names = tuple(f"x{i}" for i in range(self.cap)) + tuple(f"u{a}" for a in range(S)) \
            + tuple(f"v{b}" for b in range(S))
        ctx = flint.fmpq_mpoly_ctx.get(names, "degrevlex")
        self._big = (object(), S, ctx, ctx.gens())
        return self._big

    def big_register(self, a: np.ndarray) -> None:
        """Enter the new parameters that are entries of a matrix in the encoded form at once (in the
        order they occur), so that the encoded context grows once, not once per doubling."""
        if len(self.syms) < MAX_VARS:
            return
        index, big, new = self.index, self.big, {}
        for x in a.flat:                       # a matrix of parameters (the parameters of other
            if isinstance(x, se.Symbol) and x not in index and x not in big:   # entries: one by one)
                new[x] = None
        for y in new:
            big[y] = len(self.big_syms)
            self.big_syms.append(y)
        self.big_ctx()

    def big_var(self, sym):
        """The encoded parameter u_a v_b of a symbol that is not (and never will be) a ring variable:
        parameter k is the pair (a, b) of the square-shell enumeration (k = b² + a for a < b,
        k = a² + a + b otherwise), the same at every S."""
        k = self.big.get(sym)
        if k is None:
            k = self.big[sym] = len(self.big_syms)
            self.big_syms.append(sym)
        _, S, ctx, gens = self.big_ctx()
        a, b = _unpair(k)
        return gens[self.cap + a] * gens[self.cap + S + b]

    def big_from_se(self, x) -> "_BigPoly":
        """A symengine expression as a :class:`_BigPoly` (memoized), or NotRational: a non-polynomial
        expression, or one of degree > 1 in the encoded parameters (where the encoding is not faithful)."""
        try:
            hit = self.big_memo[x]
        except KeyError:
            hit = False
        except TypeError:
            raise NotRational(f"not a symbolic expression: {type(x).__name__}") from None
        if hit is None:
            raise NotRational("not representable in the encoded form")
        if hit is not False:
            return hit
        r = self.memo.get(x) if isinstance(x, se.Basic) else None
        if r is not None and not r[1]:
            out = _BigPoly(self, r[0].project_to_context(self.big_ctx()[2]), False)
        else:
            Incompatible = _incompatible_error()
            while True:
                key = self._big_key()
                try:
                    p, lin = self._big_conv(x, {})
                except NotRational:
                    self.big_memo[x] = None
                    raise
                except _Restart:
                    continue
                except Incompatible:
                    if key == self._big_key():
                        raise
                    continue
                if key == self._big_key():
                    break
            out = _BigPoly(self, p, lin)
        self.big_memo[x] = out
        return out

    def _big_key(self):
        return self.big_ctx()[0]

    def _big_conv(self, x, memo):
        """(polynomial in the encoded context, whether it involves an encoded parameter)."""
        _, S, ctx, gens = self.big_ctx()
        if isinstance(x, int):
            return ctx.constant(x), False
        if isinstance(x, Fraction):
            return ctx.constant(flint.fmpq(x.numerator, x.denominator)), False
        if not isinstance(x, se.Basic):
            raise NotRational(f"not a symbolic expression: {type(x).__name__}")
        hit = memo.get(x)
        if hit is not None:
            return hit
        if x.is_Symbol:
            i = self.index.get(x)
            if i is None and x not in self.big and len(self.syms) < MAX_VARS:
                v = self.version
                self.var(x)                            # a ring variable while there is room
                if v != self.version:
                    raise _Restart()
                i = self.index[x]
            out = (self.big_ctx()[3][i], False) if i is not None else (self.big_var(x), True)
        elif x.is_Number:
            if x.is_Integer:
                out = (ctx.constant(int(x)), False)
            elif x.is_Rational:
                out = (ctx.constant(flint.fmpq(int(x.p), int(x.q))), False)
            else:
                raise NotRational(f"not a rational number: {x}")
        elif x.is_Add:
            acc, lin = None, False
            for t in x.args:
                p, l = self._big_conv(t, memo)
                acc = p if acc is None else acc + p
                lin = lin or l
            out = (acc, lin)
        elif x.is_Mul:
            acc, lin = None, False
            for t in x.args:
                p, l = self._big_conv(t, memo)
                if l and lin:
                    raise NotRational("of degree > 1 in the encoded parameters")
                acc = p if acc is None else acc * p
                lin = lin or l
            out = (acc, lin)
        elif x.is_Pow:
            b, e = x.args
            if not e.is_Integer or int(e) < 0:
                raise NotRational(f"not a polynomial: {x}")
            p, l = self._big_conv(b, memo)
            k = int(e)
            if l and k > 1:
                raise NotRational("of degree > 1 in the encoded parameters")
            out = (p ** k, l and k == 1)
        else:
            raise NotRational(f"not a polynomial: {type(x).__name__}")
        memo[x] = out
        return out

    def _big_name(self, nm: str):
        """A variable name of an encoded context: ("x", symbol), ("u", a) or ("v", b) (memoized)."""
        hit = self._big_name_memo.get(nm)
        if hit is None:
            if nm[0] == "x":
                hit = ("x", self.syms[int(nm[1:])])
            elif nm[0] in "uv":
                hit = (nm[0], int(nm[1:]))
            else:
                raise AssertionError(f"an unknown variable {nm!r} in the encoded form")
            self._big_name_memo[nm] = hit
        return hit

    def big_to_se(self, p):
        """An encoded polynomial (of degree <= 1 in the encoded parameters) as a symengine expression,
        read from flint's text of it (terms "c*x0^2*u3*v5" joined by " + " and " - ")."""
        if p.is_zero():
            return se.Integer(0)
        name = self._big_name
        big_syms = self.big_syms
        terms = []
        for tok in str(p).replace(" - ", " + -").split(" + "):
            neg = tok[0] == "-"
            fs = (tok[1:] if neg else tok).split("*")
            head = fs[0]
            if head[0].isdigit():
                num, _, den = head.partition("/")
                c = se.Integer(int(num)) if not den else se.Rational(int(num), int(den))
                fs = fs[1:]
            else:
                c = se.Integer(1)
            out = [-c if neg else c]
            ua = vb = None
            for f in fs:
                nm, _, e = f.partition("^")
                kind, v = name(nm)
                if kind == "x":
                    out.append(v if not e else se.Pow(v, int(e)))
                elif e or (ua if kind == "u" else vb) is not None:
                    raise AssertionError("an encoded term of degree > 1 in the encoded parameters")
                elif kind == "u":
                    ua = v
                else:
                    vb = v
            if (ua is None) != (vb is None):
                raise AssertionError("an encoded term with half a parameter")
            if ua is not None:
                out.append(big_syms[_pair(ua, vb)])
            terms.append(se.Mul(*out) if len(out) > 1 else out[0])
        return se.Add(*terms) if len(terms) > 1 else terms[0]


class _Restart(Exception):
    """The ring grew during a conversion to the encoded form: convert again."""


def _pair(a: int, b: int) -> int:
    return b * b + a if a < b else a * a + a + b


def _unpair(k: int) -> tuple[int, int]:
    from math import isqrt
    s = isqrt(k)
    t = k - s * s
    return (t, s) if t < s else (s, t - s)


def _rational_polynomial(e) -> bool:
    """Whether the symengine expression ``e`` is built from symbols and rational numbers by sums,
    products and powers with nonnegative integer exponents (a polynomial over Q in its symbols)."""
    stack = [e]
    while stack:
        x = stack.pop()
        if isinstance(x, (se.Symbol, se.Integer, se.Rational)):
            continue
        if isinstance(x, (se.Add, se.Mul)):
            stack.extend(x.args)
        elif isinstance(x, se.Pow):
            base, exp = x.args
            if not isinstance(exp, se.Integer) or exp < 0:
                return False
            stack.append(base)
        else:
            return False
    return True


class _BigPoly:
    """An entry of a generic (:class:`ObjMat`) matrix that involves parameters beyond the ring's
    MAX_VARS (a generic operator's coefficients): a flint polynomial in the ring's variables and
    2S more, u_0..u_(S-1), v_0..v_(S-1), where parameter k is u_a v_b ((a, b) = _unpair(k)).

    The map is a ring homomorphism that is injective on polynomials of degree <= 1 in the encoded
    parameters (their monomials u_a v_b are distinct and no ring variable is encoded), so the zero
    test of such a value is exact.  Every value is kept of degree <= 1: ``lin`` says (possibly
    conservatively) that it involves an encoded parameter, a product of two such values, a power
    or a quotient is computed as a symengine expression instead (the generic path, exact), and so
    is any operation with an expression that is not a polynomial of degree <= 1."""

    __slots__ = ("R", "p", "key", "lin", "s")

    def __init__(self, R: PolyRing, p, lin: bool, key=None) -> None:
        self.R, self.p, self.lin, self.s = R, p, lin, None
        self.key = key if key is not None else R.big_ctx()[0]

    def _symengine_(self):
        from stiefelsym._lazy import symengine_opaque
        return symengine_opaque()

    def _cur(self):
        big = self.R._big
        if big is None or self.key is not big[0] or len(self.R.big_syms) > big[1] * big[1]:
            big = self.R.big_ctx()
            if self.key is not big[0]:
                self.p = self.p.project_to_context(big[2])
                self.key = big[0]
        return self.p

    def _of(self, o):
        if type(o) is _BigPoly:
            return o
        try:
            return self.R.big_from_se(o)
        except NotRational:
            return None

    def to_se(self):
        if self.s is None:
            self.s = self.R.big_to_se(self._cur())
            self.R.big_memo[self.s] = self     # the way back (a value read and converted again)
        return self.s

    def is_zero(self) -> bool:
        return self.p.is_zero()

    def __bool__(self) -> bool:
        return not self.p.is_zero()

    def _new(self, p, lin):
        return _BigPoly(self.R, p, lin, self.key)

    def __add__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() + o if _plain(o) else NotImplemented
        return self._new(self._cur() + b._cur(), self.lin or b.lin)

    __radd__ = __add__

    def __sub__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() - o if _plain(o) else NotImplemented
        return self._new(self._cur() - b._cur(), self.lin or b.lin)

    def __rsub__(self, o):
        b = self._of(o)
        if b is None:
            return o - self.to_se() if _plain(o) else NotImplemented
        return self._new(b._cur() - self._cur(), self.lin or b.lin)

    def __neg__(self):
        return self._new(-self._cur(), self.lin)

    def __mul__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() * o if _plain(o) else NotImplemented
        if self.lin and b.lin:                 # degree 2 in the encoded parameters: not faithful
            return self.to_se() * b.to_se()
        return self._new(self._cur() * b._cur(), self.lin or b.lin)

    __rmul__ = __mul__

    def __truediv__(self, o):
        return self.to_se() / (o.to_se() if type(o) is _BigPoly else o)

    def __rtruediv__(self, o):
        return o / self.to_se()

    def __pow__(self, k):
        return self.to_se() ** k

    def __repr__(self):
        return f"_BigPoly({self.to_se()})"


def _plain(o) -> bool:
    return isinstance(o, (se.Basic, int, Fraction))


@engine_number_type
class _RF:
    """A scalar of the exact backend kept in flint: a rational function (numerator, denominator
    atoms) of one ring, as a trace, a pairing or an entry of a matrix of the backend leaves it.

    Sums, products, quotients and integer powers of such scalars, and with integers and fractions,
    stay in flint; anything else meets the scalar as its symengine expression (:meth:`to_se`,
    converted once and remembered by the ring for the way back).  So a scalar computed from
    entries (a minor, a Plücker coordinate, a bracket's sum) and then put back into a matrix or
    tested for zero is never converted to symengine and back.  The zero test is exact: the
    numerator is the zero polynomial."""

    __slots__ = ("R", "n", "d", "v", "s")

    def __init__(self, R: "PolyRing", rf: tuple) -> None:
        self.R, (self.n, self.d), self.v, self.s = R, rf, R.version, None

    def _symengine_(self):
        # what symengine's arithmetic sees of it: a matrix (as for _BigPoly), so that with a symengine
        # operand on the left symengine returns NotImplemented and the reflected operator below
        # computes in flint (the operand converted, memoized); the engine converts a scalar to
        # symengine only through normalize(), from_se() or to_se()
        from stiefelsym._lazy import symengine_opaque
        return symengine_opaque()

    def _sympy_(self):
        return self.to_se()._sympy_()

    def rf(self) -> tuple:
        """(numerator, atoms) in the ring's current context."""
        if self.v != self.R.version:
            self.n, self.v = self.R.lift(self.n), self.R.version
        return (self.n, self.d)

    def to_se(self):
        if self.s is None:
            self.s = self.R.to_se(self.R.rf_reduce(self.rf()))
        return self.s

    def is_zero(self) -> bool:
        return self.n.is_zero()

    def _of(self, o):
        """o as a rational function of this ring, or None."""
        t = type(o)
        if t is _RF:
            return o.rf() if o.R is self.R else None
        if t is int or t is Fraction:
            return (self.R.const(o), NODEN)
        if isinstance(o, se.Basic):
            try:
                return self.R.from_se(o)
            except NotRational:
                return None
        return None

    def _new(self, rf: tuple) -> "_RF":
        return _RF(self.R, rf)

    def __add__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() + o if _plain(o) else NotImplemented
        return self._new(self.R.rf_add(self.rf(), b))

    __radd__ = __add__

    def __neg__(self):
        n, d = self.rf()
        return self._new((-n, d))

    def __pos__(self):
        return self

    def __sub__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() - o if _plain(o) else NotImplemented
        return self._new(self.R.rf_add(self.rf(), (-b[0], b[1])))

    def __rsub__(self, o):
        b = self._of(o)
        if b is None:
            return o - self.to_se() if _plain(o) else NotImplemented
        n, d = self.rf()
        return self._new(self.R.rf_add(b, (-n, d)))

    def __mul__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() * o if _plain(o) else NotImplemented
        return self._new(self.R.rf_mul(self.rf(), b))

    __rmul__ = __mul__

    def _inverse(self, rf: tuple) -> tuple:
        try:
            return self.R.rf_inv(rf)
        except ZeroDivisionError:
            raise ZeroDivisionError("division by an identically zero expression") from None

    def __truediv__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() / o if _plain(o) else NotImplemented
        return self._new(self.R.rf_mul(self.rf(), self._inverse(b)))

    def __rtruediv__(self, o):
        b = self._of(o)
        if b is None:
            return o / self.to_se() if _plain(o) else NotImplemented
        return self._new(self.R.rf_mul(b, self._inverse(self.rf())))

    def __pow__(self, k):
        if type(k) is not int:
            return self.to_se() ** k
        n, d = self.rf() if k >= 0 else self._inverse(self.rf())
        k = abs(k)
        return self._new((n ** k, tuple((a, m * k) for a, m in d)))

    def __eq__(self, o):
        b = self._of(o)
        if b is None:
            return self.to_se() == o
        return self.R.rf_add(self.rf(), (-b[0], b[1]))[0].is_zero()

    def __ne__(self, o):
        return not self == o

    def __hash__(self):
        return hash(self.to_se())

    def __float__(self):
        return float(self.to_se())

    def __int__(self):
        return int(self.to_se())

    def __str__(self):
        return str(self.to_se())

    def __repr__(self):
        return f"_RF({self.to_se()})"


def _se(x):
    """An entry of a generic matrix as a symengine expression."""
    return x.to_se() if type(x) is _BigPoly or type(x) is _RF else x


# ----------------------------------------------------------------------------- matrices
class PolyMat:
    """A matrix of polynomial numerators (numpy object array) over one denominator (atoms)."""

    __slots__ = ("a", "den", "ctx", "z", "o", "c")

    def __init__(self, a: np.ndarray, den: tuple, ctx, z: bool = False, c: bool = False) -> None:
        #: z: known to be the zero matrix (derivatives of constants: products skip it)
        self.a, self.den, self.ctx, self.z = a, den, ctx, z
        #: the entries as symengine expressions, once computed (read only)
        self.o = None
        #: c: no atom of den divides every numerator (see PolyBackend._cancelled)
        self.c = c or not den


class ObjMat:
    """The generic representation for a matrix flint cannot hold: symengine expressions."""

    __slots__ = ("a",)

    def __init__(self, a: np.ndarray) -> None:
        self.a = a


def _scalar_array(x) -> np.ndarray:
    out = np.empty((), dtype=object)
    out[()] = x
    return out


class PolyBackend(Backend):
    """Whole-matrix operations over rational functions in flint (see the module docstring)."""

    #: a symbolic solution of the stacked gradients stays here (not converted to symengine and back)
    keeps_solutions = True

    def __init__(self, field, ring: PolyRing) -> None:
        self.field, self.ring = field, ring
        #: results of operations, keyed by the operation and its operands' identities (see _remember)
        self._memo: dict = {}

    # -- helpers ---------------------------------------------------------------------
    def _fix(self, s):
        """A PolyMat or RatMat in the ring's current context (its numerators lifted once when the
        context grew)."""
        R = self.ring
        if s.ctx is not R.ctx:
            lift = R.lift
            out = np.empty(s.a.shape, dtype=object)
            for idx, x in np.ndenumerate(s.a):
                out[idx] = lift(x)
            s.a, s.ctx = out, R.ctx
        return s

    def _fill(self, m: int, k: int, x) -> np.ndarray:
        a = np.empty((m, k), dtype=object)
        a.fill(x)
        return a

    def _pm(self, a: np.ndarray, den: tuple) -> PolyMat:
        return PolyMat(a, den, self.ring.ctx)

    def _scale(self, a: np.ndarray, f) -> np.ndarray:
        return _ew_scale(a, f)

    def _to(self, s: PolyMat, D: tuple) -> np.ndarray:
        """The numerators of s over the larger denominator D."""
        if s.den == D:
            return s.a
        f = self.ring.den_poly(_minus(D, s.den))
        return self._scale(s.a, f)

    def _reduce(self, a: np.ndarray, den: tuple) -> PolyMat:
        """Cancel every atom that divides every numerator (exact divisions, smallest entry first:
        an atom that does not divide usually fails at the first try)."""
        if not den:
            return self._pm(a, den)
        R = self.ring
        nz = [(i, x) for i, x in enumerate(a.flat) if not x.is_zero()]
        if not nz:
            return self._pm(a, NODEN)
        DomainError = _domain_error()
        nz.sort(key=lambda t: len(t[1]))
        out, changed = [], False
        for k, e in den:
            f = R.atoms[k]
            while e > 0:
                try:
                    q = [(i, x / f) for i, x in nz]
                except DomainError:
                    break
                nz, e, changed = q, e - 1, True
            if e:
                out.append((k, e))
        if changed:
            a = self._fill(a.shape[0], a.shape[1], R.zero)
            flat = a.reshape(-1)
            for i, x in nz:
                flat[i] = x
        return PolyMat(a, tuple(out), R.ctx, c=True)

    def _cancelled(self, s: PolyMat) -> PolyMat:
        """s with every atom of its denominator that divides all its numerators cancelled, before s
        enters a product: a sum over a common denominator keeps the factors its terms were scaled by
        (a/d + b/d² is (ad + b)/d², and ad + b may have d as a factor again), and a product of such
        numerators multiplies those factors too (the 8 x 8 products of the coupled big Lax pairs: 10
        times the time of the cancelled ones).  The same matrix, so s itself takes the cancelled
        numerators and denominator (its storage is replaced, never written in place: views of the old
        storage keep the old numerators over the old denominator, the same values)."""
        if s.c:
            return s
        if s.ctx is not self.ring.ctx:
            s = self._fix(s)
        r = self._reduce(s.a, s.den)
        s.a, s.den, s.c = r.a, r.den, True
        return s

    def _obj(self, s) -> np.ndarray:
        """The entries as symengine expressions, read only (converted once per matrix)."""
        if type(s) is ObjMat:
            return s.a
        if s.o is None:
            s.o = self._to_obj(s)
        return s.o

    def _generic(self, a: np.ndarray):
        """The result of an operation on generic matrices: symengine entries expanded, encoded ones
        (:class:`_BigPoly`) kept; a matrix whose entries are all encoded without an encoded
        parameter goes back to flint's representation."""
        f = self.field.normalize
        out = np.empty(a.shape, dtype=object)
        polys = True
        for idx, x in np.ndenumerate(a):
            if type(x) is _BigPoly:
                polys = polys and not x.lin
                out[idx] = x
            else:
                out[idx] = f(x)
                polys = False
        if polys and out.size:
            ctx = self.ring.ctx
            for idx, x in np.ndenumerate(out):
                out[idx] = x._cur().project_to_context(ctx)
            return self._pm(out, NODEN)
        return ObjMat(out)

    # -- conversions -------------------------------------------------------------------
    def from_obj(self, a):
        R = self.ring
        m, k = a.shape
        try:
            v = R.version
            rfs = [R.from_se(x) for x in a.flat]
            while v != R.version:      # the context grew on the way
                v = R.version
                rfs = [R.from_se(x) for x in a.flat]
        except NotRational:
            a = np.vectorize(_se, otypes=[object])(a) if a.size else a    # no scalar of the backend in a generic matrix
            if len(R.syms) < MAX_VARS and not R.big:
                return ObjMat(a.copy())
            # parameters beyond the ring's: entries in the encoded form where they are polynomials
            # of degree <= 1 in those parameters (see _BigPoly), symengine expressions otherwise
            R.big_register(a)
            out = np.empty(a.shape, dtype=object)
            for idx, x in np.ndenumerate(a):
                try:
                    out[idx] = R.big_from_se(x)
                except NotRational:
                    out[idx] = x
            return ObjMat(out)
        D = NODEN
        for r in rfs:
            if r[1] and r[1] != D:
                D = _merge_max(D, r[1])
        out = np.empty((m, k), dtype=object)
        flat = out.reshape(-1) if out.size else out
        for i, (n, d) in enumerate(rfs):
            flat[i] = n if d == D else n * R.den_poly(_minus(D, d))
        return self._pm(out, D)

    def to_obj(self, s):
        if type(s) is PolyMat and s.z:          # a zero matrix about to be filled in (scene charts)
            return self._fill(s.a.shape[0], s.a.shape[1], self.field.const(0))
        if type(s) is ObjMat:
            out = np.empty(s.a.shape, dtype=object)
            for idx, x in np.ndenumerate(s.a):
                out[idx] = _se(x)
            return out
        return self._obj(s).copy()

    def _to_obj(self, s):
        if type(s) is RatMat:
            return ratmat.to_obj(self, s)
        s = self._fix(s)
        R = self.ring
        out = np.empty(s.a.shape, dtype=object)
        for idx, x in np.ndenumerate(s.a):
            out[idx] = R.to_se(R.rf_reduce((x, s.den)) if s.den else (x, NODEN))
        return out

    def shape(self, s):
        return s.a.shape

    def values_at(self, s, draw) -> list | None:
        """The entries of a matrix at a point of the ring's variables, as flint rationals: ``s`` is a
        matrix of this backend or an array of the field's scalars (a matrix built entry by entry), and
        ``draw(k)`` gives the point's k coordinates (one per variable that occurs, in the order of the
        variables' names).  None
        where a denominator vanishes at the point; NotImplemented for an entry flint does not hold
        (symengine expressions beyond the ring), which the caller evaluates its own way."""
        R = self.ring
        if type(s) is PolyMat:
            s = self._fix(s)
            shape = s.a.shape
            nums = s.a if not s.z else None
            dens = None
        elif type(s) is RatMat:
            s = ratmat.fix(self, s)
            shape, nums, dens = s.a.shape, s.a, s.d
        elif type(s) is np.ndarray:
            shape = s.shape
            nums, dens = np.empty(shape, dtype=object), np.empty(shape, dtype=object)
            for idx, x in np.ndenumerate(s):
                if type(x) is _RF:
                    if x.R is not R:
                        # a scalar of another field's ring: its variable indices and denominator atoms are
                        # that ring's, not this one's (the contexts are shared by size): its own expression
                        return NotImplemented
                    nums[idx], dens[idx] = x.rf()
                    continue
                if type(x) is _BigPoly:
                    return NotImplemented
                try:
                    nums[idx], dens[idx] = R.from_se(x)
                except NotRational:
                    return NotImplemented
            ctx = R.ctx                  # the context may have grown while converting: lift once
            for idx, x in np.ndenumerate(nums):
                if x.context() is not ctx:
                    nums[idx] = R.lift(x)
        else:
            return NotImplemented
        # the point's coordinates are drawn for the variables that occur, in the order of their names (the
        # same point whatever else the ring holds: the draw does not depend on other matrices or runs)
        used: set[int] = set()
        for x in (nums.flat if nums is not None else ()):
            used.update(i for i, e in enumerate(x.degrees()) if e > 0)
        for d in ([s.den] if dens is None else dens.flat):
            for k, _e in d:
                used.update(i for i, e in enumerate(R.atoms[k].degrees()) if e > 0)
        order = sorted(used, key=lambda i: str(R.syms[i]))
        point = [0] * R.ctx.nvars()
        for i, v in zip(order, draw(len(order))):
            point[i] = v
        atoms: dict[int, Any] = {}

        def den_at(d: tuple):
            out = flint.fmpq(1)
            for k, e in d:
                v = atoms.get(k)
                if v is None:
                    v = atoms[k] = R.atoms[k](*point)
                out = out * v ** e
            return out

        common = den_at(s.den) if type(s) is PolyMat else flint.fmpq(1)
        if common == 0:
            return None
        rows = []
        for i in range(shape[0]):
            row = []
            for j in range(shape[1]):
                v = nums[i, j](*point) if nums is not None else flint.fmpq(0)
                d = common if dens is None else den_at(dens[i, j])
                if d == 0:
                    return None
                row.append(v / d)
            rows.append(row)
        return rows

    def row_terms(self, s) -> list[int] | None:
        """The number of terms of each row's numerators (what evaluating the row costs), or None for a matrix of
        symengine entries."""
        if type(s) is ObjMat:
            return None
        if type(s) is np.ndarray:          # a matrix built entry by entry: the field's scalars
            out = []
            for row in s.tolist():
                count = 0
                for x in row:
                    if type(x) is _RF and x.R is self.ring:
                        count += len(x.n)
                        continue
                    if type(x) in (_RF, _BigPoly):
                        return None
                    try:
                        count += len(self.ring.from_se(x)[0])
                    except NotRational:
                        return None
                out.append(count)
            return out
        s = ratmat.fix(self, s) if type(s) is RatMat else self._fix(s)
        if type(s) is PolyMat and s.z:
            return [0] * s.a.shape[0]
        return [sum(len(x) for x in row if x) for row in s.a.tolist()]

    def take(self, s, rows, cols):
        """A block without converting the rest of the matrix: numerators sliced over the same
        denominator (then reduced), or the generic entries sliced."""
        ix = np.ix_(rows, cols)
        if type(s) is ObjMat:
            return ObjMat(s.a[ix].copy())
        if type(s) is RatMat:
            s = ratmat.fix(self, s)
            return ratmat.make(self, s.a[ix].copy(), s.d[ix].copy())
        s = self._fix(s)
        return self._reduce(s.a[ix].copy(), s.den)

    def entry(self, s, i, j):
        """One entry, converted alone (the generic representation of the rest is not built)."""
        if type(s) is ObjMat:
            return _se(s.a[i, j])
        if s.o is not None:
            return s.o[i, j]
        R = self.ring
        if type(s) is RatMat:
            s = ratmat.fix(self, s)
            x, e = s.a[i, j], s.d[i, j]
        else:
            s = self._fix(s)
            x, e = s.a[i, j], s.den
        return _RF(R, R.rf_reduce((x, e)) if e else (x, NODEN))

    def accepts(self, x):
        return isinstance(x, (se.Basic, int, Fraction)) or type(x) is _RF and x.R is self.ring

    # -- constructors -------------------------------------------------------------------
    def zeros(self, m, k):
        return PolyMat(self._fill(m, k, self.ring.zero), NODEN, self.ring.ctx, True)

    def identity(self, m):
        a = self._fill(m, m, self.ring.zero)
        one = self.ring.one
        for i in range(m):
            a[i, i] = one
        return self._pm(a, NODEN)

    def from_consts(self, a):
        R = self.ring
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = R.ctx.constant(int(x))
        return self._pm(out, NODEN)

    # sparse, diag, unit: the generic constructors (from_obj of symengine entries)

    # -- arithmetic -------------------------------------------------------------------
    def add(self, a, b):
        if type(a) is ObjMat or type(b) is ObjMat:
            return self._generic(self._obj(a) + self._obj(b))
        if type(a) is RatMat or type(b) is RatMat:
            return ratmat.add(self, a, b)
        if a.z:
            return b
        if b.z:
            return a
        return self._entrywise("+", _ew_add, a, b)

    def sub(self, a, b):
        if type(a) is ObjMat or type(b) is ObjMat:
            return self._generic(self._obj(a) - self._obj(b))
        if type(a) is RatMat or type(b) is RatMat:
            return ratmat.sub(self, a, b)
        if b.z:
            return a
        if a.z:
            return self.neg(b)
        return self._entrywise("-", _ew_sub, a, b)

    def _entrywise(self, op: str, ew, a, b):
        """a op b for two PolyMats (op "+" or "-", ew its entrywise form), over the larger of
        their denominators; the stored result when the same operands were met before."""
        key = (op, id(a), id(b))
        hit = self._memo.get(key)
        if hit is not None and hit[0] is a and hit[1] is b:
            return hit[2]
        ctx = self.ring.ctx
        if a.ctx is not ctx or b.ctx is not ctx:
            a, b = self._fix(a), self._fix(b)
        if a.den == b.den:
            out = PolyMat(ew(a.a, b.a), a.den, ctx)
        else:
            D = _merge_max(a.den, b.den)
            out = self._pm(ew(self._to(a, D), self._to(b, D)), D)
        return self._remember(key, (a, b, out))

    def neg(self, a):
        if type(a) is ObjMat:
            return ObjMat(-a.a)
        if type(a) is RatMat:
            return ratmat.neg(self, a)
        if a.z:
            return a
        a = self._fix(a)
        return self._pm(-a.a, a.den)

    def matmul(self, a, b):
        if type(a) is ObjMat or type(b) is ObjMat:
            A, B = self._obj(a), self._obj(b)
            if A.shape[1] == 0:
                return ObjMat(self._fill(A.shape[0], B.shape[1], self.field.const(0)))
            return self._generic(np.dot(A, B))
        if type(a) is RatMat or type(b) is RatMat:
            return ratmat.matmul(self, a, b)
        (m, k), n = a.a.shape, b.a.shape[1]
        if a.z or b.z or k == 0 or m == 0 or n == 0:
            return self.zeros(m, n)
        key = ("@", id(a), id(b))
        memo = self._memo
        hit = memo.get(key)
        if hit is not None and hit[0] is a and hit[1] is b:
            return hit[2]
        # a b = (bᵀ aᵀ)ᵀ: the product of the transposes met already (a derivative of Yᵀ Q − Qᵀ Y along a flow
        # has Ẏᵀ Q and Qᵀ Ẏ), transposed instead of computed again
        ta, tb = memo.get(("T", id(a))), memo.get(("T", id(b)))
        if ta is not None and tb is not None and ta[0] is a and tb[0] is b:
            hit = memo.get(("@", id(tb[2]), id(ta[2])))
            if hit is not None and hit[0] is tb[2] and hit[1] is ta[2]:
                return self._remember(key, (a, b, self.T(hit[2])))
        R = self.ring
        a0, b0 = a, b               # the operands as given: the memo's key and entry are theirs
        if a.ctx is not R.ctx or b.ctx is not R.ctx:
            a, b = self._fix(a), self._fix(b)
        a, b = self._cancelled(a), self._cancelled(b)
        prod = _dot_content(a.a, b.a, R.zero)
        if a.den or b.den:
            out = self._reduce(prod, _merge_add(a.den, b.den))
        else:
            out = PolyMat(prod, NODEN, R.ctx)
        return self._remember(key, (a0, b0, out))

    def smul(self, a, c):
        if type(a) is RatMat:
            try:
                n, d = self.ring.from_se(c)
            except NotRational:
                a = ObjMat(self._obj(a))       # the generic product below
            else:
                return ratmat.smul(self, a, n, d)
        if type(a) is PolyMat and a.z:
            return a
        if type(a) is not ObjMat:
            try:
                n, d = self.ring.from_se(c)
            except NotRational:
                pass
            else:
                key = ("*", id(a), c)
                try:
                    hit = self._memo.get(key)
                except TypeError:           # an unhashable constant: not remembered
                    key, hit = None, None
                if hit is not None and hit[0] is a:
                    return hit[2]
                if a.ctx is not self.ring.ctx:
                    a = self._fix(a)
                if n.is_zero():
                    return self.zeros(*a.a.shape)
                out = self._scale(a.a, n)
                out = self._reduce(out, _merge_add(a.den, d)) if d else self._pm(out, a.den)
                return out if key is None else self._remember(key, (a, None, out))
        A = self._obj(a)
        out = np.empty(A.shape, dtype=object)
        for idx, x in np.ndenumerate(A):
            out[idx] = x * c
        return self._generic(out)

    def T(self, a):
        if type(a) is ObjMat:
            return ObjMat(a.a.T.copy())
        if type(a) is RatMat:
            return ratmat.T(self, a)
        if a.z:
            return self.zeros(a.a.shape[1], a.a.shape[0])
        key = ("T", id(a))
        hit = self._memo.get(key)
        if hit is not None and hit[0] is a:
            return hit[2]                      # the same transpose: its products meet the memo too
        a0 = a                      # the operand as given: the memo's key and entry are its
        if a.ctx is not self.ring.ctx:
            a = self._fix(a)
        out = PolyMat(a.a.T, a.den, a.ctx)    # a view: storage is never written in place
        self._remember(("T", id(out)), (out, None, a0))     # and the transpose of that view is a itself
        return self._remember(key, (a0, None, out))

    def _remember(self, key, entry):
        """An operation's result, kept for the same operands met again within this field (a
        PolyMat's storage is never written in place; the operands are kept alive with it, so
        their ids are not reused: every entry holds the objects whose ids are in its key); at most 128 results,
        of small matrices only, are kept (then the memo starts again: dropping the oldest entries one by one kept
        large operands alive longer, and a rank of the catalog took 8% more time)."""
        out = entry[2]
        if out.a.size <= 64:
            memo = self._memo
            if len(memo) >= 128:
                memo = self._memo = {}
            try:
                memo[key] = entry
            except TypeError:                  # an unhashable constant of smul: not remembered
                pass
        return out

    def _scalar(self, n, d):
        R = self.ring
        return _RF(R, R.rf_reduce((n, d)))

    def trace(self, a):
        if type(a) is ObjMat:
            acc = self.field.const(0)
            for i in range(a.a.shape[0]):
                acc = acc + a.a[i, i]
            return self.field.normalize(acc)
        if type(a) is RatMat:
            return ratmat.trace(self, a)
        a = self._fix(a)
        acc = self.ring.zero
        for i in range(a.a.shape[0]):
            acc = acc + a.a[i, i]
        return self._scalar(acc, a.den)

    def scalars(self, a):
        """The entries of a matrix of numerators over one denominator as scalars of the backend
        (rational functions kept in flint, not reduced), row by row; None for a matrix held otherwise.
        A nonzero residual is tested and printed from these, never converted to symengine as a whole
        (for a refuted statement that conversion costs more than computing the residual)."""
        if type(a) is not PolyMat:
            return None
        a = self._fix(a)
        R, den = self.ring, a.den
        if a.z:
            return [_RF(R, (R.zero, NODEN)) for _ in range(a.a.size)]
        return [_RF(R, (x, den)) for x in a.a.flat]

    def product_cost(self, a, b) -> int:
        """The term products of the product a b: sum_k (terms of column k of a) (terms of row k of b) (the
        shapes' product for matrices not held as polynomials)."""
        if type(a) is not PolyMat or type(b) is not PolyMat:
            (m, k), n = self.shape(a), self.shape(b)[1]
            return m * k * n
        if a.z or b.z:
            return 0
        cols = [_terms(c) for c in a.a.T.tolist()]
        return sum(c * _terms(r) for c, r in zip(cols, b.a.tolist()) if c)

    def trace_matmul(self, a, b):
        """tr(a b) = sum_ik a_ik b_ki: the diagonal of the product only (the trace of a power
        M^k computed as M^(k-1) M needs m of its m^2 entries, the largest polynomials of the chain;
        as a Frobenius product of a and bᵀ, half the products when both are symmetric or both skew)."""
        if type(a) is not PolyMat or type(b) is not PolyMat:
            return self.trace(self.matmul(a, b))
        if a.z or b.z:
            return self._scalar(self.ring.zero, NODEN)
        if a.ctx is not self.ring.ctx or b.ctx is not self.ring.ctx:
            a, b = self._fix(a), self._fix(b)
        a, b = self._cancelled(a), self._cancelled(b)
        return self._scalar(_frobenius(a.a, b.a.T, self.ring.zero), _merge_add(a.den, b.den))

    def inner(self, a, b):
        if type(a) is ObjMat or type(b) is ObjMat:
            acc = self.field.const(0)
            for x, y in zip(self._obj(a).flat, self._obj(b).flat):
                acc = acc + x * y
            return self.field.normalize(acc)
        if type(a) is RatMat or type(b) is RatMat:
            return ratmat.inner(self, a, b)
        a, b = self._cancelled(self._fix(a)), self._cancelled(self._fix(b))
        return self._scalar(_frobenius(a.a, b.a, self.ring.zero), _merge_add(a.den, b.den))

    def is_zero(self, a):
        if type(a) is ObjMat:
            return all(self.field.is_zero(x) for x in a.a.flat)
        if type(a) is RatMat:
            return ratmat.is_zero(self, a)
        return a.z or not any(a.a.flat)

    def product_vanishes(self, a, b) -> bool:
        """Whether a b = 0 exactly (every entry of the product of the numerators the zero polynomial), computing
        the product of the rows of a and the columns of b that are not renamed copies of others
        (:func:`_renamed_copies`): a row of a that is σ(another row) for a substitution σ of variables that no
        entry of b contains has σ(that row) b = σ(that row's products), zero when they are; a column of b
        likewise by a substitution of variables no entry of a contains.  A matrix of (f(λ_j))_j at several
        values of a parameter λ the other factor does not contain repeats one row under λ_0 -> λ_j."""
        if type(a) is not PolyMat or type(b) is not PolyMat:
            return self.is_zero(self.matmul(a, b))
        (m, k), n = a.a.shape, b.a.shape[1]
        if a.z or b.z or k == 0 or m == 0 or n == 0:
            return True
        R = self.ring
        if a.ctx is not R.ctx or b.ctx is not R.ctx:
            a, b = self._fix(a), self._fix(b)
        row_vars, col_vars = _row_variables(a.a), _row_variables(b.a.T)
        in_a, in_b = set().union(*row_vars), set().union(*col_vars)
        rows = _renamed_copies(a.a, row_vars, in_b) if in_a - in_b else list(range(m))
        cols = _renamed_copies(b.a.T, col_vars, in_a) if in_b - in_a else list(range(n))
        known = _vanishing_rows(b.a, R.ctx)
        rows = [i for i in rows if not known.holds(a.a[i])]
        A, B = a.a[rows], b.a[:, cols]
        if A.size == 0 or B.size == 0:
            return True
        if any(_dot_content(A, B, R.zero).flat):
            return False
        known.add(A)
        return True

    def block(self, grid):
        if any(type(b) is ObjMat for row in grid for b in row):
            return self._generic(np.concatenate([np.concatenate([self._obj(b) for b in row], axis=1)
                                                 for row in grid], axis=0))
        if any(type(b) is RatMat for row in grid for b in row):
            return ratmat.block(self, grid)
        grid = [[self._fix(b) for b in row] for row in grid]
        D = NODEN
        for row in grid:
            for b in row:
                D = _merge_max(D, b.den)
        a = np.concatenate([np.concatenate([self._to(b, D) for b in row], axis=1) for row in grid], axis=0)
        return self._pm(a, D)

    def inv(self, a):
        """N/D inverted as D adj(N)/det(N): fraction-free Gauss-Jordan (Bareiss) on [N | I],
        every division exact; systems beyond ``field.max_solve`` when numeric pivots suffice, a small core
        carries them or their entries have degree <= 1 (up to LINEAR_MAX_SOLVE), or else (up to WORKED_MAX_SOLVE)
        while the elimination's work stays within SOLVE_TERM_PRODUCTS."""
        if type(a) is ObjMat:
            m = a.a.shape[0]
            I = self._fill(m, m, self.field.const(0))
            for i in range(m):
                I[i, i] = self.field.const(1)
            sol = self.field.solve(a.a.tolist(), I.tolist())
            out = np.empty((m, m), dtype=object)
            for i in range(m):
                for j in range(m):
                    out[i, j] = sol[i][j]
            return ObjMat(out)
        if type(a) is RatMat:
            a = ratmat.common(self, a)          # the inverse over one denominator
        a = self._fix(a)
        R = self.ring
        m = a.a.shape[0]
        if m == 0:
            return self.zeros(0, 0)
        N = [[a.a[i, j] for j in range(m)] for i in range(m)]
        # beyond the rules of size and shape, a system of at most WORKED_MAX_SOLVE rows is eliminated while its
        # work (the term products of its steps, counted before each step) stays within SOLVE_TERM_PRODUCTS: where
        # it would not, it stops at the same step on every machine
        beyond = m > self.field.max_solve and not _small_core(N, self.field.max_solve) \
            and (a.den or not _numeric_pivots(N)) and not (m <= LINEAR_MAX_SOLVE and not a.den and _linear(N))
        if beyond and m > WORKED_MAX_SOLVE:
            raise SymbolicBudget(f"a symbolic {m}x{m} linear solve")
        left = SOLVE_TERM_PRODUCTS if beyond else None
        rows = [N[i] + [R.one if j == i else R.zero for j in range(m)] for i in range(m)]
        prev = R.one
        for k in range(m):
            piv = None
            for i in range(k, m):
                x = rows[i][k]
                if not x.is_zero() and (piv is None or len(x) < len(rows[piv][k])):
                    piv = i
            if piv is None:
                raise DegenerateError("singular symbolic linear system")
            rows[k], rows[piv] = rows[piv], rows[k]
            rk = rows[k]
            p = rk[k]
            if _TERM_CAP is not None or left is not None:
                lp, lk = len(p), _terms(rk)
                count = sum(lp * _terms(rows[i]) + len(rows[i][k]) * lk for i in range(m) if i != k)
                if left is not None:
                    left -= count
                    if left < 0:
                        raise SymbolicBudget(f"a symbolic {m}x{m} linear solve")
                _spend(count, "a step of a symbolic inverse")
            for i in range(m):
                if i == k:
                    continue
                ri = rows[i]
                f = ri[k]
                if f.is_zero():
                    if prev.is_one() and p.is_one():
                        continue
                    rows[i] = [x if j == k else (p * x) / prev for j, x in enumerate(ri)]
                    continue
                rows[i] = [R.zero if j == k else (p * x - f * rk[j]) / prev for j, x in enumerate(ri)]
            prev = p
        det = rows[0][0]                       # every diagonal entry is det(PN) now
        c, atoms = R.factor(det)
        num = R.den_poly(a.den) / c
        out = np.empty((m, m), dtype=object)
        for i in range(m):
            for j in range(m):
                out[i, j] = rows[i][m + j] * num
        return self._reduce(out, atoms)


#: the most term products one symbolic product or elimination step may take (None: no cap); set for a
#: block by :func:`term_cap`.  The count is that of the operands (sums of terms of the entries that meet),
#: known before the product starts: a run stopped by the cap stops at the same step on every machine.
_TERM_CAP: int | None = None


class term_cap:
    """A context in which a symbolic product (of matrices, a trace of a product, a Frobenius product) or a
    step of a symbolic inverse whose operands would take more than ``limit`` term products raises
    :class:`SymbolicBudget` before it starts (the mutation analysis, where a point method has already
    refuted the mutant: see :data:`stiefelsym.analyses.mutate.MUTANT_REFUTED_TERM_PRODUCTS`)."""

    def __init__(self, limit: int | None) -> None:
        self.limit = limit

    def __enter__(self) -> None:
        global _TERM_CAP
        self._old, _TERM_CAP = _TERM_CAP, self.limit

    def __exit__(self, *exc: Any) -> None:
        global _TERM_CAP
        _TERM_CAP = self._old


def _balanced_sum(xs: list):
    """The sum of a nonempty list of polynomials, added pairwise in a balanced tree."""
    while len(xs) > 1:
        xs = [xs[k] + xs[k + 1] if k + 1 < len(xs) else xs[k] for k in range(0, len(xs), 2)]
    return xs[0]


def _terms(xs) -> int:
    return sum(len(x) for x in xs if x)


def _spend(count: int, what: str) -> None:
    if _TERM_CAP is not None and count > _TERM_CAP:
        raise SymbolicBudget(f"{what} of {count:,} term products (the cap is {_TERM_CAP:,})")


# Entrywise operations that skip zero entries: a flint operation costs about half a microsecond
# however small its operands, and the chart's matrices are sparse (X = (E_1..E_r), Phi, derivatives
# along a flow).  A zero operand is passed through (entries are never modified in place).
def _ew_add(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    out = np.empty(a.size, dtype=object)
    for i, x, y in zip(range(a.size), a.flat, b.flat):
        out[i] = (x + y if y else x) if x else y
    return out.reshape(a.shape)


def _ew_sub(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    out = np.empty(a.size, dtype=object)
    for i, x, y in zip(range(a.size), a.flat, b.flat):
        out[i] = (x - y if y else x) if x else (-y if y else x)
    return out.reshape(a.shape)


def _ew_scale(a: np.ndarray, f) -> np.ndarray:
    out = np.empty(a.size, dtype=object)
    for i, x in zip(range(a.size), a.flat):
        out[i] = x * f if x else x
    return out.reshape(a.shape)


def _dot(a: np.ndarray, b: np.ndarray, zero) -> np.ndarray:
    """The product of two arrays of polynomials, skipping zero entries (structural zeros are
    common: X = (E_1..E_r), derivatives of constants, block matrices) and products by one in
    outer products (X X^T, X P^T at X = (E_1..E_r))."""
    m, k = a.shape
    n = b.shape[1]
    if _TERM_CAP is not None:
        _spend(sum(_terms(a[:, i].tolist()) * _terms(b[i].tolist()) for i in range(k)), "a symbolic product")
    out = np.empty(m * n, dtype=object)
    if k == 1:
        row = b[0].tolist()
        pos = 0
        for x in a[:, 0].tolist():
            if not x:
                out[pos:pos + n].fill(zero)
            elif x.is_one():
                for j, y in enumerate(row):
                    out[pos + j] = y
            else:
                for j, y in enumerate(row):
                    out[pos + j] = x * y if y else zero
            pos += n
        return out.reshape(m, n)
    bt = b.T.tolist()
    pos = 0
    for ai in a.tolist():
        nz = [(i, x) for i, x in enumerate(ai) if x]
        if not nz:
            out[pos:pos + n].fill(zero)
            pos += n
            continue
        for bj in bt:
            acc = None
            for i, x in nz:
                y = bj[i]
                if y:
                    acc = x * y if acc is None else acc + x * y
            out[pos] = zero if acc is None else acc
            pos += 1
    return out.reshape(m, n)


#: a product of at least this many products of terms (Σ_k (Σ_i |a_ik|)(Σ_j |b_kj|)) first takes out the common
#: factor of each operand's entries (about 40 ms of flint's products of terms; two gcds of the smallest entries
#: cost a few ms)
CONTENT_TERMS = 2_000_000


#: the contents of the last operands (:func:`_content`), by the operand's id: the array is kept in the entry, so
#: the id is not reused while the entry lives (an operand met again in another product is not looked at again)
_CONTENTS: "OrderedDict[int, tuple]" = OrderedDict()
CONTENTS_KEPT = 8


def _content(a: np.ndarray):
    """The greatest common divisor g of the nonzero entries of a and the array of the quotients, or None
    when g is a constant or is not found cheaply: the gcd of the two smallest entries, then an exact division
    of each other entry by it (its quotient kept); None at the first entry it does not divide."""
    hit = _CONTENTS.get(id(a))
    if hit is not None and hit[0] is a:
        return hit[1]
    out = _content_of(a)
    _CONTENTS[id(a)] = (a, out)
    while len(_CONTENTS) > CONTENTS_KEPT:
        _CONTENTS.popitem(last=False)
    return out


def _content_of(a: np.ndarray):
    nz = [(i, x) for i, x in enumerate(a.flat) if x]
    if len(nz) < 2:
        return None
    nz.sort(key=lambda t: len(t[1]))
    g = nz[0][1].gcd(nz[1][1])
    if g.is_constant():
        return None
    DomainError = _domain_error()
    quotients: list = []
    for i, x in nz:
        try:
            quotients.append((i, x / g))
        except DomainError:
            # g does not divide every entry: the plain product (finding the part of g that x has takes a gcd
            # of g with a large x, or a factorization of g, each of which can cost more than the product:
            # g of 82,944 terms ran out of memory where the plain product took 12 s, stop 88 h2 F1)
            return None
    out = np.empty(a.size, dtype=object)
    out.fill(nz[0][1] * 0)
    for i, q in quotients:
        out[i] = q
    return g, out.reshape(a.shape)


def _dot_content(a: np.ndarray, b: np.ndarray, zero) -> np.ndarray:
    """:func:`_dot`, with the common factor of each operand's entries taken out first when the product is large
    (a column V adj(M)E_1 has the factors of the minors of V in every entry: the product ⟨v, Bv⟩ of the
    tangency claim at (5, 5) multiplies polynomials of 2,202 terms where the quotients have a few) and
    multiplied into the product's entries after."""
    k = a.shape[1]
    if k > 1 and not _TERM_CAP:
        rows = [sum(len(x) for x in a[:, i].tolist() if x) for i in range(k)]
        cols = [sum(len(y) for y in b[i].tolist() if y) for i in range(k)]
        if sum(x * y for x, y in zip(rows, cols)) >= CONTENT_TERMS:
            ca, cb = _content(a), _content(b)
            if ca is not None or cb is not None:
                factors = []
                if ca is not None:
                    factors.append(ca[0])
                    a = ca[1]
                if cb is not None:
                    factors.append(cb[0])
                    b = cb[1]
                prod = _dot(a, b, zero)
                # one factor after the other (the expanded product of the two has more terms than both)
                out = np.empty(prod.size, dtype=object)
                for i, x in enumerate(prod.flat):
                    if x:
                        for g in factors:
                            x = x * g
                    out[i] = x
                return out.reshape(prod.shape)
    return _dot(a, b, zero)


class _VanishingRows:
    """The rows r found with r b = 0 (every entry the zero polynomial) for one array b of polynomials, by the
    lengths of their entries: a row equal to one of them, entry by entry, has r b = 0 without a product (the
    pencil's (A2) system at (6, 6) multiplies its 24 rows by the kernel, then the same 24 rows among 96 by the
    same kernel, built again from the same entries)."""

    def __init__(self, b: np.ndarray) -> None:
        self.b = b
        self.rows: dict[tuple, list[list]] = {}

    @staticmethod
    def key(entries: list) -> tuple:
        return tuple(len(x) if x else 0 for x in entries)

    def holds(self, row: np.ndarray) -> bool:
        entries = row.tolist()
        return any(all(x == y for x, y in zip(entries, seen)) for seen in self.rows.get(self.key(entries), ()))

    def add(self, A: np.ndarray) -> None:
        for entries in A.tolist():
            self.rows.setdefault(self.key(entries), []).append(entries)


#: the rows of the last kernels' products that vanish (:class:`_VanishingRows`), by the context, the shape and the
#: lengths of the kernel's entries (a kernel equal entry by entry to one met before shares its rows)
_VANISHING: "OrderedDict[tuple, list[_VanishingRows]]" = OrderedDict()
VANISHING_KEPT = 2


def _vanishing_rows(b: np.ndarray, ctx) -> _VanishingRows:
    """The rows known to vanish against b, a kernel's numerators in the context ``ctx`` (kept with b)."""
    key = (id(ctx), b.shape, _VanishingRows.key(b.flat))
    for hit in _VANISHING.get(key, ()):
        if hit.b is b or all(x == y for x, y in zip(hit.b.flat, b.flat)):
            _VANISHING.move_to_end(key)
            return hit
    hit = _VanishingRows(b)
    _VANISHING.setdefault(key, []).append(hit)
    _VANISHING.move_to_end(key)
    while len(_VANISHING) > VANISHING_KEPT:
        _VANISHING.popitem(last=False)
    return hit


def _row_variables(a: np.ndarray) -> list[set[int]]:
    """For each row of an array of polynomials, the indices of the variables that occur in some entry of it."""
    out = []
    for row in a.tolist():
        used: set[int] = set()
        for x in row:
            if x:
                used.update(i for i, e in enumerate(x.degrees()) if e)
        out.append(used)
    return out


def _renamed_copies(a: np.ndarray, variables: list[set[int]], fixed: set[int]) -> list[int]:
    """The rows of an array of polynomials to keep: every other row equals σ(a kept row), σ the substitution of
    the kept row's variables outside ``fixed`` (in increasing order) by the row's own (in increasing order),
    which fixes every variable in ``fixed``; each equality is checked exactly, entry by entry.  Rows with no
    variable outside ``fixed`` are kept.  ``variables``: each row's variables (:func:`_row_variables`)."""
    kept: list[int] = []
    seen: dict[tuple, list[tuple[list[int], list]]] = {}
    gens = None
    for i, row in enumerate(a.tolist()):
        free = sorted(variables[i] - fixed)
        if not free:
            kept.append(i)
            continue
        key = (len(free), tuple(len(x) if x else 0 for x in row))
        copy = False
        for own, rep in seen.get(key, ()):
            if gens is None:
                gens = list(next(x for x in a.flat if x).context().gens())
            sub = list(gens)
            for v, w in zip(own, free):
                sub[v] = gens[w]
            if all(y == x.compose(*sub) if x else not y for x, y in zip(rep, row)):
                copy = True
                break
        if not copy:
            kept.append(i)
            seen.setdefault(key, []).append((free, row))
    return kept


def _parity(a: np.ndarray) -> int:
    """+1 when the square array of polynomials is symmetric, -1 when it is skew (with a zero
    diagonal), 0 otherwise (or when it is not square); every comparison is exact."""
    m, k = a.shape
    if m != k or m < 2:
        return 0
    sym = skew = True
    for i in range(m):
        if skew and a[i, i]:
            skew = False
        for j in range(i + 1, m):
            x, y = a[i, j], a[j, i]
            if sym and x != y:
                sym = False
            if skew and x != -y:
                skew = False
            if not (sym or skew):
                return 0
    return 1 if sym else -1


def _frobenius(a: np.ndarray, b: np.ndarray, zero):
    """sum_ij a_ij b_ij.  When a and b are both symmetric, or both skew (checked entry by entry),
    the terms (i, j) and (j, i) are equal: the upper triangle is summed once and doubled (half the
    products); when one is symmetric and the other skew they cancel, and the sum is the diagonal's."""
    if _TERM_CAP is not None:
        _spend(sum(len(x) * len(y) for x, y in zip(a.flat, b.flat) if x and y), "a symbolic trace of a product")
    pa = _parity(a)
    pb = _parity(b) if pa else 0
    acc = zero
    if not pb:
        for x, y in zip(a.flat, b.flat):
            if x and y:
                acc = acc + x * y
        return acc
    m = a.shape[0]
    if pa == pb:
        for i in range(m):
            for j in range(i + 1, m):
                x, y = a[i, j], b[i, j]
                if x and y:
                    acc = acc + x * y
        acc = acc + acc
    for i in range(m):
        x, y = a[i, i], b[i, i]
        if x and y:
            acc = acc + x * y
    return acc


#: the largest inverse of a matrix of polynomials of degree <= 1 (I + S in the Cayley chart at r = n, a pencil
#: λI − A): Bareiss elimination keeps minors of degree <= k at step k, so the entries stay small (at r = n = 6,
#: (I + S)⁻¹ in 15 parameters takes well under a second); a general symbolic matrix has field.max_solve
LINEAR_MAX_SOLVE = 6

#: the most term products (the sum over its steps, counted as :func:`_spend` counts them) of a symbolic inverse
#: beyond the rules of size and shape above (field.max_solve, a small core, numeric pivots, degree <= 1 up to
#: LINEAR_MAX_SOLVE), of at most WORKED_MAX_SOLVE rows: a step that would exceed it raises :class:`SymbolicBudget`
#: before it starts, so that a solve beyond it stops at the same step on every machine, after at most this much
#: work (about 0.1 s).  M = I + S11 + KᵀK of the reduced Cayley chart at (6, 5) (5 x 5 of degree 2 in 15
#: parameters) takes 533,529 in 0.05 s; at (7, 6) (6 x 6 in 21) it would take 19.4 million (2.3 s), and I + S at
#: r = n = 7 (7 x 7 of degree 1) 25.7 million (3.5 s)
SOLVE_TERM_PRODUCTS = 1_000_000

#: the largest symbolic system SOLVE_TERM_PRODUCTS admits (a larger one beyond the rules is refused for its size:
#: the singular 9 x 9 of the constraints' second derivatives of two mutants of double-neumann-diagonal at (4, 3)
#: stays refused, as the mutation analysis records it)
WORKED_MAX_SOLVE = 6


def _linear(N) -> bool:
    """Whether every entry of N is a polynomial of total degree at most 1."""
    for row in N:
        for x in row:
            deg = getattr(x, "total_degree", None)
            if deg is None or not x.is_zero() and deg() > 1:
                return False
    return True


def _small_core(N, k: int) -> bool:
    """Whether at most k rows (with their columns) carry every nonzero entry off the diagonal of N
    (a vertex cover of its pattern).  Each row outside such a cover has one nonzero entry outside
    the cover's columns, its diagonal: eliminating those rows divides by diagonal entries only, and
    what is left is a symbolic k x k system on the cover (its Schur complement), within the budget
    of a k x k solve.  An arrowhead (μI − A with the chart's diagonal blocks A11, A22 and r or
    n − r at most k) is such a matrix."""
    m = len(N)
    nbr: dict[int, set[int]] = {}
    for i in range(m):
        for j in range(i + 1, m):
            if not (N[i][j].is_zero() and N[j][i].is_zero()):
                nbr.setdefault(i, set()).add(j)
                nbr.setdefault(j, set()).add(i)
    if any(N[i][i].is_zero() for i in range(m) if i not in nbr):
        return False                            # a zero pivot outside the core: leave it to the general rule

    def cover(nbr: dict[int, set[int]], k: int) -> bool:
        if not nbr:
            return True
        if k == 0:
            return False
        v = max(nbr, key=lambda u: len(nbr[u]))
        # an edge (v, u) is covered by v, or else by every neighbour of v
        options = [[v]] + ([sorted(nbr[v])] if len(nbr[v]) <= k else [])
        for take in options:
            rest = {u: ws - set(take) for u, ws in nbr.items() if u not in take}
            if cover({u: ws for u, ws in rest.items() if ws}, k - len(take)):
                return True
        return False
    return cover(nbr, k)


def _numeric_pivots(N) -> bool:
    """Whether Gaussian elimination finds a nonzero constant pivot at every step (then no
    fractions appear); the rule of :meth:`SymbolicField.solve`."""
    rows = [list(r) for r in N]
    m = len(rows)
    for col in range(m):
        piv = next((i for i in range(col, m) if rows[i][col].is_constant() and not rows[i][col].is_zero()), None)
        if piv is None:
            return False
        rows[col], rows[piv] = rows[piv], rows[col]
        p = rows[col][col]
        for i in range(col + 1, m):
            f = rows[i][col]
            if not f.is_zero():
                f = f / p
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[col])]
    return True


# ---------------------------------------------------------------------------------------------
# the number system whose matrices this module keeps

class SymbolicField(Field):
    """symengine expressions in the chart parameters; zero means identically zero."""

    name = "symbolic"

    #: matrices live in flint (:mod:`stiefelsym.backends.polyfield`); False (or the environment variable
    #: STIEFELSYM_EXACT_BACKEND=symengine): numpy arrays of symengine expressions, as before
    native = os.environ.get("STIEFELSYM_EXACT_BACKEND", "flint") != "symengine"

    def __init__(self, width: int = 0) -> None:
        self.symbols: dict[str, se.Symbol] = {}
        self._poly_ring = None
        #: the variables its flint ring is expected to reach (:class:`PolyRing`)
        self._width = width

    def const(self, q):
        if type(q) is int:
            return se.Integer(q)
        q = Fraction(q)
        return se.Integer(q.numerator) / se.Integer(q.denominator)

    def param(self, name, rng=None):
        s = se.Dummy(name)   # unforgeable: a symbol a claim makes with this name is another one
        self.symbols[name] = s
        return s

    #: the type of the encoded entries of the exact backend's generic matrices
    #: (:class:`stiefelsym.backends.polyfield._BigPoly`, set with the first ring): converted to symengine
    #: where they leave the backend
    _encoded_type = None

    def normalize(self, x):
        if type(x) is self._encoded_type or type(x) is _RF:
            return x.to_se()
        return se.expand(x)

    def pairing(self, x):
        # a flint scalar stays in flint: sums, products, quotients and the zero test are exact there,
        # and it meets symengine (converted once) only where an expression needs it
        if type(x) is _RF:
            return x
        return self.normalize(x)

    def poly_ring(self):
        """The flint rational-function ring of this field's symbols (created on first use)."""
        if self._poly_ring is None:
            if SymbolicField._encoded_type is None:
                # set once: assigning a class attribute invalidates the interpreter's attribute caches
                SymbolicField._encoded_type = _BigPoly
            self._poly_ring = PolyRing(self._width)
        return self._poly_ring

    def ring_width(self) -> int:
        """The number of variables its flint ring holds (0 before the ring is used)."""
        return 0 if self._poly_ring is None else len(self._poly_ring.syms)

    def native_backend(self):
        """Whole matrices as flint polynomial numerators over one common denominator."""
        if not self.native:
            return None
        return PolyBackend(self, self.poly_ring())

    def is_zero(self, x):
        """Exact: x as a rational function over flint has the zero numerator (an expression flint
        cannot hold goes through symengine's expansion and SymPy's cancel)."""
        if isinstance(x, se.Basic) and x.is_Number:
            return x == 0
        if type(x) is self._encoded_type or type(x) is _RF:
            return x.is_zero()
        if self.native:
            try:
                return self.poly_ring().from_se(x)[0].is_zero()
            except NotRational:
                pass
        return self._is_zero_sympy(x)

    @staticmethod
    def _is_zero_sympy(x):
        e = se.expand(x)
        if e == 0:
            return True
        if e.is_Number:
            return False
        num, _den = e.as_numer_denom()
        num = se.expand(num)
        if num == 0:
            return True
        if _rational_polynomial(num):
            # an expanded polynomial in symbols with rational coefficients is symengine's canonical sum of
            # distinct monomials: it is 0 only as the empty sum, so this one is not 0 (and neither is x,
            # its numerator over a nonzero denominator)
            return False
        import sympy
        return sympy.cancel(sympy.together(sympy.sympify(e))) == 0

    def pivot_cost(self, x):
        e = se.expand(_se(x))
        if e == 0:
            return math.inf
        if e.is_Number:
            return 0.0
        if self.is_zero(e):
            return math.inf
        return float(len(str(e)))

    def _numeric_pivots(self, M) -> bool:
        """Whether Gaussian elimination finds a nonzero numeric pivot at every step."""
        rows = [[se.expand(_se(x)) for x in row] for row in M]
        m = len(rows)
        for col in range(m):
            piv = next((i for i in range(col, m) if rows[i][col].is_Number and rows[i][col] != 0), None)
            if piv is None:
                return False
            rows[col], rows[piv] = rows[piv], rows[col]
            for i in range(col + 1, m):
                f = rows[i][col] / rows[col][col]
                if f != 0:
                    rows[i] = [se.expand(a - f * b) for a, b in zip(rows[i], rows[col])]
        return True

    #: largest system solved by cofactors (larger ones raise SymbolicBudget)
    max_solve = 3

    def solve(self, M, B):
        """Elimination when numeric pivots suffice (then no fractions appear); otherwise
        Y = adj(M) B / det(M) with determinants by fraction-free elimination."""
        m = len(M)
        # the backend's scalars as symengine expressions, every kind of them (an encoded polynomial, a
        # rational function kept in flint): symengine would take either for an empty matrix (its
        # conversion, symengine_opaque) and return 0x0 matrices as the solution's entries
        M = [[_se(x) for x in row] for row in M]
        B = [[_se(x) for x in row] for row in B]
        if all(se.expand(x).is_Number for row in M for x in row) or self._numeric_pivots(M):
            return Field.solve(self, M, B)
        if m > self.max_solve:
            raise SymbolicBudget(f"a symbolic {m}x{m} linear solve")
        A = se.DenseMatrix(m, m, [se.expand(x) for row in M for x in row])
        det = se.expand(A.det())
        if self.is_zero(det):
            raise DegenerateError("singular symbolic linear system")
        adj = [[None] * m for _ in range(m)]
        for i in range(m):
            for j in range(m):
                rows = [k for k in range(m) if k != j]
                cols = [k for k in range(m) if k != i]
                minor = se.DenseMatrix(m - 1, m - 1, [A[a, b] for a in rows for b in cols]) if m > 1 else None
                cof = se.expand(minor.det()) if minor is not None else se.Integer(1)
                adj[i][j] = cof if (i + j) % 2 == 0 else -cof
        k = len(B[0]) if B else 0
        return [[se.expand(sum((adj[i][l] * B[l][j] for l in range(m)), se.Integer(0))) / det
                 for j in range(k)] for i in range(m)]
