// The kang2008 ripple solver's GPU twin (ripple_step.comp, ripple_stamp.comp): its storage
// buffers, uniform locations, modes and work-group sizes, written once and read as GLSL by the
// shaders and as C++ by interaction/kang2008/gpu/ripple_gpu.cpp. tests/gl/test_gpu_bindings.cpp
// checks them against the compiled programs.
#ifndef KANG2008_BINDINGS_GLSL
#define KANG2008_BINDINGS_GLSL
#ifdef __cplusplus
#define SHARED_CONST constexpr int
#else
#define SHARED_CONST const int
#endif

// Row-major N×M float levels, index z·M + x.
SHARED_CONST KANG2008_CURRENT_BUFFER = 0;   // both: Vh(t); step mode 1: the source
SHARED_CONST KANG2008_PREVIOUS_BUFFER = 1;  // both: Vh(t−1); step: Vh(t+1) out; mode 1: destination
SHARED_CONST KANG2008_SPONGE_BUFFER = 2;    // step: s(d), N row factors then M column factors
SHARED_CONST KANG2008_STAMPS_BUFFER = 2;    // stamp: the stamp list
SHARED_CONST KANG2008_PH_BUFFER = 3;        // stamp: eq. 4 PH per box cell, −1 outside the disc
SHARED_CONST KANG2008_OWNER_BUFFER = 4;     // stamp: per cell 0, or the claiming stamp + 1

SHARED_CONST KANG2008_SIZE_LOCATION = 0;         // both: ivec2 (M columns, N rows)
SHARED_CONST KANG2008_DAMPING_LOCATION = 1;      // step: float DF of eq. 2
SHARED_CONST KANG2008_SPONGE_LOCATION = 2;       // step: int 1 = absorbing band present
SHARED_CONST KANG2008_MODE_LOCATION = 3;         // step: int KANG2008_MODE_*
SHARED_CONST KANG2008_SHIFT_LOCATION = 4;        // step: ivec2 mode 1's (dx, dz)
SHARED_CONST KANG2008_PASS_LOCATION = 1;         // stamp: int 0 claim, 1 write
SHARED_CONST KANG2008_FIRST_STAMP_LOCATION = 2;  // stamp: int stamp of work group z = 0
SHARED_CONST KANG2008_STAMP_COUNT_LOCATION = 3;  // stamp: int stamps in the list

SHARED_CONST KANG2008_MODE_STEP = 0;   // eq. 1–2 step
SHARED_CONST KANG2008_MODE_SHIFT = 1;  // scroll a level by whole cells into the other

SHARED_CONST KANG2008_STEP_TILE = 16;  // ripple_step.comp's local size, per axis
SHARED_CONST KANG2008_STAMP_TILE = 8;  // ripple_stamp.comp's local size, per axis

#undef SHARED_CONST
#endif
