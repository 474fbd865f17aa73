#!/usr/bin/env bash
# The profile-guided release build (issue 40): the release binary built
# again with the branch and call counts of a training run, so that the
# compiler lays out and inlines the interpreter's paths as they are taken.
# Same source, same output; on this project's 2-core machine it takes
# about a fifth fewer instructions a statement (callgrind) than
# `cargo build --release`. A release for students is built this way.
#
#   benches/pgo.sh            # builds target/pgo/release/chasles
#
# Steps: (1) an instrumented release build (`-Cprofile-generate`) in
# target/pgo-gen; (2) a training run of it over every example script
# (examples/*.chs, the book's worked examples), the error scripts
# (tests/errors), the symbolic benchmarks (benches/*.chs) and issue 14's
# script of 11k statements printed, silenced, as JSON and checked;
# (3) `llvm-profdata merge`; (4) the release build with
# `-Cprofile-use` in target/pgo. The training touches no file of the
# checkout (pictures go to a temporary folder).
#
# Needs an llvm-profdata that reads the profiles of rustc's LLVM:
# rustup's (`rustup component add llvm-tools`), or Debian's
# (`apt-get install llvm-19`; version 19 reads rustc 1.95's LLVM 22
# profiles). Two full release builds: about 12 minutes on 2 cores.
# Not run in CI (it only builds a faster binary of the same program).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

profdata=
host=$(rustc -vV | sed -n 's/^host: //p')
for p in "$(rustc --print sysroot)/lib/rustlib/$host/bin/llvm-profdata" \
    llvm-profdata-22 llvm-profdata-21 llvm-profdata-20 llvm-profdata-19; do
    if command -v "$p" > /dev/null 2>&1; then
        profdata=$(command -v "$p")
        break
    fi
done
if [ -z "$profdata" ]; then
    echo "pgo.sh: no llvm-profdata for rustc's LLVM: rustup component add llvm-tools, or apt-get install llvm-19" >&2
    exit 2
fi

data=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$data" "$work"' EXIT

echo "pgo.sh: (1) instrumented build" >&2
RUSTFLAGS="-Cprofile-generate=$data" CARGO_TARGET_DIR="$root/target/pgo-gen" \
    cargo build --release --locked --quiet
gen="$root/target/pgo-gen/release/chasles"

echo "pgo.sh: (2) training run" >&2
python3 - "$work" <<'PY'
import sys
sys.path.insert(0, "benches")
from book_python import script, silent_script
open(f"{sys.argv[1]}/s.chs", "w").write(script(11000))
open(f"{sys.argv[1]}/q.chs", "w").write(silent_script(11000))
PY
# (each script from a copy of its folder: a `draw` writes beside it)
cp -r examples "$work/examples"
(
    cd "$work/examples"
    for f in *.chs; do "$gen" run "$f" > /dev/null 2>&1 || true; done
    "$gen" run --json ./*.chs > /dev/null 2>&1 || true
)
for f in tests/errors/*/*.chs; do "$gen" run --no-write "$f" > /dev/null 2>&1 || true; done
for f in benches/*.chs; do "$gen" run "$f" > /dev/null 2>&1 || true; done
"$gen" run "$work/s.chs" > /dev/null
"$gen" run "$work/q.chs" > /dev/null
"$gen" run --json "$work/s.chs" > /dev/null
"$gen" check "$work/s.chs" > /dev/null

echo "pgo.sh: (3) $profdata merge" >&2
"$profdata" merge -o "$root/target/chasles.profdata" "$data"

echo "pgo.sh: (4) profile-guided build" >&2
RUSTFLAGS="-Cprofile-use=$root/target/chasles.profdata" CARGO_TARGET_DIR="$root/target/pgo" \
    cargo build --release --locked --quiet
echo "$root/target/pgo/release/chasles"
