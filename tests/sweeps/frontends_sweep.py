#!/usr/bin/env python3
"""Front ends against each other (LANGUAGE.md §§1, 11, 15): the diagnostics
`chasles lsp` publishes for a document against the errors and warnings
`chasles check FILE` prints for the same text, for every script under
examples/ and tests/errors/ and seeded variants of them (frames swapped so
products stop cancelling, syntax errors, unknown names, wrong argument
counts, non-rotation matrices, `given` symbols, multi-line statements, tabs,
Unicode names, CRLF), also after incremental and full `didChange` edits.

    python3 tests/sweeps/frontends_sweep.py [SEED] [VARIANTS_PER_SCRIPT]

CHASLES names the binary (default: target/debug/chasles). Prints each
disagreement as a JSON line and a count per pair at the end; exit 1 if any.
The seeded, fast subset of this is tests/frontends_agree.rs.
"""
import glob, json, os, random, re, subprocess, sys, tempfile, threading, queue

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.environ.get("CHASLES", os.path.join(ROOT, "target/debug/chasles"))
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
per = int(sys.argv[2]) if len(sys.argv) > 2 else 6
R = random.Random(seed)


# ---- variants ---------------------------------------------------------------

def swap_frames(t):
    names = re.findall(r"\b([RT]|Ad)_([a-z])([a-z])\b", t)
    if not names:
        return t + "\nT_ab = Trans((1, 2, 3))\nT_cb = Trans((0, 1, 0))\nT_ab * T_cb\n"
    p, a, b = R.choice(names)
    old, new = f"{p}_{a}{b}", f"{p}_{b}{a}"
    # one use (not the binding) swapped
    spots = [m.start() for m in re.finditer(r"\b" + re.escape(old) + r"\b", t)]
    at = R.choice(spots)
    return t[:at] + new + t[at + len(old):]


def syntax_error(t):
    lines = t.split("\n")
    i = R.randrange(len(lines))
    junk = R.choice([")", "(", "@", "= =", "[1, 2", "*", "1 +", "$", ",,"])
    lines[i] = lines[i] + " " + junk
    return "\n".join(lines)


def unknown_name(t):
    lines = t.split("\n")
    i = R.randrange(len(lines) + 1)
    lines.insert(i, R.choice(["x = Rotzz(1)", "y = undefined_thing + 1", "T_ab * T_zz",
                              "q = AxisAng(1)", "np.array([1, 2])", "syms x"]))
    return "\n".join(lines)


def wrong_arity(t):
    lines = t.split("\n")
    i = R.randrange(len(lines) + 1)
    lines.insert(i, R.choice(["Rotz(1, 2)", "a = Ad()", "MatrixExp3(1, 2, 3)",
                              "b = cross((1, 0, 0))", "T = RpToTrans(Rotz(1))"]))
    return "\n".join(lines)


def non_rotation(t):
    lines = t.split("\n")
    i = R.randrange(len(lines) + 1)
    lines.insert(i, R.choice(["R_ab = [1, 2, 3; 4, 5, 6; 7, 8, 9]",
                              "R_cd = [1, 0, 0; 0, 1, 0; 0, 0, 1.001]",
                              "T_ab = [1, 0, 0, 1; 0, 2, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]",
                              "log([1, 2; 3, 4])", "R = SO3([2, 0, 0; 0, 1, 0; 0, 0, 1])"]))
    return "\n".join(lines)


def givens(t):
    head = R.choice(["given T_ab, T_bc : SE3\nT_ab * T_cb\n",
                     "given θ, t1 : scalar\nRotz(θ) * Rotz(t1)\nsqrt(θ) == 2 ω̂\n",
                     "given R_sb : SO3\ngiven w_b : vec3\nR_sb * w_b\nR_sb.T * w_b\n",
                     "given V_b : twist\ngiven T_sb : SE3\nAd(T_sb) * V_b\nAd(T_sb) * V_s\n"])
    return head + t


def multiline(t):
    lines = t.split("\n")
    i = R.randrange(len(lines) + 1)
    lines.insert(i, R.choice(["M = [1, 0, 0\n     0, 1, 0\n     0, 0, 2]\nR_ab = M",
                              "T_ab = [1, 0, 0, 1;\n  0, 1, 0, 2;\n  0, 0, 1, 3;\n  0, 0, 0, 1]\nT_ab * T_cb",
                              "v = (1,\n  2,\n  3) +\n (1, 2)",
                              "x = Rotz(\n  30 deg) * (1,\n 0, 0) * T_xy"]))
    return "\n".join(lines)


def tabs_unicode(t):
    lines = t.split("\n")
    i = R.randrange(len(lines) + 1)
    lines.insert(i, R.choice(["θ\t= 30°\n\tR_ab = Rotz(θ)\tT_cd",
                              "ω̂ = (0, 0, 1)\nR_ab = Rot(ω̂, 1) * R_cd",
                              "𝜃 = 1; ω̂_b = (0, 0, 1); 𝜃 * ω̂_b + (1, 2)",
                              "\t\tθ₁ = π/2\n\t\tRotz(θ₁) * T_ab_bad"]))
    return "\n".join(lines)


def crlf(t):
    return t.replace("\r\n", "\n").replace("\n", "\r\n")


def bom(t):
    return "\ufeff" + t


VARIANTS = [swap_frames, syntax_error, unknown_name, wrong_arity, non_rotation,
            givens, multiline, tabs_unicode, crlf, bom]


# ---- chasles check ---------------------------------------------------------

HEAD = re.compile(r"^(.*?):(\d+):(\d+): (?:(\w+) error|(warning)|(note)): (.*)$")


def char_col_to_byte(text, line, col):
    """1-based line and character column (as check prints) to a byte offset."""
    b = text.encode("utf-8")
    lines = text.split("\n")
    off = sum(len(l.encode("utf-8")) + 1 for l in lines[:line - 1])
    return off + len(lines[line - 1][:col - 1].encode("utf-8"))


def check_files(paths, how=("check",)):
    p = subprocess.run([BIN, *how, *paths], capture_output=True, timeout=600)
    err = p.stderr.decode("utf-8", "replace")
    if "panicked" in err:
        print(json.dumps({"panic": err[-2000:]}))
    return parse_stderr(err, paths)


def parse_stderr(err, paths):
    """Each diagnostic's header and first help line from rendered stderr."""
    out = {q: [] for q in paths}
    last = None
    for ln in err.split("\n"):
        m = HEAD.match(ln)
        if m and m.group(1) in out:
            f, line, col = m.group(1), int(m.group(2)), int(m.group(3))
            sev = "error" if m.group(4) else (m.group(5) or m.group(6))
            last = [line, col, sev, m.group(4), m.group(7), None]
            out[f].append(last)
        elif last is not None and ln.lstrip().startswith("= help: ") and last[5] is None:
            last[5] = ln.lstrip()[len("= help: "):]
    return {f: [tuple(x) for x in v] for f, v in out.items()}


# ---- chasles lsp -----------------------------------------------------------

class Lsp:
    def __init__(self):
        self.p = subprocess.Popen([BIN, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.q = queue.Queue()
        threading.Thread(target=self.reader, daemon=True).start()
        self.id = 0
        self.pending = []
        self.request("initialize", {"processId": None, "rootUri": None, "capabilities": {}})
        self.notify("initialized", {})

    def reader(self):
        f = self.p.stdout
        while True:
            n = None
            while True:
                h = f.readline()
                if not h:
                    return
                h = h.strip()
                if not h:
                    break
                if h.startswith(b"Content-Length:"):
                    n = int(h.split(b":")[1])
            self.q.put(json.loads(f.read(n)))

    def send(self, v):
        b = json.dumps(v).encode()
        self.p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(b) + b)
        self.p.stdin.flush()

    def notify(self, m, params):
        self.send({"jsonrpc": "2.0", "method": m, "params": params})

    def request(self, m, params):
        self.id += 1
        self.send({"jsonrpc": "2.0", "id": self.id, "method": m, "params": params})
        while True:
            v = self.q.get(timeout=60)
            if v.get("id") == self.id:
                return v.get("result")
            self.pending.append(v)

    def diagnostics(self, uri, version):
        for i, v in enumerate(self.pending):
            if v["params"]["uri"] == uri and v["params"].get("version") == version:
                return self.pending.pop(i)["params"]["diagnostics"]
        while True:
            v = self.q.get(timeout=60)
            if v.get("method") != "textDocument/publishDiagnostics":
                continue
            if v["params"]["uri"] == uri and v["params"].get("version") == version:
                return v["params"]["diagnostics"]
            self.pending.append(v)


def utf16_to_byte(text, line, ch):
    lines = text.split("\n")
    off = sum(len(l.encode("utf-8")) + 1 for l in lines[:line])
    l = lines[line] if line < len(lines) else ""
    units = 0
    for i, c in enumerate(l):
        if units >= ch:
            return off + len(l[:i].encode("utf-8"))
        units += 2 if ord(c) > 0xFFFF else 1
    return off + len(l.encode("utf-8"))


SEV = {1: "error", 2: "warning", 3: "note"}


def from_lsp(text, diags):
    out = []
    for d in diags:
        s = d["range"]["start"]
        sev = SEV[d["severity"]]
        helps = [r["message"][len("help: "):] for r in d.get("relatedInformation") or []
                 if r["message"].startswith("help: ")]
        out.append((utf16_to_byte(text, s["line"], s["character"]), sev,
                    d["code"] if sev == "error" else None, d["message"],
                    helps[0].split("\n")[0] if helps else None))
    return sorted(out)


def from_check(text, errs):
    skip = 0
    if text.startswith("\ufeff"):
        # check reads the text without its byte-order mark
        text, skip = text[1:], 3
    return sorted((char_col_to_byte(text, l, c) + skip, sev, kind, msg, h)
                  for (l, c, sev, kind, msg, h) in errs)


def position(text, i):
    """The LSP position (line, UTF-16 column) of character index i."""
    before = text[:i]
    line = before.count("\n")
    col = before[before.rfind("\n") + 1:]
    return {"line": line, "character": sum(2 if ord(c) > 0xFFFF else 1 for c in col)}


def incremental(old, new):
    """One ranged change turning `old` into `new` (common ends kept)."""
    a = 0
    while a < min(len(old), len(new)) and old[a] == new[a]:
        a += 1
    b = 0
    while b < min(len(old), len(new)) - a and old[-1 - b] == new[-1 - b]:
        b += 1
    # (a position between the \r and the \n of a line break is no position
    # of the protocol's: a client never sends one)
    if 0 < a < len(old) and old[a - 1:a + 1] == "\r\n":
        a -= 1
    end = len(old) - b
    if 0 < end < len(old) and old[end - 1:end + 1] == "\r\n":
        b -= 1
    return {"range": {"start": position(old, a), "end": position(old, len(old) - b)},
            "text": new[a:len(new) - b]}


def run_vs_check(text, ran, checked):
    """Disagreements of `run --keep-going` with `check` on one text. Every
    error check reports, run reports too (check decides no numbers, so run
    may report more: a domain error, an assert, what only numbers decide,
    and after a statement that failed on its numbers, what used its name);
    an error of run at the place of one of check's says the same, with the
    same help."""
    bad = []
    errs_run = [x for x in ran if x[1] == "error"]
    errs_check = [x for x in checked if x[1] == "error"]
    line_of = lambda off: text.encode("utf-8")[:off].count(b"\n")
    for x in errs_check:
        if x in errs_run:
            continue
        same_place = [y for y in errs_run if y[0] == x[0]]
        # (a statement that failed on its numbers in run bound nothing: run
        # stops a later statement on the line at that name instead)
        if not same_place and any(y[2] == "name" and line_of(y[0]) == line_of(x[0])
                                  for y in errs_run):
            continue
        bad.append(("check_only", x, same_place[0] if same_place else None))
    return bad


# ---- the sweep -------------------------------------------------------------

def main():
    scripts = sorted(glob.glob(os.path.join(ROOT, "examples/*.chs")) +
                     glob.glob(os.path.join(ROOT, "tests/errors/*/*.chs")))
    cases = []
    for s in scripts:
        t = open(s, encoding="utf-8").read()
        name = os.path.relpath(s, ROOT)
        cases.append((name, t))
        for k in range(per):
            f = R.choice(VARIANTS)
            v = f(t)
            if R.random() < 0.3:
                v = R.choice(VARIANTS)(v)
            cases.append((f"{name}#{k}:{f.__name__}", v))
    tmp = tempfile.mkdtemp(prefix="chasles-fe-")
    paths = []
    for i, (_, t) in enumerate(cases):
        p = os.path.join(tmp, f"c{i}.chs")
        with open(p, "w", encoding="utf-8", newline="") as f:
            f.write(t)
        paths.append(p)
    checked = check_files(paths)
    ran = check_files(paths, ("run", "--keep-going", "--no-write", "--timeout", "20"))
    lsp = Lsp()
    bad = {"lsp vs check": 0, "lsp after didChange vs check": 0, "run vs check": 0}
    n_edits = 0
    for i, ((name, t), p) in enumerate(zip(cases, paths)):
        uri = f"file:///sweep/c{i}.chs"
        lsp.notify("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "chasles",
                                                             "version": 1, "text": t}})
        got = from_lsp(t, lsp.diagnostics(uri, 1))
        want = from_check(t, checked[p])
        if got != want:
            bad["lsp vs check"] += 1
            print(json.dumps({"case": name, "file": p, "lsp_only": [x for x in got if x not in want],
                              "check_only": [x for x in want if x not in got]}, ensure_ascii=False))
        r = run_vs_check(t, from_check(t, ran[p]), want)
        if r:
            bad["run vs check"] += 1
            print(json.dumps({"case": name, "file": p, "run_vs_check": r}, ensure_ascii=False))
        # The same document edited into the next case's text (incrementally,
        # then back in full): the diagnostics are check's of the new text.
        j = (i + 1) % len(cases)
        nxt, q = cases[j][1], paths[j]
        for version, change, text, path in [(2, incremental(t, nxt), nxt, q),
                                            (3, {"text": t}, t, p)]:
            lsp.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": version},
                                                  "contentChanges": [change]})
            # (a request checks a changed document at once, not after the
            # debounce)
            lsp.request("textDocument/documentSymbol", {"textDocument": {"uri": uri}})
            got = from_lsp(text, lsp.diagnostics(uri, version))
            want = from_check(text, checked[path])
            n_edits += 1
            if got != want:
                bad["lsp after didChange vs check"] += 1
                print(json.dumps({"case": name, "edit": version, "file": path,
                                  "lsp_only": [x for x in got if x not in want],
                                  "check_only": [x for x in want if x not in got]},
                                 ensure_ascii=False))
        lsp.notify("textDocument/didClose", {"textDocument": {"uri": uri}})
    for k, v in bad.items():
        n = n_edits if "didChange" in k else len(cases)
        print(f"{k}: {n} cases, {v} disagree", file=sys.stderr)
    return 1 if any(bad.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
