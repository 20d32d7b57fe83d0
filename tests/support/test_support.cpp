// Shared test helpers.
#include "support/test_support.h"

#include "core/error.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

namespace ob::test {

ProcessResult runOceanbox(const std::string& args) { return runShell("\"$OCEANBOX\" " + args); }

std::string withoutLeakCheck() {
#if defined(__SANITIZE_ADDRESS__)
    return "ASAN_OPTIONS=detect_leaks=0 ";
#else
    return "";
#endif
}

ProcessResult runShell(const std::string& command) {
    std::string cmd = std::string("cd '") + OCEANBOX_SOURCE_DIR + "' && OCEANBOX='" + OCEANBOX_EXE + "' && { " + command +
                      "; } 2>&1";
    ProcessResult result;
    const auto start = std::chrono::steady_clock::now();
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) result.output.append(buf.data(), n);
    int status = pclose(pipe);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::optional<std::string> inputErrorWithin(double seconds, std::function<void()> load) {
    auto done = std::make_shared<std::promise<std::string>>();
    std::future<std::string> message = done->get_future();
    std::thread([done, load] {
        try {
            load();
            done->set_value("");
        } catch (const InputError& e) {
            done->set_value(e.what());
        } catch (const std::exception& e) {
            done->set_value(std::string("not an InputError: ") + e.what());
        }
    }).detach();
    if (message.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) return std::nullopt;
    return message.get();
}

std::string tempPath(const std::string& name) {
    static std::atomic<int> counter{0};
    static std::once_flag emptied;
    auto dir = std::filesystem::temp_directory_path() / ("oceanbox_test_" + std::to_string(getpid()));
    // A folder left by an earlier process of the same pid is emptied first: its files must not
    // collide with this process's (mkfifo at an existing name fails). Once per process, before any
    // thread's first file (tests call this from several threads).
    std::call_once(emptied, [&] { std::filesystem::remove_all(dir); });
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
