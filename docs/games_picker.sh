#!/bin/sh
# docs/games.md: the scene picker. Run from the repository root under a virtual display:
#   xvfb-run -a -s "-screen 0 1280x720x24" docs/games_picker.sh
# It opens targets.toml at 960×540, unfolds the "scenes" window (bottom left) and presses F12
# (oceanbox_shot_001.png in the current folder).
build/bin/oceanbox play config/scenes/targets.toml --size 960x540 &
PID=$!
sleep 6
xdotool search --name oceanbox windowfocus
xdotool mousemove 20 520 click 1
sleep 1.5
xdotool key F12
sleep 1.5
kill $PID
