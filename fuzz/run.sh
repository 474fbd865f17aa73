#!/bin/sh
# Seeds the corpus and runs the pipeline target on one core.
#   fuzz/run.sh [SECONDS]        (default 600)
# Needs a nightly toolchain and `cargo install cargo-fuzz`.
set -eu
cd "$(dirname "$0")"
./seed.sh
cd ..
exec cargo +nightly fuzz run pipeline fuzz/corpus/pipeline -- \
    -dict=fuzz/chasles.dict -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
    -max_total_time="${1:-600}" -print_final_stats=1
