// SPDX-License-Identifier: MIT
// The entry points of the Open CASCADE plugin (libhula_occt.so, occt_plugin.cpp): the occt kernel
// backend and the fairing baselines, loaded with dlopen on first use (hula/core/plugin.hpp) so that a
// program which never asks for them (every `hula` command but the few that do) does not load and
// relocate Open CASCADE's toolkits at start-up.
#pragma once

#include <span>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/oli/kernel/kernel.hpp"
#include "hula/oli/kernel/occt_fairing.hpp"

namespace hula::oli::detail {

/// The occt backend, a stateless instance that lives as long as the process.
inline constexpr const char* kOcctKernelSymbol = "hula_occt_kernel";
using OcctKernelFunction = const Kernel* (*)();

/// occt_fairing_baselines(ends, points), written into `out`.
inline constexpr const char* kOcctFairingSymbol = "hula_occt_fairing_baselines";
using OcctFairingFunction = void (*)(const FairingEnds& ends, std::span<const Vec3> points,
                                     std::vector<FairingBaseline>& out);

}  // namespace hula::oli::detail
