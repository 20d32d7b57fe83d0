// `oceanbox dump gerstner` and `dump surface`: the Gerstner layer on a rest grid, and the
// composite surface at given world points, as float32 .npy (docs/references.md#contracts).
#pragma once
#include "ocean/gerstner.h"
#include "ocean/ocean_def.h"
#include "water/water_query.h"

#include <string>

namespace ob::game {

/// Writes the Gerstner surface of def at time `time` (seconds) to out as .npy of shape
/// [grid, grid, 6]: element [j, i, :] = (x, y, z, nx, ny, nz), the position (metres) of rest
/// point (α, β) = (i·extent/grid, j·extent/grid) and its unit normal. gravity in m/s².
/// Generated waves (def.count > 0) need `ocean` (their spectrum). Returns ob::EXIT_OK;
/// throws ob::InputError for grid outside [1, 4096], extent not > 0, a non-finite time or a
/// def validate() rejects; ob::RuntimeError if the file cannot be written.
int dumpGerstner(const ob::ocean::GerstnerDef& def, float gravity, double time, int grid, float extent,
                 const std::string& out, const ob::ocean::OceanDef* ocean = nullptr);

/// Reads pointsNpy, float32 [K, 2] of world (x, z), samples water at each (at the query's
/// current time) and writes out as [K, 5] = (height, nx, ny, nz, vertical velocity): metres,
/// unit normal, m/s. Returns ob::EXIT_OK; throws ob::InputError for an unreadable file, any
/// other shape or a non-finite coordinate; ob::RuntimeError if out cannot be written.
int dumpSurface(const ob::water::WaterQuery& water, const std::string& pointsNpy, const std::string& out);

} // namespace ob::game
