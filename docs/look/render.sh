#!/bin/sh
# Renders docs/look.md's pictures with one build: sh docs/look/render.sh BIN OUTDIR [SCENES_DIR]
# BIN the oceanbox executable (its own shaders/ are read), OUTDIR where X.png go, SCENES_DIR the
# scene folder (default config/scenes). 640×360, llvmpipe through OSMesa, about 5 minutes.
set -e
BIN=$1 OUT=$2 S=${3:-config/scenes}
R="$BIN run --headless --size 640x360"
FIXED="--set camera.mode=fixed"
# Foam 3.4 s after a cannonball's hit (the drops landed round it).
$R $S/cannon.toml --frames 75 --steps-per-frame 4 --screenshot $OUT/cannon.png
# A fish's jump and splash at 4 s.
$R $S/fish.toml --frames 60 --steps-per-frame 4 --screenshot $OUT/fish.png
# The player's ship at full throttle (W held 2 s), seen from its port side at 5 s.
$R $S/default.toml --frames 60 --steps-per-frame 5 --input docs/look/full_throttle.toml --screenshot $OUT/trail.png
# The Kelvin wake from a headland 70 m up, the sun low ahead of the ship, at the scene's end (100 s).
$R $S/wake.toml --steps-per-frame 8 --screenshot $OUT/wake_300m.png
# From 6 m under the surface, looking up toward the ship.
$R $S/default.toml --frames 3 $FIXED --set "camera.position=[2.0,-6.0,-26.0]" --set "camera.target=[0.0,0.0,-15.0]" --screenshot $OUT/under.png
# A calm sea (1 m/s) under a smooth sky, from 3 m up: the gradients where 8 bits band.
$R $S/spectrum_only.toml --frames 3 --set ocean.wind_speed=1 $FIXED --set "camera.position=[0,3,-300]" --set "camera.target=[0,2,0]" --screenshot $OUT/calm.png
# The sun's glitter, the sun 17° up ahead, from 10 m up, at 1 and 10 m/s.
for U in 1 10; do
  $R $S/spectrum_only.toml --frames 3 --set ocean.wind_speed=$U $FIXED --set "camera.position=[0,10,-300]" \
    --set "camera.target=[0,4,-250]" --set "render.sun_direction=[0,0.3,1]" --screenshot $OUT/glitter_$U.png
done
# Crests toward the default scene's low sun, from 2.5 m up.
$R $S/default.toml --frames 3 $FIXED --set "camera.position=[6.0,2.5,-40.0]" --set "camera.target=[10.0,0.5,0.0]" --screenshot $OUT/crest.png
