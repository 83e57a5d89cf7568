#!/bin/sh
# fzf: pick a model with a live preview of each file as fzf moves.
#   find . -name '*.obj' -o -name '*.stl' -o -name '*.ply' | fzf-preview.sh
# fzf sets FZF_PREVIEW_COLUMNS and FZF_PREVIEW_LINES for the preview command
# and quotes {} itself.
exec fzf --ansi --preview 'termshade render --size ${FZF_PREVIEW_COLUMNS}x${FZF_PREVIEW_LINES} --format ansi --glyphs auto --color 256 -- {} 2>&1' "$@"
