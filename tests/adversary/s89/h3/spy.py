# ruff: noqa: E402
"""Run the CLI with a spy on _trace_words (prints the words found per graph to stderr)."""
import sys
import stiefelsym.ir.evaluate as e
orig = e._trace_words
def spy(g, deps, taken):
    out = orig(g, deps, taken)
    for i, (s, words, atoms, tree) in out.items():
        print("WORDS", i, [(c, w) for c, w in words], "tree", tree, file=sys.stderr)
    return out
e._trace_words = spy
from stiefelsym.cli import main
sys.exit(main())
