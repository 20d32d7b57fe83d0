// The ewave ripple solver's GPU twin (ewave_step.comp around the ocean's ocean_fft.comp, whose
// numbers are in common_bindings.glsl): its storage buffers, uniform locations, modes and
// work-group size, written once and read as GLSL by the shader and as C++ by
// interaction/ewave/gpu/ewave_gpu.cpp. tests/gl/test_gpu_bindings.cpp checks them against the
// compiled program.
#ifndef EWAVE_BINDINGS_GLSL
#define EWAVE_BINDINGS_GLSL
#ifdef __cplusplus
#define SHARED_CONST constexpr int
#else
#define SHARED_CONST const int
#endif

// Row-major N×N complex floats, index row·N + column.
SHARED_CONST EWAVE_SPECTRUM_BUFFER = 0;  // mode rotate: S
SHARED_CONST EWAVE_FIELD_BUFFER = 1;     // mode rotate: Y out; ring, sponge: w in place
SHARED_CONST EWAVE_ROTATION_BUFFER = 2;  // per |row|, |column| in [0, N/2]: (a, b, c, 0)
SHARED_CONST EWAVE_SPONGE_BUFFER = 5;    // mode sponge: exp(−γΔt) per cell (3, 4: the FFT's)
SHARED_CONST EWAVE_SUM_BUFFER = 6;       // modes sponge, total, restore: Σh per work group, then the total after them

SHARED_CONST EWAVE_N_LOCATION = 0;     // int N, power of two
SHARED_CONST EWAVE_MODE_LOCATION = 1;  // int EWAVE_MODE_*
SHARED_CONST EWAVE_LEVEL_LOCATION = 2; // float: the mean level of h the absorbing border keeps, m

SHARED_CONST EWAVE_MODE_ROTATE = 0;  // rotate every mode
SHARED_CONST EWAVE_MODE_RING = 1;    // fixed border: the outer ring to 0
SHARED_CONST EWAVE_MODE_SPONGE = 2;  // absorbing border: the sponge factors towards the level, then Σh per work group
SHARED_CONST EWAVE_MODE_TOTAL = 3;   // one work group: the work groups' sums added
SHARED_CONST EWAVE_MODE_RESTORE = 4; // h shifted so that its mean is the level again

SHARED_CONST EWAVE_TILE = 16;  // ewave_step.comp's local size, per axis

#undef SHARED_CONST
#endif
