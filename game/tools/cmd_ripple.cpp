// `oceanbox ripple`: kang2008 loads Vh(t) and Vh(t−1), steps eq. 1–2 with the fixed boundary and
// saves Vh(t); ewave loads h and v, steps them exactly per Fourier mode and saves h (each model's
// stepArrays, through the registration table: interaction/ripple_arrays.h).
#include "tools/cmd_ripple.h"

#include "core/error.h"
#include "core/npy.h"
#include "interaction/ripple_arrays.h"

#include <algorithm>
#include <climits>
#include <cmath>
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

// Where the first value that is not a finite number lies in a [rows, cols] field; false when none.
bool firstNonFinite(const float* data, size_t count, size_t cols, size_t& row, size_t& col) {
    for (size_t i = 0; i < count; ++i)
        if (!std::isfinite(data[i])) {
            row = i / cols;
            col = i % cols;
            return true;
        }
    return false;
}

// A field read from a file holds finite numbers only: one NaN or inf spreads over the field.
void checkFinite(const NpyArray& a, const std::string& path) {
    size_t row = 0, col = 0;
    if (a.shape.size() == 2 && firstNonFinite(a.data.data(), a.data.size(), a.shape[1], row, col))
        throw InputError(path + ": the value at (row " + std::to_string(row) + ", column " + std::to_string(col) + ") is " +
                         numberText(a.data[row * a.shape[1] + col]) + ", not a finite number");
}

// The solved field is finite: values near a float's limit (3e38) or flags that make the
// step's factors overflow (--cell-size 1e-30) would write NaN or inf. Exit 2: the input did it.
void checkSolved(const float* data, const std::vector<size_t>& shape, const RippleArgs& args, const std::string& flags) {
    size_t row = 0, col = 0;
    if (firstNonFinite(data, shape[0] * shape[1], shape[1], row, col))
        throw InputError("ripple: after " + std::to_string(args.steps) + " steps the field at (row " + std::to_string(row) +
                         ", column " + std::to_string(col) + ") is " + numberText(data[row * shape[1] + col]) +
                         ", not a finite number: the values of --in " + args.in + flags +
                         " make the step overflow (give smaller values); nothing written");
}

NpyArray readField(const std::string& path, size_t minSide) {
    NpyArray h = readNpy(path);
    if (h.shape.size() != 2 || h.shape[0] < minSide || h.shape[1] < minSide)
        throw InputError(path + ": need a 2-D field of shape [N, M] with N, M >= " + std::to_string(minSide) +
                         ", got shape " + shapeText(h.shape));
    if (h.shape[0] > size_t(INT_MAX) || h.shape[1] > size_t(INT_MAX))
        throw InputError(path + ": shape " + shapeText(h.shape) + " is too large");
    checkFinite(h, path);
    return h;
}

NpyArray readSameShape(const std::string& path, const std::string& flag, const NpyArray& like, const std::string& likePath) {
    NpyArray p = readNpy(path);
    if (p.shape != like.shape)
        throw InputError(path + ": shape " + shapeText(p.shape) + " (" + flag + ") differs from --in " + likePath + " shape " +
                         shapeText(like.shape));
    checkFinite(p, path);
    return p;
}

int ewaveCommand(const RippleArgs& args) {
    // --- flags
    if (!args.prev.empty()) throw InputError("ripple: --prev is for --model kang2008; ewave takes the velocity with --vel");
    if (!(args.damping >= 0.0f && std::isfinite(args.damping)))
        throw InputError("ripple: --damping " + numberText(args.damping) + ": ewave's decay time must be >= 0 s (0 = none)");
    if (!(args.viscosity >= 0.0f && std::isfinite(args.viscosity)))
        throw InputError("ripple: --viscosity " + numberText(args.viscosity) + " must be >= 0 m2/s");
    if (!(args.dt > 0.0f && std::isfinite(args.dt))) throw InputError("ripple: --dt " + numberText(args.dt) + " must be > 0 s");
    if (!(args.cellSize > 0.0f && std::isfinite(args.cellSize)))
        throw InputError("ripple: --cell-size " + numberText(args.cellSize) + " must be > 0 m");
    interaction::RippleBoundary boundary = interaction::RippleBoundary::Periodic;
    if (!args.boundary.empty() && !enumFromName(args.boundary, boundary))
        throw InputError("ripple: --boundary " + args.boundary + ": need periodic, fixed or absorbing");

    // --- fields
    NpyArray h = readField(args.in, 2);
    NpyArray v;
    if (!args.vel.empty()) v = readSameShape(args.vel, "--vel", h, args.in);

    // --- solve (the model's stepArrays, through the registration table)
    interaction::RippleArrays field{int(h.shape[0]), int(h.shape[1]), h.data, v.data, args.cellSize, args.dt, boundary,
                                    args.damping, args.viscosity, args.steps};
    interaction::stepRippleArrays(args.model, field);
    checkSolved(field.height.data(), h.shape, args,
                (args.vel.empty() ? "" : ", --vel " + args.vel) + ", --cell-size " + numberText(args.cellSize) + ", --dt " +
                    numberText(args.dt));

    writeNpy(args.out, h.shape, field.height.data());
    return 0;
}

} // namespace

int rippleCommand(const RippleArgs& args) {
    if (args.model != "kang2008" && args.model != "ewave")
        throw InputError("ripple: --model " + args.model + ": need kang2008 ([Kang2008] eq. 1-2) or ewave");
    if (args.in.empty()) throw InputError("ripple: --in is required (a float32 .npy field [N, M])");
    if (args.out.empty()) throw InputError("ripple: --out is required (the .npy file to write)");
    if (args.steps < 0) throw InputError("ripple: --steps " + std::to_string(args.steps) + " is negative (need >= 0)");
    if (args.model == "ewave") return ewaveCommand(args);

    // --- flags
    if (!args.vel.empty()) throw InputError("ripple: --vel is for --model ewave; kang2008 takes Vh(t-1) with --prev");
    if (!args.boundary.empty() && args.boundary != "fixed")
        throw InputError("ripple: --boundary " + args.boundary + ": kang2008 runs with the fixed boundary only");
    if (!(args.damping >= 0.0f && args.damping <= 1.0f))
        throw InputError("ripple: --damping " + numberText(args.damping) + " is outside [0, 1]");

    // --- fields
    NpyArray h = readField(args.in, 1);
    NpyArray p;
    if (!args.prev.empty()) p = readSameShape(args.prev, "--prev", h, args.in);

    // --- solve (the model's stepArrays, through the registration table)
    interaction::RippleArrays field{int(h.shape[0]), int(h.shape[1]), h.data, p.data, 1.0f, 1.0f, interaction::RippleBoundary::Fixed,
                                    args.damping, 0.0f, args.steps};
    interaction::stepRippleArrays(args.model, field);
    checkSolved(field.height.data(), h.shape, args, args.prev.empty() ? "" : ", --prev " + args.prev);

    writeNpy(args.out, h.shape, field.height.data());
    return 0;
}

} // namespace ob::game
