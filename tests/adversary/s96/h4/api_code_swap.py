"""Stop 96, h4: a claim of ``stiefelsym.load(files=...)`` (traced in a child process: its function is a
TracedFunction whose graph is data), its ``__code__`` attribute set to a false statement's: the graph verified is
still the file's (true), so `proved` is the right verdict of what is verified (compare api_inprocess_swap.py)."""
import stiefelsym
from stiefelsym.methods import fixed_size as fs


def false_body(s):
    return {"r": s.X.T @ s.P}


def main():
    claims = stiefelsym.load(files=[__file__.replace("api_code_swap.py", "c3_swap_target.py")], catalog=False)
    target = next(x for x in claims if x.id == "h4s-swap")
    out = []
    for step in ("before", "after"):
        if step == "after":
            target.func.__code__ = false_body.__code__
        out.append((step, type(target.func).__name__, fs.run_exact(target, 3, 2, 0).verdict,
                    [r.verdict for r in stiefelsym.verify([target], sizes=[(3, 2)], methods=["exact"], jobs=1)]))
    print(out)
    return out


if __name__ == "__main__":
    main()
