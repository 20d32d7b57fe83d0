#!/bin/sh
# Every test but the long whole-scene runs under AddressSanitizer + UBSan (docs/reliability.md).
# LeakSanitizer's exit-time check stops every thread with a ptrace'd tracer; that tracer itself
# sometimes crashes ("Tracer caught signal 11", google/sanitizers#1353: a runtime fault, not a
# leak, seen here about once in a few thousand GL test processes). Tests that failed only that
# way, and only those, run once more; a leak report, an ASan or UBSan report or a failed check
# fails as before.
# Usage: sh tests/sanitizers/ctest-asan.sh [build directory, default build-asan]
dir=${1:-build-asan}
log="$dir/ctest-asan.log"
ctest --test-dir "$dir" -LE long --output-on-failure -j2 --output-log "$log" && exit 0
crashes=$(grep -c "LeakSanitizer has encountered a fatal error" "$log")
failed=$(grep -c "(Failed)\|(Subprocess aborted)\|(SEGFAULT)\|(Timeout)\|(Exception)" "$log")
reports=$(grep -c "ERROR: LeakSanitizer: detected\|ERROR: AddressSanitizer\|runtime error:" "$log")
if [ "$crashes" -gt 0 ] && [ "$crashes" -ge "$failed" ] && [ "$reports" -eq 0 ]; then
    echo "ctest-asan.sh: $failed test(s) failed only by LeakSanitizer's tracer crash; running them again"
    exec ctest --test-dir "$dir" --rerun-failed --output-on-failure
fi
exit 1
