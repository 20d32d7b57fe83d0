// The current layer's pressure projection (Stam 1999, "Stable Fluids" §2): u ← u − ∇φ with φ
// chosen so that the discrete divergence of the result is 0 (φ = p·dt/ρ per Δ, in m/s).
//
// Discretisation: the staggered grid of current_layer.h, periodic at the patch's edges. Cell c's
// divergence times Δ is D_c = u_E − u_W + v_N − v_S (its four faces); the correction of a face
// between cells L and R is φ_R − φ_L; so D = 0 after it when A·φ = −D, A the graph Laplacian
// (A·φ)_c = Σ_n (φ_c − φ_n) over c's open neighbours n.
//  - Open patch (no wall): A is diagonal in Fourier space, λ(k) = 4·sin²(πk_x/n) + 4·sin²(πk_z/n),
//    so one real-to-complex FFT of D, φ̂ = −D̂/λ (k = 0 left at 0: the mean flow, the layer's
//    momentum, is untouched) and one inverse. Exact up to float rounding.
//  - Walls: the faces of a wall cell carry no flow (u = 0: no flux through a wall); A then runs
//    over open cells only. After the FFT step above (which takes the bulk of the divergence), the
//    faces touching walls are zeroed and the rest is solved by conjugate gradients preconditioned
//    with the modified incomplete Cholesky factor MIC(0) (τ = 0.97), warm-started from the last
//    step's φ, until max |D| ≤ tolerance.
//  - Open edge (CurrentEdge::Open): the pressure departure on the edge is 0 (an outflow
//    condition: the ring of cells outside holds −φ of the cell inside it, so a face on the edge
//    takes the gradient 2·φ_inside and water leaves or enters freely). The edge faces are the
//    padded arrays' ghost faces on the west and south (u(−1, j), v(i, −1)) and the last stored
//    ones on the east and north (u(n − 1, j), v(i, n − 1)). A is then diagonal in the sine basis
//    sin(πk(i + ½)/n): λ(k) = 4·sin²(πk_x/(2n)) + 4·sin²(πk_z/(2n)), k = 1..n, a DST-II forward
//    and a DST-III back (FFTW's RODFT10, RODFT01); no mode is 0, so the mean flow is not kept
//    (momentum leaves with the water). The pair is computed through one real n × n FFT each way
//    (Makhoul 1980; FFTW's own r2r kinds have no vector code and cost 4× its r2c): with the
//    checkerboard sign (−1)^(i+j), a DST-II is a DCT-II read backwards; a 2-D DCT-II is the r2c
//    of the cells reordered (even indices ascending, odd ones descending) and a twiddle per mode
//    that reads the modes K and its mirror; the DST-III back is the same in reverse.
#pragma once
#include "currents/current_layer.h"

#include <cstdint>
#include <vector>

struct fftwf_plan_s;

namespace ob::currents {

/// The projection's FFT plans and scratch, and the wall solve's warm start; the faces are the
/// caller's (padded arrays, current_layer.h's layout).
class CurrentProjection {
public:
    /// n cells a side; `open`: the outflow edge (file comment), else periodic.
    explicit CurrentProjection(int n, bool open = false);
    ~CurrentProjection();
    CurrentProjection(const CurrentProjection&) = delete;
    CurrentProjection& operator=(const CurrentProjection&) = delete;

    /// Makes the faces divergence-free on the n × n grid (no walls): periodic, k = 0 untouched; or
    /// with the open edge. `add` (m/s) is added to every face in the same pass (a uniform flow: no
    /// divergence; periodic only).
    void projectPeriodic(float* u, float* v, glm::vec2 add = glm::vec2(0.0f));
    /// Whether the edge is open (the outflow condition) rather than periodic.
    bool open() const { return m_open; }
    /// With `solid` (n² cells, 1 = wall): projectPeriodic, faces touching a wall zeroed, then
    /// MIC(0)-PCG on the open cells until max |D| ≤ tolerance (m/s) or maxIterations.
    WallSolve projectWithWalls(float* u, float* v, const uint8_t* solid, float tolerance, int maxIterations);
    /// Divergence times Δ of every cell into `out` (n²), m/s (wall faces as they stand).
    void divergence(const float* u, const float* v, float* out) const;
    /// Moves the warm start with the grid (scrollCells' convention); new cells 0.
    void scroll(glm::ivec2 shift);
    /// The wall solve's φ (warm start), n², m/s.
    const std::vector<float>& phi() const { return m_phi; }
    /// Forgets the warm start (no wall this step).
    void clearWarmStart();
    /// Splits the per-face loops over at most `threads` workers (1: inline).
    void setThreads(int threads) { m_threads = threads; }

private:
    size_t face(int i, int j) const { return size_t(j + 1) * size_t(m_n + 2) + size_t(i + 1); }
    // Cell (i, j)'s neighbour index, or −1 beyond an open edge (periodic: wrapped).
    long neighbour(int i, int j) const;
    void applyGradientOpen(float* u, float* v, const float* phi, const uint8_t* solid) const;
    void projectOpen(float* u, float* v);
    void prepareOpen();
    void closeWallFaces(float* u, float* v, const uint8_t* solid) const;
    void applyGradient(float* u, float* v, const float* phi, const uint8_t* solid, glm::vec2 add = glm::vec2(0.0f)) const;
    void factor(const uint8_t* solid);
    void applyA(const float* x, float* out, const uint8_t* solid) const;
    void precondition(const float* r, float* z);
    int forwardRows(const float* r, int j);  // precondition's sweeps, a block of rows from j (the .cpp)
    int backwardRows(float* z, int j);

    int m_n;
    bool m_open = false;
    int m_threads = 1;
    int rowChunk() const { return m_threads > 1 ? (m_n + m_threads - 1) / m_threads : m_n; }
    float* m_div = nullptr;     // n² real, FFTW-aligned (open: the reordered, signed divergence, then φ reordered)
    float* m_spec = nullptr;    // n × (n/2 + 1) complex
    float* m_phiFft = nullptr;  // n² real
    fftwf_plan_s* m_forward = nullptr;
    fftwf_plan_s* m_backward = nullptr;
    std::vector<float> m_coef;  // periodic, per mode: −1/(λ·n²), 0 at k = 0; open: prepareOpen's
    std::vector<float> m_cos, m_sin;  // open: the twiddles cos, sin(πk/(2n)), k = 0..n − 1
    // Wall solve (n² each).
    std::vector<float> m_phi, m_r, m_z, m_s, m_t, m_precon, m_pw, m_q;
    std::vector<float> m_row;  // a row's terms from its neighbouring row (precondition)
    std::vector<uint8_t> m_factored;  // the mask m_precon was made for
};

} // namespace ob::currents
