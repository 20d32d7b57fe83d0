// GL tests only: a compute probe (tests/gl/shaders/<probe>) compiled with the engine's shader
// includes beside it, so it calls the shaders' own functions.
#pragma once
#include "gfx/shader.h"
#include "support/test_support.h"

#include <cstdlib>
#include <filesystem>

namespace ob::test {

/// Copies shaders/ and the probe into a temporary folder (`folder` under the test's temp path)
/// and loads the probe from there.
inline gfx::Program loadShaderProbe(const char* probe, const char* folder = "probe_shaders") {
    namespace fs = std::filesystem;
    const fs::path dir = tempPath(folder);
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(fs::path(OCEANBOX_SOURCE_DIR) / "shaders"))
        fs::copy_file(entry.path(), dir / entry.path().filename(), fs::copy_options::overwrite_existing);
    fs::copy_file(fs::path(OCEANBOX_SOURCE_DIR) / "tests/gl/shaders" / probe, dir / probe, fs::copy_options::overwrite_existing);
    setenv("OCEANBOX_SHADER_DIR", dir.c_str(), 1);
    gfx::Program program = gfx::loadProgram(probe, {probe});
    unsetenv("OCEANBOX_SHADER_DIR");
    return program;
}

} // namespace ob::test
