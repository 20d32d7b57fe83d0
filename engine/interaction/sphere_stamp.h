// Bounding spheres and their Table 2 decision, [Kang2008] eq. 3–7 (docs/references.md#ripple-layer),
// shared by every ripple model: an object is a set of spheres; each sphere, each step, decides by
// Table 2 whether it stamps, and the model makes of the stamp its own source (kang2008 writes the
// footprint into its field, kang2008/footprint_stamp.h; ewave a pressure).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

namespace ob::interaction {

/// SD of eq. 5: which half of the sphere shapes the water.
enum class SphereDirection : int8_t {
    Down = -1,  ///< lower half: pushes the water down
    Auto = 0,   ///< from the vertical velocity: rising (> 0) → Up, otherwise (falling, resting) → Down
    Up = 1,     ///< upper half: pulls the water up
};

/// Eq. 6 object description: weight, speed and size, in any units used alike for O and B.
struct AccelerationRef {
    float weight = 1.0f;  ///< kg, > 0
    float speed = 1.0f;   ///< m/s, > 0
    float size = 1.0f;    ///< sphere radius, m, > 0
};

/// One bounding sphere of an object (docs/references.md#ripple-layer; paper: cannon SR 5, SHR 1.0, AF 0;
/// fish SHR 1.4, AF −0.3, SD by motion; ship 6 spheres SR 7, SHR 0.2, AF 0.3).
struct BoundingSphere {
    glm::vec3 offset{0.0f};  ///< centre in the object's local frame, m
    float radius = 0.5f;     ///< m, > 0; SR in cells = radius / cell size
    SphereDirection direction = SphereDirection::Auto;  ///< SD
    float heightRatio = 1.0f;  ///< SHR, > 0: 1 sphere, > 1 taller ellipsoid, < 1 flatter
    bool afFromMotion = false;       ///< false: AF = accelerationFactor; true: eq. 6 against reference
    float accelerationFactor = 0.0f; ///< AF when fixed, dimensionless, > −1 keeps the sign of Vh(t−1)
    AccelerationRef reference;       ///< eq. 6 reference object B (used when afFromMotion)
};

/// Table 2 phase of one sphere.
enum class ContactPhase : uint8_t {
    Free,      ///< not touching the water and not known to be above it (start, or deep under)
    Airborne,  ///< entirely above the water surface
    Contact,   ///< touched the surface; fixHeight and baseRipple hold their first-contact values
};

/// Per-sphere runtime state for Table 2; zero-initialised = Free.
struct SphereContact {
    ContactPhase phase = ContactPhase::Free;  ///< see ContactPhase
    float fixHeight = 0.0f;   ///< world height of the water surface at first contact, m
    float baseRipple = 0.0f;  ///< ripple Vh(t) at the centre cell at first contact: eq. 5's base, m
    /// True from first contact until the sphere leaves the water or sinks deep.
    bool inContact() const { return phase == ContactPhase::Contact; }
};

/// Eq. 6: AF = ((w·v)/s) / ((refW·refV)/refS) − 1. Positive: stronger rebound; negative:
/// the surface settles faster. refW, refV, refS, s > 0.
float accelerationFactor(float w, float v, float s, float refW, float refV, float refS);

/// One row of a footprint: cells dx = dx0 .. dx0+count−1 at row offset dz from the centre.
struct FootprintRow {
    int dz;      ///< row offset from the centre cell, cells
    int dx0;     ///< first column offset, cells (= −halfwidth)
    int count;   ///< number of cells in the row (2·halfwidth + 1)
    int offset;  ///< index of the row's first PH value in FootprintProfile::ph
};

/// Eq. 3–4 footprint of a sphere of radius SR cells centred on a cell: every cell with
/// PR = sqrt(dx² + dz²) < SR, and its PH = sqrt(SR² − PR²) in cells.
struct FootprintProfile {
    float radiusCells = 0.0f;        ///< SR, cells
    std::vector<FootprintRow> rows;  ///< rows with at least one cell, dz ascending
    std::vector<float> ph;           ///< PH per cell, rows concatenated
};

/// Builds the eq. 3–4 footprint for SR cells (SR in (0, 1] covers only the centre cell, SR <= 0 none).
FootprintProfile makeFootprint(float radiusCells);

/// Footprints by SR, computed once per distinct SR (exact float value) and kept; references
/// stay valid until clear().
class FootprintCache {
public:
    /// The footprint for SR cells, built on first use.
    const FootprintProfile& get(float radiusCells);
    /// Number of distinct footprints held.
    size_t size() const { return m_profiles.size(); }
    /// Drops every footprint.
    void clear() { m_profiles.clear(); }

private:
    std::unordered_map<uint32_t, FootprintProfile> m_profiles;  // key: bits of SR
};

/// Table 2 for one sphere and one step, before the sphere moves; returns true to stamp.
/// centreY, radius: the sphere's world centre height and radius, m. surfaceY: the water
/// surface height (all layers) below the centre now, m. rippleAtCentre: Vh(t) at the
/// centre cell now, m. With bottom = centreY − radius, top = centreY + radius:
///  not in contact: bottom > surfaceY → Airborne, no stamp; else if top >= surfaceY
///    (touching) or the sphere was Airborne (it passed the surface within the step) →
///    FIRST CONTACT: fixHeight = surfaceY, baseRipple = rippleAtCentre, Contact, stamp;
///    else (under water, never touched) → Free, no stamp;
///  in contact: bottom > max(fixHeight, surfaceY) → left the water: Airborne, no stamp;
///    top < fixHeight → entirely below fixHeight, no stamp (and Free once top < fixHeight −
///    2·radius: deep enough that its own splash cannot reach it, so a later contact stores
///    a fresh fixHeight); bottom <= fixHeight <= top → crossing, stamp; else no stamp.
/// (Inline: the swarm runs it for 100,000 spheres a step.)
inline bool updateContact(SphereContact& c, float centreY, float radius, float surfaceY, float rippleAtCentre) {
    const float bottom = centreY - radius, top = centreY + radius;
    if (c.phase != ContactPhase::Contact) {
        if (bottom > surfaceY) {
            c.phase = ContactPhase::Airborne;
            return false;
        }
        if (top >= surfaceY || c.phase == ContactPhase::Airborne) {
            // Step 1, first contact. A sphere that went from entirely above to entirely
            // below within one step crossed the surface during it: it stamps this once.
            c.phase = ContactPhase::Contact;
            c.fixHeight = surfaceY;
            c.baseRipple = rippleAtCentre;
            return true;
        }
        c.phase = ContactPhase::Free;
        return false;
    }
    if (bottom > std::max(c.fixHeight, surfaceY)) {
        // Out of the water: the next touch is a new first contact.
        c.phase = ContactPhase::Airborne;
        return false;
    }
    if (top < c.fixHeight) {
        // Step 2: entirely below fixHeight, no stamp.
        if (top < c.fixHeight - 2.0f * radius) c.phase = ContactPhase::Free;
        return false;
    }
    // Step 3: crossing fixHeight (top >= fixHeight here).
    return bottom <= c.fixHeight;
}


/// Where a sphere is and how it moves this step.
struct SphereMotion {
    float gridX = 0.0f;     ///< centre x in field cells (column; cell centres at integers)
    float gridZ = 0.0f;     ///< centre z in field cells (row)
    float centreY = 0.0f;   ///< centre height, world m
    float verticalVelocity = 0.0f;  ///< m/s, + up; picks SD when direction is Auto
    float speed = 0.0f;     ///< |velocity|, m/s (eq. 6 Ov)
    float mass = 1.0f;      ///< kg (eq. 6 Ow)
    float surfaceY = 0.0f;  ///< water surface height (all layers) below the centre, world m
};

/// One sphere's stamp for a step: where it lands and eq. 5–7's numbers.
struct RippleStamp {
    int cx = 0, cz = 0;          ///< centre cell (column x, row z); may lie outside the field
    float radiusCells = 0.0f;    ///< SR, cells; <= 0 stamps nothing
    float base = 0.0f;           ///< eq. 5 base height, m (the centre's ripple at first contact)
    float heightScale = 0.0f;    ///< SD·SHR·cell size, m per cell of PH
    float accelerationFactor = 0.0f;  ///< AF of eq. 7
};

/// Table 2 for one sphere and one step, the decision every path shares (CPU, batched, GPU):
/// updateContact, then SD from def.direction (or the vertical velocity), AF fixed or from
/// eq. 6 (O = mass, speed, radius) and SR = def.radius / cellSize. The centre snaps to the
/// nearest cell (round half up), so footprints depend only on SR; the sub-cell position error
/// is at most half a cell. `rippleAt(cx, cz)` gives Vh(t) at the centre cell of a rows × cols
/// field; it is called only inside the field and before contact, the one time it counts.
/// Returns true and fills `out` when the sphere stamps. (Inline: the swarm runs it for
/// 100,000 spheres a step.)
template <class RippleAt>
inline bool planStamp(int rows, int cols, float cellSize, const BoundingSphere& def, SphereContact& contact,
                      const SphereMotion& m, RippleAt&& rippleAt, RippleStamp& out) {
    // Clamped so that a sphere far off the patch converts to int safely (it stamps nothing).
    const int cx = int(std::clamp(std::floor(m.gridX + 0.5f), -1.0e9f, 1.0e9f));
    const int cz = int(std::clamp(std::floor(m.gridZ + 0.5f), -1.0e9f, 1.0e9f));
    const bool inside = cx >= 0 && cx < cols && cz >= 0 && cz < rows;
    const float ripple = inside && !contact.inContact() ? rippleAt(cx, cz) : 0.0f;
    if (!updateContact(contact, m.centreY, def.radius, m.surfaceY, ripple)) return false;

    float sd = float(int(def.direction));
    if (def.direction == SphereDirection::Auto) sd = m.verticalVelocity > 0.0f ? 1.0f : -1.0f;
    out.accelerationFactor = def.afFromMotion ? accelerationFactor(m.mass, m.speed, def.radius, def.reference.weight,
                                                                   def.reference.speed, def.reference.size)
                                              : def.accelerationFactor;
    out.cx = cx;
    out.cz = cz;
    out.radiusCells = def.radius / cellSize;
    out.base = contact.baseRipple;
    out.heightScale = sd * def.heightRatio * cellSize;
    return true;
}

/// Table 2 for one sphere, as stepSphere decides it, without touching a field: updates the
/// contact and, when the sphere stamps this step, fills `out` with the stamp stepSphere would
/// apply. `current` is Vh(t) (rows × cols, row-major) as the caller last read it back: the
/// centre cell's value becomes eq. 5's base at first contact. Returns true to stamp.
bool planSphereStamp(std::span<const float> current, int rows, int cols, float cellSize, const BoundingSphere& def,
                     SphereContact& contact, const SphereMotion& motion, RippleStamp& out);

} // namespace ob::interaction
