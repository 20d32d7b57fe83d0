// Window settings, section [window]: plain data, read by the scene without the platform.
#pragma once
#include "core/schema.h"

namespace ob::platform {

/// A framebuffer's side, px: the range of [window] width and height, --size and a
/// recording's size (a GL 4.5 implementation guarantees at least 16384; 8192 keeps the
/// targets of one frame within a few GiB).
constexpr int MIN_FRAMEBUFFER_PX = 16;
constexpr int MAX_FRAMEBUFFER_PX = 8192;

/// Window and context settings, section [window].
struct WindowDef {
    int width = 1280;       ///< framebuffer width (px), [16, 8192]
    int height = 720;       ///< framebuffer height (px), [16, 8192]
    bool vsync = true;      ///< wait for the display's refresh (window only)
    float ui_scale = 0.0f;  ///< the overlay's size, [0.25, 4]; 0: auto (display DPI x framebuffer height / 720)
};

template <class V> void describe(V& v, WindowDef& d) {
    v.field("width", d.width, range(MIN_FRAMEBUFFER_PX, MAX_FRAMEBUFFER_PX), "framebuffer width (px)");
    v.field("height", d.height, range(MIN_FRAMEBUFFER_PX, MAX_FRAMEBUFFER_PX), "framebuffer height (px)");
    v.field("vsync", d.vsync, "wait for the display's refresh (window only)");
    v.field("ui_scale", d.ui_scale, autoOrRange(0.25, 4), "the overlay's size (0: auto from the display's DPI and the window's height)");
}

} // namespace ob::platform
