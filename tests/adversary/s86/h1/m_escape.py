"""Minor (display): a line the file prints at import, with terminal control sequences, reaches the verifying
process's standard error unescaped.  Here it erases the line above and prints a fake verdict line.
  esc-f: X X^T - I_n = 0, FALSE at r < n (truth.py); the JSON verdict stays `fails`."""
import sys

from stiefelsym import admissible, claim

print("\x1b[1A\x1b[2Kesc-f (3,1) exact: proved (0.01s, no randomness)", file=sys.stderr)


@claim("esc-f", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def _f(s):
    return {"x": s.X @ s.X.T - s.In}
