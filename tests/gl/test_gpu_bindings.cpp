// The one table of binding points, locations and std140 blocks (shaders/common_bindings.glsl,
// gfx/gpu_bindings.h) against what the GL compiler made of every program: each program the
// renderer builds (every pass, the water variants of a frame with all layers) and the ocean's
// compute programs, read back through program interface queries.
#include "gfx/gl.h"
#include "gfx/gpu_bindings.h"
#include "ewave_bindings.glsl"
#include "kang2008_bindings.glsl"
#include "ripple_levels_bindings.glsl"
#include "gfx/renderer.h"
#include <glm/gtc/matrix_transform.hpp>
#include "gfx/shader.h"
#include "ocean/gpu/ocean_textures.h"
#include "platform/platform.h"

#include <catch2/catch.hpp>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace ob;
using namespace ob::gfx::glsl;

namespace {

// What each name must be bound to, written here by hand from the shaders' meaning (not read
// from the table under test): samplers and images → unit, plain uniforms → location, inputs →
// attribute, blocks → binding point.
const std::map<std::string, int> EXPECTED_UNITS = {
    {"u_displacement", DISPLACEMENT_UNIT}, {"u_slopes", SLOPES_UNIT}, {"u_ripples", RIPPLES_UNIT}, {"u_sky", SKY_UNIT},
    {"u_reflection", REFLECTION_UNIT}, {"u_refraction", REFRACTION_UNIT}, {"u_detail", DETAIL_UNIT},
    {"u_reflectionDepth", REFLECTION_DEPTH_UNIT}, {"u_foamMap", FOAM_UNIT}, {"u_rippleSlopes", RIPPLE_SLOPES_UNIT},
    {"u_foamPattern", FOAM_PATTERN_UNIT}, {"u_source", POST_SOURCE_UNIT}, {"u_rippleLevels", RIPPLE_LEVELS_UNIT},
    {"u_rippleLevelSlopes", RIPPLE_LEVEL_SLOPES_UNIT}, {"u_sceneDepth", SCENE_DEPTH_UNIT}, {"u_hullOutlines", HULL_OUTLINE_UNIT},
};
const std::map<std::string, int> EXPECTED_IMAGES = {{"u_displacement", OCEAN_DISPLACEMENT_IMAGE}, {"u_slopes", OCEAN_SLOPES_IMAGE}};
const std::map<std::string, int> EXPECTED_LOCATIONS = {
    {"u_model", OBJECT_MODEL_LOCATION}, {"u_tint", OBJECT_TINT_LOCATION}, {"u_surfacePlane", OBJECT_SURFACE_PLANE_LOCATION},
    {"u_right", SPLASH_RIGHT_LOCATION}, {"u_up", SPLASH_UP_LOCATION}, {"u_sprite", SPLASH_SPRITE_LOCATION},
    {"u_face", SKY_FACE_LOCATION}, {"u_texel", FXAA_TEXEL_LOCATION}, {"u_sharpness", FXAA_SHARPNESS_LOCATION},
    {"u_n", OCEAN_N_LOCATION}, {"u_time", OCEAN_TIME_LOCATION}, {"u_log2n", OCEAN_LOG2N_LOCATION},
    {"u_columns", OCEAN_COLUMNS_LOCATION}, {"u_lambda", OCEAN_LAMBDA_LOCATION},
};
const std::map<std::string, int> EXPECTED_ATTRIBUTES = {
    {"a_position", MESH_POSITION_ATTRIB}, {"a_normal", MESH_NORMAL_ATTRIB}, {"a_color", MESH_COLOR_ATTRIB},
    {"a_uv", GRID_UV_ATTRIB}, {"a_drop", SPLASH_DROP_ATTRIB},
};
const std::map<std::string, int> EXPECTED_BLOCKS = {{"FrameUniforms", FRAME_BLOCK}, {"WaterUniforms", WATER_BLOCK}};
const std::map<std::string, int> EXPECTED_STORAGE = {
    {"Modes", OCEAN_MODES_BUFFER}, {"Quarter", OCEAN_QUARTER_BUFFER}, {"WaveNumbers", OCEAN_WAVE_NUMBERS_BUFFER},
    {"Spectra", OCEAN_SPECTRA_BUFFER}, {"Twiddles", OCEAN_TWIDDLES_BUFFER},
};
// Each block member's C++ offset: std140 must put it at the same byte.
#define MEMBER(block, member) {#block "." #member, offsetof(block, member)}
#define ARRAY(block, member) {#block "." #member "[0]", offsetof(block, member)}
const std::map<std::string, size_t> CPP_OFFSETS = {
    MEMBER(FrameUniforms, viewProjection), MEMBER(FrameUniforms, inverseViewProjection), MEMBER(FrameUniforms, cameraPositionTime),
    MEMBER(FrameUniforms, sunDirectionFresnel), MEMBER(FrameUniforms, waterColorExposure), MEMBER(FrameUniforms, viewport),
    MEMBER(FrameUniforms, surfaceClip), MEMBER(FrameUniforms, depthParams), MEMBER(FrameUniforms, shading),
    MEMBER(FrameUniforms, switches), MEMBER(FrameUniforms, waterline), MEMBER(FrameUniforms, sky), MEMBER(FrameUniforms, sunLight), MEMBER(FrameUniforms, sunCloud), ARRAY(WaterUniforms, corner), MEMBER(WaterUniforms, cascadeSize),
    MEMBER(WaterUniforms, waterParams), MEMBER(WaterUniforms, gridParams), MEMBER(WaterUniforms, rippleParams),
    MEMBER(WaterUniforms, foamParams), MEMBER(WaterUniforms, cascadeFade), MEMBER(WaterUniforms, cascadeFadeEnd),
    MEMBER(WaterUniforms, farFade), MEMBER(WaterUniforms, cascadeSlopeVariance), MEMBER(WaterUniforms, glitterParams),
    MEMBER(WaterUniforms, crest), ARRAY(WaterUniforms, rippleLevels), MEMBER(WaterUniforms, rippleFade),
    ARRAY(WaterUniforms, gerstner), MEMBER(WaterUniforms, hullCount),
    ARRAY(WaterUniforms, hullFromWorld), ARRAY(WaterUniforms, hullPlan),
};
#undef MEMBER
#undef ARRAY
const std::map<std::string, size_t> CPP_SIZES = {{"FrameUniforms", sizeof(FrameUniforms)}, {"WaterUniforms", sizeof(WaterUniforms)}};

std::string resourceName(GLuint program, GLenum interface, GLuint index) {
    char name[256];
    GLsizei length = 0;
    glGetProgramResourceName(program, interface, index, sizeof name, &length, name);
    return std::string(name, size_t(length));
}

GLint resourceValue(GLuint program, GLenum interface, GLuint index, GLenum property) {
    GLint value = -1;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

GLint activeCount(GLuint program, GLenum interface) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
    return count;
}

bool isSampler(GLint type) {
    switch (type) {
    case GL_SAMPLER_2D: case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_CUBE: return true;
    default: return false;
    }
}
bool isImage(GLint type) { return type == GL_IMAGE_2D_ARRAY || type == GL_IMAGE_2D; }

// Checks one program's every active interface against the expectations; `seen` collects the
// names met, so the test can require that every entry of the table was exercised.
void checkProgram(const std::string& label, GLuint program, std::set<std::string>& seen) {
    INFO("program " << label);
    const auto expect = [&](const std::map<std::string, int>& table, const std::string& name, GLint actual, const char* what) {
        INFO(what << " " << name);
        const auto it = table.find(name);
        REQUIRE(it != table.end());  // every binding a program declares is in the table
        CHECK(actual == it->second);
        seen.insert(std::string(what) + " " + name);
    };
    for (GLuint i = 0; i < GLuint(activeCount(program, GL_UNIFORM)); ++i) {
        const std::string name = resourceName(program, GL_UNIFORM, i);
        if (resourceValue(program, GL_UNIFORM, i, GL_BLOCK_INDEX) >= 0) {  // a block member: its std140 offset
            INFO("member " << name);
            const auto it = CPP_OFFSETS.find(name);
            REQUIRE(it != CPP_OFFSETS.end());
            CHECK(size_t(resourceValue(program, GL_UNIFORM, i, GL_OFFSET)) == it->second);
            seen.insert("member " + name);
            continue;
        }
        const GLint type = resourceValue(program, GL_UNIFORM, i, GL_TYPE);
        const GLint location = resourceValue(program, GL_UNIFORM, i, GL_LOCATION);
        if (isSampler(type) || isImage(type)) {
            GLint unit = -1;
            glGetUniformiv(program, location, &unit);  // a sampler's or image's binding is its value
            expect(isImage(type) ? EXPECTED_IMAGES : EXPECTED_UNITS, name, unit, isImage(type) ? "image" : "sampler");
        } else {
            expect(EXPECTED_LOCATIONS, name, location, "uniform");
            CHECK(glGetUniformLocation(program, name.c_str()) == location);
        }
    }
    for (GLuint i = 0; i < GLuint(activeCount(program, GL_UNIFORM_BLOCK)); ++i) {
        const std::string name = resourceName(program, GL_UNIFORM_BLOCK, i);
        expect(EXPECTED_BLOCKS, name, resourceValue(program, GL_UNIFORM_BLOCK, i, GL_BUFFER_BINDING), "block");
        CHECK(glGetUniformBlockIndex(program, name.c_str()) == i);
        CHECK(size_t(resourceValue(program, GL_UNIFORM_BLOCK, i, GL_BUFFER_DATA_SIZE)) == CPP_SIZES.at(name));
    }
    for (GLuint i = 0; i < GLuint(activeCount(program, GL_SHADER_STORAGE_BLOCK)); ++i) {
        const std::string name = resourceName(program, GL_SHADER_STORAGE_BLOCK, i);
        expect(EXPECTED_STORAGE, name, resourceValue(program, GL_SHADER_STORAGE_BLOCK, i, GL_BUFFER_BINDING), "storage block");
    }
    for (GLuint i = 0; i < GLuint(activeCount(program, GL_PROGRAM_INPUT)); ++i) {
        const std::string name = resourceName(program, GL_PROGRAM_INPUT, i);
        if (name.rfind("gl_", 0) == 0) continue;  // built-ins (gl_VertexID) have no location
        expect(EXPECTED_ATTRIBUTES, name, resourceValue(program, GL_PROGRAM_INPUT, i, GL_LOCATION), "attribute");
    }
}

// A frame that builds every program: FFT layers, ripples and a foam map, an object across the
// surface (both object programs) whose hull the water is clipped out of, splash drops (both
// sprite programs), FXAA below scale 1; with the eye at `eyeHeight` (m; below the surface: the
// water's underwater variant).
void renderEverything(gfx::Renderer& renderer, const ocean::OceanTextures& textures, float eyeHeight) {
    static std::vector<float> ripples(16 * 16, 0.01f), foam(8 * 8, 0.5f);
    gfx::WaterView water;
    water.displacement = &textures.displacement();
    water.slopes = &textures.slopes();
    water.cascades = 2;
    water.resolution = 16;
    water.cascadeSize = {100.0f, 20.0f, 0.0f, 0.0f};
    water.gerstner = {glm::vec4(0.1f, 0.0f, 0.2f, 0.0f)};
    water.ripples = ripples.data();
    water.rippleCells = 16;
    water.foam = foam.data();
    water.foamCells = 8;
    gfx::CameraView camera;
    camera.position = glm::vec3(0.0f, eyeHeight, 10.0f);
    camera.view = glm::lookAt(camera.position, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    camera.projection = glm::perspective(1.0f, 16.0f / 9.0f, 0.1f, 2000.0f);
    gfx::ObjectDraw ship;  // 8 m across the surface: cut per vertex in the reflection and refraction
    ship.mesh = gfx::MeshKind::Box;
    ship.model = glm::scale(glm::mat4(1.0f), glm::vec3(8.0f));
    gfx::ObjectDraw ball;  // small, across the surface: the tangent plane cut
    ball.model = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 0.0f, 0.0f)), glm::vec3(0.5f));
    water.hulls.push_back({glm::inverse(ship.model), nullptr});
    const std::vector<gfx::SplashDrop> drops = {glm::vec4(0.0f, 1.0f, 0.0f, 0.05f)};
    renderer.render(camera, water, {ship, ball}, 0.0, {160, 90}, drops);
}

} // namespace

TEST_CASE("every program's bindings, locations and std140 offsets are those of common_bindings.glsl", "[gl][render][bindings]") {
    auto platform = platform::createHeadlessPlatform({160, 90});
    const int errorsBefore = gfx::glErrorCount();
    gfx::RenderDef def;
    def.antialias = gfx::Antialias::Fxaa;
    def.resolution_scale = 0.5f;
    gfx::Renderer renderer(def);
    const ocean::OceanTextures textures(16, 2);
    renderEverything(renderer, textures, 5.0f);
    renderEverything(renderer, textures, -3.0f);  // a second water variant
    std::set<std::string> seen;
    size_t programs = 0;
    for (const auto& [label, program] : renderer.programs()) checkProgram(label, program, seen), ++programs;
    CHECK(programs == 12);  // sky bake, sky, two water variants, foam bake, 2 object, 2 splash, upscale, 2 FXAA
    for (const char* file : {"ocean_spectrum.comp", "ocean_fft.comp", "ocean_unpack.comp"}) {
        const gfx::Program program = gfx::loadProgram(file, {file});
        checkProgram(file, program.id(), seen);
    }
    // Every entry of the expectations was met in some program: none is stale, and the frame
    // above built what it was meant to.
    const std::pair<const std::map<std::string, int>*, const char*> tables[] = {
        {&EXPECTED_UNITS, "sampler"}, {&EXPECTED_IMAGES, "image"}, {&EXPECTED_LOCATIONS, "uniform"},
        {&EXPECTED_ATTRIBUTES, "attribute"}, {&EXPECTED_BLOCKS, "block"}, {&EXPECTED_STORAGE, "storage block"}};
    for (const auto& [table, what] : tables)
        for (const auto& [name, value] : *table) {
            const std::string key = std::string(what) + " " + name;
            INFO(key);
            CHECK(seen.count(key) == 1);
        }
    for (const auto& [name, offset] : CPP_OFFSETS) {
        INFO(name);
        CHECK(seen.count("member " + name) == 1);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

namespace {

// A ripple solver's compute program against its own table (shaders/<solver>_bindings.glsl):
// every active uniform and storage block in the table and at its number, every entry met, and
// the local size the C++ dispatch divides by. Tables by hand from the shaders' meaning.
void checkSolverProgram(const char* file, const std::map<std::string, int>& locations, const std::map<std::string, int>& storage,
                        int tile) {
    INFO("program " << file);
    const gfx::Program program = gfx::loadProgram(file, {file});
    const GLuint id = program.id();
    std::set<std::string> seen;
    for (GLuint i = 0; i < GLuint(activeCount(id, GL_UNIFORM)); ++i) {
        const std::string name = resourceName(id, GL_UNIFORM, i);
        INFO("uniform " << name);
        REQUIRE(locations.count(name) == 1);
        CHECK(resourceValue(id, GL_UNIFORM, i, GL_LOCATION) == locations.at(name));
        seen.insert(name);
    }
    for (GLuint i = 0; i < GLuint(activeCount(id, GL_SHADER_STORAGE_BLOCK)); ++i) {
        const std::string name = resourceName(id, GL_SHADER_STORAGE_BLOCK, i);
        INFO("storage block " << name);
        REQUIRE(storage.count(name) == 1);
        CHECK(resourceValue(id, GL_SHADER_STORAGE_BLOCK, i, GL_BUFFER_BINDING) == storage.at(name));
        seen.insert(name);
    }
    CHECK(seen.size() == locations.size() + storage.size());
    GLint local[3] = {0, 0, 0};
    glGetProgramiv(id, GL_COMPUTE_WORK_GROUP_SIZE, local);
    CHECK(local[0] == tile);
    CHECK(local[1] == tile);
}

// Every active uniform of a program in `expected` and at its number (a sampler's or image's
// unit, else its location), every entry met.
void checkUniformNumbers(GLuint id, const std::map<std::string, int>& expected) {
    std::set<std::string> seen;
    for (GLuint i = 0; i < GLuint(activeCount(id, GL_UNIFORM)); ++i) {
        const std::string name = resourceName(id, GL_UNIFORM, i);
        INFO("uniform " << name);
        REQUIRE(expected.count(name) == 1);
        const GLint type = resourceValue(id, GL_UNIFORM, i, GL_TYPE), location = resourceValue(id, GL_UNIFORM, i, GL_LOCATION);
        GLint actual = location;
        if (isSampler(type) || isImage(type)) glGetUniformiv(id, location, &actual);
        CHECK(actual == expected.at(name));
        seen.insert(name);
    }
    CHECK(seen.size() == expected.size());
}

} // namespace

TEST_CASE("the ripple solvers' compute programs use the numbers of their bindings files", "[gl][ripple_gpu][ewave_gpu][bindings]") {
    auto platform = platform::createHeadlessPlatform({64, 64});
    const int errorsBefore = gfx::glErrorCount();
    checkSolverProgram("ripple_step.comp",
                       {{"u_size", KANG2008_SIZE_LOCATION}, {"u_damping", KANG2008_DAMPING_LOCATION},
                        {"u_sponge", KANG2008_SPONGE_LOCATION}, {"u_mode", KANG2008_MODE_LOCATION}, {"u_shift", KANG2008_SHIFT_LOCATION}},
                       {{"Current", KANG2008_CURRENT_BUFFER}, {"Previous", KANG2008_PREVIOUS_BUFFER}, {"Sponge", KANG2008_SPONGE_BUFFER}},
                       KANG2008_STEP_TILE);
    checkSolverProgram("ripple_stamp.comp",
                       {{"u_size", KANG2008_SIZE_LOCATION}, {"u_pass", KANG2008_PASS_LOCATION},
                        {"u_firstStamp", KANG2008_FIRST_STAMP_LOCATION}, {"u_stampCount", KANG2008_STAMP_COUNT_LOCATION}},
                       {{"Current", KANG2008_CURRENT_BUFFER}, {"Previous", KANG2008_PREVIOUS_BUFFER}, {"Stamps", KANG2008_STAMPS_BUFFER},
                        {"Ph", KANG2008_PH_BUFFER}, {"Owner", KANG2008_OWNER_BUFFER}},
                       KANG2008_STAMP_TILE);
    checkSolverProgram("ewave_step.comp",
                       {{"u_n", EWAVE_N_LOCATION}, {"u_mode", EWAVE_MODE_LOCATION}, {"u_level", EWAVE_LEVEL_LOCATION}},
                       {{"Spectrum", EWAVE_SPECTRUM_BUFFER}, {"Field", EWAVE_FIELD_BUFFER}, {"Rotation", EWAVE_ROTATION_BUFFER},
                        {"Sponge", EWAVE_SPONGE_BUFFER}, {"Sum", EWAVE_SUM_BUFFER}},
                       EWAVE_TILE);
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("the ripple levels' compute program uses the numbers of its bindings file", "[gl][levels][bindings]") {
    auto platform = platform::createHeadlessPlatform({64, 64});
    const gfx::Program program = gfx::loadProgram("ripple_levels.comp", {"ripple_levels.comp"});
    const GLuint id = program.id();
    // Samplers and images by their unit, the rest by location, as water_layers.cpp binds them.
    const std::map<std::string, int> expected = {
        {"u_states", RIPPLE_LEVEL_STATES_UNIT},         {"u_heights", RIPPLE_LEVEL_HEIGHT_IMAGE},
        {"u_levelSlopes", RIPPLE_LEVEL_SLOPE_IMAGE},    {"u_level", RIPPLE_LEVEL_LOCATION},
        {"u_weights", RIPPLE_LEVEL_WEIGHTS_LOCATION},   {"u_grid", RIPPLE_LEVEL_GRID_LOCATION}};
    checkUniformNumbers(id, expected);
    GLint local[3] = {0, 0, 0};
    glGetProgramiv(id, GL_COMPUTE_WORK_GROUP_SIZE, local);
    CHECK(local[0] == RIPPLE_LEVEL_TILE);
    CHECK(local[1] == RIPPLE_LEVEL_TILE);
}

TEST_CASE("level 0's ripple slope program uses the numbers of its bindings file", "[gl][levels][bindings]") {
    auto platform = platform::createHeadlessPlatform({64, 64});
    const gfx::Program program = gfx::loadProgram("ripple_slopes.comp", {"ripple_slopes.comp"});
    const GLuint id = program.id();
    const std::map<std::string, int> expected = {
        {"u_rippleHeights", RIPPLE_SLOPES_HEIGHT_UNIT}, {"u_rippleSlopesOut", RIPPLE_SLOPES_IMAGE}, {"u_grid", RIPPLE_SLOPES_GRID_LOCATION}};
    checkUniformNumbers(id, expected);
}
