// `oceanbox dump gerstner` / `dump surface`: GerstnerField on a rest grid → [N, N, 6];
// WaterQuery at the points of a [K, 2] file → [K, 5].
#include "tools/cmd_dump_surface.h"

#include "core/error.h"
#include "core/log.h"
#include "core/npy.h"
#include "core/printable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

namespace ob::game {

namespace {

constexpr int MAX_GRID = 4096;  // [4096, 4096, 6] float32 = 384 MiB
constexpr size_t GERSTNER_CHANNELS = 6;
constexpr size_t SURFACE_CHANNELS = 5;

std::string surfaceShapeText(const std::vector<size_t>& shape) {
    std::string s = "[";
    for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + "]";
}

// A coordinate as a message shows it (%g: 1e+12).
std::string coordinateText(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

// "2.7e+04 m" and why, for a message.
std::string exactCoordinateText(double kMax) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "%.3g m: beyond it a float coordinate (exact to 2^-24 of itself) holds the shortest wave's phase "
                  "(k = %.3g rad/m) only to %g rad or worse",
                  largestExactCoordinate(kMax), kMax, DUMP_PHASE_TOLERANCE_RAD);
    return buf;
}

} // namespace

double largestExactCoordinate(double kMax) {
    return kMax > 0.0 ? DUMP_PHASE_TOLERANCE_RAD / (kMax * 0x1p-24) : std::numeric_limits<double>::infinity();
}

double largestWavenumber(const std::vector<ocean::GerstnerWave>& waves, const ocean::OceanFftCpu* fft) {
    double k = 0.0;
    for (const ocean::GerstnerWave& w : waves) k = std::max(k, std::hypot(double(w.kx), double(w.kz)));
    if (fft)
        for (int c = 0; c < fft->cascadeCount(); ++c) k = std::max(k, std::numbers::pi * fft->resolution() / fft->patchSize(c));
    return k;
}

int dumpGerstner(const ob::ocean::GerstnerDef& def, float gravity, double time, int grid, float extent,
                 const std::string& out, const ob::ocean::OceanDef* ocean) {
    if (grid < 1 || grid > MAX_GRID)
        throw InputError("--grid: must be in [1, " + std::to_string(MAX_GRID) + "], got " + std::to_string(grid));
    if (!(extent > 0.0f) || !std::isfinite(extent))
        throw InputError("--extent: must be a finite length > 0 metres, got " + std::to_string(extent));
    if (!std::isfinite(time)) throw InputError("--time: must be a finite number of seconds");
    if (!(gravity > 0.0f)) throw InputError("ocean.gravity: must be > 0 m/s², got " + std::to_string(gravity));
    if (def.count > 0 && !ocean)
        throw RuntimeError("dumpGerstner: gerstner.count > 0 needs the [ocean] spectrum to draw the waves from");
    const std::vector<std::string> errors = ocean::validate(def, ocean);
    if (!errors.empty()) {
        std::string message;
        for (const std::string& e : errors) message += (message.empty() ? "" : "\n") + e;
        throw InputError(message);
    }

    const std::vector<ocean::GerstnerWave> waves = ocean ? ocean::resolveWaves(def, *ocean) : def.waves;
    const double kMax = largestWavenumber(waves, nullptr);
    if (double(extent) > largestExactCoordinate(kMax))
        throw InputError("--extent " + coordinateText(extent) + ": the rest points reach |x| = " + coordinateText(extent) +
                         " m, and at most " + exactCoordinateText(kMax) + " (give a smaller extent)");
    ocean::GerstnerField field(waves, gravity);
    field.setTime(time);
    const size_t n = size_t(grid);
    std::vector<float> data(n * n * GERSTNER_CHANNELS);
    std::vector<float> alpha(n), beta(n);
    std::vector<ocean::GerstnerPoint> row(n);
    for (size_t i = 0; i < n; ++i) alpha[i] = float(double(i) * extent / double(grid));
    for (size_t j = 0; j < n; ++j) {
        std::fill(beta.begin(), beta.end(), float(double(j) * extent / double(grid)));
        field.evaluate(alpha.data(), beta.data(), n, row.data());
        float* dst = data.data() + j * n * GERSTNER_CHANNELS;
        for (size_t i = 0; i < n; ++i) {
            const ocean::GerstnerPoint& p = row[i];
            const float v[GERSTNER_CHANNELS] = {p.position.x, p.position.y, p.position.z, p.normal.x, p.normal.y, p.normal.z};
            std::copy(v, v + GERSTNER_CHANNELS, dst + i * GERSTNER_CHANNELS);
        }
    }
    writeNpy(out, {n, n, GERSTNER_CHANNELS}, data.data());
    logInfo("gerstner: wrote %s [%zu, %zu, 6] at t = %g s (%d waves, extent %g m)", out.c_str(), n, n, time,
            field.waveCount(), double(extent));
    return EXIT_OK;
}

int dumpSurface(const ob::water::WaterQuery& water, const std::string& pointsNpy, const std::string& out, double kMax) {
    const NpyArray points = readNpy(pointsNpy);
    if (points.shape.size() != 2 || points.shape[1] != 2)
        throw InputError(pointsNpy + ": expected float32 points of shape [K, 2] (world x, z), got shape " +
                         surfaceShapeText(points.shape));
    const size_t k = points.shape[0];
    std::vector<glm::vec2> xz(k);
    for (size_t i = 0; i < k; ++i) {
        xz[i] = {points.data[2 * i], points.data[2 * i + 1]};
        if (!std::isfinite(xz[i].x) || !std::isfinite(xz[i].y))
            throw InputError(pointsNpy + ": point " + std::to_string(i) + " is not a finite (x, z)");
        if (std::max(std::fabs(double(xz[i].x)), std::fabs(double(xz[i].y))) > largestExactCoordinate(kMax))
            throw InputError(pointsNpy + ": point " + std::to_string(i) + " (" + coordinateText(xz[i].x) + ", " +
                             coordinateText(xz[i].y) + ") lies beyond |x|, |z| <= " + exactCoordinateText(kMax));
    }
    std::vector<water::WaterSample> samples(k);
    water.sampleBatch(xz, samples);
    std::vector<float> data(k * SURFACE_CHANNELS);
    for (size_t i = 0; i < k; ++i) {
        const water::WaterSample& s = samples[i];
        const float v[SURFACE_CHANNELS] = {s.height, s.normal.x, s.normal.y, s.normal.z, s.verticalVelocity};
        std::copy(v, v + SURFACE_CHANNELS, data.data() + i * SURFACE_CHANNELS);
    }
    writeNpy(out, {k, SURFACE_CHANNELS}, data.data());
    logInfo("surface: wrote %s [%zu, 5] (height, nx, ny, nz, vertical velocity)", out.c_str(), k);
    return EXIT_OK;
}

} // namespace ob::game
