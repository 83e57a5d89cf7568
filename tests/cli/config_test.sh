#!/usr/bin/env bash
# Configuration files (CLI11): the viewer's defaults from the user's file,
# render's only from --config FILE, the command line over both, and bad
# files refused with exit 2, named, without blocking.
# Usage: config_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
CHECK_TIMEOUT=10
source "$src/tests/support/checks.sh"
cube=$src/data/cube.dat
mkdir -p "$work/xdg/termshade"
printf 'glyphs = "braille"\n' >"$work/xdg/termshade/config.toml"
printf '# shared keys set render too; [render] wins for render\nglyphs = "braille"\ncolor = "truecolor"\n[render]\nshade = "lambert"\n' >"$work/mine.toml"
"$bin" render "$cube" --size 30x10 >"$work/plain"
"$bin" render "$cube" --size 30x10 --glyphs braille --color truecolor --shade lambert --format ansi >"$work/asked.ans"

# render: only a file named by --config, before or after the model, either spelling.
check render_reads_named_config 0 "" -- "$bin" render "$cube" --size 30x10 --format ansi --config "$work/mine.toml"
expect render_named_config_is_as_asked cmp -s "$work/out" "$work/asked.ans"
check render_config_equals_form 0 "" -- "$bin" render --config="$work/mine.toml" "$cube" --size 30x10 --format ansi
expect render_config_equals_form_same cmp -s "$work/out" "$work/asked.ans"
check command_line_wins 0 "" -- "$bin" render "$cube" --size 30x10 --config "$work/mine.toml" --glyphs ramp --color 256 --shade contrast
expect command_line_wins_same cmp -s "$work/out" "$work/plain"
check render_ignores_user_config 0 "" -- env XDG_CONFIG_HOME="$work/xdg" "$bin" render "$cube" --size 30x10
expect render_ignores_user_config_same cmp -s "$work/out" "$work/plain"

# The viewer: the user's file unless --no-config (seen through --print-config).
check viewer_reads_user_config 0 "" -- env XDG_CONFIG_HOME="$work/xdg" "$bin" --print-config
expect viewer_user_config_printed grep -qx 'glyphs="braille"' "$work/out"
check viewer_no_config 0 "" -- env XDG_CONFIG_HOME="$work/xdg" "$bin" --no-config --print-config
expect viewer_no_config_default grep -qx 'glyphs=""' "$work/out"
mkdir -p "$work/home/.config/termshade"
cp "$work/xdg/termshade/config.toml" "$work/home/.config/termshade/"
check viewer_home_config 0 "" -- env -u XDG_CONFIG_HOME HOME="$work/home" "$bin" --print-config
expect viewer_home_config_printed grep -qx 'glyphs="braille"' "$work/out"
check no_user_config_is_fine 0 "" -- env XDG_CONFIG_HOME="$work/none" "$bin" --print-config
check render_print_config 0 "" -- "$bin" render "$cube" --config "$work/mine.toml" --print-config
expect render_print_config_shows_render grep -qx 'render.shade="lambert"' "$work/out"

# Bad files: exit 2, the file named, nothing read from what is not a file.
check named_config_missing 2 "no such configuration file" -- "$bin" render "$cube" --config "$work/missing.toml"
mkfifo "$work/fifo.toml"
check config_fifo_refused 2 "not a regular file" -- "$bin" render "$cube" --config "$work/fifo.toml"
ln -s "$work/fifo.toml" "$work/xdg/termshade/config.toml.fifo"
mkdir -p "$work/fifohome/termshade" && mkfifo "$work/fifohome/termshade/config.toml"
check user_config_fifo_refused 2 "not a regular file" -- env XDG_CONFIG_HOME="$work/fifohome" "$bin" --print-config
check config_folder_refused 2 "not a regular file" -- "$bin" render "$cube" --config "$work"
head -c 70000 /dev/zero | tr '\0' '#' >"$work/big.toml"
check config_too_big 2 "over 64 KiB" -- "$bin" render "$cube" --config "$work/big.toml"
printf 'glyphs = "sixel"\n' >"$work/badvalue.toml"
check config_bad_value 2 "glyphs" -- "$bin" render "$cube" --config "$work/badvalue.toml"
printf 'no-such-option = 1\n' >"$work/unknown.toml"
check config_unknown_key 2 "unknown.toml: INI was not able to parse no-such-option" -- "$bin" render "$cube" --config "$work/unknown.toml"
printf 'glyphs = "\033]0;owned\007"\n' >"$work/escape.toml"
check config_escape_bytes 2 "" -- "$bin" render "$cube" --config "$work/escape.toml"
expect config_escape_bytes_escaped bash -c "! grep -q $'\\x1b' '$work/err'"
check config_after_bench_refused 2 "" -- "$bin" bench models "$cube" --config "$work/mine.toml"
finish
