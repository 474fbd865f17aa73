#!/usr/bin/env bash
# Instructions per statement of issue 14's script (callgrind counts
# instructions, not seconds, so the figure is repeatable on a shared
# machine). Runs the release binary on 11k and 21k statements (both long
# enough to run on three threads, `syntax::AHEAD_FROM`) and prints
# (I(21k) - I(11k)) / 10k for `run` (every result printed), `run` of the
# same script with every statement ended by `;` (silenced: nothing
# printed) and `check`, all threads' instructions and the evaluating
# thread's; then, from the 11k `run` on one thread, the part of each
# statement spent in parsing (the statement reader), in the interpreter
# (check and evaluation) and in printing.
#
#   benches/instructions.sh [--kinds] [path/to/chasles]
#
# With --kinds, it then prints the evaluating thread's instructions per
# statement for each of the script's kinds of statement alone (`exp`, the
# product, `log`, the adjoint, and the literal `S = (...)`), silenced,
# each repeated 10k and 20k times after the lines that bind its operands
# (the scripts are long enough to be read ahead, as the 11k and 21k
# ones: a script under `syntax::AHEAD_FROM` runs on one thread, and its
# figure would include parsing).
#
# Needs valgrind and python3; not run in CI.
set -euo pipefail
cd "$(dirname "$0")/.."
kinds=
if [ "${1:-}" = --kinds ]; then kinds=1; shift; fi
bin=${1:-target/release/chasles}
[ "${1:-}" ] || cargo build --release --quiet
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp" <<'PY'
import sys
sys.path.insert(0, "benches")
from book_python import script, silent_script
for n in (11000, 21000):
    open(f"{sys.argv[1]}/s{n}.chs", "w").write(script(n))
    open(f"{sys.argv[1]}/q{n}.chs", "w").write(silent_script(n))
PY
# Instructions of one run: all threads', then the evaluating thread's (the
# one that did the most: a long script is read ahead and its text written
# on two more threads, issue 40, so the evaluating thread's count is the
# run's critical path).
count() {
  rm -f "$tmp/cg-$1-$3"*
  valgrind --tool=callgrind --separate-threads=yes \
    --callgrind-out-file="$tmp/cg-$1-$3" "$bin" "$1" "$2" >/dev/null 2>"$tmp/err"
  cat "$tmp/cg-$1-$3"-* | awk '/^totals:/ { t += $2; if ($2 > m) m = $2 } END { print t, m }'
}
for mode in run:s run:q check:s; do
  m=${mode%:*} f=${mode#*:}
  read -r a am <<<"$(count "$m" "$tmp/${f}11000.chs" "${f}11000")"
  read -r b bm <<<"$(count "$m" "$tmp/${f}21000.chs" "${f}21000")"
  label=$m; [ "$f" = q ] && label="run (silenced by ;)"
  echo "$label: $(( (b - a) / 10000 )) instructions per statement," \
    "$(( (bm - am) / 10000 )) of them on the evaluating thread"
done
# Where a printed statement's instructions go (inclusive costs of the
# 11k run on one thread, CHASLES_THREADS=1, divided by 11k: start-up is
# in none of them). Read from the plain release build: with line tables
# (`debug = "line-tables-only"`) callgrind splits each function by the
# file of its inlined code, and these three figures come out wrong (the
# totals above stay right).
CHASLES_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$tmp/cg-one" "$bin" run \
  "$tmp/s11000.chs" >/dev/null 2>"$tmp/err"
callgrind_annotate --inclusive=yes "$tmp/cg-one" 2>/dev/null |
  awk '
    function n(s) { gsub(",", "", s); return s / 11000 }
    !p && index($0, ":chasles::syntax::statements_read::{{closure}} [") { p = n($1) }
    !e && index($0, ":chasles::eval::interp::Interp::stmt [") { e = n($1) }
    !o && index($0, ":chasles::output::text::write_outcome [") { o = n($1) }
    END { printf "per printed statement: parse %d, check and evaluate %d, print %d\n", p, e, o }'
[ "$kinds" ] || exit 0
python3 - "$tmp" <<'PY'
import sys
sys.path.insert(0, "benches")
from book_python import LINES
first = "S = (0, 0, 1, 0, 2, 0);\n" + "".join(l + ";\n" for l in LINES[:3])
kinds = {"exp": LINES[0], "product": LINES[2], "log": LINES[3], "adjoint": LINES[4],
         "literal": "S = (0, 0, 1, 0, 2, 0)"}
for k, line in kinds.items():
    for n in (10000, 20000):
        open(f"{sys.argv[1]}/k-{k}-{n}.chs", "w").write(first + (line + ";\n") * n)
PY
for k in exp product log adjoint literal; do
  read -r _ a <<<"$(count run "$tmp/k-$k-10000.chs" "k-$k-10000")"
  read -r _ b <<<"$(count run "$tmp/k-$k-20000.chs" "k-$k-20000")"
  echo "$k alone (silenced): $(( (b - a) / 10000 )) instructions per statement on the evaluating thread"
done
