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
expect_error "mesh: glyph out of range" 1 "glyph" -- mesh --glyph 999999 -o "$tmp/out.svg"
expect_error "mesh: no glyph for char" 1 "no glyph" -- mesh --char "$(printf '\xE4\xB8\xAD')" -o "$tmp/out.svg"
expect_error "mesh: PNG output refused" 1 "SVG only" -- mesh --char g -o "$tmp/out.png"

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

# --- shape: NURBS JSON and SVG input --------------------------------------------
shapes="$(dirname "$0")/../fixtures/shapes"
if timeout 120 "$CURVETEXT" shape --input "$shapes/pentagram-evenodd.json" -o "$tmp/star.png" 2>"$tmp/stderr" &&
   [ "$(png_size "$tmp/star.png")" = "240 240" ]; then
  ok "shape: even-odd pentagram (JSON)"
else
  bad "shape: even-odd pentagram: $(cat "$tmp/stderr")"
fi
if timeout 120 "$CURVETEXT" shape --input "$shapes/ellipse-arc.svg" --size 100x50 --aa none -o "$tmp/ellipse.png" \
     2>"$tmp/stderr" && [ "$(png_size "$tmp/ellipse.png")" = "100 50" ]; then
  ok "shape: SVG arcs with --size"
else
  bad "shape: SVG arcs with --size: $(cat "$tmp/stderr")"
fi
# Strokes: the drawing with its strokes against the same shapes with none (only the first is filled).
sed 's/"stroke": {[^}]*},//' "$shapes/strokes.json" >"$tmp/no-strokes.json"
if timeout 120 "$CURVETEXT" shape --input "$shapes/strokes.json" -o "$tmp/strokes.png" 2>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" shape --input "$tmp/no-strokes.json" -o "$tmp/no-strokes.png" 2>>"$tmp/stderr" &&
   read -r w h _ ink_strokes ink_none <<<"$(python3 "$(dirname "$0")/png_diff.py" "$tmp/strokes.png" "$tmp/no-strokes.png")" &&
   [ "$w $h" = "480 320" ] && [ "$ink_strokes" -gt $((ink_none * 3)) ]; then
  ok "shape: strokes (JSON) drawn"
else
  bad "shape: strokes (JSON): $(cat "$tmp/stderr") ink ${ink_strokes:-?} vs ${ink_none:-?}"
fi
printf '{"shapes": [{"stroke": {"join": "mitre"}, "contours": [[{"line": [[0,0],[1,0]]}]]}]}' >"$tmp/join.json"
expect_error "shape: unknown stroke join" 1 "known: miter, miter-clip, round, bevel, arcs" -- shape --input "$tmp/join.json" -o "$tmp/out.png"
printf '{"shapes": [{"contours": [[{"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,1,0,0,1,1]}}]]}]}' >"$tmp/knots.json"
printf '{"shapes": [{"contours": [[{"bezier": {"points": [[0,0],[1,1],[2,0]], "weights": [1,-1,1]}}]]}]}' >"$tmp/weight.json"
printf '{"shapes": [{"contours": [[{"line": [[0,0],[1e300,0],[1,1]]}]]}]}' >"$tmp/huge.json"
printf '{"shapes": [\n  {"contours": [[{"line": [[0,0],[1,0]]}]],}\n]}' >"$tmp/syntax.json"
printf '<svg><path d="M0 0 L10 0 L nan 5 Z"/></svg>' >"$tmp/nan.svg"
printf '<svg><path d="M0 0 A5 5 0 0 1 1e999 0 Z"/></svg>' >"$tmp/inf.svg"
printf 'M0 0 L1 1' >"$tmp/shape.txt"
expect_error "shape: bad knot vector" 1 "non-decreasing" -- shape --input "$tmp/knots.json" -o "$tmp/out.png"
expect_error "shape: negative weight" 1 "weight" -- shape --input "$tmp/weight.json" -o "$tmp/out.png"
expect_error "shape: huge coordinate" 1 "larger than" -- shape --input "$tmp/huge.json" -o "$tmp/out.png"
expect_error "shape: JSON syntax" 1 "line 2, column" -- shape --input "$tmp/syntax.json" -o "$tmp/out.png"
expect_error "shape: NaN in SVG path" 1 "expected a number" -- shape --input "$tmp/nan.svg" -o "$tmp/out.png"
expect_error "shape: inf in SVG arc" 1 "out of range" -- shape --input "$tmp/inf.svg" -o "$tmp/out.png"
expect_error "shape: unknown extension" 1 ".json or .svg" -- shape --input "$tmp/shape.txt" -o "$tmp/out.png"
expect_error "shape: missing file" 1 "nonexistent.svg" -- shape --input "$tmp/nonexistent.svg" -o "$tmp/out.png"
expect_error "shape: bad size" 2 "--size" -- shape --input "$shapes/ellipse-arc.svg" --size 100 -o "$tmp/out.png"
expect_error "shape: image too large" 1 "image" -- shape --input "$shapes/ellipse-arc.svg" --scale 1000 -o "$tmp/out.png"
expect_error "shape: no input" 2 "--input" -- shape -o "$tmp/out.png"

# --- paragraph layout (render --width ..., layout --json) -------------------------
if timeout 60 "$CURVETEXT" layout --size 20 --width 150 --text "Hello world, a paragraph that wraps" --json >"$tmp/layout.json" 2>"$tmp/stderr" &&
   python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); l=d["lines"]; assert len(l)>=2 and l[0]["start"]==0 and l[-1]["end"]==35 and l[1]["baseline"]>l[0]["baseline"] and l[0]["runs"][0]["glyphs"][0]["cluster"]==0' "$tmp/layout.json"; then
  ok "layout --json wraps"
else
  bad "layout --json: $(cat "$tmp/stderr")"
fi
if timeout 60 "$CURVETEXT" render --size 20 --width 150 --align center --markup --text "Hello <b>bold</b> <color=red>world</color> wraps here" -o "$tmp/para.png" 2>"$tmp/stderr" &&
   [ "$(png_size "$tmp/para.png" | cut -d' ' -f1)" = "182" ]; then
  ok "render --width (image width = width + 2 margins)"
else
  bad "render --width: $(cat "$tmp/stderr") $(png_size "$tmp/para.png" 2>/dev/null)"
fi
expect_error "layout: negative width" 2 "--width" -- layout --size 20 --width -3 --text hi --json
expect_error "layout: width not a number" 2 "--width" -- layout --size 20 --width wide --text hi --json
expect_error "layout: bad align" 2 "--align" -- layout --size 20 --align sideways --text hi --json
expect_error "layout: bad ellipsis" 2 "--ellipsis" -- layout --size 20 --ellipsis both --text hi --json
expect_error "layout: bad direction" 2 "--direction" -- layout --size 20 --direction up --text hi --json
expect_error "layout: negative max lines" 2 "--max-lines" -- layout --size 20 --max-lines -1 --text hi --json
expect_error "layout: invalid UTF-8" 1 "UTF-8" -- layout --size 20 --text-file "$tmp/badutf8.txt" --json
expect_error "layout: missing fallback font" 1 "nonexistent" -- layout --size 20 --font "$tmp/nonexistent.ttf" --text hi --json
expect_error "render: bad markup" 1 "markup" -- render --size 20 --width 100 --markup --text "<b>open" -o "$tmp/out.png"
expect_error "render: size NaN with width" 1 "size" -- render --size nan --width 100 --text hi -o "$tmp/out.png"
expect_error "render: paragraph image too large" 1 "image" -- render --size 20 --width 100000 --text hi -o "$tmp/out.png"

# --- transforms ----------------------------------------------------------------
if timeout 120 "$CURVETEXT" render --size 24 --text "Hamburg" --rotate 30 --scale 1.5,1 --skew 10 -o "$tmp/rot.png" 2>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" render --size 24 --text "Hamburg" --perspective 40 -o "$tmp/persp.png" 2>>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" render --size 24 --text "Hamburg" --transform 1,0.2,0,0,1,0,0,0.001,1 -o "$tmp/matrix.png" 2>>"$tmp/stderr"; then
  read -r w h <<<"$(png_size "$tmp/rot.png")"
  # Rotated 30 degrees the image is the bounding box of the turned rectangle: taller than the plain 60 px line.
  if [ "$h" -gt 80 ]; then ok "render transformed ${w}x${h}"; else bad "render --rotate 30: height $h, want > 80"; fi
else
  bad "render with transforms failed: $(cat "$tmp/stderr")"
fi
expect_error "render: NaN rotation" 1 "finite" -- render --size 20 --text hi --rotate nan -o "$tmp/out.png"
expect_error "render: infinite matrix entry" 1 "finite" -- render --size 20 --text hi --transform 1,0,0,0,1,0,0,0,inf -o "$tmp/out.png"
expect_error "render: huge matrix entry" 1 "limit" -- render --size 20 --text hi --transform 1e300,0,0,0,1,0 -o "$tmp/out.png"
expect_error "render: singular scale" 1 "singular" -- render --size 20 --text hi --scale 0 -o "$tmp/out.png"
expect_error "render: perspective 95 degrees" 1 "perspective" -- render --size 20 --text hi --perspective 95 -o "$tmp/out.png"
expect_error "render: behind the viewer" 1 "behind" -- render --size 20 --text Hamburgefontsiv --perspective 80,20 -o "$tmp/out.png"
expect_error "render: transformed image too large" 1 "largest side" -- render --size 20 --text hi --scale 1e5 -o "$tmp/out.png"
expect_error "render: matrix with 3 numbers" 2 "6 or 9" -- render --size 20 --text hi --transform 1,2,3 -o "$tmp/out.png"
# Paragraphs take the same transforms: rotated, the image is the turned rectangle's bounding box.
if timeout 120 "$CURVETEXT" render --size 16 --width 120 --text "A paragraph that wraps onto lines" --rotate 30 -o "$tmp/prot.png" 2>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" render --size 16 --width 120 --text "A paragraph that wraps" --perspective 40 --skew 5 -o "$tmp/ppersp.png" 2>>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" render --size 16 --width 120 --text "A paragraph that wraps" --scale 1.5,1 -o "$tmp/pscale.png" 2>>"$tmp/stderr"; then
  read -r w h <<<"$(png_size "$tmp/prot.png")"
  read -r sw sh <<<"$(png_size "$tmp/pscale.png")"
  # Unturned: 152 px wide (120 + 2 margins); turned 30 degrees both sides grow; scaled 1.5 wide: 228.
  if [ "$w" -gt 152 ] && [ "$h" -gt 152 ] && [ "$sw" -eq 228 ]; then ok "render paragraph transformed ${w}x${h}, scaled ${sw}x${sh}"
  else bad "render paragraph --rotate 30: ${w}x${h}, --scale 1.5,1: ${sw}x${sh}"; fi
else
  bad "render paragraph with transforms failed: $(cat "$tmp/stderr")"
fi
expect_error "render: paragraph NaN rotation" 1 "finite" -- render --size 20 --text hi --rotate nan --width 100 -o "$tmp/out.png"
expect_error "render: paragraph singular map" 1 "singular" -- render --size 20 --text hi --scale 0,1 --width 100 -o "$tmp/out.png"
expect_error "render: paragraph behind the viewer" 1 "behind" -- render --size 20 --width 300 --text "Hamburgefontsiv and more" --perspective 80,20 -o "$tmp/out.png"
expect_error "render: paragraph transformed image too large" 1 "largest side" -- render --size 20 --text hi --width 100 --scale 1e4 -o "$tmp/out.png"
expect_error "render: perspective default distance twice" 2 "first" -- render --size 20 --text hi --perspective 10 --perspective 20 -o "$tmp/out.png"
for mode in vbaa msaa auto; do
  if timeout 120 "$CURVETEXT" render --size 12 --text "Hamburg" --aa $mode --rotate 10 -o "$tmp/$mode.png" 2>"$tmp/stderr"; then
    ok "render --aa $mode"
  else
    bad "render --aa $mode failed: $(cat "$tmp/stderr")"
  fi
done
expect_error "render: unknown aa mode" 1 "vbaa" -- render --size 20 --text hi --aa ssaa -o "$tmp/out.png"

# --- debug view, blending, gamma, vbaa filter -----------------------------------
for extra in "--debug" "--blend linear" "--blend srgb --gamma 1.8" "--aa vbaa --vbaa-filter paper" \
             "--aa vbaa --vbaa-filter 0.25 --blend linear --fg #ffffff --bg #000000"; do
  # shellcheck disable=SC2086
  if timeout 120 "$CURVETEXT" render --size 16 --text "Hamburg" $extra -o "$tmp/opt.png" 2>"$tmp/stderr" &&
     [ -s "$tmp/opt.png" ]; then
    ok "render $extra"
  else
    bad "render $extra failed: $(cat "$tmp/stderr")"
  fi
done
shape_json="$tmp/arc.json"
echo '{"size": [60, 40], "view": [-5, -5, 55, 35], "shapes": [{"contours": [[{"bezier": {"points": [[0, 0], [25, 50], [50, 0]], "weights": [1, 0.5, 1]}}, {"line": [[50, 0], [0, 0]]}]]}]}' >"$shape_json"
if timeout 120 "$CURVETEXT" shape --input "$shape_json" --debug --blend linear --gamma 1.5 -o "$tmp/arc.png" 2>"$tmp/stderr"; then
  ok "shape --debug --blend linear --gamma 1.5"
else
  bad "shape --debug failed: $(cat "$tmp/stderr")"
fi
expect_error "render: NaN gamma" 1 "--gamma must be a number from 0.25 to 4" -- render --size 20 --text hi --gamma nan -o "$tmp/out.png"
expect_error "render: gamma 0" 1 "--gamma must be" -- render --size 20 --text hi --gamma 0 -o "$tmp/out.png"
expect_error "render: gamma 10" 1 "--gamma must be" -- render --size 20 --text hi --gamma 10 -o "$tmp/out.png"
expect_error "render: gamma not a number" 2 "needs a number" -- render --size 20 --text hi --gamma dark -o "$tmp/out.png"
expect_error "render: unknown blending" 1 "unknown blending 'gamma'" -- render --size 20 --text hi --blend gamma -o "$tmp/out.png"
expect_error "render: unknown vbaa filter" 1 "unknown vbaa filter" -- render --size 20 --text hi --vbaa-filter gauss -o "$tmp/out.png"
expect_error "render: NaN vbaa ring" 1 "unknown vbaa filter" -- render --size 20 --text hi --vbaa-filter nan -o "$tmp/out.png"
expect_error "render: vbaa ring above 1" 1 "unknown vbaa filter" -- render --size 20 --text hi --vbaa-filter 2 -o "$tmp/out.png"
for extra in "--debug" "--blend linear --gamma 1.8" "--aa vbaa --vbaa-filter paper" "--aa auto" "--aa auto --scale 30"; do
  # shellcheck disable=SC2086
  if timeout 120 "$CURVETEXT" render --size 16 --width 120 --markup --text "<u>Hamburg</u> <s>and</s> more words" $extra -o "$tmp/popt.png" 2>"$tmp/stderr" &&
     [ -s "$tmp/popt.png" ]; then
    ok "render paragraph $extra"
  else
    bad "render paragraph $extra failed: $(cat "$tmp/stderr")"
  fi
done
expect_error "render: paragraph NaN gamma" 1 "--gamma must be" -- render --size 20 --text hi --gamma nan --width 100 -o "$tmp/out.png"
expect_error "render: paragraph unknown blending" 1 "unknown blending" -- render --size 20 --text hi --blend x --width 100 -o "$tmp/out.png"
expect_error "render: paragraph unknown vbaa filter" 1 "unknown vbaa filter" -- render --size 20 --text hi --vbaa-filter -1 --width 100 -o "$tmp/out.png"
# Shapes: auto, the vbaa filter and transforms (--scale stays pixels per unit there).
for extra in "--aa auto" "--aa vbaa --vbaa-filter 0.25" "--rotate 30" "--perspective 40 --aa auto" "--skew 10,5 --transform 1,0,0,0,2,0" \
             "--scale 4 --aa auto"; do
  # shellcheck disable=SC2086
  if timeout 120 "$CURVETEXT" shape --input "$shape_json" $extra -o "$tmp/sopt.png" 2>"$tmp/stderr" && [ -s "$tmp/sopt.png" ]; then
    ok "shape $extra"
  else
    bad "shape $extra failed: $(cat "$tmp/stderr")"
  fi
done
read -r w h <<<"$(png_size "$tmp/sopt.png")"
if [ "$w" -eq 240 ] && [ "$h" -eq 160 ]; then ok "shape --scale 4 is pixels per unit (240x160)"; else bad "shape --scale 4: ${w}x${h}, want 240x160"; fi
timeout 120 "$CURVETEXT" shape --input "$shape_json" --rotate 90 -o "$tmp/srot.png" 2>"$tmp/stderr"
read -r w h <<<"$(png_size "$tmp/srot.png")"
if [ "$w" -eq 40 ] && [ "$h" -eq 60 ]; then ok "shape --rotate 90 turns the 60x40 image (40x60)"; else bad "shape --rotate 90: ${w}x${h}, want 40x60"; fi
expect_error "shape: NaN rotation" 1 "finite" -- shape --input "$shape_json" --rotate nan -o "$tmp/out.png"
expect_error "shape: singular transform" 1 "singular" -- shape --input "$shape_json" --transform 1,0,0,0,0,0 -o "$tmp/out.png"
expect_error "shape: behind the viewer" 1 "behind" -- shape --input "$shape_json" --perspective 85,10 -o "$tmp/out.png"
expect_error "shape: transformed image too large" 1 "largest side" -- shape --input "$shape_json" --transform 1000,0,0,0,1,0 -o "$tmp/out.png"
expect_error "shape: unknown vbaa filter" 1 "unknown vbaa filter" -- shape --input "$shape_json" --vbaa-filter big -o "$tmp/out.png"
expect_error "shape: skew 90" 1 "skew" -- shape --input "$shape_json" --skew 90 -o "$tmp/out.png"
expect_error "shape: NaN gamma" 1 "--gamma must be" -- shape --input "$shape_json" --gamma nan -o "$tmp/out.png"
expect_error "shape: unknown blending" 1 "unknown blending" -- shape --input "$shape_json" --blend lin -o "$tmp/out.png"

# --- input limits: a clear error in bounded time, no image ----------------------
expect_error "render: endless --text-file stops at the limit" 1 "larger than the limit" -- render --size 16 --text-file /dev/zero -o "$tmp/out.png"
expect_error "render: endless standard input stops at the limit" 1 "standard input is larger than the limit" -- render --size 16 --text-file - -o "$tmp/out.png" </dev/zero
expect_error "render: --perspective 89.99 leaves a sliver" 1 "sliver" -- render --size 32 --text Hello --perspective 89.99 -o "$tmp/out.png"
deep=$(printf '<b>%.0s' $(seq 1000))x$(printf '</b>%.0s' $(seq 1000))
expect_error "render: markup nested 1000 deep" 1 "nested deeper than 64" -- render --size 16 --width 200 --markup --text "$deep" -o "$tmp/out.png"
python3 -c "import sys; sys.stdout.write('a' + '\u0301' * 20000)" >"$tmp/marks.txt"
expect_error "render: a + 20000 combining marks" 1 "grapheme cluster of 20001" -- render --size 16 --text-file "$tmp/marks.txt" -o "$tmp/out.png"
# Text effects: white text on white shows only its outline or shadow; --outline and the markup's
# outline= draw the same image.
if timeout 60 "$CURVETEXT" render --size 40 --text Hi --fg white --outline 2,black -o "$tmp/outline.png" 2>"$tmp/stderr" &&
   timeout 60 "$CURVETEXT" render --size 40 --markup --text '<span outline="2 black">Hi</span>' --fg white -o "$tmp/outline-markup.png" 2>>"$tmp/stderr" &&
   timeout 60 "$CURVETEXT" render --size 40 --text Hi --fg white --shadow 3,3,4,black -o "$tmp/shadow.png" 2>>"$tmp/stderr" &&
   read -r _ _ same ink_outline ink_markup <<<"$(python3 "$(dirname "$0")/png_diff.py" "$tmp/outline.png" "$tmp/outline-markup.png")" &&
   read -r _ _ _ ink_shadow _ <<<"$(python3 "$(dirname "$0")/png_diff.py" "$tmp/shadow.png" "$tmp/shadow.png")" &&
   [ "$same" -eq 0 ] && [ "$ink_outline" -gt $((150 * 255)) ] && [ "$ink_shadow" -gt $((150 * 255)) ]; then
  ok "render: --outline, markup outline= and --shadow drawn (ink $ink_outline, $ink_shadow)"
else bad "render: text effects: $(cat "$tmp/stderr") ${same:-?} ${ink_outline:-?} ${ink_shadow:-?}"; fi
expect_error "render: --outline without a colour" 1 "expected W,COLOR" -- render --text x --outline 3 -o "$tmp/out.png"
expect_error "render: negative --outline" 1 "outline width must not be negative" -- render --text x --outline -3,red -o "$tmp/out.png"
expect_error "render: NaN shadow blur" 1 "blur radius must be a finite number" -- render --text x --shadow 1,1,nan,red -o "$tmp/out.png"
expect_error "render: --outline wider than an em" 1 "outline width must be a number from 0 to 16 px" -- render --size 16 --text x --outline 300,red -o "$tmp/out.png"
expect_error "render: --shadow blur past the limit" 1 "blur radius must be a number from 0 to 128 px" -- render --text x --shadow 0,0,1e6,red -o "$tmp/out.png"
expect_error "render: --outline with SVG output" 1 "apply to PNG output only" -- render --text x --outline 3,red -o "$tmp/out.svg"
expect_error "render: markup outline without a colour" 1 "outline: expected 'W COLOR'" -- render --markup --text '<span outline="3">x</span>' -o "$tmp/out.png"
printf '<svg width="100" height="100"><path d="M10 10 L90 90 L10 90 Z" fill="none" stroke="black"/></svg>' >"$tmp/stroke.svg"
# An SVG stroke is drawn: a triangle's outline 1 unit wide has about 273 px of ink at 1 px per unit.
if timeout 60 "$CURVETEXT" shape --input "$tmp/stroke.svg" -o "$tmp/stroke.png" 2>"$tmp/stderr" &&
   read -r _ _ _ ink _ <<<"$(python3 "$(dirname "$0")/png_diff.py" "$tmp/stroke.png" "$tmp/stroke.png")" &&
   [ "$ink" -gt $((250 * 255)) ] && [ "$ink" -lt $((300 * 255)) ]; then ok "shape: SVG stroke drawn (ink $ink)"
else bad "shape: SVG stroke: $(cat "$tmp/stderr") ink ${ink:-?}"; fi
printf '<svg width="100" height="100"><path d="M10 10 L90 90" stroke="black" transform="scale(1 2)"/></svg>' >"$tmp/stroke2.svg"
if timeout 60 "$CURVETEXT" shape --input "$tmp/stroke2.svg" -o "$tmp/out.png" 2>"$tmp/stderr"; then ok "shape: SVG stroke under a non-uniform scale drawn"; else bad "shape: SVG stroke under a non-uniform scale: $(cat "$tmp/stderr")"; fi
expect_error "layout: markup error names its byte" 1 "markup, byte 7: </b> does not close <i>" -- layout --size 16 --markup --text "<b><i>x</b></i>" --json
# Markup nests: the bold word inside a coloured span is still bold.
if timeout 60 "$CURVETEXT" layout --size 16 --markup --text "<color=red>red <b>bold</b></color>" --json >"$tmp/tree.json" 2>"$tmp/stderr" &&
   grep -q 'DejaVuSans-Bold' "$tmp/tree.json"; then
  ok "layout: <b> inside <color> keeps the bold face"
else
  bad "layout: <b> inside <color> lost the bold face: $(head -c 300 "$tmp/tree.json") $(cat "$tmp/stderr")"
fi

# --- one layout path: every render is a paragraph (bidi, fallback) ------------------
here=$(dirname "$0")
cli_abs=$(realpath "$CURVETEXT")
# The default render of right-to-left, joined and fallback text equals the
# paragraph path's image (--width 0) pixel for pixel, and the layout behind
# it is right: Hebrew right to left, Arabic joined, CJK from a fallback face.
for sample in "שלום עולם" "Arabic سلام عليكم text" "中文字体 and Latin"; do
  if timeout 120 "$CURVETEXT" render --size 24 --text "$sample" -o "$tmp/default.png" 2>"$tmp/stderr" &&
     timeout 120 "$CURVETEXT" render --size 24 --text "$sample" --width 0 -o "$tmp/para0.png" 2>>"$tmp/stderr" &&
     cmp -s "$tmp/default.png" "$tmp/para0.png"; then
    ok "render '$sample' equals the paragraph path's image"
  else
    bad "render '$sample' differs from --width 0: $(cat "$tmp/stderr")"
  fi
done
timeout 60 "$CURVETEXT" layout --size 24 --text "שלום" >"$tmp/he.json" 2>"$tmp/stderr"
timeout 60 "$CURVETEXT" layout --size 24 --text "سلام" >"$tmp/ar.json" 2>>"$tmp/stderr"
timeout 60 "$CURVETEXT" layout --size 24 --text "س" >"$tmp/ar1.json" 2>>"$tmp/stderr"
timeout 60 "$CURVETEXT" layout --size 24 --text "中文" >"$tmp/cjk.json" 2>>"$tmp/stderr"
if python3 - "$tmp" <<'PY'
import json, sys
d = sys.argv[1]
glyphs = lambda f: [g for r in json.load(open(d + f))["lines"][0]["runs"] for g in r["glyphs"]]
runs = lambda f: json.load(open(d + f))["lines"][0]["runs"]
he = glyphs("/he.json")
# Visual order right to left: the first character (cluster 0) is drawn rightmost.
assert runs("/he.json")[0]["direction"] == "rtl" and max(he, key=lambda g: g["x"])["cluster"] == 0, he
ar, alone = glyphs("/ar.json"), glyphs("/ar1.json")
first = [g for g in ar if g["cluster"] == 0][0]
assert first["id"] != alone[0]["id"], "seen initial form is the isolated one: not joined"
assert all(g["id"] != 0 for g in glyphs("/cjk.json")) and "DejaVu" not in runs("/cjk.json")[0]["font"]
PY
then ok "layout: Hebrew right to left, Arabic joined, CJK from a fallback font"; else bad "layout of Hebrew/Arabic/CJK: $(cat "$tmp/stderr")"; fi
# --font takes a fontconfig family name as well as a file.
serif=$(fc-match -f '%{file}' "DejaVu Serif")
if timeout 120 "$CURVETEXT" render --size 20 --font "DejaVu Serif" --text Hamburg -o "$tmp/family.png" 2>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" render --size 20 --font "$serif" --text Hamburg -o "$tmp/file.png" 2>>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" render --size 20 --text Hamburg -o "$tmp/sans.png" 2>>"$tmp/stderr" &&
   cmp -s "$tmp/family.png" "$tmp/file.png" && ! cmp -s "$tmp/family.png" "$tmp/sans.png"; then
  ok "render --font 'DejaVu Serif' (family name) equals the file's image"
else
  bad "render --font family name: $(cat "$tmp/stderr")"
fi
# fontconfig answers any family with its best match: a family it lacks is refused, not replaced.
expect_error "render: unknown family refused" 1 "no font family 'No Such Family'" -- render --size 20 --font "No Such Family" --text hi -o "$tmp/out.png"
expect_error "render: face index of a family" 1 "face-index" -- render --size 20 --font "DejaVu Serif" --face-index 1 --text hi -o "$tmp/out.png"

# --- output formats, standard streams, option forms -----------------------------
expect_error "render: unknown output extension" 1 "out.jpg" -- render --size 20 --text hi -o "$tmp/out.jpg"
[ -e "$tmp/out.jpg" ] && bad "render: wrote out.jpg despite the error"
expect_error "shape: svg output refused" 1 "PNG only" -- shape --input "$shapes/ellipse-arc.svg" -o "$tmp/out.svg"
expect_error "render: raster option with SVG" 1 "--aa applies to PNG" -- render --size 20 --text hi --aa none -o "$tmp/out.svg"
expect_error "render: underline in SVG refused" 1 "underline" -- render --size 20 --markup --text "<u>hi</u>" -o "$tmp/out.svg"
expect_error "render: bad --format" 2 "--format" -- render --text hi --format gif -o -
if timeout 120 "$CURVETEXT" render --size 24 --text "Hamburg Qg" -o "$tmp/vec.svg" 2>"$tmp/stderr" &&
   head -c 5 "$tmp/vec.svg" | grep -q "<svg" &&
   timeout 120 "$CURVETEXT" render --size 24 --text "Hamburg Qg" -o "$tmp/vec.png" 2>>"$tmp/stderr" &&
   timeout 120 "$CURVETEXT" shape --input "$tmp/vec.svg" -o "$tmp/vec-back.png" 2>>"$tmp/stderr" &&
   read -r w h maxdiff ink_png ink_svg <<<"$(python3 "$here/png_diff.py" "$tmp/vec.png" "$tmp/vec-back.png")" &&
   # The SVG's outlines (rounded to 1/1000 px) drawn as a shape: the same
   # exact-area coverage as the text, so at most a few levels apart (the
   # text's glyphs blend one over another where two share a pixel, the
   # shape's union is one coverage; the shape goes through an 8-bit buffer).
   [ "$maxdiff" -le 4 ] && [ "$ink_png" -gt 10000 ] &&
   python3 -c "import sys; a, b = int(sys.argv[1]), int(sys.argv[2]); sys.exit(abs(a - b) > 1e-3 * a)" "$ink_png" "$ink_svg"; then
  ok "render -o x.svg: outlines drawn back equal the PNG (${w}x${h}, max diff $maxdiff, ink $ink_png vs $ink_svg)"
else
  bad "render -o x.svg: $(cat "$tmp/stderr") ${maxdiff:-} ${ink_png:-} ${ink_svg:-}"
fi
(cd "$tmp" && timeout 120 "$cli_abs" render --size 24 --text "Hamburg Qg" -o - >"$tmp/stdout.png" 2>"$tmp/stderr")
if cmp -s "$tmp/stdout.png" "$tmp/vec.png" && [ ! -e "$tmp/-" ]; then ok "render -o - writes the PNG to standard output"
else bad "render -o -: $(cat "$tmp/stderr"); file '-' exists: $([ -e "$tmp/-" ] && echo yes || echo no)"; fi
if timeout 120 "$CURVETEXT" render --size 24 --text "Hamburg Qg" --format svg -o - >"$tmp/stdout.svg" 2>"$tmp/stderr" &&
   cmp -s "$tmp/stdout.svg" "$tmp/vec.svg"; then ok "render --format svg -o - writes the SVG to standard output"
else bad "render --format svg -o -: $(cat "$tmp/stderr")"; fi
if printf 'Hamburg Qg\n' | timeout 120 "$CURVETEXT" render --size 24 --text - -o "$tmp/stdin1.png" 2>"$tmp/stderr" &&
   printf 'Hamburg Qg' | timeout 120 "$CURVETEXT" render --size 24 --text-file - -o "$tmp/stdin2.png" 2>>"$tmp/stderr" &&
   cmp -s "$tmp/stdin1.png" "$tmp/vec.png" && cmp -s "$tmp/stdin2.png" "$tmp/vec.png"; then
  ok "render --text - and --text-file - read standard input"
else
  bad "render text from standard input: $(cat "$tmp/stderr")"
fi
if timeout 120 "$CURVETEXT" render --size=24 --text="Hamburg Qg" --output="$tmp/eq.png" 2>"$tmp/stderr" &&
   cmp -s "$tmp/eq.png" "$tmp/vec.png"; then ok "render --opt=value"; else bad "render --opt=value: $(cat "$tmp/stderr")"; fi
expect_error "render: a flag given a value" 2 "--debug takes no value" -- render --text hi --debug=1 -o "$tmp/out.png"
# Default size 32 px: DejaVu Sans' line is ceil(2*16 + 32*1.164) = 70 px high.
if timeout 120 "$CURVETEXT" render --text "Hamburg" -o "$tmp/nosize.png" 2>"$tmp/stderr" &&
   [ "$(png_size "$tmp/nosize.png" | cut -d' ' -f2)" = "70" ]; then ok "render without --size (32 px)"
else bad "render without --size: $(cat "$tmp/stderr") $(png_size "$tmp/nosize.png" 2>/dev/null)"; fi
# layout prints JSON without --json; letter and word spacing widen the line.
if timeout 60 "$CURVETEXT" layout --size 20 --text "ab cd" >"$tmp/plain.json" 2>"$tmp/stderr" &&
   timeout 60 "$CURVETEXT" layout --size 20 --text "ab cd" --letter-spacing 3 >"$tmp/ls.json" 2>>"$tmp/stderr" &&
   timeout 60 "$CURVETEXT" layout --size 20 --text "ab cd" --word-spacing=7 --json >"$tmp/ws.json" 2>>"$tmp/stderr" &&
   python3 - "$tmp" <<'PY'
import json, sys
width = lambda f: json.load(open(sys.argv[1] + f))["logical"][2]
base = width("/plain.json")
# 5 clusters, 3 px after each (the last one's trailing spacing may be kept or not); one space, 7 px.
assert width("/ls.json") - base in (12, 15), (base, width("/ls.json"))
assert abs(width("/ws.json") - base - 7) < 1e-3, (base, width("/ws.json"))
PY
then ok "layout: JSON by default, --letter-spacing, --word-spacing"; else bad "layout JSON/spacing: $(cat "$tmp/stderr")"; fi
# --- many images from one process: --jobs ---------------------------------------
# Each job's image equals the one its options give alone, byte for byte, with
# fallback, markup, a family name, a transform and SVG among them; a bad job is
# reported with its line and the others are still done.
mkdir -p "$tmp/batch"
cat >"$tmp/batch/jobs.jsonl" <<JOBS
{"text": "Hamburg Qg", "size": 24, "output": "$tmp/batch/a.png"}
{"text": "Caf\u00e9 \u4e2d\u6587 \u0627\u0644\u0639\u0631\u0628\u064a\u0629", "size": 20, "fg": "#204080", "output": "$tmp/batch/b.png"}

{"text": "<b>Bold</b> <i>it</i> <u>u</u>", "markup": true, "font": ["DejaVu Serif", "Noto Sans"], "output": "$tmp/batch/c.png"}
{"text": "x", "sizee": 3, "output": "$tmp/batch/bad1.png"}
{"text": "Turned", "rotate": 30, "scale": "1.5,1", "aa": "vbaa", "debug": false, "output": "$tmp/batch/d.png"}
{"text": "x" "output": "$tmp/batch/bad2.png"}
{"text-file": "$tmp/text.txt", "width": 60, "align": "center", "output": "$tmp/batch/e.svg"}
JOBS
single_args=(
  "a.png|--text|Hamburg Qg|--size|24"
  "b.png|--text|Café 中文 العربية|--size|20|--fg|#204080"
  "c.png|--text|<b>Bold</b> <i>it</i> <u>u</u>|--markup|--font|DejaVu Serif|--font|Noto Sans"
  "d.png|--text|Turned|--rotate|30|--scale|1.5,1|--aa|vbaa"
  "e.svg|--text-file|$tmp/text.txt|--width|60|--align|center"
)
timeout 120 "$CURVETEXT" render --jobs "$tmp/batch/jobs.jsonl" >"$tmp/batch/report" 2>"$tmp/batch/stderr"
rc=$?
same=0
for spec in "${single_args[@]}"; do
  IFS='|' read -r -a parts <<<"$spec"
  timeout 120 "$CURVETEXT" render "${parts[@]:1}" -o "$tmp/batch/single-${parts[0]}" 2>>"$tmp/batch/stderr-single" &&
    cmp -s "$tmp/batch/single-${parts[0]}" "$tmp/batch/${parts[0]}" && same=$((same + 1))
done
if [ "$rc" -eq 1 ] && [ "$same" -eq 5 ] && [ ! -e "$tmp/batch/bad1.png" ] && [ ! -e "$tmp/batch/bad2.png" ] &&
   [ "$(wc -l <"$tmp/batch/report")" -eq 7 ] &&
   grep -qF '{"line":5,"error":"unknown key \"sizee\""}' "$tmp/batch/report" &&
   grep -qF "{\"line\":4,\"output\":\"$tmp/batch/c.png\"}" "$tmp/batch/report" &&
   grep -qF "jobs.jsonl:7: column 14: expected ',' or '}'" "$tmp/batch/stderr" &&
   grep -qF "2 of 7 jobs failed" "$tmp/batch/stderr"; then
  ok "render --jobs: 5 images equal to single renders, 2 bad lines reported by number"
else
  bad "render --jobs: exit $rc, $same of 5 equal; report: $(cat "$tmp/batch/report"); stderr: $(cat "$tmp/batch/stderr" "$tmp/batch/stderr-single" 2>/dev/null)"
fi
# From standard input, and shape too; every job done: exit 0.
if printf '{"input": "%s", "output": "%s"}\n{"input": "%s", "size": "100x50", "aa": "none", "output": "%s"}\n' \
     "$shapes/pentagram-evenodd.json" "$tmp/batch/star.png" "$shapes/ellipse-arc.svg" "$tmp/batch/ellipse.png" |
   timeout 120 "$CURVETEXT" shape --jobs - >"$tmp/batch/report" 2>"$tmp/batch/stderr" &&
   cmp -s "$tmp/batch/star.png" "$tmp/star.png" && cmp -s "$tmp/batch/ellipse.png" "$tmp/ellipse.png" &&
   [ "$(wc -l <"$tmp/batch/report")" -eq 2 ] && [ ! -s "$tmp/batch/stderr" ]; then
  ok "shape --jobs -: images equal to single renders"
else
  bad "shape --jobs -: $(cat "$tmp/batch/report" "$tmp/batch/stderr")"
fi
expect_error "render --jobs with other options" 2 "takes no other options" -- render --jobs "$tmp/batch/jobs.jsonl" --size 3
expect_error "render --jobs after other options" 2 "takes no other options" -- render --size 3 --jobs "$tmp/batch/jobs.jsonl"
expect_error "render --jobs: no such file" 1 "cannot read the job list" -- render --jobs "$tmp/batch/none.jsonl"
# A line over the limit (8 MiB) and a list of over 100,000 jobs: refused, bounded.
python3 -c "import sys; sys.stdout.write('{\"text\": \"' + 'a' * (9 << 20) + '\"}\n{\"text\": \"after\", \"output\": \"' + sys.argv[1] + '\"}\n')" \
  "$tmp/batch/after.png" >"$tmp/batch/long.jsonl"
timeout 60 "$CURVETEXT" render --jobs "$tmp/batch/long.jsonl" >"$tmp/batch/report" 2>"$tmp/batch/stderr"
rc=$?
if [ "$rc" -eq 1 ] && grep -qF "long.jsonl:1: longer than 8388608 bytes" "$tmp/batch/stderr" && [ -s "$tmp/batch/after.png" ]; then
  ok "render --jobs: an overlong line refused, the next job done"
else
  bad "render --jobs overlong line: exit $rc, $(head -c 300 "$tmp/batch/stderr")"
fi
python3 -c "import sys; sys.stdout.write('{}\n' * 100001)" >"$tmp/batch/many.jsonl"
timeout 60 "$CURVETEXT" render --jobs - <"$tmp/batch/many.jsonl" >"$tmp/batch/report" 2>"$tmp/batch/stderr"
rc=$?
if [ "$rc" -eq 1 ] && grep -qF "standard input:100001: more than 100000 jobs" "$tmp/batch/stderr" &&
   [ "$(wc -l <"$tmp/batch/report")" -eq 100000 ]; then
  ok "render --jobs: a list of more than 100,000 jobs stops there"
else
  bad "render --jobs too many: exit $rc, $(tail -n 2 "$tmp/batch/stderr")"
fi

# Every option a command parses is listed in --help and in docs/cli.md.
"$CURVETEXT" --help >"$tmp/help.txt"
missing=""
for o in $(grep -ohE '(a|o) == "--[a-z-]+"' "$here/../../tools/curvetext/"*.cpp | grep -oE -- '--[a-z-]+' | sort -u); do
  grep -q -- "$o" "$tmp/help.txt" || missing="$missing $o(help)"
  grep -q -- "\`$o" "$here/../../docs/cli.md" || missing="$missing $o(docs)"
done
if [ -z "$missing" ]; then ok "every option is in --help and docs/cli.md"; else bad "options missing:$missing"; fi

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
