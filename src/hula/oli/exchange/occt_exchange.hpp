// SPDX-License-Identifier: MIT
// The Open CASCADE side of the exchange, run only inside the hula-exchange
// helper process (never in a caller: OCCT's readers may crash on bad files).
// See exchange.hpp for the file contents and detail/protocol.hpp for how
// requests and answers travel.
#pragma once

#include <filesystem>

#include "hula/oli/exchange/detail/protocol.hpp"
#include "hula/oli/exchange/exchange.hpp"

namespace hula::oli::detail {

/// Writes the request's curves to request.path (via a temporary file renamed over it).
/// @throws as export_curves, except HelperFailure
[[nodiscard]] ExportReport write_exchange_file(const ExportRequest& request);

/// Reads the curves of a STEP or IGES file.
/// @throws as import_curves, except HelperFailure
[[nodiscard]] ImportReport read_exchange_file(const std::filesystem::path& path);

}  // namespace hula::oli::detail
