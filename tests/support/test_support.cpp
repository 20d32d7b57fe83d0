// Shared test helpers.
#include "support/test_support.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace ob::test {

ProcessResult runOceanbox(const std::string& args) { return runShell("\"$OCEANBOX\" " + args); }

ProcessResult runShell(const std::string& command) {
    std::string cmd = std::string("cd '") + OCEANBOX_SOURCE_DIR + "' && OCEANBOX='" + OCEANBOX_EXE + "' && { " + command +
                      "; } 2>&1";
    ProcessResult result;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) result.output.append(buf.data(), n);
    int status = pclose(pipe);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    return result;
}

std::string tempPath(const std::string& name) {
    static int counter = 0;
    auto dir = std::filesystem::temp_directory_path() / ("oceanbox_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return (dir / (std::to_string(counter++) + "_" + name)).string();
}

std::string writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

} // namespace ob::test

#include "support/test_image.h"

#include <stb_image.h>

namespace ob::test {

Image loadPng(const std::string& path) {
    Image img;
    int n = 0;
    unsigned char* data = stbi_load(path.c_str(), &img.w, &img.h, &n, 3);
    if (!data) return Image{};
    img.rgb.assign(data, data + size_t(img.w) * size_t(img.h) * 3);
    stbi_image_free(data);
    return img;
}

} // namespace ob::test
