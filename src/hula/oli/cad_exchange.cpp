// SPDX-License-Identifier: MIT
#include "hula/oli/cad_exchange.hpp"

#include <string>

namespace hula::oli {

std::shared_ptr<const Kernel> document_kernel(const Document& document) {
  return make_kernel(document.options().backend);
}

std::vector<ExportCurve> export_items(const Document& document, std::span<const Label> labels) {
  if (labels.empty()) throw Error(Errc::InvalidArgument, "no labels to export", {.field = "labels"});
  std::vector<ExportCurve> out;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto entity = document.find(labels[i]);
    if (!entity)
      throw Error(Errc::InvalidArgument, "label " + std::to_string(labels[i].value) + " is not in the document",
                  {.field = "labels", .index = i});
    if (entity->kind() != EntityKind::Curve)
      throw Error(Errc::InvalidArgument,
                  "label " + std::to_string(labels[i].value) + " is not a curve (STEP and IGES carry curves only)",
                  {.field = "labels", .index = i});
    ExportCurve item = export_curve(entity->attributes().name, entity->curve());
    item.colour = entity->attributes().colour;
    item.layer = entity->attributes().layer;
    out.push_back(std::move(item));
  }
  return out;
}

ExportReport export_entities(const Document& document, std::span<const Label> labels, const std::filesystem::path& path,
                             ExchangeFormat format, const ExchangeOptions& options) {
  const auto items = export_items(document, labels);
  return export_curves(path, items, format, options);
}

std::vector<Label> add_imported(Edit& edit, const ImportReport& report, const std::filesystem::path& source,
                                std::optional<ExchangeFormat> format) {
  const bool iges = (format ? *format : exchange_format_for_path(source)) == ExchangeFormat::Iges;
  std::vector<Label> out;
  for (const auto& c : report.curves) {
    Provenance p;
    p.operation = iges ? "import:iges" : "import:step";
    p.tool_version = HULA_VERSION;
    p.details["file"] = source.string();
    p.details["source"] = c.source;
    p.details["type"] = c.type;
    Attributes attributes;
    attributes.name = c.name;
    if (!c.colour.empty()) attributes.colour = c.colour;
    if (!c.layer.empty()) attributes.layer = c.layer;
    out.push_back(edit.add_curve(curve::Curve(c.curve), attributes, p));
  }
  return out;
}

}  // namespace hula::oli
