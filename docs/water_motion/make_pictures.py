#!/usr/bin/python3
"""The pictures of docs/water_motion.md: the water moving what floats.

Run from the repository root (a build in build/):

    /usr/bin/python3 docs/water_motion/make_pictures.py [NAME ...]

NAME is one of the sequences below: ship_crates, stir_ball, flotsam, storm (all of them when
none is named); storm_tables prints the storm runs' tables again from their saved stats.
--reuse-tracks reads the tracks from the CSV files an earlier run wrote instead of running for
them again.

Each sequence runs its scene headless with `oceanbox run`, deterministic (one simulation step
per frame; the same state at any number of steps a frame): first once per track time with
--stats, for the bodies' positions (their tracks, written to NAME_tracks.csv and drawn over a
frame), at 64 x 36 px, or at the frame size where cursor input drives it (the cursor's rays are
the framebuffer's); then at full size, the scene's screenshot events giving the frames, laid
side by side with ImageMagick (`montage`) into docs/water_motion/NAME.png, an 8-bit palette PNG.
Scenes are run from copies in temporary folders (their screenshot events write beside them).
Python 3.11 or later (tomllib), ImageMagick, numpy (the storm's surface query).
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import tomllib

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
HERE = os.path.join(ROOT, "docs", "water_motion")
OCEANBOX = os.environ.get("OCEANBOX") or os.path.join(ROOT, "build", "bin", "oceanbox")  # another build: OCEANBOX=path
STEP_HZ = 60          # [sim] step_hz of every scene here
WIDTH, HEIGHT = 960, 540  # the frames, px
FRAME = f"{WIDTH}x{HEIGHT}"
TILE = "640x360"      # one frame of a sheet
TRACK_COLOURS = ["#ffd84a", "#ff6a3d", "#7cff6b", "#ff5cf0", "#5ce1ff", "#ffffff"]


def run(scene, folder, seconds, size="64x36", steps_per_frame=None, sets=(), extra=()):
    """`oceanbox run` of `scene` for `seconds` of simulated time; its --stats as a dict."""
    steps = round(seconds * STEP_HZ)
    spf = steps_per_frame or max(d for d in range(1, 61) if steps % d == 0)
    stats = os.path.join(folder, "stats.json")
    cmd = [OCEANBOX, "run", scene, "--headless", "--size", size, "--steps-per-frame", str(spf),
           "--frames", str(steps // spf), "--stats", stats, *extra]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(stats) as f:
        return json.load(f)


def positions(stats):
    return {b["name"]: b["position"] for b in stats["bodies"] if b["name"]}


def tracks(scene, times, sets=(), extra=(), size="64x36"):
    """Every named body's position at each of `times` (s): {name: [(t, x, y, z), ...]}. (A run
    with cursor input must track at its frame size: the cursor's rays are the framebuffer's.)"""
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        copy = os.path.join(tmp, os.path.basename(scene))
        shutil.copy(scene, copy)
        for t in times:
            for name, p in positions(run(copy, tmp, t, size=size, sets=sets, extra=extra)).items():
                out.setdefault(name, []).append((t, *p))
    return out


def read_tracks(path):
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            out.setdefault(row["name"], []).append(tuple(float(row[k]) for k in ("t_s", "x_m", "y_m", "z_m")))
    return out


def tracks_cached(scene, csv_path, times, sets=(), extra=(), size="64x36"):
    """tracks(), or with --reuse-tracks the CSV an earlier run wrote."""
    if REUSE and os.path.exists(csv_path):
        return read_tracks(csv_path)
    track = tracks(scene, times, sets, extra, size)
    write_tracks(csv_path, track)
    return track


def write_tracks(path, track):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["name", "t_s", "x_m", "y_m", "z_m"])
        for name, rows in track.items():
            for r in rows:
                w.writerow([name, f"{r[0]:.2f}", *(f"{v:.3f}" for v in r[1:])])


def project(camera, width, height, p):
    """World point p → framebuffer pixel (x right, y down) of a fixed camera (the renderer's
    lookAt with +y up and a perspective of vertical fov_deg, game/world/camera.cpp)."""
    eye, target = camera["position"], camera["target"]
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(c * c for c in f))
    f = [c / n for c in f]
    s = [f[1] * 0 - f[2] * 1, f[2] * 0 - f[0] * 0, f[0] * 1 - f[1] * 0]  # f × up
    n = math.sqrt(sum(c * c for c in s))
    s = [c / n for c in s]
    u = [s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]]
    d = [a - b for a, b in zip(p, eye)]
    xc, yc, zc = sum(a * b for a, b in zip(s, d)), sum(a * b for a, b in zip(u, d)), sum(a * b for a, b in zip(f, d))
    t = math.tan(math.radians(camera.get("fov_deg", 60.0)) / 2.0)
    nx, ny = xc / (zc * t * width / height), yc / (zc * t)
    return (nx + 1.0) * 0.5 * width, (1.0 - ny) * 0.5 * height


def draw_tracks(frame, out, camera, track, names, width, height, colour=None, stroke=2):
    """The tracks of `names` drawn over `frame`: a line through every position, a ring where
    the body started (each body its own colour, or all `colour`)."""
    args = ["convert", frame, "-fill", "none", "-strokewidth", str(stroke)]
    for k, name in enumerate(names):
        pts = [project(camera, width, height, (x, 0.0, z)) for _, x, _, z in track[name]]
        colour_k = colour or TRACK_COLOURS[k % len(TRACK_COLOURS)]
        args += ["-stroke", colour_k, "-draw", "polyline " + " ".join(f"{x:.1f},{y:.1f}" for x, y in pts)]
        x0, y0 = pts[0]
        args += ["-draw", f"circle {x0:.1f},{y0:.1f} {x0 + 5:.1f},{y0:.1f}"]
    subprocess.run(args + [out], check=True)


MAX_BYTES = 300_000   # a picture of the docs at most (about)


def sheet(frames, labels, out, tile=TILE, columns=2):
    """Frames side by side, each labelled, as an 8-bit palette PNG; the tiles shrink by tenths
    until it fits MAX_BYTES."""
    w, h = (int(v) for v in tile.split("x"))
    rows = (len(frames) + columns - 1) // columns
    for scale in (1.0, 0.9, 0.8, 0.7, 0.6):
        args = ["montage"]
        for f, label in zip(frames, labels):
            args += ["-label", label, f]
        args += ["-tile", f"{columns}x{rows}", "-geometry", f"{round(w * scale)}x{round(h * scale)}+3+3", "-pointsize",
                 str(round(18 * max(scale, 0.8))), "-background", "#202020", "-fill", "#e0e0e0", "PNG24:" + out + ".tmp.png"]
        subprocess.run(args, check=True)
        subprocess.run(["convert", out + ".tmp.png", "-dither", "FloydSteinberg", "-colors", "256", "PNG8:" + out], check=True)
        os.remove(out + ".tmp.png")
        if os.path.getsize(out) <= MAX_BYTES:
            break


def frames_of(scene, size, steps_per_frame, seconds, sets=(), extra=()):
    """Runs `scene` at full size in a temporary copy; its screenshot events' files, in event order,
    and the final stats."""
    tmp = tempfile.mkdtemp()
    copy = os.path.join(tmp, os.path.basename(scene))
    shutil.copy(scene, copy)
    with open(scene, "rb") as f:
        events = [e for e in tomllib.load(f).get("events", []) if e.get("action") == "screenshot"]
    # A screenshot event is taken by the frame after its step: run a little past the last one.
    stats = run(copy, tmp, seconds + 0.25, size=size, steps_per_frame=steps_per_frame, sets=sets, extra=extra)
    return tmp, [(e["at"], os.path.join(tmp, e["file"])) for e in events], stats


def camera_of(scene):
    with open(scene, "rb") as f:
        return tomllib.load(f)["camera"]


def close_up(scene, seconds, camera, track, names, size=FRAME):
    """The scene at `seconds` seen from `camera` (its keys set on the command line), with the
    tracks of `names` drawn over it; the picture's path (in a temporary folder)."""
    tmp = tempfile.mkdtemp()
    copy = os.path.join(tmp, os.path.basename(scene))
    shutil.copy(scene, copy)
    out = os.path.join(tmp, "close_up.png")
    sets = [f"camera.{k}=[{', '.join(f'{v:g}' for v in camera[k])}]" for k in ("position", "target")]
    sets.append(f"camera.fov_deg={camera['fov_deg']:g}")
    run(copy, tmp, seconds, size=size, sets=sets, extra=["--screenshot", out])
    w, h = (int(v) for v in size.split("x"))
    draw_tracks(out, out, camera, {n: [r for r in track[n] if r[0] <= seconds + 1e-6] for n in names}, names, w, h)
    return out


def print_displacements(track, names, until):
    print(f"{'body':10s} start x, z     farthest from the start (m, at s)   at {until:g} s: dx, dz (m)")
    for n in names:
        rows = [r for r in track[n] if r[0] <= until + 1e-6]
        x0, z0 = rows[0][1], rows[0][3]
        far = max(rows, key=lambda r: math.hypot(r[1] - x0, r[3] - z0))
        print(f"{n:10s} {x0:6.2f} {z0:6.2f}   {far[1] - x0:+.2f}, {far[3] - z0:+.2f} at {far[0]:4.1f}"
              f"                  {rows[-1][1] - x0:+.2f}, {rows[-1][3] - z0:+.2f}")


def ship_crates():
    """A ship at 5 m/s passing crates 4 and 8 m beside its track and two in it behind its stern."""
    scene = os.path.join(HERE, "ship_crates.toml")
    track = tracks_cached(scene, os.path.join(HERE, "ship_crates_tracks.csv"), [1.0 / STEP_HZ] + [0.5 * k for k in range(1, 33)])
    crates = sorted(n for n in track if n.startswith("crate"))
    print("crate      start x, z     most out from the track (m, at s)   at 16 s: dx, dz (m)")
    for n in crates:
        rows = track[n]
        x0, z0 = rows[0][1], rows[0][3]
        side = 1.0 if x0 > 0.5 else -1.0 if x0 < -0.5 else 0.0
        out = max(rows, key=lambda r: side * (r[1] - x0))
        print(f"{n:10s} {x0:6.2f} {z0:6.2f}   {side * (out[1] - x0):+.2f} at {out[0]:4.1f}"
              f"                        {rows[-1][1] - x0:+.2f}, {rows[-1][3] - z0:+.2f}")
    tmp, shots, _ = frames_of(scene, FRAME, 4, 14.0)
    beside = close_up(scene, 14.0, {"position": [13.0, 21.0, -8.0], "target": [2.5, 0.0, -8.0], "fov_deg": 40.0}, track,
                      [n for n in crates if not n.startswith("crate_t")])
    behind = close_up(scene, 14.0, {"position": [7.0, 12.0, -38.0], "target": [0.0, 0.0, -38.0], "fov_deg": 40.0}, track,
                      [n for n in crates if n.startswith("crate_t")])
    labels = [f"t = {t:g} s" for t, _ in shots] + ["14 s, nearer: the tracks of the crates beside", "14 s, nearer: the tracks of the crates in the track"]
    sheet([f for _, f in shots] + [beside, behind], labels, os.path.join(HERE, "ship_crates.png"), tile="560x315", columns=3)
    for f in (tmp, os.path.dirname(beside), os.path.dirname(behind)):
        shutil.rmtree(f)


STIR = {"start": 1.0, "seconds": 6.0, "radius": 0.4, "turns_per_s": 1.0, "rate_hz": 30.0}


def write_stir_input(path, scene, width, height):
    """The stir's input: the left button held while the cursor runs STIR's circle about the
    origin on still water, as framebuffer pixels of the scene's fixed camera at width x height
    (`size` makes `run` render at it)."""
    camera = camera_of(scene)
    lines = [f"# docs/water_motion.md: the stir's circle for {os.path.basename(scene)} (written by make_pictures.py):",
             f"# the left button held {STIR['seconds']:g} s from {STIR['start']:g} s while the cursor runs a circle of "
             f"{STIR['radius']:g} m about the origin", f"# at {STIR['turns_per_s']:g} turn/s, as framebuffer pixels of the scene's camera.",
             f"size = [{width}, {height}]", ""]

    def pixel(t):
        a = 2.0 * math.pi * STIR["turns_per_s"] * t
        x, y = project(camera, width, height, (STIR["radius"] * math.cos(a), 0.0, STIR["radius"] * math.sin(a)))
        return f"[{x:.3f}, {y:.3f}]"

    lines += ["[[mouse]]", f"at = {STIR['start']:.3f}", 'button = "left"', f"hold = {STIR['seconds']:.3f}", f"pos = {pixel(0.0)}", ""]
    n = round(STIR["seconds"] * STIR["rate_hz"])
    for k in range(1, n + 1):
        t = k / STIR["rate_hz"]
        lines += ["[[move]]", f"at = {STIR['start'] + t:.3f}", f"pos = {pixel(t)}", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def stir_ball():
    """Balls 1.2 to 2.6 m from a circular stir held 6 s on still water, with the current layer
    and without it."""
    scene = os.path.join(HERE, "stir_ball.toml")
    inp = os.path.join(HERE, "stir_input.toml")
    write_stir_input(inp, scene, WIDTH, HEIGHT)
    times = [1.0 / STEP_HZ] + [0.5 * k for k in range(1, 31)]
    fine = sorted(set(times) | {0.25 * k for k in range(4, 33)})  # every 0.25 s while the water turns fastest
    track = tracks_cached(scene, os.path.join(HERE, "stir_ball_tracks.csv"), fine, extra=["--input", inp], size=FRAME)
    still = tracks_cached(scene, os.path.join(HERE, "stir_ball_tracks_no_layer.csv"), times, sets=["currents.enabled=false"],
                          extra=["--input", inp], size=FRAME)
    balls = sorted(n for n in track if n.startswith("ball"))
    print("with the current layer:")
    print_displacements(track, balls, 15.0)
    print("without it (currents.enabled=false):")
    print_displacements(still, balls, 15.0)
    tmp, shots, _ = frames_of(scene, FRAME, 4, 15.0, extra=["--input", inp])
    last_t, last = shots[-1]
    upto = lambda tr: {n: [r for r in tr[n] if r[0] <= last_t + 1e-6] for n in balls}
    draw_tracks(last, last, camera_of(scene), upto(still), balls, WIDTH, HEIGHT, colour="#ffffff", stroke=1)
    draw_tracks(last, last, camera_of(scene), upto(track), balls, WIDTH, HEIGHT, stroke=3)
    labels = [f"t = {t:g} s" + (" (the stir from 1 s to 7 s)" if k == 1 else "" if f != last else
              ": the balls' tracks (white: without the current layer)") for k, (t, f) in enumerate(shots)]
    sheet([f for _, f in shots], labels, os.path.join(HERE, "stir_ball.png"))
    shutil.rmtree(tmp)


def flotsam():
    """Balls, crates and barrels on a 10 m/s wind sea for 60 s, two fixed posts for reference."""
    scene = os.path.join(HERE, "flotsam.toml")
    track = tracks_cached(scene, os.path.join(HERE, "flotsam_tracks.csv"), [1.0 / STEP_HZ] + [3.0 * k for k in range(1, 21)])
    bodies = [n for n in track if not n.startswith("post")]
    print_displacements(track, bodies, 60.0)
    for n in bodies:
        rows = track[n]
        print(f"{n:10s} mean drift over the last 30 s: {(rows[-1][1] - rows[-11][1]) / 30.0:.3f} m/s downwind (+x), "
              f"{(rows[-1][3] - rows[-11][3]) / 30.0:+.3f} m/s across")
    # What carries them: the same 60 s without the air's drag on the bodies (no leeway), and
    # without the current layer too (the waves alone).
    with tempfile.TemporaryDirectory() as tmp:
        copy = os.path.join(tmp, "flotsam.toml")
        shutil.copy(scene, copy)
        for label, sets in (("no windage (environment.air_density=0)", ["environment.air_density=0"]),
                            ("no windage, no current layer", ["environment.air_density=0", "currents.enabled=false"])):
            end = positions(run(copy, tmp, 60.0, sets=sets))
            print(f"{label}: drift over 60 s (m): " +
                  ", ".join(f"{n} {end[n][0] - track[n][0][1]:+.2f}" for n in bodies))
    tmp, shots, _ = frames_of(scene, FRAME, 8, 59.5)
    last_t, last = shots[-1]
    colour = lambda n: "#ffd84a" if n.startswith("ball") else "#ff6a3d" if n.startswith("crate") else "#7cff6b"
    for n in bodies:
        draw_tracks(last, last, camera_of(scene), {n: [r for r in track[n] if r[0] <= last_t + 1e-6]}, [n], WIDTH, HEIGHT, colour=colour(n))
    labels = [f"t = {t:g} s" + (": tracks of the balls (yellow), crates (red), barrels (green)" if f == last else "")
              for t, f in shots]
    sheet([f for _, f in shots], labels, os.path.join(HERE, "flotsam.png"))
    shutil.rmtree(tmp)


# The Sea panel's sliders (game/ui/sea_panel.cpp) at their tops over the storm preset
# (game/world/sea_presets.cpp), and the scene keys' own maxima (engine/ocean/ocean_def.h).
STORM_PRESET = ["ocean.amplitude=0.002", "gerstner.count=8", "sky.cloud_cover=1.0"]
STORMS = {
    "sliders": ("the storm preset, every slider at its top: wind 30 m/s, choppiness 3, swell 3",
                STORM_PRESET + ["ocean.wind_speed=30", "ocean.choppiness=3", "gerstner.amplitude_scale=3"]),
    "keys": ("the keys' maxima: wind 60 m/s, choppiness 10 (the storm preset's swell 1.5)",
             STORM_PRESET + ["ocean.wind_speed=60", "ocean.choppiness=10", "gerstner.amplitude_scale=1.5"]),
}
STORM_SECONDS = 30.0
STORM_SHOTS = [10.0, 20.0, 29.5]


def surface_under(scene, sets, seconds, points, tmp):
    """`oceanbox dump surface`: the composite surface's height at world (x, z) points."""
    import numpy as np
    pts = os.path.join(tmp, "points.npy")
    out = os.path.join(tmp, "surface.npy")
    np.save(pts, np.asarray(points, dtype=np.float32).reshape(-1, 2))
    cmd = [OCEANBOX, "dump", "surface", scene, "--time", f"{seconds:g}", "--points", pts, "--out", out]
    for x in sets:
        cmd += ["--set", x]
    subprocess.run(cmd, check=True, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return [float(h) for h in np.load(out)[:, 0]]


def storm_table(key, tmp):
    """The bodies at the end of a storm run (its storm_KEY_stats.json) and the surface under
    each: the drawn one (the run's keys) and the one bodies ride, the same sea at choppiness 1
    at most (bodies ride the waves' own orbits: a choppiness above 1 sharpens the drawn crests
    only). Without the ripples; a fixed body (the cannon's pillar) has no probes."""
    title, sets = STORMS[key]
    with open(os.path.join(HERE, f"storm_{key}_stats.json")) as f:
        saved = json.load(f)
    scene = os.path.join(ROOT, "config", "scenes", "default.toml")
    bodies = saved["bodies"]
    xz = [(b["position"][0], b["position"][2]) for b in bodies]
    chop = min(float(next(x for x in sets if x.startswith("ocean.choppiness=")).split("=")[1]), 1.0)
    drawn = surface_under(scene, sets, saved["seconds"], xz, tmp)
    rides = surface_under(scene, sets + [f"ocean.choppiness={chop:g}"], saved["seconds"], xz, tmp)
    print(f"{title} ({saved['seconds']:g} s):")
    print(f"  {'body':8s} {'type':6s} {'x':>8s} {'y':>7s} {'z':>8s}  drawn surface  ridden surface  y - ridden  under water")
    for b, hd, hr in zip(bodies, drawn, rides):
        x, y, z = b["position"]
        print(f"  {b['name'] or '-':8s} {b['type']:6s} {x:8.2f} {y:7.2f} {z:8.2f}  {hd:13.2f}  {hr:14.2f}  {y - hr:+10.2f}"
              f"  {b['submerged_fraction']:11.2f}")


def storm():
    """config/scenes/default.toml in the steepest seas a player can set, and beyond: every body
    rides the surface (its --stats and the surface under it)."""
    scene = os.path.join(ROOT, "config", "scenes", "default.toml")
    frames, labels = [], []
    for key, (title, sets) in STORMS.items():
        tmp = tempfile.mkdtemp()
        copy = os.path.join(tmp, "default.toml")
        with open(scene) as f, open(copy, "w") as g:
            g.write(f.read())
            for t in STORM_SHOTS:
                g.write(f'\n[[events]]\nat = {t}\naction = "screenshot"\nfile = "storm_{key}_{t:04.1f}.png"\n')
        stats = run(copy, tmp, STORM_SECONDS, size=FRAME, steps_per_frame=8, sets=sets)
        with open(os.path.join(HERE, f"storm_{key}_stats.json"), "w") as f:
            json.dump({"command_sets": sets, "seconds": STORM_SECONDS, "bodies": stats["bodies"],
                       "state_hash": stats["state_hash"]}, f, indent=1)
        storm_table(key, tmp)
        for t in STORM_SHOTS:
            frames.append(os.path.join(tmp, f"storm_{key}_{t:04.1f}.png"))
            labels.append(f"{key}: t = {t:g} s")
        print(f"  ({title}; frames in {tmp})")
    sheet(frames, labels, os.path.join(HERE, "storm.png"), tile="560x315", columns=3)
    for f in frames[::3]:
        shutil.rmtree(os.path.dirname(f), ignore_errors=True)


def storm_tables():
    """The storm runs' tables again, from their saved stats (no run)."""
    with tempfile.TemporaryDirectory() as tmp:
        for key in STORMS:
            if os.path.exists(os.path.join(HERE, f"storm_{key}_stats.json")):
                storm_table(key, tmp)


SEQUENCES = {"storm_tables": storm_tables, "ship_crates": ship_crates, "stir_ball": stir_ball, "flotsam": flotsam, "storm": storm}
REUSE = "--reuse-tracks" in sys.argv

if __name__ == "__main__":
    for name in [a for a in sys.argv[1:] if not a.startswith("--")] or [k for k in SEQUENCES if k != "storm_tables"]:
        SEQUENCES[name]()
