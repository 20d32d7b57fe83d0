// The surface current layer in the world (engine/currents): made from [currents], added to the
// water's query (one velocity for bodies and foam), fed each step with the bodies' impulses
// (sim/objects.h WaterImpulses: Newton's third law), the wind and the walls, then stepped.
#pragma once
#include "currents/currents_def.h"
#include "ecs/schedule.h"
#include "ecs/world.h"

namespace ob::game {

/// Creates the current layer resource and the impulses it takes (nothing when disabled), and
/// adds it to the ocean's query. waterDensity in kg/m³. After addOcean.
void addCurrents(ecs::World& world, const currents::CurrentsDef& def, float waterDensity);
/// Interaction phase: the layer follows the ripple patch (or stays put without one), takes the
/// wind at 10 m, the fixed bodies' footprints as walls and the step's impulses, then steps.
void currentsSystem(ecs::World& world, const ecs::Tick& tick);

} // namespace ob::game
