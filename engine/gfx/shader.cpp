// Shader loading: include expansion with #line markers, compile, link, readable errors.
#include "gfx/shader.h"

#include "core/error.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace ob::gfx {

std::string shaderDirectory() {
    const char* env = std::getenv("OCEANBOX_SHADER_DIR");
    if (env && *env) return env;
    return std::string(OCEANBOX_SOURCE_DIR) + "/shaders";
}

namespace {

// Source-string numbers in #line directives index this list of file names.
struct Expansion {
    std::vector<std::string> files;
    std::string text;
};

// The file's path as messages give it: the folder it is read from, then its name.
std::string shaderPath(const std::string& name) { return shaderDirectory() + "/" + name; }

void expand(const std::string& name, Expansion& out, int depth, const std::string& defines = {}) {
    if (depth > 16) throw RuntimeError(shaderPath(name) + ": #include nested too deeply (a cycle?); fix the #include lines");
    std::ifstream in(shaderPath(name));
    if (!in) throw RuntimeError("shader file not found: " + shaderPath(name) +
                                " (set OCEANBOX_SHADER_DIR to a complete copy of the shaders/ folder)");
    int index = int(out.files.size());
    out.files.push_back(name);
    std::string line;
    int lineNo = 0;
    static const std::regex INCLUDE(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    std::smatch m;
    while (std::getline(in, line)) {
        ++lineNo;
        if (std::regex_match(line, m, INCLUDE)) {
            out.text += "#line 1 " + std::to_string(out.files.size()) + "\n";
            expand(m[1].str(), out, depth + 1);
            out.text += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
        } else {
            out.text += line + "\n";
            if (lineNo == 1 && line.find("#version") != std::string::npos)
                out.text += defines + "#line 2 " + std::to_string(index) + "\n";
        }
    }
}

// Rewrites "0:12(5): error" (Mesa) and "0(12) : error" (NVIDIA) to "<folder>/file:12: error".
std::string mapLog(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex LOCATION(R"((\d+)[:(](\d+)\)?(\(\d+\))?\s*:)");
    std::string out;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, LOCATION) && m.position(0) < 4) {
            const std::string digits = m[1].str();
            size_t file = SIZE_MAX;  // a number beyond size_t names no file
            std::from_chars(digits.data(), digits.data() + digits.size(), file);
            std::string name = file < files.size() ? shaderPath(files[file]) : "?";
            line = name + ":" + m[2].str() + ":" + m.suffix().str();
        }
        out += "  " + line + "\n";
    }
    return out;
}

GLenum stageOf(const std::string& name) {
    auto ends = [&](const char* ext) { return name.size() > 5 && name.compare(name.size() - 5, 5, ext) == 0; };
    if (ends(".vert")) return GL_VERTEX_SHADER;
    if (ends(".frag")) return GL_FRAGMENT_SHADER;
    if (ends(".comp")) return GL_COMPUTE_SHADER;
    if (ends(".geom")) return GL_GEOMETRY_SHADER;
    throw RuntimeError(shaderPath(name) + ": unknown shader stage (expected .vert .frag .comp .geom)");
}

} // namespace

Program loadProgram(const char* label, std::initializer_list<const char*> files, const std::string& defines) {
    Program program(glCreateProgram());
    glObjectLabel(GL_PROGRAM, program.id(), -1, label);
    std::vector<Handle<GlKind::Shader>> shaders;
    for (const char* file : files) {
        Expansion e;
        expand(file, e, 0, defines);
        Handle<GlKind::Shader> shader(glCreateShader(stageOf(file)));
        glObjectLabel(GL_SHADER, shader.id(), -1, file);
        const char* src = e.text.c_str();
        glShaderSource(shader.id(), 1, &src, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint len = 0;
            glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &len);
            std::string log(size_t(len > 0 ? len : 1), '\0');
            glGetShaderInfoLog(shader.id(), GLsizei(log.size()), nullptr, log.data());
            throw RuntimeError("shader " + shaderPath(file) + " failed to compile (fix the lines below, or set "
                               "OCEANBOX_SHADER_DIR to a good copy of the shaders/ folder):\n" +
                               mapLog(log.c_str(), e.files));
        }
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(len > 0 ? len : 1), '\0');
        glGetProgramInfoLog(program.id(), GLsizei(log.size()), nullptr, log.data());
        throw RuntimeError(std::string("program '") + label + "' failed to link (its stages disagree; fix the shaders " +
                           "in " + shaderDirectory() + "):\n" + mapLog(log.c_str(), {}));
    }
    for (auto& s : shaders) glDetachShader(program.id(), s.id());
    return program;
}

} // namespace ob::gfx
