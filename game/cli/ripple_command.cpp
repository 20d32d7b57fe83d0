// oceanbox ripple: a bare ripple solver on .npy fields, no scene (docs/references.md#contracts).
#include "cli/cli_checks.h"
#include "cli/commands.h"
#include "core/file_identity.h"
#include "core/file_write.h"
#include "tools/cmd_ripple.h"

#include <CLI/CLI.hpp>
#include <memory>

namespace ob::game {

void addRippleCommand(CLI::App& app, CommandAction& action) {
    auto ripple = std::make_shared<RippleArgs>();
    CLI::App* cmd = app.add_subcommand("ripple", "run a bare ripple solver on a .npy field: kang2008 ([Kang2008] eq. 1-2, "
                                                 "fixed boundary) or ewave (dispersive, exact per Fourier mode)");
    cmd->add_option("--model", ripple->model, "kang2008 (default) or ewave");
    cmd->add_option("--in", ripple->in, "kang2008 Vh(t), ewave h: float32 .npy [N, M]")->required()->check(NON_EMPTY_PATH);
    cmd->add_option("--prev", ripple->prev, "kang2008: Vh(t-1), same shape (default: --in)")->check(NON_EMPTY_PATH);
    cmd->add_option("--vel", ripple->vel, "ewave: the vertical velocity v (m/s), same shape (default: 0)")->check(NON_EMPTY_PATH);
    cmd->add_option("--steps", ripple->steps, "steps K >= 0")->required();
    cmd->add_option("--damping", ripple->damping, "kang2008: damping factor DF in [0, 1]; ewave: decay time (s, 0 = none)")
        ->required()
        ->check(FINITE_NUMBER);
    cmd->add_option("--viscosity", ripple->viscosity, "ewave: effective viscosity (m2/s, default 0)")->check(FINITE_NUMBER);
    cmd->add_option("--dt", ripple->dt, "ewave: step (s, default 1/60)")->check(FINITE_NUMBER);
    cmd->add_option("--cell-size", ripple->cellSize, "ewave: metres per cell (default 0.25)")->check(FINITE_NUMBER);
    cmd->add_option("--boundary", ripple->boundary, "ewave: periodic (default), fixed or absorbing; kang2008: fixed");
    cmd->add_option("--out", ripple->out, "kang2008 Vh(t), ewave h after K steps (.npy)")->required()->check(NON_EMPTY_PATH);
    cmd->callback([&action, ripple] {
        action = [ripple] {
            checkWritable(ripple->out, "output");
            checkOutputsApart({{"--in", ripple->in}, {"--prev", ripple->prev}, {"--vel", ripple->vel}}, {{"--out", ripple->out}});
            return rippleCommand(*ripple);
        };
    });
}

} // namespace ob::game
