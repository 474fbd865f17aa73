#!/usr/bin/env bash
# Instructions per statement of issue 14's script (callgrind counts
# instructions, not seconds, so the figure is repeatable on a shared
# machine). Runs the release binary on 1k and 11k statements and prints
# (I(11k) - I(1k)) / 10k for `run` (every result printed) and `check`.
#
#   benches/instructions.sh [path/to/chasles]
#
# Needs valgrind and python3; not run in CI.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-target/release/chasles}
[ "${1:-}" ] || cargo build --release --quiet
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp" <<'PY'
import sys
sys.path.insert(0, "benches")
from book_python import script
for n in (1000, 11000):
    open(f"{sys.argv[1]}/s{n}.chs", "w").write(script(n))
PY
count() {
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" "$bin" "$1" "$2" \
    >/dev/null 2>"$tmp/err"
  grep -o 'refs: *[0-9,]*' "$tmp/err" | tr -dc 0-9
}
for mode in run check; do
  a=$(count "$mode" "$tmp/s1000.chs")
  b=$(count "$mode" "$tmp/s11000.chs")
  echo "$mode: $(( (b - a) / 10000 )) instructions per statement"
done
