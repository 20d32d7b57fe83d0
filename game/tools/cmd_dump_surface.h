// `oceanbox dump gerstner` and `dump surface`: the Gerstner layer on a rest grid, and the
// composite surface at given world points, as float32 .npy (docs/references.md#contracts).
#pragma once
#include "ocean/gerstner.h"
#include "ocean/ocean_def.h"
#include "ocean/ocean_fft_cpu.h"
#include "water/water_query.h"

#include <string>

namespace ob::game {

/// How far a phase may be off before a dump is refused (rad): 1 % of a wave's height.
constexpr double DUMP_PHASE_TOLERANCE_RAD = 0.01;

/// The largest |x| (m) at which a float coordinate still holds the phase k·x of a wave of
/// wavenumber `kMax` to DUMP_PHASE_TOLERANCE_RAD: a float is exact to half its spacing,
/// 2^-24·|x|, so the phase to kMax·2^-24·|x|. Beyond it a dump would be rounding noise (NaN
/// once the phase no longer reduces), so it is refused. Infinite for kMax = 0 (a flat sea).
double largestExactCoordinate(double kMax);

/// The largest wavenumber of the layers dump surface samples (rad/m): every Gerstner wave's,
/// and the finest FFT cascade's Nyquist wavenumber π·N / L_c (`fft` may be null).
double largestWavenumber(const std::vector<ocean::GerstnerWave>& waves, const ocean::OceanFftCpu* fft);

/// Writes the Gerstner surface of def at time `time` (seconds) to out as .npy of shape
/// [grid, grid, 6]: element [j, i, :] = (x, y, z, nx, ny, nz), the position (metres) of rest
/// point (α, β) = (i·extent/grid, j·extent/grid) and its unit normal. gravity in m/s².
/// Generated waves (def.count > 0) need `ocean` (their spectrum). Returns ob::EXIT_OK;
/// throws ob::InputError for grid outside [1, 4096], extent not > 0, a non-finite time or a
/// def validate() rejects, an extent beyond largestExactCoordinate of the shortest wave;
/// ob::RuntimeError if the file cannot be written.
int dumpGerstner(const ob::ocean::GerstnerDef& def, float gravity, double time, int grid, float extent,
                 const std::string& out, const ob::ocean::OceanDef* ocean = nullptr);

/// Reads pointsNpy, float32 [K, 2] of world (x, z), samples water at each (at the query's
/// current time) and writes out as [K, 5] = (height, nx, ny, nz, vertical velocity): metres,
/// unit normal, m/s. Returns ob::EXIT_OK; throws ob::InputError for an unreadable file, any
/// other shape, a non-finite coordinate or one beyond largestExactCoordinate(kMax) (`kMax`:
/// largestWavenumber of the layers `water` sums; 0: a flat sea, no bound); ob::RuntimeError if out cannot be written.
int dumpSurface(const ob::water::WaterQuery& water, const std::string& pointsNpy, const std::string& out, double kMax = 0.0);

} // namespace ob::game
