// Shader programs from files in shaders/, with `#include "file.glsl"` and error logs that
// name the file and line.
#pragma once
#include "gfx/handles.h"

#include <initializer_list>
#include <string>

namespace ob::gfx {

/// The folder shaders are read from: $OCEANBOX_SHADER_DIR, else the source tree's shaders/.
std::string shaderDirectory();

/// Compiles and links the named stage files (e.g. {"water_flat.vert", "water_flat.frag"};
/// the stage comes from the extension: .vert .frag .comp .geom). Throws ob::RuntimeError
/// with the compiler log mapped to file:line on failure or a missing file. `defines`: lines
/// (e.g. "#define WATER_FULL_QUALITY\n") put after each stage's #version line.
Program loadProgram(const char* label, std::initializer_list<const char*> files, const std::string& defines = {});

} // namespace ob::gfx
