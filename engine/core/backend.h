// Where a kernel that has a GPU twin runs (the `backend` keys of [ocean] and [ripples]).
#pragma once
#include <array>
#include <cstdint>

namespace ob {

/// `Auto` takes the GPU on a hardware GPU and the CPU on a software rasteriser.
enum class Backend : uint8_t { Auto, Cpu, Gpu };
constexpr std::array<const char*, 3> names(Backend) { return {"auto", "cpu", "gpu"}; }

} // namespace ob
