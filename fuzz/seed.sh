#!/bin/sh
# Creates the seed corpus fuzz/corpus/pipeline from every example and error
# script (the corpus itself is not committed).
set -eu
cd "$(dirname "$0")"
mkdir -p corpus/pipeline
for f in ../examples/*.chs ../tests/errors/*/*.chs; do
    kind=$(basename "$(dirname "$f")")
    cp "$f" "corpus/pipeline/${kind}_$(basename "$f")"
done
echo "seeded $(ls corpus/pipeline | wc -l) files"
