#!/bin/sh
# Renders docs/look.md's weather pictures (glitter across scales, fresh foam, clouds, a gale and
# its spume, a level view under water): sh docs/look/weather.sh BIN OUTDIR [SCENES_DIR]. llvmpipe through
# OSMesa, about 6 minutes.
set -e
BIN=$1 OUT=$2 S=${3:-config/scenes}
R="$BIN run --headless"
FIXED="--set camera.mode=fixed"
# Calm morning glitter: 2 m/s, the sun 30° up ahead, from 3 m up looking 6° down (glints near,
# the band far).
$R --size 1280x720 $S/spectrum_only.toml --frames 3 --set ocean.wind_speed=2 $FIXED --set "camera.position=[0,3,0]" \
  --set "camera.target=[0,1.9489,10]" --set "render.sun_direction=[0,0.57735,1]" --set render.foam=false --screenshot $OUT/glitter_calm.png
# The default sea (16 m/s, the sun low) at step 240 (4 s; every fourth step drawn): glints where
# the lobe washed white.
$R --size 1280x720 $S/default.toml --frames 60 --steps-per-frame 4 --screenshot $OUT/sea_16_full.png
convert $OUT/sea_16_full.png -crop 640x360+0+360 +repage $OUT/sea_16.png  # its lower left quarter, pixel for pixel
rm $OUT/sea_16_full.png
# Fair weather (the breeze preset's cloud_cover 0.3) and a gale (the storm preset's keys).
$R --size 640x360 $S/default.toml --frames 30 --set sky.cloud_cover=0.3 --set ocean.wind_speed=8 --set "camera.target=[0,12,-9]" --screenshot $OUT/clouds_03.png
$R --size 640x360 $S/default.toml --frames 120 --set sky.cloud_cover=1 --set ocean.wind_speed=20 --set ocean.amplitude=0.002 \
  --set ocean.choppiness=1.4 --set gerstner.amplitude_scale=1.5 --screenshot $OUT/gale.png
# Spume at force 10 (25 m/s, the gale's keys) from 45 m up, the wind away to the upper right.
$R --size 640x360 $S/default.toml --frames 60 --steps-per-frame 5 --set sky.cloud_cover=1 --set ocean.wind_speed=25 \
  --set ocean.amplitude=0.002 --set ocean.choppiness=1.4 --set gerstner.amplitude_scale=1.5 $FIXED \
  --set "camera.position=[-20.0,45.0,-45.0]" --set "camera.target=[0.0,0.0,-10.0]" --screenshot $OUT/spume_25.png
# Level under water at 3 m, auto exposure on and off (40 frames at 1/60 s adapt it 2/3 of the way).
for A in on off; do
  $R --size 640x360 $S/default.toml --frames 40 $FIXED --set "camera.position=[10,-3,-30]" --set "camera.target=[10,-3,0]" \
    --set render.auto_exposure=\"$A\" --screenshot $OUT/under_level_$A.png
done
# Fresh foam about a second after a cannonball's hit (the hit at about 1.6 s).
$R --size 640x360 $S/cannon.toml --frames 40 --steps-per-frame 4 --screenshot $OUT/foam_fresh.png
