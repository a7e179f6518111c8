"""I1: a claim of stiefelsym.load(files=F) verified at a size outside its file's metadata tables (n > 16): the new
check of traced sizes looks at graphs only.  fails_at: an `error` record; a where= condition: NoGraph naming "the
command" and no fix."""
import stiefelsym
c = stiefelsym.load(files="c4/f4_failsat.py").get("h2-fa")
print("fails_at, (17,1):", [(r.verdict, r.expected, r.message[:150]) for r in
                            stiefelsym.verify(c, sizes=[(17, 1)], methods=["modular"])])
c = stiefelsym.load(files="c4/f4_failsat.py", sizes=[(17, 2)]).get("h2-fa")
print("fails_at, loaded at (17,2), run at (17,1):", [(r.verdict, r.expected) for r in
                                                     stiefelsym.verify(c, sizes=[(17, 1)], methods=["modular"])])
w = stiefelsym.load(files="c3/f3_door.py").get("h2-where")
try:
    stiefelsym.verify(w, sizes=[(17, 2)], methods=["modular"])
except ValueError as e:
    print("where, (17,2):", type(e).__name__, e)
d = stiefelsym.load(files="c8/f8_door_where.py").get("h2-door-where")
try:
    stiefelsym.verify(d, sizes=[(17, 2)], methods=["modular"])
except ValueError as e:
    print("sized claim with where, (17,2):", type(e).__name__, e)
