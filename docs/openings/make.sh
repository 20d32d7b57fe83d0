#!/bin/sh
# Each scene's opening as `play` shows it in a 960x540 window, 30 frames in: "before" from a build
# of the previous version (BEFORE=path/to/its/oceanbox, its own config/scenes), "after" from
# this one. Run from the repository root under a virtual display:
#   Xvfb :42 -screen 0 1280x720x24 & DISPLAY=:42 BEFORE=../old/build/bin/oceanbox docs/openings/make.sh
set -e
out=docs/openings
for scene in config/scenes/*.toml; do
    name=$(basename "$scene" .toml)
    [ "$name" = fish_swarm ] && continue  # a benchmark, not a sight
    [ -n "$KEEP" ] && [ -f "$out/${name}_after.png" ] && continue  # KEEP=1: only the missing ones
    if [ -n "$BEFORE" ]; then
        "$BEFORE" play "$(dirname "$BEFORE")/../../$scene" --size 960x540 --frames 30 --screenshot "$out/${name}_before.png" || true
    fi
    build/bin/oceanbox play "$scene" --size 960x540 --frames 30 --screenshot "$out/${name}_after.png"
done
