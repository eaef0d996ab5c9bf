// SPDX-License-Identifier: MIT
// The backend registry: make_kernel(name) for the document, which records the
// name and asks for the same backend when it is reopened.
#include "hula/oli/kernel/kernel.hpp"

#include "hula/oli/kernel/native_kernel.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/core/plugin.hpp"
#include "hula/oli/kernel/detail/occt_plugin.hpp"
#endif

namespace hula::oli {
namespace {

// Backends are stateless: one instance of each for the whole program, held by a non-owning
// shared_ptr-compatible static.
const std::shared_ptr<const Kernel>& native_instance() {
  static const std::shared_ptr<const Kernel> k = std::make_shared<const NativeKernel>();
  return k;
}

}  // namespace

const Kernel& native_kernel() { return *native_instance(); }

std::vector<std::string> kernel_names() {
#ifdef HULA_WITH_OCCT
  return {"native", "occt"};
#else
  return {"native"};
#endif
}

std::shared_ptr<const Kernel> make_kernel(std::string_view name) {
  if (name == "native") return native_instance();
#ifdef HULA_WITH_OCCT
  if (name == "occt") {
    // Open CASCADE is loaded on the first request only (detail/occt_plugin.hpp); the plugin's
    // instance lives as long as the process, so the pointer owns nothing.
    static const std::shared_ptr<const Kernel> k(
        reinterpret_cast<detail::OcctKernelFunction>(plugin_symbol("occt", detail::kOcctKernelSymbol))(),
        [](const Kernel*) {});
    return k;
  }
#endif
  std::string known;
  for (const auto& n : kernel_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error(Errc::InvalidArgument,
              "unknown kernel backend '" + std::string(name) + "' (this build has: " + known + ")",
              {.field = "backend"});
}

#ifdef HULA_WITH_OCCT
std::vector<FairingBaseline> occt_fairing_baselines_in_plugin(const FairingEnds& ends, std::span<const Vec3> points) {
  static const auto fair =
      reinterpret_cast<detail::OcctFairingFunction>(plugin_symbol("occt", detail::kOcctFairingSymbol));
  std::vector<FairingBaseline> out;
  fair(ends, points, out);
  return out;
}
#endif

}  // namespace hula::oli
