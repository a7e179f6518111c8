# ruff: noqa: E702, E731, E741
"""Compare every verdict in logs/*.json with the truth (truth_numpy_output.txt; tricks by hand)."""
import glob
import json
import collections
truth = {}
lines = open('/tmp/s88h1/out/truth_numpy_output.txt').read().splitlines()
hdr = lines[0].split()[1:]
sizes0 = sizes = [tuple(map(int, h.split(','))) for h in hdr]
for ln in lines[1:]:
    if ln.startswith('(') or not ln.strip():
        continue
    if ln.startswith('claims2'):
        sizes = [tuple(map(int, h.split(','))) for h in ln.split()[1:]]
        continue
    parts = [p[0] if p[0] in '0X' and '(' in p else p for p in ln.split()]
    name, marks = parts[0], parts[1:]
    tv = {sz: (m == '0') for sz, m in zip(sizes, marks)}
    if name.startswith('potential-constant'):
        truth['s88h1-potential-constant'] = {k: v for k, v in tv.items() if k[0] == k[1]}
        truth['s88h1-potential-constant-twin'] = {k: v for k, v in tv.items() if k[0] == k[1] + 1}
    else:
        truth['s88h1-' + name] = tv
# tricks: truth by hand, a function of (n, r)
H = {
 's88h1k-slice-trap': lambda n, r: False,
 's88h1k-tiny-constant': lambda n, r: n == 1,
 's88h1k-huge-cancel': lambda n, r: False,
 's88h1k-huge-cancel-true': lambda n, r: True,
 's88h1k-bool-constant': lambda n, r: True,
 's88h1k-caught-refusal': lambda n, r: False,
 's88h1k-state-flip': lambda n, r: False,
 's88h1k-name-lam': lambda n, r: False,
 's88h1k-name-kappa-flow': lambda n, r: False,
 's88h1k-same-name-kinds': lambda n, r: False,
 's88h1k-fresh-twice': lambda n, r: False,
 's88h1k-pickle': lambda n, r: False,
 's88h1k-deepcopy': lambda n, r: False,
 's88h1k-rank-p': lambda n, r: not (r == n and n % 2 == 1),
 's88h1k-rank-p-everywhere': lambda n, r: False,
 's88h1k-d-before-rewrite': lambda n, r: False,
 's88h1k-d-before-rewrite-true': lambda n, r: True,
 's88h1k-canonical-constraints': lambda n, r: False,
 's88h1k-canonical-constraints-true': lambda n, r: True,
 's88h1k-closed-over-point': lambda n, r: r == n,
 'prep': lambda n, r: r == n or n == 1,
 's88h1k-resolvent-sign': lambda n, r: False,
 's88h1k-rank-mutated': lambda n, r: False,
 's88h1k-dict-subclass': lambda n, r: False,
 's88h1k-key-collision': lambda n, r: False,
 's88h1k-same-name-same-kind': lambda n, r: True,
 's88h1k-same-name-gen-sym': lambda n, r: False,
 's88h1k-same-name-sym-transpose': lambda n, r: True,
 's88h1k-same-name-skew-vs-gen': lambda n, r: r == 1,
 's88h1k-same-name-shapes': lambda n, r: False,
 's88h1k-names-text-nonzero-proved': lambda n, r: True,
 's88h1k-names-sym-skew': lambda n, r: False,
 's88h1k-names-scalar-vs-generic': lambda n, r: False,
 's88h1k-order-sym-then-gen': lambda n, r: r == 1,
 's88h1k-across-a': lambda n, r: True,
 's88h1k-across-b': lambda n, r: r == 1,
 's88h1k-order-skew-then-gen-text': lambda n, r: r == 1,
 's88h1k-name-kappa-text': lambda n, r: False,
 's88h1k-name-greek-kappa': lambda n, r: False,
 's88h1k-name-phi-generic': lambda n, r: n == 1,
 's88h1k-name-psi-greek': lambda n, r: False,
 's88h1k-name-lam-text': lambda n, r: False,
 's88h1-dirac-jacobi': lambda n, r: True,
 's88h1-dirac-jacobi-twin': lambda n, r: n == 1,
 's88h1-dirac-leibniz': lambda n, r: True,
 's88h1-dirac-leibniz-twin': lambda n, r: n == 1,
 's88h1-dirac-restriction': lambda n, r: True,
 's88h1-dirac-restriction-twin': lambda n, r: False,
}
H.update(getattr(__import__('builtins'), 'EXTRA_TRUTH', {}))
try:
    from truth_extra import EXTRA
    H.update(EXTRA)
except ImportError:
    pass
POS = {'proved', 'checked', 'numeric'}
cnt = collections.Counter(); wrong = []; neutral = collections.Counter(); nrec = 0
for f in sorted(glob.glob('/tmp/s88h1/out/logs/*.json')):
    try:
        d = json.load(open(f))
    except Exception as e:
        print('unreadable', f, e); continue
    for rec in d['results']:
        nrec += 1
        c, n, r, m, v = rec['claim'], rec['n'], rec['r'], rec['method'], rec['verdict']
        if c in truth:
            t = truth[c].get((n, r)) if isinstance(n, int) else all(truth[c].values())
        elif c in H:
            t = H[c](n, r) if isinstance(n, int) else all(H[c](a, b) for a, b in sizes0)
        else:
            t = None
        if t is None:
            cnt['no truth'] += 1; continue
        if v in POS and not t or v == 'fails' and t:
            wrong.append((f.split('/')[-1], c, n, r, m, v, t, rec.get('message', '')[:200]))
        elif v in POS or v == 'fails':
            cnt['right'] += 1
        else:
            neutral[(c, m, v)] += 1
print('records', nrec, dict(cnt))
print('WRONG:', len(wrong))
for w in wrong:
    print('  ', w)
print('neutral (undecided/inconclusive/error/skipped):')
for k, v in sorted(neutral.items()):
    print('  ', k, v)
