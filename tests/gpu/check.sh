#!/bin/sh
# The GPU path measured in minutes: builds if needed, runs the GL tests (the GPU twins among
# them), the frame pass by pass at 1920×1080 and 1280×720, and the ocean and ewave GPU steps
# against their CPU twins; writes OUTDIR/report.md and OUTDIR/report.csv (docs/frame.md).
#
#   tests/gpu/check.sh OUTDIR          full run (a GPU: under 5 minutes)
#   tests/gpu/check.sh OUTDIR --quick  small sizes and few frames (llvmpipe: checks the script)
#
# Headless GL: EGL on a GPU (an NVIDIA driver is found), OSMesa (llvmpipe) otherwise; set
# OCEANBOX_HEADLESS_GL=egl|osmesa to choose. BUILD_DIR (default build) is where it builds.
set -u
OUT=${1:?usage: tests/gpu/check.sh OUTDIR [--quick]}
MODE=${2:-full}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${BUILD_DIR:-$ROOT/build}
mkdir -p "$OUT" && OUT=$(cd "$OUT" && pwd)
cd "$ROOT" || exit 2
START=$(date +%s)

if [ -z "${OCEANBOX_HEADLESS_GL:-}" ]; then
    if [ -e /dev/nvidiactl ] || command -v nvidia-smi > /dev/null 2>&1; then OCEANBOX_HEADLESS_GL=egl; else OCEANBOX_HEADLESS_GL=osmesa; fi
fi
export OCEANBOX_HEADLESS_GL

if [ "$MODE" = "--quick" ]; then
    SIZES="320x180 160x90"; FRAMES=3; WARMUP=1; OCEAN_N=64; EWAVE_N=64; STEPS=5
    TESTS='[bindings]'  # the script's own check; the gl label runs the rest
else
    SIZES="1920x1080 1280x720"; FRAMES=60; WARMUP=10; OCEAN_N=256,512; EWAVE_N=256,512; STEPS=30
    TESTS='~[.]'
fi

# --- build (only what is missing)
if [ ! -x "$BUILD/bin/oceanbox" ] || [ ! -x "$BUILD/bin/tests_gl" ]; then
    echo "check: building in $BUILD"
    { cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release && cmake --build "$BUILD" -j"$(nproc)" --target oceanbox tests_gl; } \
        > "$OUT/build.log" 2>&1 || { echo "check: build failed, see $OUT/build.log"; exit 1; }
fi
BIN=$BUILD/bin
CSV=$OUT/report.csv
echo "section,name,value,unit" > "$CSV"
FAILED=0

# One row of the CSV; the Markdown tables are written per section below.
row() { echo "$1,$2,$3,$4" >> "$CSV"; }
# A bench CSV (comment lines start with #) as a Markdown table.
md_table() { grep -v '^#' "$1" | awk -F, 'NR == 1 { print "| " $0 " |"; s = "|"; for (i = 1; i <= NF; i++) s = s "---|"; print s; next } { print "| " $0 " |" }' | sed 's/,/ | /g'; }

# --- the GL tests, the GPU twins among them
echo "check: GL tests $TESTS ($OCEANBOX_HEADLESS_GL)"
t0=$(date +%s)
if "$BIN/tests_gl" "$TESTS" > "$OUT/tests_gl.log" 2>&1; then TESTS_RESULT=passed; else TESTS_RESULT=FAILED; FAILED=1; fi
SUMMARY=$(grep -E '^(All tests passed|test cases:)' "$OUT/tests_gl.log" | tail -1)
row tests tests_gl "$TESTS_RESULT" "$(($(date +%s) - t0)) s"

# --- the frame, pass by pass (GPU timer queries)
for size in $SIZES; do
    echo "check: bench frame default $size"
    if ! "$BIN/oceanbox" bench frame default --size "$size" --frames "$FRAMES" --warmup "$WARMUP" \
        --out "$OUT/frame_$size.csv" > "$OUT/frame_$size.log" 2>&1; then FAILED=1; continue; fi
    grep -v '^#' "$OUT/frame_$size.csv" | tail -n +2 | while IFS=, read -r name value rest; do row "frame_$size" "$name" "$value" ms; done
done

# --- the GPU steps against their CPU twins (timings; their equality is in the tests above)
echo "check: bench ocean N=$OCEAN_N cpu,gpu"
"$BIN/oceanbox" bench ocean --sizes "$OCEAN_N" --backend cpu,gpu --no-render --frames "$STEPS" --warmup 2 \
    --out "$OUT/ocean.csv" > "$OUT/ocean.log" 2>&1 || FAILED=1
# One phase's median ms of a headless run (--stats JSON), the ripple or ocean backend chosen.
phase_ms() {  # NAME PHASE SCENE SETTINGS...
    name=$1 phase=$2 scene=$3; shift 3
    what=ripples; [ "$phase" = ocean ] && what=ocean
    "$BIN/oceanbox" run "config/scenes/$scene.toml" --headless --frames "$STEPS" --size 320x180 "$@" \
        --stats "$OUT/$name.json" > "$OUT/$name.log" 2>&1 || { FAILED=1; return; }
    ms=$(python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['phases'][sys.argv[2]]['median_ms'])" "$OUT/$name.json" "$phase")
    row twins "$name" "$ms" "ms $phase phase"
    TWINS="$TWINS
| $name | $phase | $ms | $(grep -o "$what: .*backend" "$OUT/$name.log" | head -1) |"
}
TWINS=""
for backend in cpu gpu; do
    for n in $(echo "$OCEAN_N" | tr , ' '); do
        echo "check: ocean N=$n $backend"
        phase_ms "ocean_${n}_$backend" ocean default --set ocean.resolution="$n" --set ocean.backend="\"$backend\""
    done
    for n in $(echo "$EWAVE_N" | tr , ' '); do
        echo "check: ewave N=$n $backend"
        phase_ms "ewave_${n}_$backend" interaction cannon --set ripples.model='"ewave"' --set ripples.resolution="$n" \
            --set ripples.backend="\"$backend\""
    done
done

# --- the report
{
    echo "# GPU check ($(date -u '+%Y-%m-%d %H:%M UTC'))"
    echo
    echo "- commit: $(git rev-parse --short HEAD 2>/dev/null || echo '?'), mode: $MODE, headless GL: $OCEANBOX_HEADLESS_GL"
    grep -h -m1 '^# machine:' "$OUT"/frame_*.csv 2>/dev/null | head -1 | sed 's/^# */- /'
    echo "- GL tests ($TESTS): **$TESTS_RESULT** — $SUMMARY (log: tests_gl.log)"
    echo "- total: $(($(date +%s) - START)) s"
    for size in $SIZES; do
        [ -f "$OUT/frame_$size.csv" ] || continue
        echo; echo "## The default scene's frame at $size (ms, medians; gpu.pass.* by timer queries)"; echo
        md_table "$OUT/frame_$size.csv"
    done
    echo; echo "## GPU steps beside their CPU twins (median ms of the phase a frame, 320x180; equality: the tests above)"; echo
    echo "| run | phase | ms | backend |"
    echo "|---|---|---|---|$TWINS"
    if [ -f "$OUT/ocean.csv" ]; then
        echo; echo "## bench ocean: the FFT alone (ms_fft: the backend's, ms_fftw: FFTW's)"; echo
        md_table "$OUT/ocean.csv"
    fi
} > "$OUT/report.md"
echo "check: $OUT/report.md, $OUT/report.csv ($(($(date +%s) - START)) s)"
[ "$FAILED" = 0 ] || { echo "check: something failed; see the logs in $OUT"; exit 1; }
