#!/usr/bin/env bash
# Replace the committed sample with the default report of an output folder made by
# `./setup.sh report` (out/default). The CSVs are kept gzipped; CI compares every non-timing
# value of a fresh default report with them (tests/same_results.py).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
from=${1:-out/default}
test -s "$from/report.md" || { echo "update.sh: $from holds no report.md" >&2; exit 2; }
# gnuplot's SVG wraps every stroke in a group of its own: scour merges and rounds them, which
# halves the plots with the same picture (keeps the sample under 3 MB).
command -v scour > /dev/null || { echo "update.sh: needs scour (Debian: scour)" >&2; exit 2; }
rm -rf "$here/plots"
mkdir "$here/plots"
for svg in "$from"/plots/*.svg; do
  scour -q -i "$svg" -o "$here/plots/$(basename "$svg")" --enable-id-stripping --shorten-ids --create-groups \
    --remove-descriptive-elements --strip-xml-prolog --set-precision=5
done
cp "$from/report.md" "$from/stability.md" "$from/answer.csv" "$here/"
for f in results orders local_orders stability stability_spin; do
  gzip -9 -n -c "$from/$f.csv" > "$here/$f.csv.tmp" && mv "$here/$f.csv.tmp" "$here/$f.csv.gz"
done
echo "update.sh: sample replaced from $from ($(du -sh "$here" | cut -f1))"
