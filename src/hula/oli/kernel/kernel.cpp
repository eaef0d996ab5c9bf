// SPDX-License-Identifier: MIT
// The backend registry: make_kernel(name) for the document, which records the
// name and asks for the same backend when it is reopened.
#include "hula/oli/kernel/kernel.hpp"

#include "hula/oli/kernel/native_kernel.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/kernel/occt_kernel.hpp"
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
    static const std::shared_ptr<const Kernel> k = std::make_shared<const OcctKernel>();
    return k;
  }
#endif
  std::string known;
  for (const auto& n : kernel_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error(Errc::InvalidArgument,
              "unknown kernel backend '" + std::string(name) + "' (this build has: " + known + ")",
              {.field = "backend"});
}

}  // namespace hula::oli
