#!/bin/sh
# Builds the libFuzzer targets (clang -O1, libFuzzer's advice; -fsanitize=fuzzer,address,undefined) in build-fuzz/
# and runs each for SECONDS (default 60) on its seeds: tests/fuzz/corpus/<target>/ plus the
# project's scenes (config/scenes) and models (assets/models); the --set key-path parser and
# the .npy reader from their seeds alone. New inputs go to
# build-fuzz/corpus/<target>/, findings to build-fuzz/findings/<target>/; the script fails
# on the first target that finds one. Usage: tests/fuzz/run.sh [SECONDS] [BUILD_DIR]
set -e
seconds=${1:-60}
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${2:-$root/build-fuzz}
jobs=${OCEANBOX_FUZZ_BUILD_JOBS:-2}

cmake -S "$root" -B "$build" -DOCEANBOX_FUZZ=ON -DOCEANBOX_TESTS=OFF -DOCEANBOX_UNITY=ON \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" > /dev/null
cmake --build "$build" -j"$jobs" --target fuzz_scene fuzz_gltf fuzz_keypath fuzz_npy

status=0
for target in scene gltf keypath npy; do
  case $target in
    scene) seeds="$root/tests/fuzz/corpus/scene $root/config/scenes" ;;
    gltf) seeds="$root/tests/fuzz/corpus/gltf $root/assets/models" ;;
    keypath) seeds="$root/tests/fuzz/corpus/keypath" ;;
    npy) seeds="$root/tests/fuzz/corpus/npy" ;;
  esac
  mkdir -p "$build/corpus/$target" "$build/findings/$target"
  echo "fuzz_$target: ${seconds} s"
  # From the source tree, so scenes find assets/models; -timeout: an input that takes
  # longer than 10 s is a hang; -rss_limit_mb: one that needs more than 2 GiB is a finding.
  if ! (cd "$root" && "$build/bin/fuzz_$target" "$build/corpus/$target" $seeds \
          -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=131072 \
          -artifact_prefix="$build/findings/$target/" -print_final_stats=1 \
          > "$build/fuzz_$target.log" 2>&1); then
    echo "fuzz_$target: FOUND a crash, hang or leak; input in $build/findings/$target/, log $build/fuzz_$target.log"
    tail -n 40 "$build/fuzz_$target.log"
    status=1
  else
    grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE" "$build/fuzz_$target.log" | sed "s/^/fuzz_$target: /"
  fi
done
exit $status
