#!/usr/bin/env bash
# The CLI driven as a user would: a render that works, and bad input that must
# give a one-line error and a non-zero exit (never a crash, hang or image).
# Needs $CURVETEXT (path of the curvetext binary).
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

ok() { passed=$((passed + 1)); echo "ok   $1"; }
bad() { failed=$((failed + 1)); echo "FAIL $1"; }

# png_size FILE -> "W H" from the IHDR chunk.
png_size() {
  local w h
  w=$(od -An -tu1 -j16 -N4 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4}')
  h=$(od -An -tu1 -j20 -N4 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4}')
  echo "$w $h"
}

# expect_error NAME EXIT_CODE PATTERN -- ARGS...: runs with a 60 s limit.
expect_error() {
  local name=$1 code=$2 pattern=$3
  shift 4
  rm -f "$tmp/out.png"
  timeout 60 "$CURVETEXT" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local rc=$?
  local first_line
  first_line=$(head -n1 "$tmp/stderr")
  if [ "$rc" -ne "$code" ]; then bad "$name: exit $rc, want $code ($(head -c 300 "$tmp/stderr"))"; return; fi
  if ! grep -q -- "$pattern" <<<"$first_line"; then bad "$name: first stderr line '$first_line' lacks '$pattern'"; return; fi
  if [ "$code" -eq 1 ] && [ "$(wc -l <"$tmp/stderr")" -ne 1 ]; then bad "$name: error is not one line: $(cat "$tmp/stderr")"; return; fi
  if [ -e "$tmp/out.png" ]; then bad "$name: wrote an image despite the error"; return; fi
  ok "$name"
}

# --- a render that works ------------------------------------------------------
if timeout 120 "$CURVETEXT" render --size 48 --text "Hello, world" -o "$tmp/hello.png" 2>"$tmp/stderr"; then
  if [ "$(head -c 8 "$tmp/hello.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; then
    read -r w h <<<"$(png_size "$tmp/hello.png")"
    # DejaVu Sans at 48 px: ascender 0.928 em, descender -0.236 em; height =
    # ceil(2*16 + 48*(0.928+0.236)) = 88.
    if [ "$h" -eq 88 ] && [ "$w" -gt 250 ] && [ "$w" -lt 400 ]; then ok "render default font ${w}x${h}"; else bad "render size ${w}x${h}"; fi
  else
    bad "render wrote no PNG"
  fi
else
  bad "render Hello, world failed: $(cat "$tmp/stderr")"
fi

if timeout 120 "$CURVETEXT" render --size 20 --text "fi AV" --features "-liga,kern" --margin 4 --aa curves \
     --curve paper --fg "#204080" --bg white -o "$tmp/opts.png" 2>"$tmp/stderr"; then
  read -r w h <<<"$(png_size "$tmp/opts.png")"
  if [ "$h" -eq 32 ]; then ok "render with options ${w}x${h}"; else bad "render with options: height $h, want ceil(8+20*1.164)=32"; fi
else
  bad "render with options failed: $(cat "$tmp/stderr")"
fi

printf 'From a file\n' >"$tmp/text.txt"
if timeout 120 "$CURVETEXT" render --size 16 --text-file "$tmp/text.txt" -o "$tmp/file.png" 2>"$tmp/stderr"; then
  ok "render --text-file"
else
  bad "render --text-file failed: $(cat "$tmp/stderr")"
fi

# --- check and mesh ---------------------------------------------------------------
if timeout 120 "$CURVETEXT" check --max-glyphs 120 --json >"$tmp/check.json" 2>"$tmp/stderr"; then
  if grep -q '"glyphs": 120' "$tmp/check.json" && grep -q '"failed": 0' "$tmp/check.json" &&
     grep -q '"build_us_median"' "$tmp/check.json" && grep -q '"mean_bytes"' "$tmp/check.json"; then
    ok "check --json on the first 120 glyphs"
  else
    bad "check --json output: $(head -c 300 "$tmp/check.json")"
  fi
else
  bad "check failed: $(head -c 300 "$tmp/check.json") $(cat "$tmp/stderr")"
fi
if timeout 60 "$CURVETEXT" mesh --char g -o "$tmp/g.svg" 2>"$tmp/stderr" && grep -q "<svg" "$tmp/g.svg" &&
   [ "$(grep -c "<polygon" "$tmp/g.svg")" -gt 20 ] && grep -q "invariants hold" "$tmp/g.svg"; then
  ok "mesh --char g"
else
  bad "mesh --char g: $(cat "$tmp/stderr")"
fi
expect_error "mesh: glyph out of range" 1 "glyph" -- mesh --glyph 999999 -o "$tmp/out.png"
expect_error "mesh: no glyph for char" 1 "no glyph" -- mesh --char "$(printf '\xE4\xB8\xAD')" -o "$tmp/out.png"

# --- bad input ------------------------------------------------------------------
head -c 4096 /dev/urandom >"$tmp/corrupt.ttf"
: >"$tmp/empty.ttf"
printf 'bad \xC3\x28 utf8' >"$tmp/badutf8.txt"

expect_error "missing font" 1 "nonexistent.ttf" -- render --font "$tmp/nonexistent.ttf" --size 20 --text hi -o "$tmp/out.png"
expect_error "corrupt font" 1 "corrupt.ttf" -- render --font "$tmp/corrupt.ttf" --size 20 --text hi -o "$tmp/out.png"
expect_error "empty font file" 1 "empty.ttf" -- render --font "$tmp/empty.ttf" --size 20 --text hi -o "$tmp/out.png"
expect_error "bad face index" 1 "face" -- render --face-index 7 --size 20 --text hi -o "$tmp/out.png"
expect_error "empty text" 1 "empty" -- render --size 20 --text "" -o "$tmp/out.png"
expect_error "invalid UTF-8" 1 "UTF-8" -- render --size 20 --text-file "$tmp/badutf8.txt" -o "$tmp/out.png"
expect_error "size zero" 1 "size" -- render --size 0 --text hi -o "$tmp/out.png"
expect_error "size negative" 1 "size" -- render --size -5 --text hi -o "$tmp/out.png"
expect_error "size NaN" 1 "size" -- render --size nan --text hi -o "$tmp/out.png"
expect_error "size absurd" 1 "size" -- render --size 1e9 --text hi -o "$tmp/out.png"
expect_error "image too large" 1 "image" -- render --size 5000 --text "a long line of text" -o "$tmp/out.png"
expect_error "size not a number" 2 "--size" -- render --size big --text hi -o "$tmp/out.png"
expect_error "unknown option" 2 "unknown option" -- render --size 20 --text hi --bogus -o "$tmp/out.png"
expect_error "no output" 2 "-o" -- render --size 20 --text hi
expect_error "both text sources" 2 "exactly one" -- render --size 20 --text hi --text-file "$tmp/text.txt" -o "$tmp/out.png"
expect_error "bad aa mode" 1 "antialiasing" -- render --size 20 --text hi --aa blurry -o "$tmp/out.png"
expect_error "bad colour" 1 "colo" -- render --size 20 --text hi --fg "#12345" -o "$tmp/out.png"
expect_error "unknown axis" 1 "wght" -- render --size 20 --text hi --variations wght=700 -o "$tmp/out.png"
expect_error "bad feature" 1 "feature" -- render --size 20 --text hi --features "=,=" -o "$tmp/out.png"
expect_error "unwritable output" 1 "nodir" -- render --size 20 --text hi -o "$tmp/nodir/out.png"
# No GL device: libglvnd finds no EGL vendor library.
__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent expect_error "no EGL display" 1 "EGL" -- render --size 20 --text hi -o "$tmp/out.png"

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
