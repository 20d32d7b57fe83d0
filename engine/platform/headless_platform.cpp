// The headless platform's choice between OSMesa and EGL.
#include "platform/platform.h"

#include "core/error.h"

#include <cstdlib>
#include <string>

namespace ob::platform {

std::unique_ptr<Platform> createHeadlessPlatform(glm::ivec2 size) {
    const char* env = std::getenv("OCEANBOX_HEADLESS_GL");
    const std::string choice = env && *env ? env : "osmesa";
    if (choice == "osmesa") return createOsmesaPlatform(size);
    if (choice == "egl") return createEglPlatform(size);
    throw InputError("OCEANBOX_HEADLESS_GL: must be \"osmesa\" or \"egl\", got \"" + choice + "\"");
}

} // namespace ob::platform
