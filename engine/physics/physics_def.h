// Rigid-body physics and water forces, section [physics].
#pragma once
#include "core/schema.h"
#include "environment/environment_def.h"

namespace ob::physics {

/// The Bullet world and how the water pushes bodies.
struct PhysicsDef {
    float gravity = environment::STANDARD_ENVIRONMENT.gravity;  ///< m/s², downward: environment.gravity, set when the scene is built (not a key)
    float water_density = environment::STANDARD_ENVIRONMENT.water_density;  ///< ρ of the water, kg/m³: environment.water_density, set likewise (not a key)
    float air_density = environment::STANDARD_ENVIRONMENT.air_density;      ///< ρ_a of the air, kg/m³: environment.air_density, set likewise (not a key)
    float linear_drag = 1000.0f;        ///< linear drag per submerged probe area, N·s/m per m², [0, 1e6]; stands in for the
                                        ///< wave-radiation damping of a heaving body (order ρ·ω·r ≈ 2000 for r = 0.5 m)
    float quadratic_drag = 0.6f;        ///< ½·ρ·C_d factor: quadratic drag coefficient C_d, [0, 100]
    float added_mass = 0.5f;            ///< added-mass coefficient C_a (a sphere's, potential flow), [0, 2]
    float air_drag = 1.0f;              ///< windage: air drag coefficient C_da of the emerged part, [0, 10]
    float angular_damping = 0.3f;       ///< angular velocity damping per second while in water, [0, 1]
    bool buoyancy_along_normal = false; ///< true: buoyancy along the surface normal; false: straight up
    int substeps = 1;                   ///< Bullet sub-steps per simulation step, [1, 16]
};

template <class V> void describe(V& v, PhysicsDef& d) {
    if constexpr (requires { v.refuse("", std::string()); })
        for (const char* key : {"gravity", "water_density"}) v.refuse(key, environment::movedHere(key));
    v.field("linear_drag", d.linear_drag, range(0, 1e6), "linear drag per submerged probe area, N·s/m per m²", LIVE);
    v.field("quadratic_drag", d.quadratic_drag, range(0, 100), "quadratic drag coefficient C_d", LIVE);
    v.field("added_mass", d.added_mass, range(0, 2), "added-mass coefficient C_a of the probes (Morison)", LIVE);
    v.field("air_drag", d.air_drag, range(0, 10), "windage: air drag coefficient of the emerged part", LIVE);
    v.field("angular_damping", d.angular_damping, range(0, 1), "angular velocity damping per second in water", LIVE);
    v.field("buoyancy_along_normal", d.buoyancy_along_normal, "buoyancy along the surface normal instead of up", LIVE);
    v.field("substeps", d.substeps, range(1, 16), "Bullet sub-steps per simulation step");
}

} // namespace ob::physics
