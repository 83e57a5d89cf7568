#!/usr/bin/env bash
# How much of the window a model fills, with render's default framing and
# with the viewer's (--fit): rows and columns holding any drawn cell.
# Usage: tools/framing/fill_fraction.sh path/to/termshade COLSxROWS MODEL...
# Prints a Markdown table (docs/viewer.md#framing).
set -eu
bin=$1 size=$2
shift 2
cols=${size%x*} rows=${size#*x}
covered() {  # MODEL [render options]: "ROWS COLS"
  "$bin" render "$@" --size "$size" | awk '
    { if ($0 ~ /[^ ]/) r++; for (i = 1; i <= length($0); i++) if (substr($0, i, 1) != " ") c[i] = 1 }
    END { n = 0; for (k in c) n++; print r + 0, n }'
}
share() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
echo "| model ($size) | rows, default | rows, --fit | columns, default | columns, --fit |"
echo "| --- | --- | --- | --- | --- |"
for model in "$@"; do
  read -r r0 c0 < <(covered "$model")
  read -r r1 c1 < <(covered "$model" --fit)
  echo "| $(basename "$model") | $r0 ($(share "$r0" "$rows")) | $r1 ($(share "$r1" "$rows")) |" \
    "$c0 ($(share "$c0" "$cols")) | $c1 ($(share "$c1" "$cols")) |"
done
