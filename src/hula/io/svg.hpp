// SPDX-License-Identifier: MIT
// A small SVG figure builder for the figures the studies and `hula analyse`
// write: curves and fins in the plane (equal aspect), graphs with axes and
// ticks (curvature profiles, convergence graphs, optionally log-scaled), scatter
// plots (Pareto fronts) and heat maps over a grid (energy maps, Figure 55).
// Data are given in their own units; the figure fits its frame to everything
// added. A NaN in a polyline breaks it; a NaN cell of a heat map stays blank.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace hula::io {

/// `text` with & < > " replaced by their XML entities (SVG text, titles and attributes).
[[nodiscard]] std::string xml_escape(const std::string& text);

/// How a series is drawn.
struct SvgStyle {
  /// Stroke colour (any SVG colour). Default black.
  std::string stroke = "#000000";
  /// Stroke width in pixels. Default 1.5.
  double width = 1.5;
  /// Fill colour of markers. Default: the stroke colour.
  std::string fill{};
  /// SVG dash array ("6 4" for dashed), empty for solid.
  std::string dash{};
};

/// A figure: add data, then render().
class SvgFigure {
 public:
  /// @param width, height size in pixels (clamped to >= 100).
  explicit SvgFigure(double width = 800, double height = 600);

  /// Title drawn above the frame.
  void set_title(std::string title);
  /// Draws a frame with ticks and labels on both axes (a graph). Without it
  /// the figure shows the data alone (a drawing of curves).
  void set_axes(std::string x_label, std::string y_label);
  /// Same scale on both axes (drawings of curves). Default false.
  void set_equal_aspect(bool equal);
  /// Logarithmic y axis (convergence graphs); values <= 0 are skipped. Default false.
  void set_log_y(bool log_y);

  /// A polyline through (x[i], y[i]); a NaN coordinate breaks it.
  /// @throws hula::Error(Errc::InvalidArgument) if x and y differ in size.
  void add_polyline(std::span<const double> x, std::span<const double> y, const SvgStyle& style = {},
                    std::string legend = {});
  /// Separate segments (x0[i], y0[i]) -> (x1[i], y1[i]), e.g. fins.
  /// @throws hula::Error(Errc::InvalidArgument) if the sizes differ.
  void add_segments(std::span<const double> x0, std::span<const double> y0, std::span<const double> x1,
                    std::span<const double> y1, const SvgStyle& style = {}, std::string legend = {});
  /// Circular markers of `radius` pixels at (x[i], y[i]).
  /// @throws hula::Error(Errc::InvalidArgument) if the sizes differ.
  void add_points(std::span<const double> x, std::span<const double> y, const SvgStyle& style = {}, double radius = 3.0,
                  std::string legend = {});
  /// A heat map: values[j * xs.size() + i] is the value at (xs[i], ys[j]);
  /// each cell is drawn around its node, coloured from dark blue (smallest
  /// finite value) to yellow (largest); NaN cells stay blank. A colour bar
  /// with the value range is drawn at the right.
  /// @throws hula::Error(Errc::InvalidArgument) if values.size() != xs.size() * ys.size()
  ///   or either axis has fewer than 2 nodes.
  void add_heatmap(std::span<const double> xs, std::span<const double> ys, std::span<const double> values,
                   std::string legend = {});

  /// The SVG document.
  [[nodiscard]] std::string render() const;

 private:
  struct Item {
    enum class Kind { Polyline, Segments, Points } kind;
    std::vector<double> a, b, c, d;
    SvgStyle style;
    double radius = 3.0;
    std::string legend;
  };
  struct Heatmap {
    std::vector<double> xs, ys, values;
    std::string legend;
  };
  double width_, height_;
  std::string title_, x_label_, y_label_;
  bool axes_ = false, equal_ = false, log_y_ = false;
  std::vector<Item> items_;
  std::vector<Heatmap> heatmaps_;
};

}  // namespace hula::io
