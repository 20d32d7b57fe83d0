// The ripple levels' per-frame passes (ripple_levels.comp, ripple_slopes.comp): their texture
// units, images and uniform locations, written once and read as GLSL by the shaders and as C++
// by gfx/water_layers.cpp.
#ifndef RIPPLE_LEVELS_BINDINGS_GLSL
#define RIPPLE_LEVELS_BINDINGS_GLSL
#ifdef __cplusplus
#define SHARED_CONST constexpr int
#else
#define SHARED_CONST const int
#endif

SHARED_CONST RIPPLE_LEVEL_STATES_UNIT = 0;    // sampler2DArray: per coarse level L (0-based) layers 4L..4L+3 = h0, h1, v0, v1
SHARED_CONST RIPPLE_LEVEL_HEIGHT_IMAGE = 0;   // r32f image2DArray: the heights the water shader reads (layer L)
SHARED_CONST RIPPLE_LEVEL_SLOPE_IMAGE = 1;    // rg32f image2DArray: their central differences, one cell of margin (layer L)
SHARED_CONST RIPPLE_LEVEL_LOCATION = 0;       // int L, the level (layer) written
SHARED_CONST RIPPLE_LEVEL_WEIGHTS_LOCATION = 1;  // vec4 the cubic's weights of (h0, h1, v0, v1)
SHARED_CONST RIPPLE_LEVEL_GRID_LOCATION = 2;  // vec2 (cells per side N, cell size m)
SHARED_CONST RIPPLE_LEVEL_TILE = 8;           // work group side (both passes)
// Level 0's slopes (ripple_slopes.comp), made when its heights are uploaded
SHARED_CONST RIPPLE_SLOPES_HEIGHT_UNIT = 0;   // sampler2D: level 0's heights, N² (r32f)
SHARED_CONST RIPPLE_SLOPES_IMAGE = 1;         // rg32f image2D: their central differences, (N + 2)², one cell of margin
SHARED_CONST RIPPLE_SLOPES_GRID_LOCATION = 0; // vec2 (cells per side N, 1 / (2 × cell size) per m)

#endif
