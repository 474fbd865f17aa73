#!/usr/bin/env python3
"""Given-first against numbers-first (LANGUAGE.md §7): python3 given_run.py SEED NSCRIPTS [ITEMS],
MODE=all|partly|subs, CHASLES=binary. Mismatches as JSON lines; summarise with given_summary.py."""
import json, os, subprocess, sys, math
import given_gen as gen

seed, n = int(sys.argv[1]), int(sys.argv[2])
n_items = int(sys.argv[3]) if len(sys.argv) > 3 else 6
gen.R.seed(seed)
D = os.path.join(os.environ.get("SWEEP_DIR", "/tmp/given_sweep"), f"s{seed}")
os.makedirs(D, exist_ok=True)


def flat(v):
    if isinstance(v, list):
        out = []
        for x in v:
            out += flat(x)
        return out
    if isinstance(v, bool):
        return [float(v)]
    if isinstance(v, (int, float)):
        return [float(v)]
    if v is None:
        return [float("nan")]
    return [v]


def run(files):
    p = subprocess.run([gen.BIN, "run", "--json", "--keep-going", "--timeout", "20", *files],
                       capture_output=True, text=True, timeout=600)
    res = {}
    for line in p.stdout.splitlines():
        try:
            o = json.loads(line)
        except Exception:
            continue
        res.setdefault(os.path.basename(o["file"]), {})[o["line"]] = o
    if "panicked" in p.stderr:
        print(json.dumps({"panic": p.stderr[-2000:], "files": files}), flush=True)
    return res


def close(x, y, tol):
    fx, fy = flat(x), flat(y)
    if len(fx) != len(fy):
        return False
    scale = max([abs(v) for v in fx + fy if isinstance(v, float) and math.isfinite(v)] + [1.0])
    for u, v in zip(fx, fy):
        if isinstance(u, str) or isinstance(v, str):
            if u != v:
                return False
            continue
        if math.isnan(u) and math.isnan(v):
            continue
        if math.isinf(u) or math.isinf(v):
            if u != v:
                return False
            continue
        if abs(u - v) > tol * scale:
            return False
    return True


def sub(x, y, h):
    if isinstance(x, list):
        return [sub(u, v, h) for u, v in zip(x, y)]
    return (x - y) / h


cases = []
for i in range(n):
    va, vb = gen.pick(gen.VALUES), gen.pick(gen.VALUES)
    items, s, m = gen.scripts(n_items, va, vb, os.environ.get('MODE', 'all'))
    fs, fn = f"{D}/{i}s.chs", f"{D}/{i}n.chs"
    open(fs, "w").write(s)
    open(fn, "w").write(m)
    cases.append((i, items, s, m, fs, fn))

B = 25
stats = {}
for j in range(0, len(cases), B):
    batch = cases[j:j + B]
    out = run([c[4] for c in batch] + [c[5] for c in batch])
    for (i, items, s, m, fs, fn) in batch:
        rs, rn = out.get(os.path.basename(fs), {}), out.get(os.path.basename(fn), {})
        sl, nl = s.splitlines(), m.splitlines()
        for k, (kind, e, extra) in enumerate(items, 1):
            x = f"X{k}"
            # definition line (1-based) and print line on each side
            sdef = next(t for t, l in enumerate(sl, 1) if l.startswith(x + " = "))
            sprt = max(t for t, l in enumerate(sl, 1) if l == x)
            so = rs.get(sprt)
            sdo = rs.get(sdef)
            if kind == "diff":
                pp = max(t for t, l in enumerate(nl, 1) if l == x + "p")
                mm = max(t for t, l in enumerate(nl, 1) if l == x + "m")
                a, b = rn.get(pp), rn.get(mm)
                if a is None or b is None or "error" in a or "error" in b:
                    no = a if (a and "error" in a) else (b if b and "error" in b else {"error": {"kind": "missing"}})
                else:
                    try:
                        no = {"type": a["type"], "value": sub(a["value"], b["value"], 2e-6)}
                    except Exception:
                        no = {"error": {"kind": "fd-fail", "message": str(a["value"])[:80]}}
                tol = 2e-5
            else:
                nprt = max(t for t, l in enumerate(nl, 1) if l == x)
                no = rn.get(nprt)
                tol = 1e-9
            if so is None or no is None:
                cat = "missing"
            elif "error" in so and "error" in no:
                cat = "both-err"
            elif "error" in so:
                cat = "sym-refuses"
            elif "error" in no:
                cat = "sym-answers-num-refuses"
            elif so.get("type") == "symbolic" or (isinstance(so.get("value"), str) and not isinstance(no.get("value"), str)):
                cat = "still-symbolic"
            elif not close(so["value"], no["value"], tol):
                cat = "value-differs"
            else:
                cat = "ok" if so.get("type") == no.get("type") or kind == "diff" else "type-differs"
            stats[cat] = stats.get(cat, 0) + 1
            if cat not in ("ok", "both-err"):
                print(json.dumps({"cat": cat, "kind": kind, "a": s.split("\n")[-1 - len(items) - 2] if False else None,
                                  "file": fs, "x": x, "expr": e, "extra": extra,
                                  "sym": so, "symdef": sdo if sdo and ("error" in sdo or "warnings" in sdo) else None,
                                  "num": no}), flush=True)
print(json.dumps({"stats": stats, "seed": seed, "n": n}), flush=True)
