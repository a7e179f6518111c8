"""Stop 64: the review's files (tests/adversary/s64/review) and the user trial's statements (s64/user).  See
tests/adversary/README.md, Stop 64."""
import json
import subprocess
import sys

import pytest

from adversary_cli import cli, HERE, ROOT

USER = HERE / "s64" / "user"
REVIEW = HERE / "s64" / "review"


def _results(*args, cwd=ROOT):
    run = cli("verify", *args, "--no-report", "--format", "json", "--timeout", "60", "--jobs", "2", cwd=cwd)
    assert run.returncode in (0, 1), run.stderr[-2000:]
    return json.loads(run.stdout)["results"]


# -- a claim's words in the reports ------------------------------------------------------------------------------

def test_a_docstring_cannot_rewrite_its_verdict_or_read_a_file_into_the_latex_report(tmp_path):
    """The review's docstring redefined \\textit inside $...$ so that the PDF said "verified ... by modular" for a
    failing claim, and a statement with \\input{/etc/hostname} read a local file into the report of whoever compiled
    it: both passed the deny-list of math_ok.  A formula of a claim may now use the vocabulary of mathematics only
    (latex.MATH_COMMANDS); anything else is set as plain text.  The failing claims of a claims file that cite a
    label of the paper are a note, not a note for the paper's authors."""
    out = tmp_path / "rep"
    run = cli("verify", "--claims", str(REVIEW / "tex_verdict.py"), "--claims", str(REVIEW / "tex_inject.py"),
              "--method", "modular", "--jobs", "1", "--report-dir", str(out))
    assert run.returncode == 1, run.stderr[-2000:]      # two false statements, expected to hold
    verdicts = {r["claim"]: r["verdict"] for r in json.loads((out / "results.json").read_text())["results"]}
    assert verdicts == {"r64-tex-verdict": "fails", "r64-tex-false": "fails", "r64-tex-true": "checked"}
    for name in ("verification.tex", "verification-runs.tex"):
        tex = (out / name).read_text()
        for words in ("\\global\\let\\origit", "\\gdef\\textit", "\\input{/etc/hostname}"):
            assert words not in tex, (name, words)
        assert "\\textbackslash{}input" in tex and "\\textbackslash{}gdef" in tex
    md = (out / "verification.md").read_text()
    assert "Note for the authors" not in md and "Note for the authors" not in (out / "verification.tex").read_text()


@pytest.mark.parametrize("tex", [
    r"\global\let\origit\textit", r"\gdef\textit#1{x}", r"X \input{/etc/hostname}", r"\def\x{1}", r"\catcode`\@=11",
    r"^^5cinput{/etc/passwd}", r"x % the rest of the line", r"\csname textit\endcsname", r"\write18{ls}",
    r"\begin{verbatim}x\end{verbatim}", r"\end{document}", "x\x00y", "x\x1b[31m", r"\renewcommand{\tr}{det}",
    r"\text{\input{/etc/hostname}}", r"\mathscr{X}", r"\immediate\openout1=x",
])
def test_math_outside_the_vocabulary_is_plain_text(tex):
    from stiefelsym.latex import math_ok, tex_balanced, tex_display, tex_text
    assert not math_ok(tex) and not tex_balanced(tex)
    for rendered in (tex_text(f"a ${tex}$ b"), tex_display(tex)):
        assert not any(f"\\{c}" in rendered.replace("\\textbackslash{}", "")
                       for c in ("global", "gdef", "input", "def", "catcode", "csname", "write", "openout"))
        assert "^^" not in rendered and "\x00" not in rendered and "\x1b" not in rendered


@pytest.mark.parametrize("tex", [
    r"\dot X = P - \tfrac{1}{2}(1 + 2\kappa) X P^T X", r"\frac{d}{dt} L(\lambda) = [L(\lambda), M(\lambda)]",
    r"\operatorname{rank} \begin{pmatrix} a & b \\ c & d \end{pmatrix} = 2", r"\left\langle \Phi, \Phi \right\rangle",
    r"\{ x \in \mathbb{R}^n \mid \|x\| = 1 \}", r"\tr (X^T A X) \ne 0,\quad \det \ddim V = \Span\{e_1\}",
    r"x^2_1 + {x^2}^3 + \frac12 + \sqrt[3]{x} + e^{i\theta} + \mathbb R^n + \left\{ x \right.",
])
def test_the_vocabulary_of_mathematics_is_typeset(tex):
    from stiefelsym.latex import math_ok
    assert math_ok(tex)


def test_control_characters_are_named_in_latex_text():
    from stiefelsym.latex import tex_escape
    assert tex_escape("a\x00b\x1bc\td") == r"a\texttt{[U+0000]}b\texttt{[U+001B]}c d"


# -- malformed input ---------------------------------------------------------------------------------------------

def test_a_malformed_record_is_refused_by_tables_in_one_line(tmp_path):
    """`tables --results` with a record whose verdict is a list was a TypeError traceback (exit 1): the file is read
    with the same record check as report and check."""
    path = tmp_path / "results.json"
    path.write_text(json.dumps({"meta": {}, "results": [{"claim": "prep", "n": 2, "r": 1, "method": "modular",
                                                          "verdict": ["proved"]}]}))
    run = cli("tables", "--size", "2,1", "--results", str(path))
    assert run.returncode == 2 and "record 1 is malformed: verdict is a list" in run.stderr, run.stderr[-2000:]
    assert "Traceback" not in run.stderr


def test_free_says_error_for_a_claim_refused_at_every_size(tmp_path):
    """An ill-formed claim (a float constant, a misspelt scene name, a list of residuals) was `undecided` under free,
    which is always as expected: a CI job running free alone was green.  Refused with symbolic sizes and at a fixed
    size too, it is an `error` (exit 1); a claim that needs coordinates stays `undecided`."""
    claims = tmp_path / "mistakes.py"
    claims.write_text(
        "from stiefelsym import admissible, claim\n\n\n"
        "@claim('m64-float', kind='id', sizes=admissible(n_max=3))\n"
        "def f(s):\n    \"\"\"A float.\"\"\"\n    return {'r': 0.5 * (s.X.T @ s.X - s.Ir)}\n\n\n"
        "@claim('m64-name', kind='id', sizes=admissible(n_max=3))\n"
        "def g(s):\n    \"\"\"A misspelt letter.\"\"\"\n    return {'r': s.phi}\n\n\n"
        "@claim('m64-entry', kind='id', sizes=admissible(n_max=3))\n"
        "def h(s):\n    \"\"\"An entry (true: a column of X has norm 1).\"\"\"\n"
        "    return {'r': (s.X.T @ s.X)[0, 0] - 1}\n")
    run = cli("verify", "--claims", str(claims), "--method", "free", "--no-report")
    assert run.returncode == 1, run.stdout + run.stderr
    from adversary_cli import parse
    assert parse(run.stdout) == {"m64-float": "error", "m64-name": "error", "m64-entry": "undecided"}, run.stdout


def test_check_names_a_claims_file_given_relative_to_another_directory(tmp_path):
    """check and report from another directory than the run's said only "claims file not found" (user trials)."""
    out = tmp_path / "rep"
    run = cli("verify", "u64-prep-kappa", "--claims", "tests/adversary/s64/user/claims.py", "--size", "3,2",
              "--method", "modular", "--report-dir", str(out))
    assert run.returncode == 0, run.stderr[-2000:]
    run = cli("check", "--no-rerun", str(out / "results.json"), cwd=tmp_path)
    assert run.returncode == 2 and "relative to the directory the run was made in" in run.stderr, run.stderr
    run = cli("check", "--no-rerun", str(out / "results.json"), "--claims", str(USER / "claims.py"), cwd=tmp_path)
    assert run.returncode == 0 and "0 rejected" in run.stdout, run.stdout + run.stderr
    run = cli("report", "--results", str(out / "results.json"), "--report-dir", str(tmp_path / "re"), cwd=tmp_path)
    assert run.returncode == 2 and "relative to the directory the run was made in" in run.stderr, run.stderr
    run = cli("report", "--results", str(out / "results.json"), "--report-dir", str(tmp_path / "re"),
              "--claims", str(USER / "claims.py"), cwd=tmp_path)
    assert run.returncode == 0, run.stderr


# -- the user trial ----------------------------------------------------------------------------------------------

def test_the_python_api_verifies_claims_that_name_engine_steps():
    """From Python, after a plain `import stiefelsym`, every claim of a file that uses stiefelsym.twisted or
    stiefelsym.systems was `error` (NoGraph) and free `undecided` (an engine object not registered): the steps are
    registered by their modules, which the caller had not imported (the command line imports them all)."""
    code = ("import json, stiefelsym\n"
            f"rs = stiefelsym.verify(['u64-gras-r2', 'u64-psi0-flows-coincide', 'u64-double-gl-momentum'], "
            f"files={str(USER / 'claims.py')!r}, sizes=['3,2'], methods=['modular', 'free'])\n"
            "print(json.dumps([(r.claim, r.method, r.verdict) for r in rs]))\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert run.returncode == 0, run.stderr[-2000:]
    verdicts = json.loads(run.stdout.splitlines()[-1])
    assert {v for _, m, v in verdicts if m == "modular"} == {"checked"}, verdicts
    assert {v for _, m, v in verdicts if m == "free"} == {"proved"}, verdicts


def test_the_user_trials_statements_hold_and_their_twins_fail():
    """Twelve statements of §5, §7 and Appendices 1 and 2 written by a user (the Neumann flow and its Lax pair in
    μ = 1/λ, conserved energies and traces, the Grassmannian reduction at r = 2, the sphere at n = 3, the magnetic
    Lax pair and Ψ₁₂, the double and coupled systems' momenta), each with a false twin (numpy: s64/user/indep.py):
    under modular at (3,2) and (4,2), where each is stated."""
    sizes = ("--size", "3,2", "--size", "4,2", "--method", "modular")
    held = _results("--claims", str(USER / "claims.py"), *sizes)
    assert held and all(r["verdict"] in ("proved", "checked") for r in held), \
        [(r["claim"], r["n"], r["r"], r["verdict"]) for r in held if r["verdict"] not in ("proved", "checked")]
    twins = _results("--claims", str(USER / "negatives.py"), *sizes)
    assert twins
    for r in twins:
        expected = ("proved", "checked") if r["kind"] == "not" else ("fails",)
        assert r["verdict"] in expected, (r["claim"], r["n"], r["r"], r["verdict"], r["message"])


def test_a_docstring_makes_no_table_or_heading_of_the_markdown_report(tmp_path):
    """The review's multi-line docstring held a verdict table (`checked`) that verification.md printed as a table
    under the claim's title: a claim's title (and a statement that is not math) is now one paragraph of text."""
    out = tmp_path / "rep"
    run = cli("verify", "--claims", str(REVIEW / "md_inject.py"), "--method", "modular", "--jobs", "1",
              "--report-dir", str(out))
    assert run.returncode == 1, run.stderr[-2000:]
    md = (out / "verification.md").read_text()
    forged = "| (3,2) | modular | checked | – | 2 independent points | 0 | 1.7e-36 |"
    assert forged in md and not any(line.strip() == forged for line in md.splitlines())
    from stiefelsym.reports.report import _md_paragraph
    assert _md_paragraph("# a heading\n\nand more") == r"\# a heading and more"
    assert _md_paragraph("1. a list") == r"\1. a list"


# -- the second review (s64/review2) -----------------------------------------------------------------------------

REVIEW2 = HERE / "s64" / "review2"


def test_a_paper_label_cannot_open_an_html_comment_in_the_markdown_report():
    """The second review's label "x$\\n<!--$" kept its newline and "<" in a math segment: a line of verification.md
    began an HTML comment that a true claim's multi-line statement closed, with a forged `checked` table between.  A
    label, a section, a check name and a correction's description are one line of text; a claims file with another
    is refused when it is loaded."""
    run = cli("verify", "--claims", str(REVIEW2 / "md_forge.py"), "--method", "modular", "--no-report")
    assert run.returncode == 2 and "paper label" in run.stderr and "Traceback" not in run.stderr, run.stderr
    from stiefelsym.claims import Claim, SizeSpec  # noqa: F401
    from stiefelsym import admissible, claim
    for kw, words in ((dict(section="3\n| x |"), "section"), (dict(section="3", paper="a$b"), "paper label")):
        with pytest.raises(ValueError, match=words):
            claim("q64-bad", kind="id", sizes=admissible(n_max=2), **kw)(lambda s: {"r": s.X})


def test_a_check_name_of_two_lines_is_refused_under_every_method():
    from stiefelsym.claims import Claim
    from stiefelsym.claims import Size
    from stiefelsym import admissible
    from stiefelsym.run.runner import run_one

    def two_lines(s):
        return {"XtX\n| (3,2) | modular | checked |": s.X.T @ s.X - s.Ir}
    c = Claim(id="q64-name", paper=(), kind="id", section="", func=two_lines, sizes=admissible(n_max=3),
              statement="", title="")
    for method in ("exact", "modular", "free"):
        res = run_one(c, None if method == "free" else Size(3, 2), method, seed=0)
        assert res.verdict == "error" and "check name" in res.message, res.line()


@pytest.mark.parametrize("tex", [
    r"\begin {matrix} a", "{" * 300 + "x" + "}" * 300, "a\n\nb", r"\left( x", r"x \right)",
    r"\begin{matrix} a \end {pmatrix}", r"a^b^c", r"x_1_2", r"\frac", r"\frac{1}", r"a^\frac{1}{2}", r"a_",
    r"\sqrt", r"\left", r"\mathbb",
])
def test_a_formula_that_would_hang_or_stop_pdflatex_is_plain_text(tex):
    """An environment opened as \\begin {matrix} (a space) was not counted, and pdflatex looped; 300 nested braces
    exceeded TeX's 255 groups (no PDF); a blank line, an unpaired \\left, a second superscript of one nucleus or a
    command without its arguments is an error in math mode."""
    from stiefelsym.latex import math_ok
    assert not math_ok(tex)


def test_markdown_math_shows_no_html():
    from stiefelsym.reports.report import _md_escape
    out = _md_escape("a $x <!-- y\n--> z$ b")
    assert "<" not in out and ">" not in out and "\n" not in out and r"\lt" in out


# -- the second user trial (s64/user2) ---------------------------------------------------------------------------

def test_the_second_user_trials_statements_hold_and_their_twins_fail():
    """Thirteen statements of §2, §4, §6 and §8 written through the Python API (momentum maps, Noether and Manakov
    integrals, Λ₁, Λ₂ and the leaf's dimension, Perelomov's integrals in involution, the dual Lax pair) and their
    false twins (numpy: s64/user2/indep.py), under modular at (4,2): a rank said too large is inconclusive (a
    refutation needs a kernel), never a pass."""
    held = _results("--claims", str(HERE / "s64" / "user2" / "claims.py"), "--size", "4,2", "--method", "modular")
    assert held and all(r["verdict"] in ("proved", "checked") for r in held), \
        [(r["claim"], r["verdict"], r["message"][:200]) for r in held if r["verdict"] not in ("proved", "checked")]
    twins = _results("--claims", str(HERE / "s64" / "user2" / "negatives.py"), "--size", "4,2", "--method", "modular")
    assert twins
    for r in twins:
        if r["kind"] == "dim":
            assert r["verdict"] in ("fails", "inconclusive"), (r["claim"], r["verdict"])
        else:
            assert r["verdict"] == "fails", (r["claim"], r["verdict"], r["message"][:200])


@pytest.mark.slow
def test_a_rank_said_too_large_is_refuted_by_the_function_field_rank():
    """Three user trials (s63, s64, s64 #2) wrote a rank one too large and got `inconclusive` under every method: the
    rank at exact points was below the printed one, and the function-field rank, the only certain refutation
    without kernel vectors, was stopped after 5 s.  Where a point's rank is below the printed one, it now gets 60 s
    (fixed_size.REFUTING_RANK_SECONDS): the rank r(n − r) + 1 of ξ ↦ [ξ, XXᵀ] at (4,2) fails, and the true rank
    r(n − r) still passes."""
    false = _results("n63-l1-rank", "--claims", str(HERE / "s63" / "user" / "negatives.py"), "--size", "4,2",
                     "--method", "exact")
    assert [r["verdict"] for r in false] == ["fails"] and "rank over the function field" in false[0]["certificate"]
    true = _results("u63-l1-rank", "--claims", str(HERE / "s63" / "user" / "claims.py"), "--size", "4,2",
                    "--method", "exact")
    assert [r["verdict"] for r in true] in (["proved"], ["checked"]), true      # (its upper bound: 5 s, then points)


def test_a_results_file_whose_run_words_are_not_one_line_is_refused(tmp_path):
    """The second review edited a results file's meta (versions, title, platform, sections) with line breaks, and
    `report` printed a forged table from them: the words a report prints of its run are one line each, as verify
    writes them; `report` and `check` refuse a file with others (exit 2)."""
    out = tmp_path / "rep"
    assert cli("verify", "prep", "--size", "3,2", "--method", "modular", "--report-dir", str(out)).returncode == 0
    payload = json.loads((out / "results.json").read_text())
    for key, value in (("versions", {"sympy": "1\n\n| prep | checked |"}), ("title", "T\n# forged"),
                       ("platform", "x\x1b[2J"), ("sections", {"2": "a\nb"})):
        edited = json.loads(json.dumps(payload))
        edited["meta"][key] = value
        path = tmp_path / "edited.json"
        path.write_text(json.dumps(edited))
        run = cli("report", "--results", str(path), "--report-dir", str(tmp_path / "re"))
        assert run.returncode == 2 and f"meta {key}" in run.stderr, (key, run.stderr)
        run = cli("check", "--no-rerun", str(path))
        assert run.returncode == 2 and f"meta {key}" in run.stderr, (key, run.stderr)


def test_the_reuse_of_a_product_of_transposes_passes_no_false_statement():
    """The stop's own attempt (s64/own_transposes.py) on the exact method's a b = (bᵀ aᵀ)ᵀ: statements comparing a
    product with the product of the transposes (XᵀP = PᵀX, YᵀQ = QᵀY, XᵀAP = PᵀAX) fail at r = 2 and hold at r = 1
    (1 x 1 matrices), their true companions (XᵀP = −PᵀX, (XᵀAP)ᵀ = PᵀAX) are proved."""
    got = {(r["claim"], r["r"]): r["verdict"] for r in _results(
        "--claims", str(HERE / "s64" / "own_transposes.py"), "--size", "3,2", "--size", "4,1", "--method", "exact")}
    for cid in ("o64-xp-symmetric", "o64-yq-symmetric", "o64-xap-swapped"):
        assert got[(cid, 2)] == "fails" and got[(cid, 1)] == "proved", (cid, got)
    for cid in ("o64-xp-skew", "o64-xap-transpose"):
        assert got[(cid, 2)] == got[(cid, 1)] == "proved", (cid, got)
