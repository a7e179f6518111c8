import stiefelsym
res = stiefelsym.verify(files="claims.py", sizes=[(4, 2)], methods=["modular", "exact"], timeout=120)
print("ok:", res.ok, len(res))
for r in res:
    print(r.claim, r.n, r.r, r.method, r.verdict, r.expected)
neg = stiefelsym.verify("n63-manakov-cubic-lax", files="negatives.py", sizes=["4,2"], methods="modular", timeout=120)
print(neg.ok, neg[0].verdict, neg[0].rerun)
print(repr(neg[0].residual_sympy()))
for bad in [dict(claims="nope", files="claims.py"), dict(files="claims.py", sizes=[(2, 3)]),
            dict(files="claims.py", methods="magic"), dict(files="missing.py"),
            dict(claims="u63-r-equals-n", files="claims.py", sizes=[(4, 2)]), dict(files="claims.py", sizes=[(0, 0)])]:
    try:
        stiefelsym.verify(**bad, timeout=120)
        print("NO ERROR for", bad)
    except Exception as e:
        print(type(e).__name__, ":", str(e)[:200])
