// The water layers the CPU hands the renderer each frame, as textures: the ripple heights and
// their slopes, the persistent foam map, and the flat maps that stand in for absent FFT layers.
#pragma once
#include "gfx/gpu_bindings.h"
#include "gfx/handles.h"

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

namespace ob::gfx {

struct WaterView;

class WaterLayers {
public:
    WaterLayers();
    /// Uploads this frame's ripples and foam map (foam only with `foamOn`) and binds every layer's
    /// texture unit; fills the layers' entries of `u` (rippleParams, foamParams). `fft`: the FFT
    /// layers are drawn (else the flat maps are bound).
    void upload(const WaterView& water, bool fft, bool foamOn, WaterUniforms& u);

private:
    void makeRippleSlopes(float cellSize);
    void uploadLevels(const WaterView& water, WaterUniforms& u);
    Texture m_flatDisplacement, m_flatSlopes;  // 1×1 layers: no displacement, zero slope, J = 1
    Texture m_ripples;        // R32F heights of the ripple patch, re-uploaded every frame
    Texture m_rippleSlopes;   // RG32F central differences of the heights, one cell of margin, every frame
    Program m_slopeProgram;   // ripple_slopes.comp: those differences on the GPU
    int m_rippleCells = 0;
    Texture m_levels, m_levelSlopes;  // the coarse levels' heights and slopes, 2D arrays of MAX_RIPPLE_LEVELS layers
    Texture m_levelStates;            // their two states, 4 layers a level (h0, h1, v0, v1), uploaded when they change
    std::array<uint64_t, MAX_RIPPLE_LEVELS> m_levelVersions{};  // the states' versions uploaded (0: none)
    Program m_levelProgram;           // ripple_levels.comp: each level's cubic in time and slopes, per frame
    int m_levelCells = 0;             // their cells per side (0: not made)
    Texture m_foam;           // R32F foam coverage of the foam map, re-uploaded every frame
    int m_foamCells = 0;
};

} // namespace ob::gfx
