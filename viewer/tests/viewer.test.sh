#!/usr/bin/env bash
# The viewer's tests, one case per ctest test (viewer/tests/CMakeLists.txt):
#   viewer.test.sh CASE VIEWER REFERENCE_VIEWER PNG_PROBE OUTPUT_DIR
# Each renders under xvfb-run with Mesa's software renderer (llvmpipe) and checks the
# picture with png_probe, or checks that bad input gives the viewer's one-line reason and
# a non-zero exit.
set -uo pipefail
case_name=$1 student=$2 reference=$3 probe=$4 out=$5
mkdir -p "$out"
command -v xvfb-run >/dev/null || { echo "SKIP: xvfb-run is not installed (apt-get install xvfb xauth)"; exit 77; }
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
headless() { xvfb-run -a -s "-screen 0 1280x800x24" "$@"; }
fail() { echo "FAIL: $*"; exit 1; }

# The colours the scenes draw with (viewer/render.h, palette).
agree=4dd966 exact=c766ff surface=73a0d9 inside=5a9eff

# Runs a command that must fail: a non-zero exit, no core, and the viewer's reason in one
# line of its own ("labkit-viewer: ..."). Other tools' lines are not counted: xvfb-run,
# Mesa or X may add theirs ("problem while cleaning up temporary directory"), and no
# test may depend on them.
one_line_error() {
  local expect=$1; shift
  local err code
  err=$("$@" 2>&1 >/dev/null); code=$?
  echo "$* -> exit $code: $err"
  [ $code -ne 0 ] || fail "exit 0 for bad input"
  [ $code -lt 128 ] || fail "it crashed (exit $code)"
  [ "$(grep -c '^labkit-viewer: ' <<<"$err")" -eq 1 ] || fail "expected one 'labkit-viewer: ' line on stderr"
  grep '^labkit-viewer: ' <<<"$err" | grep -q -- "$expect" || fail "the viewer's message does not say '$expect'"
}

case $case_name in
  scene01)  # the reference's scene: green pieces, violet exact outline, blue 'in' vertices
    headless "$reference" 01 --screenshot "$out/01.png" || fail "the viewer failed"
    "$probe" "$out/01.png" $agree 500 $exact 300 $inside 30 || fail "the picture lacks the scene's colours"
    ;;
  scene02)  # green answers, violet exact rings, the blue triangle
    headless "$reference" 02 --screenshot "$out/02.png" || fail "the viewer failed"
    "$probe" "$out/02.png" $agree 200 $exact 100 $surface 300 || fail "the picture lacks the scene's colours"
    ;;
  replay)  # a token from ./labkit check opens exactly that case, in the mode its query names
    log=$(headless "$reference" 02 --case 'first_hit:1,3,5,1,3,-1,8,0,0,0,4,0,0,4,4,0,0,4,0,0,0,2,4,0,2,4,4,2,0,4,2,4,0,1,2,0,2,3,4,5,6,4,6,7' \
          --screenshot "$out/replay.png") || fail "the viewer failed: $log"
    echo "$log"
    grep -q "segment and mesh" <<<"$log" || fail "the first_hit token did not open the mesh mode"
    grep -q "L02S5.*agrees" <<<"$log" || fail "the reference's first hit does not agree"
    "$probe" "$out/replay.png" $agree 100 $exact 50 || fail "the picture lacks the scene's colours"
    log=$(headless "$reference" --case 'split_triangle:0,0,-1,4,0.5,1,1,3.5,3,0,0,1,-2' --screenshot "$out/replay01.png") ||
      fail "the viewer failed: $log"
    grep -q "lab 01 (triangle and plane)" <<<"$log" || fail "a lab 01 token without a lab number did not open lab 01"
    ;;
  stubs)  # the student's viewer on the stubs: every step says so, nothing crashes
    for lab in 01 02; do
      log=$(headless "$student" $lab --screenshot "$out/stub$lab.png") || fail "the student's viewer failed on lab $lab"
      echo "$log"
      steps=$(grep -c "^  L" <<<"$log")
      stubs=$(grep -c "not implemented yet" <<<"$log")
      [ "$steps" -gt 0 ] && [ "$steps" -eq "$stubs" ] || fail "lab $lab: $stubs of $steps steps say 'not implemented yet'"
      "$probe" "$out/stub$lab.png" $surface 150 || fail "the stub's picture lacks the scene's inputs"
    done
    for preset in frustum mesh; do
      headless "$student" 01 --preset $preset --screenshot "$out/stub-$preset.png" >/dev/null || fail "preset $preset crashed on the stubs"
    done
    for preset in shelf moving; do
      headless "$student" 02 --preset $preset --screenshot "$out/stub-$preset.png" >/dev/null || fail "preset $preset crashed on the stubs"
    done
    ;;
  presets)  # every preset of every scene opens, as the handouts' figures need, and the
    # reference agrees with the exact answer in each (a red mark there would teach a lie)
    "$reference" --list-presets | while read -r lab name rest; do
      headless "$reference" "$lab" --figure "$name" --size 480x300 --frames 2 --screenshot "$out/$lab-$name.png" \
        >"$out/$lab-$name.txt" || fail "lab $lab preset $name failed"
      "$probe" "$out/$lab-$name.png" >/dev/null || fail "lab $lab preset $name is blank"
      if grep -q ': disagrees' "$out/$lab-$name.txt"; then
        fail "lab $lab preset $name: the reference disagrees: $(grep ': disagrees' "$out/$lab-$name.txt")"
      fi
    done || exit 1
    ;;
  bad_input)
    one_line_error "no lab '99'" "$reference" 99
    one_line_error "ends after 2 numbers" "$reference" 02 --case 'segment_plane:1,2'
    one_line_error "inputs are finite numbers" "$reference" 02 --case 'segment_plane:0,0,1,0,0,-1,nan,0,0,0,0,1'
    one_line_error "is not a number" "$reference" 05 --case 'sweep_sphere_plane:1,2,zz'
    one_line_error "looks like 'query:1,2,3'" "$reference" 02 --case 'nonsense'
    one_line_error "has no query 'clip_triangle'" "$reference" 02 --case 'clip_triangle:1,2,3'
    one_line_error "scene does not draw 'emit'" "$reference" 07 --case 'emit:1,2,3'
    one_line_error "--size needs" "$reference" 02 --size 12
    one_line_error "no display" env -u DISPLAY -u WAYLAND_DISPLAY "$reference" 02
    one_line_error "OpenGL 3.3" xvfb-run -a -s "-extension GLX" "$reference" 02 --screenshot "$out/never.png"
    one_line_error "OpenGL 3.3" env MESA_GL_VERSION_OVERRIDE=3.0 xvfb-run -a "$reference" 02 --screenshot "$out/never.png"
    ;;
  *) fail "unknown case $case_name" ;;
esac
echo "PASS: $case_name"
