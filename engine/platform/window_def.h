// Window settings, section [window]: plain data, read by the scene without the platform.
#pragma once
#include "core/schema.h"

namespace ob::platform {

/// Window and context settings, section [window].
struct WindowDef {
    int width = 1280;       ///< framebuffer width (px), [16, 8192]
    int height = 720;       ///< framebuffer height (px), [16, 8192]
    bool vsync = true;      ///< wait for the display's refresh (window only)
    float ui_scale = 0.0f;  ///< the overlay's size, [0.25, 4]; 0: auto (display DPI x framebuffer height / 720)
};

template <class V> void describe(V& v, WindowDef& d) {
    v.field("width", d.width, range(16, 8192), "framebuffer width (px)");
    v.field("height", d.height, range(16, 8192), "framebuffer height (px)");
    v.field("vsync", d.vsync, "wait for the display's refresh (window only)");
    v.field("ui_scale", d.ui_scale, autoOrRange(0.25, 4), "the overlay's size (0: auto from the display's DPI and the window's height)");
}

} // namespace ob::platform
