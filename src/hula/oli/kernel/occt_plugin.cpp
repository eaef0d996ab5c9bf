// SPDX-License-Identifier: MIT
// The Open CASCADE plugin (libhula_occt.so): the entry points of detail/occt_plugin.hpp over the
// occt backend (occt_kernel.cpp) and the fairing baselines (occt_fairing.cpp), compiled into the plugin.
#include "hula/oli/kernel/detail/occt_plugin.hpp"

#include "hula/oli/kernel/occt_kernel.hpp"

HULA_PLUGIN_EXPORT const hula::oli::Kernel* hula_occt_kernel() {
  static const hula::oli::OcctKernel kernel;
  return &kernel;
}

HULA_PLUGIN_EXPORT void hula_occt_fairing_baselines(const hula::oli::FairingEnds& ends,
                                                    std::span<const hula::Vec3> points,
                                                    std::vector<hula::oli::FairingBaseline>& out) {
  out = hula::oli::occt_fairing_baselines(ends, points);
}
