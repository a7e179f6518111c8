"""The routes by which a claims file steered a verdict while claim code ran on live values, each a
class, each replayed by tricks of its own: since claims are traced into graphs that hold no value,
every method gives ``error`` or the right verdict.  (One file per class of route; the honest
version of each trick still passes.)"""
import json
import pickle
import sys
from fractions import Fraction

import numpy as np
import pytest

from stiefelsym import admissible, block
from stiefelsym.claims import Claim
from stiefelsym.ir import TraceRefused, _compiled_graph, compile_claim, trace
from stiefelsym.run.runner import run_one
from stiefelsym.claims import Size
from stiefelsym.scene import REALIZATIONS

PASSING = ("proved", "checked", "numeric")
METHODS = ("exact", "rational", "modular", "float", "auto")
STANDARD = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)


def _claim(func, expect="holds", cid=None, sizes=None):
    return Claim(id=cid or func.__name__.replace("_", "-"), paper=("prep",), kind="id", section="t", func=func,
                 sizes=sizes or admissible(5), expect=expect)


def verdicts(func, sizes=((4, 2),), methods=METHODS, expect="holds", free=True):
    c = _claim(func, expect)
    out = {(m, n, r): run_one(c, Size(n, r), m, 0).verdict for n, r in sizes for m in methods}
    if free:
        out[("free", None, None)] = run_one(c, None, "free", 0).verdict
    return out


def never_passes(func, **kw):
    v = verdicts(func, **kw)
    wrong = {k: x for k, x in v.items() if x in PASSING}
    assert not wrong, wrong


# -- 1. coordinates read through blocks and untyped spaces ----------------------------------------

def entry_through_a_block(s):
    """False: X = (I; 0) is the equivariant chart's point, read through a block with an untyped row."""
    B = block([[s.X], [s.zeros(1, s.r, ("?", "r"))]])
    return {"X11 - 1": B[0, 0] - s.q(1), "X21": B[1, 0]}


def diagonal_by_blocks(s):
    """False: XᵀDX = XᵀX for D = diag(1, 1, 2, 2) made of identity blocks (true at X = (E1, E2))."""
    D = block([[s.identity(2), s.zeros(2, 2)], [s.zeros(2, 2), s.identity(2) * 2]])
    return {"XtDX - XtX": s.X.T @ D @ s.X - s.X.T @ s.X}


def constant_untyped_matrix(s):
    """False: a constant diagonal matrix written entry by entry with untyped spaces."""
    D = s.mat([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 2, 0], [0, 0, 0, 2]])
    return {"XtDX - XtX": s.X.T @ D @ s.X - s.X.T @ s.X}


def slice_of_the_identity(s):
    """False: X equals the first r columns of I_n (the chart's point), read by a slice."""
    return {"X - In[:, :r]": s.X - s.In[:, 0:2]}


@pytest.mark.parametrize("func", [entry_through_a_block, diagonal_by_blocks, constant_untyped_matrix,
                                  slice_of_the_identity], ids=lambda f: f.__name__)
def test_coordinates_are_seen_in_the_graph_whatever_the_spaces_say(func):
    never_passes(func, methods=("exact", "auto", "modular"))


def test_entries_of_r_by_r_invariants_keep_the_equivariant_chart():
    def gram_entry(s):
        """True: the (1,1) entry of XᵀX is 1."""
        return {"(XtX)11 - 1": (s.X.T @ s.X)[0, 0] - s.q(1)}
    assert verdicts(gram_entry, sizes=((6, 2),), methods=("exact",), free=False)[("exact", 6, 2)] == "proved"


# -- 2. floats in disguise --------------------------------------------------------------------------

@pytest.mark.parametrize("c", [complex(1, 0), np.float32(1e20), np.array(1e20), 0.5, np.float64(2.0),
                               np.int64(3), Fraction(1, 2) + 0j], ids=lambda c: type(c).__name__)
def test_a_constant_that_is_not_exact_is_refused_on_every_method(c):
    def disguised(s):
        """False in exact arithmetic: (cX + X) - cX = 0 where c absorbs X in double precision."""
        Xc = s.X * c
        return {"(Xc + X) - Xc": (Xc + s.X) - Xc}
    v = verdicts(disguised, methods=("exact", "modular", "float"), free=True)
    assert all(x in ("error", "undecided") for x in v.values()), v
    with pytest.raises(TraceRefused, match="not a value of the IR|is an int or a Fraction"):
        trace(disguised, 3, 2, STANDARD)


# -- 3. exceptions as a side channel ----------------------------------------------------------------

def branch_on_a_caught_refusal(s):
    """False on one branch: the claim catches a refusal and returns a false residual."""
    try:
        float(s.lam)
    except TypeError:
        return {"X": s.X}
    return {"zero": s.X - s.X}


def branch_on_sizes_being_numbers(s):
    """A true residual where sizes are symbols, a false one where they are numbers."""
    try:
        int(s.n)
    except TypeError:
        return {"ok": s.X.T @ s.X - s.Ir}
    return {"bad": s.X.T @ s.X}


def branch_on_the_size_type(s):
    """No refusal: it looks at the private slots of its size (and of X's shape) for a number, to tell
    symbolic sizes apart.  They carry none (the number lives with the trace, behind int(n)), so it
    states X^T X = I at every size."""
    n = s.n
    slots = [object.__getattribute__(n, k) for k in type(n).__slots__]
    slots += list(object.__getattribute__(s.X, "_shape"))
    symbolic = all(getattr(x, "value", None) is None for x in slots) and "3" not in repr(s.X)
    return {"ok": s.X.T @ s.X - s.Ir} if symbolic else {"bad": s.X.T @ s.X}


def test_private_slots_of_a_size_carry_no_number():
    digests = {trace(branch_on_the_size_type, n, r, STANDARD).digest() for n, r in ((3, 2), (7, 2), (None, None))}
    assert len(digests) == 1


def branch_on_a_failed_product(s):
    """A product whose sizes do not fit, caught: the refusal is recorded anyway."""
    try:
        s.X @ s.X
    except TypeError:
        return {"bad": s.X}
    return {"bad": s.X}


@pytest.mark.parametrize("func", [branch_on_a_caught_refusal, branch_on_sizes_being_numbers,
                                  branch_on_a_failed_product], ids=lambda f: f.__name__)
def test_no_branch_of_a_claim_sees_its_method(func):
    never_passes(func)


def test_a_refusal_has_one_message_whatever_the_method():
    msgs = set()
    for n, r in ((3, 2), (4, 2), (None, None)):
        with pytest.raises(TraceRefused) as e:
            trace(lambda s: {"x": s.X + s.A}, n, r, STANDARD)
        msgs.add(str(e.value).split(" (")[0])
    assert len(msgs) == 1


def an_entry_out_of_range(s):
    """An entry of Ψ (r × r) at row n − 1: out of range where r < n (it was each backend's own IndexError,
    raised by the exact method only after the products it evaluates first)."""
    return {"x": s.Psi[s.n - 1, 0] - s.Psi[s.n - 1, 0]}


def test_an_entry_out_of_range_is_refused_when_traced_with_one_message():
    c = _claim(an_entry_out_of_range)
    res = [run_one(c, Size(3, 2), m, 0) for m in ("exact", "rational", "modular", "float")]
    assert {x.verdict for x in res} == {"error"}
    assert {x.message.split(" (at ")[0] for x in res} == {
        "TraceRefused: refused: entry index 2 out of range for an axis of length 2"}
    assert run_one(c, Size(3, 3), "exact", 0).verdict == "proved"     # in range: the claim is 0 - 0
    with pytest.raises(TraceRefused):
        trace(lambda s: {"x": s.X[0, -5]}, 4, 2, STANDARD)
    assert trace(lambda s: {"x": s.X[-1, -2]}, 4, 2, STANDARD) is not None     # Python's negative indices


def rows_reversed_twice(s):
    """True: X with its rows reversed twice is X (a step of -1)."""
    return {"x": s.X[::-1, :][::-1, :] - s.X}


def rows_reversed(s):
    """False: X with its rows reversed is X."""
    return {"x": s.X[::-1, :] - s.X}


def every_other_row_past_the_end(s):
    """True: every other row taken twice over a slice past the end (clamped), and the last entry by -1."""
    return {"x": s.X[0:100:2, :] - s.X[::2, :], "last": s.X[-1, -1] - s.X[s.n - 1, s.r - 1]}


@pytest.mark.parametrize("func, truth", [(rows_reversed_twice, True), (rows_reversed, False),
                                         (every_other_row_past_the_end, True)],
                         ids=["reversed-twice", "reversed", "steps-and-negative"])
def test_the_honest_forms_of_indexing_give_the_right_verdict_under_every_method(func, truth):
    """The stop's own probes beside the refusals above: slices with negative and odd steps, clamped slices and
    negative indices mean what Python says under every method (no method refuses them, none disagrees)."""
    c = _claim(func)
    verdicts = {m: run_one(c, Size(4, 2), m, 0).verdict for m in ("exact", "rational", "modular", "float")}
    assert set(verdicts.values()) <= (set(PASSING) if truth else {"fails"}), verdicts


def an_empty_inverse(s):
    """The inverse of a 0 × 0 matrix (an empty block of X): the exact method took it for the empty matrix and
    the point methods for a singular point (review of stop 58)."""
    E = s.X[7:, :]
    return {"x": s.tr((E @ E.T).inv()) + s.q(1)}


def a_zero_step(s):
    """A slice with step 0: Python's own ValueError at evaluation before."""
    return {"x": s.X[0:4:0, :]}


@pytest.mark.parametrize("func, message", [(an_empty_inverse, "the inverse of an empty (0 x 0) matrix"),
                                           (a_zero_step, "a slice of a matrix with step 0")],
                         ids=["empty-inverse", "zero-step"])
def test_an_empty_inverse_and_a_zero_step_are_refused_with_one_message(func, message):
    c = _claim(func)
    res = [run_one(c, Size(3, 2), m, 0) for m in ("exact", "rational", "modular", "float", "auto")]
    assert {x.verdict for x in res} == {"error"}, [(x.method, x.verdict, x.message) for x in res]
    assert all(message in x.message for x in res)


def test_a_claims_file_loaded_in_process_that_poisons_the_graph_cache_gets_no_passing_verdict():
    """The same file loaded into this process (the library's way, no fresh interpreter, no replay): the cache of
    references it fills is read by no check (Graph.refs reads the arguments each time).  With the cache read,
    exact said proved, rational checked and float numeric of this false statement (stop 58)."""
    from pathlib import Path
    from stiefelsym.claims import load_claims_file
    reg = load_claims_file(str(Path(__file__).resolve().parent / "adversary" / "s58" / "batch1.py"))
    for cid in ("s58-refs-inv-div-trace", "s58-refs-inv-div-symbolic"):
        for m in ("exact", "rational", "modular", "float"):
            assert run_one(reg.get(cid), Size(3, 2), m, 0).verdict == "error", (cid, m)


def test_a_claims_file_that_poisons_the_graph_it_is_traced_into_gets_no_passing_verdict():
    """Review of stop 58 (tests/adversary/s58/batch1.py): claim code reaches the graph being traced (s._t.g)
    and puts a list of its own under its cache of references, so that a trace-time check takes tr(PᵀP) for a
    constant divisor.  The file is traced in a fresh interpreter and its graphs are replayed here by the
    engine's tracer, which types every node again: error under every method."""
    import subprocess
    from pathlib import Path
    here = Path(__file__).resolve().parent
    batch = here / "adversary" / "s58" / "batch1.py"
    for m in ("exact", "rational", "modular", "float", "auto"):
        out = subprocess.run([sys.executable, "-m", "stiefelsym", "verify", "--claims", str(batch),
                              "s58-refs-inv-div-trace", "s58-refs-inv-div-symbolic", "--size", "3,2", "--method", m,
                              "--jobs", "1", "--no-report", "--format", "json"], capture_output=True, text=True,
                             cwd=str(here.parent), timeout=300)
        recs = json.loads(out.stdout)["results"]
        assert len(recs) == 2 and {r["verdict"] for r in recs} == {"error"}, (m, recs)


# -- 4. state across calls --------------------------------------------------------------------------

_CALLS = [0]


def stateful(s):
    """True on its first call only."""
    _CALLS[0] += 1
    return {"x": s.X.T @ s.X - s.Ir} if _CALLS[0] % 2 else {"x": s.X}


def test_a_claim_that_changes_between_tracings_is_an_error():
    v = verdicts(stateful, methods=METHODS)
    assert set(v.values()) <= {"error", "undecided"}, v


def test_every_method_evaluates_one_graph():
    calls = []

    def counted(s):
        calls.append(1)
        return {"x": s.X.T @ s.X - s.Ir}
    c = _claim(counted)
    assert run_one(c, Size(3, 2), "modular", 0).verdict in PASSING
    traced = len(calls)             # twice with symbolic sizes (compared), never at (3, 2)
    assert traced == 2
    for m in ("exact", "rational", "float", "auto"):
        assert run_one(c, Size(3, 2), m, 0).verdict in PASSING
    assert len(calls) == traced     # then only evaluated, by every method


def test_a_claim_with_a_graph_of_symbolic_sizes_is_never_traced_at_a_number():
    """The trace of such a claim holds no number of a size: not in its state, not in the frames of its
    thread; its graph at (7, 2) is its graph with symbolic sizes.  A claim refused with symbolic sizes (it
    reads int(n)) is traced at (7, 2), with the number."""
    from stiefelsym.ir.graph import Size as GSize
    seen = []

    def introspecting(s):
        t = object.__getattribute__(s, "_t")
        f, local = sys._getframe(), []
        while f is not None:
            local += [v for k, v in f.f_locals.items() if k in ("n", "r")]
            f = f.f_back
        seen.append((t._numbers(GSize(1, "n", None)), t._numbers(GSize(1, "r", None)), tuple(local)))
        return {"x": s.X.T @ s.X - s.Ir}
    g = compile_claim(introspecting, 7, 2, STANDARD)
    assert g.digest() == compile_claim(introspecting, None, None, STANDARD).digest()
    assert len(seen) == 2 and all(x[:2] == (None, None) and 7 not in x[2] and 2 not in x[2] for x in seen), seen

    def reading(s):
        seen.append(int(s.n))
        return {"x": s.X.T @ s.X - s.Ir}
    seen.clear()
    compile_claim(reading, 7, 2, STANDARD)
    assert 7 in seen


# -- 5. a constant outside the float range ----------------------------------------------------------

@pytest.mark.parametrize("q", [Fraction(1, 2**1100), Fraction(2**946), Fraction(2**1100), Fraction(3, 2**1080)],
                         ids=str)
def test_a_constant_outside_the_float_range_never_makes_a_numeric_verdict(q):
    def scaled(s):
        """False: c·tr(XᵀX) = 0 for a constant c ≠ 0."""
        return {"c tr(XtX)": s.const(q) * s.tr(s.X.T @ s.X)}
    v = verdicts(scaled, methods=("float", "auto", "modular", "rational"), free=False)
    assert not [x for x in v.values() if x in PASSING], v


# -- 6. pickling ------------------------------------------------------------------------------------

def test_a_traced_value_holds_no_point():
    def pickles(s):
        """Pickling a matrix once revealed the float point."""
        data = pickle.dumps(s.X)
        return {"x": s.X * len(data)}
    with pytest.raises(TraceRefused, match="pickled"):
        trace(pickles, 3, 2, STANDARD)
    never_passes(pickles, methods=("float", "exact"))


# -- 7. a frame that claims to be the engine --------------------------------------------------------

def spoofed_engine_frame(s):
    """False: a claim that names its module after the engine and reads the private state it finds."""
    g = sys._getframe().f_globals
    old = g["__name__"]
    g["__name__"] = "stiefelsym.methods.fixed_size"
    try:
        raw = getattr(s, "_field", None) or getattr(s.X, "_a", None)
        if raw is not None:
            return {"zero": s.X - s.X}
        return {"X": s.X}
    finally:
        g["__name__"] = old


def test_an_engine_name_buys_nothing():
    never_passes(spoofed_engine_frame)


# -- 8. results files -------------------------------------------------------------------------------

def _run_cli(args, tmp_path):
    from click.testing import CliRunner
    from stiefelsym.cli import main
    return CliRunner().invoke(main, args, catch_exceptions=False)


def test_a_hand_edited_verdict_is_caught_by_check(tmp_path):
    out = tmp_path / "rep"
    r = _run_cli(["verify", "prep", "--size", "3,2", "--method", "modular", "--report-dir", str(out)], tmp_path)
    assert r.exit_code == 0, r.output
    payload = json.loads((out / "results.json").read_text())
    assert all(len(x["digest"]) == 64 for x in payload["results"])
    assert _run_cli(["check", str(out / "results.json")], tmp_path).exit_code == 0
    payload["results"][0]["digest"] = "0" * 64
    (out / "results.json").write_text(json.dumps(payload))
    r = _run_cli(["check", str(out / "results.json")], tmp_path)
    assert r.exit_code == 1 and "REJECTED" in r.output


def test_a_correction_record_is_run_again_as_the_correction(tmp_path):
    """check runs a correction's record again as that correction (its expected verdict and erratum are the
    corrected statement's, not the printed one's): an honest file of an erratum and its correction passes,
    and the correction's record with its verdict or its expectation edited is rejected."""
    out = tmp_path / "rep"
    r = _run_cli(["verify", "manakov-dual-lax", "--size", "3,2", "--size", "4,3", "--report-dir", str(out)], tmp_path)
    assert r.exit_code == 0, r.output
    payload = json.loads((out / "results.json").read_text())
    fixed = [i for i, x in enumerate(payload["results"]) if x["variant"]]
    assert {payload["results"][i]["verdict"] for i in fixed} == {"proved"}, r.output
    assert {x["verdict"] for x in payload["results"] if not x["variant"]} == {"fails"}
    r = _run_cli(["check", str(out / "results.json")], tmp_path)
    assert r.exit_code == 0 and "0 rejected" in r.output, r.output
    for field, value in (("verdict", "checked"), ("expected", False)):
        edited = json.loads(json.dumps(payload))
        edited["results"][fixed[0]][field] = value
        (out / "results.json").write_text(json.dumps(edited))
        r = _run_cli(["check", str(out / "results.json")], tmp_path)
        assert r.exit_code == 1 and "REJECTED manakov-dual-lax" in r.output, (field, r.output)


def test_a_record_left_out_is_caught_by_check(tmp_path):
    """A results file is the whole run of its command: the failing records of a claim dropped (so that the
    file shows only its passing sizes) are missing runs the command planned, with or without reruns."""
    claims = tmp_path / "xxt.py"
    claims.write_text("from stiefelsym import admissible, claim\n\n\n"
                      "@claim('om-xxt', kind='id', sizes=admissible(n_max=3))\n"
                      "def xxt(s):\n    \"\"\"X X^T = I_n (false unless r = n).\"\"\"\n"
                      "    return {'v': s.X @ s.X.T - s.In}\n")
    out = tmp_path / "rep"
    r = _run_cli(["verify", "--claims", str(claims), "--method", "modular", "--report-dir", str(out)], tmp_path)
    payload = json.loads((out / "results.json").read_text())
    assert {x["verdict"] for x in payload["results"]} == {"checked", "fails"}, r.output
    assert _run_cli(["check", str(out / "results.json")], tmp_path).exit_code == 0
    payload["results"] = [x for x in payload["results"] if x["verdict"] != "fails"]
    (out / "results.json").write_text(json.dumps(payload))
    for extra in ([], ["--no-rerun"]):
        r = _run_cli(["check", str(out / "results.json"), *extra], tmp_path)
        assert r.exit_code == 1 and r.output.count("no record of a run its command planned") == 3, r.output
    del payload["meta"]
    (out / "results.json").write_text(json.dumps(payload))
    assert _run_cli(["check", str(out / "results.json")], tmp_path).exit_code == 2


def test_a_record_copied_is_caught_by_check_and_report(tmp_path):
    """Each run once: a copy of a record (which counts its verdict twice in every table) is rejected by check and
    refused by report; a command that asked for exact and auto has two records of auto's exact run, and they pass."""
    out = tmp_path / "rep"
    r = _run_cli(["verify", "left-momentum-map", "--size", "3,1", "--method", "exact", "--method", "auto",
                  "--method", "free", "--report-dir", str(out)], tmp_path)
    assert r.exit_code == 0, r.output
    payload = json.loads((out / "results.json").read_text())
    assert [x["method"] for x in payload["results"]].count("exact") == 2
    assert _run_cli(["check", str(out / "results.json"), "--no-rerun"], tmp_path).exit_code == 0
    exact = next(x for x in payload["results"] if x["method"] == "exact")
    free = next(x for x in payload["results"] if x["method"] == "free")
    for copies in ([exact], [free], [exact, free]):
        edited = dict(payload, results=payload["results"] + copies)
        path = tmp_path / "copied.json"
        path.write_text(json.dumps(edited))
        r = _run_cli(["check", str(path), "--no-rerun"], tmp_path)
        assert r.exit_code == 1 and r.output.count("one record more than") == len(copies), r.output
        r = _run_cli(["report", "--results", str(path), "--report-dir", str(tmp_path / "re")], tmp_path)
        assert r.exit_code == 2 and "one record more than" in r.output, r.output
    single = tmp_path / "single"
    assert _run_cli(["verify", "left-momentum-map", "--size", "3,1", "--method", "exact", "--report-dir",
                     str(single)], tmp_path).exit_code == 0
    payload = json.loads((single / "results.json").read_text())
    payload["results"] *= 2
    (single / "results.json").write_text(json.dumps(payload))
    r = _run_cli(["check", str(single / "results.json"), "--no-rerun"], tmp_path)
    assert r.exit_code == 1 and "one record more than the 1 its command made" in r.output, r.output


def test_a_free_proof_without_a_certificate_is_refused(tmp_path):
    from stiefelsym.certificate_check import main as checker
    forged = {"results": [{"claim": "prep", "method": "free", "verdict": "proved", "certificate_data": None}]}
    path = tmp_path / "forged.json"
    path.write_text(json.dumps(forged))
    assert checker([str(path)]) == 1
    empty = {"results": [{"claim": "prep", "method": "free", "verdict": "proved",
                          "certificate_data": {"format": "stiefelsym-cofactor-1", "letters": {}, "entries": []}}]}
    path.write_text(json.dumps(empty))
    assert checker([str(path)]) == 1


def test_a_certificate_moved_to_another_claim_is_caught(tmp_path):
    from stiefelsym.claims import load_catalog
    from stiefelsym.run.integrity import check_results
    from stiefelsym.run.runner import run_one as run
    cat = load_catalog()
    true = run(cat.get("prep"), None, "free", 0)
    assert true.verdict == "proved"
    rec = json.loads(json.dumps(true.to_json() if hasattr(true, "to_json") else true.__dict__, default=str))
    rec["claim"] = "neumann-lax"
    rec["digest"] = run(cat.get("neumann-lax"), None, "free", 0).digest or rec["digest"]
    lines = []
    assert check_results([rec], cat, echo=lines.append) == 1, lines


def test_the_graph_at_a_size_is_the_graph_of_symbolic_sizes_for_the_catalog_sample():
    """A claim that traces with symbolic sizes is not traced at a size: its graph there is that graph."""
    from stiefelsym.claims import load_catalog
    cat = load_catalog()
    for cid in ("prep", "neumann-lax", "euclidean-flow"):
        c = cat.get(cid)
        z = next(iter(c.sizes))
        free = _compiled_graph(c.func, None, None, STANDARD)
        assert _compiled_graph(c.func, z.n, z.r, STANDARD) is free and free.sizes is None
        assert compile_claim(c.func, z.n, z.r, STANDARD).digest() == free.digest()     # (the public one: a copy)


def test_a_passing_verdict_for_a_claim_that_does_not_trace_is_rejected():
    from stiefelsym.claims import Registry
    from stiefelsym.run.integrity import check_results

    def untraceable(s):
        """Refused at every size: a float constant."""
        return {"x": s.X * 0.5}
    reg = Registry()
    reg.add(_claim(untraceable, cid="untraceable"))
    c = reg.get("untraceable")
    words = {"paper": list(c.paper), "section": c.section, "kind": c.kind, "title": c.title, "statement": c.statement}
    forged = {"claim": "untraceable", "n": 3, "r": 2, "method": "modular", "verdict": "checked", "digest": "", **words}
    lines = []
    assert check_results([forged], reg, echo=lines.append) == 1 and "does not trace" in lines[0]
    # a record without its claim's words is refused before anything else
    assert check_results([dict(forged, statement="X = 0")], reg, echo=lines.append) == 1 and "statement" in lines[-2]
    honest = dict(forged, verdict="error")
    assert check_results([honest], reg, echo=lines.append) == 0


def test_a_hand_edited_verdict_with_the_right_digest_is_caught(tmp_path):
    """The digest binds a record to its graph, not to its verdict: check runs the record again."""
    out = tmp_path / "rep"
    assert _run_cli(["verify", "manakov-dual-lax", "--size", "3,1", "--method", "modular",
                     "--report-dir", str(out)], tmp_path).exit_code in (0, 1)
    payload = json.loads((out / "results.json").read_text())
    rec = next(x for x in payload["results"] if x["verdict"] == "fails")
    rec["verdict"] = "checked"
    (out / "results.json").write_text(json.dumps(payload))
    r = _run_cli(["check", str(out / "results.json")], tmp_path)
    assert r.exit_code == 1 and "a run again says 'fails'" in r.output


def int_size_block(s):
    """X − X + 0 with the zero block written 3 x 2: a graph at n = 3 only (with symbolic sizes the int 3
    cannot be told from n)."""
    return {"r": s.X - s.X + s.zeros(3, 2)}


def test_a_graph_of_symbolic_sizes_is_typed_at_each_size_without_running_the_claim():
    """The graph at (n, r) of a claim with a graph of symbolic sizes is that graph replayed at (n, r) by the
    tracer: a block written 3 x 2 types at (3,2) and is refused at (4,2), where no method evaluates it, and
    the dimension-free method proves nothing for a claim stated at (4,2) too."""
    assert _compiled_graph(int_size_block, 3, 2, STANDARD) is _compiled_graph(int_size_block, None, None, STANDARD)
    with pytest.raises(TraceRefused, match=r"does not type at \(4,2\)"):
        compile_claim(int_size_block, 4, 2, STANDARD)
    c = _claim(int_size_block, sizes=admissible(n_max=4, n_min=3, r_min=2, r_max=2))
    assert run_one(c, Size(4, 2), "exact", 0).verdict == "error"
    assert run_one(c, Size(3, 2), "exact", 0).verdict == "proved"
    assert run_one(c, None, "free", 0).verdict not in PASSING      # (the free scene refuses a 3 x 2 block)
    from stiefelsym.methods.dimension_free import typed_at_stated_sizes    # and the proof's own check of the stated sizes
    assert "not a graph at (4,2)" in typed_at_stated_sizes(c, int_size_block)
    assert typed_at_stated_sizes(_claim(int_size_block, sizes=admissible(n_max=3, n_min=3, r_min=2, r_max=2)),
                                 int_size_block) == ""


# -- claim code that changes a graph after the tracer checked it (stop 59) ----------------------------------

def _in_process(name: str):
    from pathlib import Path
    from stiefelsym.claims import load_claims_file
    return load_claims_file(str(Path(__file__).resolve().parent / "adversary" / "s59" / name))


@pytest.mark.parametrize("cid", ["s59-rewrite-divisor", "s59-rewrite-divisor-symbolic"])
def test_a_claim_that_rewrites_its_graph_after_a_trace_time_check_gets_error_under_every_method(cid):
    """The second statement's function, traced after the first statement's checks, points the first inverse's
    division by 2 at tr(PᵀP) in the graph being traced (s._t.g).  Loaded in-process, exact said proved, rational
    checked and float numeric of this false statement (not invertible at P = 0).  Every graph is now replayed by
    the tracer once the claim's code has run (the type-checking pass of ``ir._compile``), and the replay makes
    the division again, with its check."""
    reg = _in_process("rewrite_after_check.py")
    for m in ("exact", "rational", "modular", "float", "ball", "auto"):
        res = run_one(reg.get(cid), Size(3, 2), m, 0)
        assert res.verdict == "error", (cid, m, res.verdict, res.message)
        assert "when the tracer replays it" in res.message


def test_a_claim_cannot_change_the_literals_of_another_claims_compiled_graph():
    """A Fraction the claim handed to the tracer, and a size expression the tracer shares between graphs, were
    held by the compiled graph itself: another claim's code, run later in the same process, changed them
    (``ONE._numerator = 2``), and the false X·1 − 2X = 0 was proved, checked and numeric from the cached graph.
    The graph a method evaluates is now a copy through pickle of the replay: no object of it was ever handed
    to claim code."""
    reg = _in_process("shared_literals.py")
    for cid in ("s59-shared-fraction", "s59-shared-size"):
        assert run_one(reg.get(cid), Size(3, 2), "exact", 0).verdict == "fails"
    assert run_one(reg.get("s59-changer"), Size(3, 2), "exact", 0).verdict == "proved"
    for cid in ("s59-shared-fraction", "s59-shared-size"):
        for m in ("exact", "rational", "modular", "float"):
            res = run_one(reg.get(cid), Size(3, 2), m, 0)
            assert res.verdict == "fails", (cid, m, res.verdict, res.message)


def _statements_claim(order, early):
    from stiefelsym import Count, Inverse, Rank, RightInverse

    def kinds(s):
        return {"rank": lambda: Rank(s.mat([[s.tr(s.X.T @ s.P), 1], [0, 1]]), 2, generic=True),
                "count": lambda: Count(3, 3),
                "list": lambda: [s.X - s.X, s.P.T @ s.X + s.X.T @ s.P],
                "tuple": lambda: (s.X.T @ s.X - s.identity(s.r),),
                "const": lambda: 0,
                "inv": lambda: Inverse(lambda t, x: 2 * x, lambda t, y: y / 2, on="Sym(r)"),
                "rinv": lambda: RightInverse(lambda t, x: x + x.T, lambda t, y: y / 2, on=("R^{r×r}",), to=("Sym(r)",)),
                "nested": lambda: [[s.X - s.X], (s.P - s.P,)]}

    def func(s):
        ks = kinds(s)
        made = {k: ks[k]() for k in order} if early else {}
        return {f"{k}{i}": made[k] if early else ks[k]() for i, k in enumerate(order)}
    return func


@pytest.mark.parametrize("seed", range(12))
def test_the_replay_makes_the_claims_statements_in_the_graphs_order(seed):
    """The type-checking replay makes the values of the claim's dict (Rank, Count, lists, constants) where the
    graph has them: a Rank before an inverse statement replayed to another graph (an honest claim got `error`,
    stop 59).  Random orders of statements, made before the dict or in it, replay to the same digest; a graph
    whose order is changed does not."""
    import random
    from stiefelsym.ir.replay import GraphClaim
    rng = random.Random(seed)
    names = ["rank", "count", "list", "tuple", "const", "inv", "rinv", "nested"]
    order = rng.sample(names, rng.randint(2, len(names)))
    func = _statements_claim(order, rng.random() < 0.5)
    for z in ((None, None), (3, 2)):
        g = trace(func, *z, STANDARD)
        assert not g.refusals
        assert trace(GraphClaim(g), *z, STANDARD).digest() == g.digest(), (order, z)
    # negative control: the same values in another order are another graph
    other = _statements_claim(list(reversed(order)), False)
    assert trace(other, 3, 2, STANDARD).digest() != trace(func, 3, 2, STANDARD).digest()
