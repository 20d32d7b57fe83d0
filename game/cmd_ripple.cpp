// `oceanbox ripple`: load Vh(t) and Vh(t−1), step eq. 1–2 with the fixed boundary, save Vh(t).
#include "cmd_ripple.h"

#include "core/error.h"
#include "core/npy.h"
#include "interaction/ripple_field.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <string>

namespace ob::game {

namespace {

std::string shapeText(const std::vector<size_t>& shape) {
    std::string s = "(";
    for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + (shape.size() == 1 ? ",)" : ")");
}

std::string numberText(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

} // namespace

int rippleCommand(const RippleArgs& args) {
    // --- flags
    if (args.in.empty()) throw InputError("ripple: --in is required (a float32 .npy field [N, M])");
    if (args.out.empty()) throw InputError("ripple: --out is required (the .npy file to write)");
    if (args.steps < 0) throw InputError("ripple: --steps " + std::to_string(args.steps) + " is negative (need >= 0)");
    if (!(args.damping >= 0.0f && args.damping <= 1.0f))
        throw InputError("ripple: --damping " + numberText(args.damping) + " is outside [0, 1]");

    // --- fields
    NpyArray h = readNpy(args.in);
    if (h.shape.size() != 2 || h.shape[0] < 1 || h.shape[1] < 1)
        throw InputError(args.in + ": need a 2-D field of shape [N, M] with N, M >= 1, got shape " +
                         shapeText(h.shape));
    if (h.shape[0] > size_t(INT_MAX) || h.shape[1] > size_t(INT_MAX))
        throw InputError(args.in + ": shape " + shapeText(h.shape) + " is too large");
    NpyArray p;
    if (!args.prev.empty()) {
        p = readNpy(args.prev);
        if (p.shape != h.shape)
            throw InputError(args.prev + ": shape " + shapeText(p.shape) + " differs from --in " + args.in +
                             " shape " + shapeText(h.shape));
    }

    // --- solve
    interaction::RippleField field(int(h.shape[0]), int(h.shape[1]), interaction::RippleBoundary::Fixed);
    std::copy(h.data.begin(), h.data.end(), field.current().begin());
    const std::vector<float>& prevData = args.prev.empty() ? h.data : p.data;
    std::copy(prevData.begin(), prevData.end(), field.previous().begin());
    for (int k = 0; k < args.steps; ++k) field.step(args.damping);

    writeNpy(args.out, h.shape, field.current().data());
    return 0;
}

} // namespace ob::game
