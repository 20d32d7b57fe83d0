// The water's fine detail: the tileable detail map (DU/DV and foam streaks) and the foam's
// bubble pattern baked from it on the GPU once, and the sampler a software rasteriser reads
// their mips with.
#pragma once
#include "gfx/render_frame.h"

namespace ob::gfx {

class WaterDetail {
public:
    /// Bakes both maps (needs a current context).
    WaterDetail();
    /// DU/DV (rg, as 0.5 + 0.5·x) and foam streaks (b), RGBA8, tileable, mipmapped.
    const Texture& detailMap() const { return m_detailMap; }
    /// The persistent foam's bubble pattern over its repeat, baked from the detail map (RGBA8).
    const Texture& foamPattern() const { return m_foamPattern; }
    /// Bilinear in the nearest mip, repeated: the slopes, detail map and foam pattern on a software rasteriser.
    const Sampler& nearestMipSampler() const { return m_nearestMipSampler; }
    void listPrograms(ProgramList& out) const;

private:
    Texture m_detailMap, m_foamPattern;
    Program m_bakeProgram;  // kept: the bindings test reads its interface
    Sampler m_nearestMipSampler;
};

} // namespace ob::gfx
