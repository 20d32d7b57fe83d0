// Splashes and foam in the sandbox: bodies, fish and ships feed the splash particles
// (engine/splash) and the foam map (engine/foam); landing drops rain back on the ripple patch.
#pragma once
#include "ecs/schedule.h"
#include "foam/foam_def.h"
#include "splash/splash_def.h"

#include <cstdint>

namespace ob {
class StateHasher;
}
namespace ob::splash {
class SplashParticles;
}
namespace ob::foam {
class FoamMap;
}

namespace ob::game {

/// Creates the splash and foam resource from [splash] and [foam] (nothing when both are off;
/// no foam without a ripple patch, on whose centre it stays; its side is [foam] extent_m, else
/// the patch's). seed: [sim] seed.
void addSplashFoam(ecs::World& world, const splash::SplashDef& splash, const foam::FoamDef& foam, uint64_t seed);
/// Interaction phase, after the ripple step: crossings of every bounding sphere and fish emit
/// splashes, ship bows spray above [splash] bow_speed, the drops fly and land (stamped into the
/// ripple patch and the foam), then the foam takes whitecaps, steep ripples and hull wakes,
/// and steps with the surface's horizontal velocity (the ocean layers' particle velocity).
void splashFoamSystem(ecs::World& world, const ecs::Tick& tick);
/// [sim] pipelined: from the next step on the foam's sweep (advection, sources (a), (b), decay:
/// FoamMap::sweep, on copies of the Jacobian and the ripple heights it reads) runs on a worker
/// while the step and the frame go on; whatever reads or moves the map next waits for it (the
/// next step's splashFoamSystem, foamMap: the render's upload, the hash), so the state is the
/// same bits (docs/frame.md#pipelined).
void pipelineSplashFoam(ecs::World& world);
/// The foam's sweeps run on a worker so far (0 unless pipelined).
uint64_t foamSweepsOnWorker(ecs::World& world);
/// The live drops (null when [splash] is off).
const splash::SplashParticles* splashParticles(ecs::World& world);
/// The foam map, for "is there foam here" (null when [foam] is off, before the first step, or
/// without ripples); its sweep in flight is waited for.
const foam::FoamMap* foamMap(ecs::World& world);
/// Feeds the drops and the foam map to the state hash (nothing when absent).
void hashSplashFoam(ecs::World& world, StateHasher& h);

} // namespace ob::game
