// SPDX-License-Identifier: MIT
// Small fixtures shared by the oli tests: curves with known control points and
// a document equality that compares everything a user can observe.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/nurbs/knot_vector.hpp"
#include "hula/oli/document.hpp"

namespace hula::oli::testing {

/// A clamped uniform cubic NURBS with `n` control points (i, i % 3, 0.5 i) + offset.
inline curve::Curve cubic(std::size_t n, double offset = 0.0) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < n; ++i)
    points.emplace_back(static_cast<double>(i) + offset, static_cast<double>(i % 3), 0.5 * static_cast<double>(i));
  return curve::Curve(nurbs::NurbsCurve(nurbs::KnotVector::uniform_clamped(n, 3), std::move(points)));
}

/// The state of a document: entities (with labels, attributes, provenance,
/// data) and the revision — not the next label, which undo never takes back.
inline Json observable(const Document& doc) {
  Json out = doc.to_json();
  out.erase("backend");
  out.erase("next_label");
  return out;
}

/// The history without times (names, revisions, labels, applied flags).
inline Json history_json(const Document& doc) {
  Json out = Json::array();
  for (const HistoryEntry& h : doc.history()) {
    Json labels = Json::array();
    for (Label l : h.changed) labels.push_back(l.value);
    out.push_back(Json::array({h.revision, h.name, labels, h.applied}));
  }
  return out;
}

}  // namespace hula::oli::testing
