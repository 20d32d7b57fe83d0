// The velocity the foam map moves with, by its mode (laws in foam_flow.h); the node grid is
// FoamNodes', the wind FoamWind's.
#include "foam/foam_flow.h"

namespace ob::foam {

void FoamFlow::setUniform(glm::vec2 u) {
    m_mode = (u == glm::vec2(0.0f)) ? Mode::Still : Mode::Uniform;
    m_uniform = u;
}

std::span<float> FoamFlow::velocityX() {
    const size_t cells = size_t(m_grid.n) * size_t(m_grid.n);
    if (m_ux.empty()) m_ux.assign(cells, 0.0f), m_uz.assign(cells, 0.0f);
    m_mode = Mode::Field;
    return m_ux;
}

std::span<float> FoamFlow::velocityZ() {
    velocityX();
    return m_uz;
}

void FoamFlow::setNodes(std::span<const glm::vec2> nodes) {
    m_nodes.set(nodes);
    m_mode = Mode::Nodes;
}

void FoamFlow::refresh(const water::CompositeWater& water, int refreshSteps) {
    m_nodes.refresh(water, refreshSteps);
    m_mode = Mode::Nodes;
}

void FoamFlow::follow(const ScrollingGrid& grid) {
    m_grid = grid;
    m_wind.follow(grid);
    m_nodes.follow(grid, m_mode == Mode::Nodes);
}

void FoamFlow::setResolution(int flowResolution) {
    if (m_nodes.setResolution(flowResolution) && m_mode == Mode::Nodes) {  // the nodes no longer fit: set them again
        m_nodes.clear();
        m_mode = Mode::Still;
    }
}

} // namespace ob::foam
