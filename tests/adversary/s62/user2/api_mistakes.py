"""Bad input through the Python API: each should raise KeyError/ValueError with a clear message."""
import stiefelsym

HERE = __file__.rsplit("/", 1)[0]
cases = {
    "unknown method": dict(files=f"{HERE}/claims.py", methods="symbolic"),
    "r > n": dict(claims="u2-flow", files=f"{HERE}/claims.py", sizes=[(2, 3)]),
    "unknown claim": dict(claims="u2-nope", files=f"{HERE}/claims.py"),
    "missing file": dict(files=f"{HERE}/nope.py"),
    "size as string": dict(claims="u2-flow", files=f"{HERE}/claims.py", sizes=["4,2"]),
    "huge size": dict(claims="u2-flow", files=f"{HERE}/claims.py", sizes=[(100000, 2)], methods="modular"),
    "ball method (not in API table)": dict(claims="u2-flow", files=f"{HERE}/claims.py", sizes=[(3, 2)], methods="ball"),
}
for name, kw in cases.items():
    try:
        res = stiefelsym.verify(**kw)
        print(f"{name}: returned ok={res.ok} verdicts={[r.verdict for r in res][:4]}")
    except Exception as e:
        print(f"{name}: {type(e).__name__}: {str(e)[:300]}")
