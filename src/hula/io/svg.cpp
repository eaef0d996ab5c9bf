// SPDX-License-Identifier: MIT
#include "hula/io/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"

namespace hula::io {
namespace {

void check_sizes(std::size_t a, std::size_t b, const char* what) {
  if (a != b)
    throw Error(Errc::InvalidArgument, std::string("SvgFigure::") + what + ": coordinate arrays differ in size (" +
                                           std::to_string(a) + " vs " + std::to_string(b) + ")");
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string label(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", std::abs(v) < 1e-300 ? 0.0 : v);
  return buf;
}

// Tick positions covering [lo, hi] with a 1-2-5 step.
std::vector<double> ticks(double lo, double hi) {
  std::vector<double> out;
  const double span = hi - lo;
  if (!(span > 0)) return {lo};
  const double raw = span / 6;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) out.push_back(t);
  return out;
}

// Dark blue -> teal -> yellow.
std::string colour(double f) {
  f = std::clamp(f, 0.0, 1.0);
  const double r = f < 0.5 ? 0.27 * (1 - 2 * f) + 0.13 * 2 * f : 0.13 + (0.99 - 0.13) * (2 * f - 1);
  const double g = f < 0.5 ? 0.0 + 0.57 * 2 * f : 0.57 + (0.91 - 0.57) * (2 * f - 1);
  const double b = f < 0.5 ? 0.33 + (0.55 - 0.33) * 2 * f : 0.55 - (0.55 - 0.14) * (2 * f - 1);
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(r * 255), static_cast<int>(g * 255),
                static_cast<int>(b * 255));
  return buf;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  [[nodiscard]] bool empty() const { return !(lo <= hi); }
  void pad() {
    if (empty()) {
      lo = 0;
      hi = 1;
    } else if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi))) {
      const double d = std::max(1.0, std::abs(hi)) * 0.5;
      lo -= d;
      hi += d;
    }
  }
};

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

SvgFigure::SvgFigure(double width, double height) : width_(std::max(100.0, width)), height_(std::max(100.0, height)) {}

void SvgFigure::set_title(std::string title) { title_ = std::move(title); }
void SvgFigure::set_axes(std::string x_label, std::string y_label) {
  axes_ = true;
  x_label_ = std::move(x_label);
  y_label_ = std::move(y_label);
}
void SvgFigure::set_equal_aspect(bool equal) { equal_ = equal; }
void SvgFigure::set_log_y(bool log_y) { log_y_ = log_y; }

void SvgFigure::add_polyline(std::span<const double> x, std::span<const double> y, const SvgStyle& style,
                             std::string legend) {
  check_sizes(x.size(), y.size(), "add_polyline");
  items_.push_back({Item::Kind::Polyline, {x.begin(), x.end()}, {y.begin(), y.end()}, {}, {}, style, 0, legend});
}

void SvgFigure::add_segments(std::span<const double> x0, std::span<const double> y0, std::span<const double> x1,
                             std::span<const double> y1, const SvgStyle& style, std::string legend) {
  check_sizes(x0.size(), y0.size(), "add_segments");
  check_sizes(x0.size(), x1.size(), "add_segments");
  check_sizes(x0.size(), y1.size(), "add_segments");
  items_.push_back({Item::Kind::Segments,
                    {x0.begin(), x0.end()},
                    {y0.begin(), y0.end()},
                    {x1.begin(), x1.end()},
                    {y1.begin(), y1.end()},
                    style,
                    0,
                    std::move(legend)});
}

void SvgFigure::add_points(std::span<const double> x, std::span<const double> y, const SvgStyle& style, double radius,
                           std::string legend) {
  check_sizes(x.size(), y.size(), "add_points");
  items_.push_back(
      {Item::Kind::Points, {x.begin(), x.end()}, {y.begin(), y.end()}, {}, {}, style, radius, std::move(legend)});
}

void SvgFigure::add_heatmap(std::span<const double> xs, std::span<const double> ys, std::span<const double> values,
                            std::string legend) {
  if (xs.size() < 2 || ys.size() < 2)
    throw Error(Errc::InvalidArgument, "SvgFigure::add_heatmap: each axis needs at least 2 nodes");
  if (values.size() != xs.size() * ys.size())
    throw Error(Errc::InvalidArgument, "SvgFigure::add_heatmap: values has " + std::to_string(values.size()) +
                                           " entries, expected " + std::to_string(xs.size() * ys.size()));
  heatmaps_.push_back({{xs.begin(), xs.end()}, {ys.begin(), ys.end()}, {values.begin(), values.end()}, legend});
}

std::string SvgFigure::render() const {
  const auto ymap = [this](double y) { return log_y_ ? (y > 0 ? std::log10(y) : kNaN) : y; };
  Range rx, ry;
  for (const auto& it : items_) {
    for (double v : it.a) rx.add(v);
    for (double v : it.c) rx.add(v);
    for (double v : it.b) ry.add(ymap(v));
    for (double v : it.d) ry.add(ymap(v));
  }
  for (const auto& h : heatmaps_) {
    // Cells extend half a spacing beyond the outer nodes.
    rx.add(h.xs.front() - 0.5 * (h.xs[1] - h.xs[0]));
    rx.add(h.xs.back() + 0.5 * (h.xs.back() - h.xs[h.xs.size() - 2]));
    ry.add(ymap(h.ys.front() - 0.5 * (h.ys[1] - h.ys[0])));
    ry.add(ymap(h.ys.back() + 0.5 * (h.ys.back() - h.ys[h.ys.size() - 2])));
  }
  rx.pad();
  ry.pad();

  const bool has_legend = std::any_of(items_.begin(), items_.end(), [](const Item& i) { return !i.legend.empty(); });
  const double left = axes_ ? 80 : 20, right = heatmaps_.empty() ? 20 : 110;
  const double top = title_.empty() ? 20 : 45, bottom = axes_ ? 55 : 20;
  double pw = width_ - left - right, ph = height_ - top - bottom - (has_legend ? 20 : 0);
  double sx = pw / (rx.hi - rx.lo), sy = ph / (ry.hi - ry.lo);
  double ox = left, oy = top;
  if (equal_) {
    const double s = std::min(sx, sy);
    ox += 0.5 * (pw - s * (rx.hi - rx.lo));
    oy += 0.5 * (ph - s * (ry.hi - ry.lo));
    sx = sy = s;
    pw = s * (rx.hi - rx.lo);
    ph = s * (ry.hi - ry.lo);
  }
  const auto X = [&](double x) { return ox + (x - rx.lo) * sx; };
  const auto Y = [&](double y) { return oy + ph - (ymap(y) - ry.lo) * sy; };

  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width_) + "\" height=\"" + num(height_) +
                    "\" viewBox=\"0 0 " + num(width_) + " " + num(height_) +
                    "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
                    "fill=\"white\"/>\n";
  if (!title_.empty())
    out += "<text x=\"" + num(width_ / 2) + "\" y=\"25\" text-anchor=\"middle\" font-size=\"15\">" +
           xml_escape(title_) + "</text>\n";

  for (const auto& h : heatmaps_) {
    Range rv;
    for (double v : h.values) rv.add(v);
    rv.pad();
    const std::size_t nx = h.xs.size(), ny = h.ys.size();
    const auto edge = [](const std::vector<double>& n, std::size_t i, int side) {
      if (side < 0) return i == 0 ? n[0] - 0.5 * (n[1] - n[0]) : 0.5 * (n[i - 1] + n[i]);
      return i + 1 == n.size() ? n[i] + 0.5 * (n[i] - n[i - 1]) : 0.5 * (n[i] + n[i + 1]);
    };
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const double v = h.values[j * nx + i];
        if (!std::isfinite(v)) continue;
        const double x0 = X(edge(h.xs, i, -1)), x1 = X(edge(h.xs, i, 1));
        const double y0 = Y(edge(h.ys, j, 1)), y1 = Y(edge(h.ys, j, -1));
        out += "<rect x=\"" + num(x0) + "\" y=\"" + num(std::min(y0, y1)) + "\" width=\"" + num(x1 - x0 + 0.3) +
               "\" height=\"" + num(std::abs(y1 - y0) + 0.3) + "\" fill=\"" + colour((v - rv.lo) / (rv.hi - rv.lo)) +
               "\"/>\n";
      }
    // Colour bar.
    const double bx = width_ - right + 20, bw = 18;
    for (int k = 0; k < 50; ++k) {
      const double f = k / 49.0;
      out += "<rect x=\"" + num(bx) + "\" y=\"" + num(top + ph * (1 - f) - ph / 50) + "\" width=\"" + num(bw) +
             "\" height=\"" + num(ph / 50 + 0.5) + "\" fill=\"" + colour(f) + "\"/>\n";
    }
    out += "<text x=\"" + num(bx + bw + 4) + "\" y=\"" + num(top + 10) + "\">" + label(rv.hi) + "</text>\n";
    out += "<text x=\"" + num(bx + bw + 4) + "\" y=\"" + num(top + ph) + "\">" + label(rv.lo) + "</text>\n";
    if (!h.legend.empty())
      out += "<text x=\"" + num(bx) + "\" y=\"" + num(top + ph + 20) + "\">" + xml_escape(h.legend) + "</text>\n";
  }

  if (axes_) {
    out += "<rect x=\"" + num(ox) + "\" y=\"" + num(oy) + "\" width=\"" + num(pw) + "\" height=\"" + num(ph) +
           "\" fill=\"none\" stroke=\"#444\"/>\n";
    for (double t : ticks(rx.lo, rx.hi)) {
      out += "<line x1=\"" + num(X(t)) + "\" y1=\"" + num(oy + ph) + "\" x2=\"" + num(X(t)) + "\" y2=\"" +
             num(oy + ph + 5) + "\" stroke=\"#444\"/>\n";
      out += "<text x=\"" + num(X(t)) + "\" y=\"" + num(oy + ph + 18) + "\" text-anchor=\"middle\">" + label(t) +
             "</text>\n";
    }
    for (double t : ticks(ry.lo, ry.hi)) {
      if (log_y_ && std::abs(t - std::round(t)) > 1e-9) continue;
      const double y = oy + ph - (t - ry.lo) * sy;
      out += "<line x1=\"" + num(ox - 5) + "\" y1=\"" + num(y) + "\" x2=\"" + num(ox) + "\" y2=\"" + num(y) +
             "\" stroke=\"#444\"/>\n";
      out += "<text x=\"" + num(ox - 8) + "\" y=\"" + num(y + 4) + "\" text-anchor=\"end\">" +
             (log_y_ ? "1e" + label(t) : label(t)) + "</text>\n";
    }
    out += "<text x=\"" + num(ox + pw / 2) + "\" y=\"" + num(oy + ph + 40) + "\" text-anchor=\"middle\">" +
           xml_escape(x_label_) + "</text>\n";
    out += "<text transform=\"translate(18 " + num(oy + ph / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
           xml_escape(y_label_) + "</text>\n";
  }

  const auto stroke_attrs = [](const SvgStyle& s) {
    std::string a = " stroke=\"" + s.stroke + "\" stroke-width=\"" + num(s.width) + "\"";
    if (!s.dash.empty()) a += " stroke-dasharray=\"" + s.dash + "\"";
    return a;
  };
  for (const auto& it : items_) {
    switch (it.kind) {
      case Item::Kind::Polyline: {
        std::string pts;
        const auto flush = [&] {
          if (!pts.empty()) out += "<polyline fill=\"none\"" + stroke_attrs(it.style) + " points=\"" + pts + "\"/>\n";
          pts.clear();
        };
        for (std::size_t i = 0; i < it.a.size(); ++i) {
          const double x = X(it.a[i]), y = Y(it.b[i]);
          if (!std::isfinite(x) || !std::isfinite(y)) {
            flush();
            continue;
          }
          pts += num(x) + "," + num(y) + " ";
        }
        flush();
        break;
      }
      case Item::Kind::Segments: {
        std::string d;
        for (std::size_t i = 0; i < it.a.size(); ++i) {
          const double x0 = X(it.a[i]), y0 = Y(it.b[i]), x1 = X(it.c[i]), y1 = Y(it.d[i]);
          if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) continue;
          d += "M" + num(x0) + " " + num(y0) + "L" + num(x1) + " " + num(y1);
        }
        if (!d.empty()) out += "<path fill=\"none\"" + stroke_attrs(it.style) + " d=\"" + d + "\"/>\n";
        break;
      }
      case Item::Kind::Points: {
        const std::string fill = it.style.fill.empty() ? it.style.stroke : it.style.fill;
        for (std::size_t i = 0; i < it.a.size(); ++i) {
          const double x = X(it.a[i]), y = Y(it.b[i]);
          if (!std::isfinite(x) || !std::isfinite(y)) continue;
          out += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(it.radius) + "\" fill=\"" + fill +
                 "\"/>\n";
        }
        break;
      }
    }
  }

  if (has_legend) {
    double lx = left;
    const double ly = height_ - 10;
    for (const auto& it : items_) {
      if (it.legend.empty()) continue;
      // The legend's mark is the plotted one: a marker for points, a stroke for lines and segments.
      if (it.kind == Item::Kind::Points)
        out += "<circle cx=\"" + num(lx + 12) + "\" cy=\"" + num(ly - 4) + "\" r=\"" + num(it.radius) + "\" fill=\"" +
               (it.style.fill.empty() ? it.style.stroke : it.style.fill) + "\"/>\n";
      else
        out += "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly - 4) + "\" x2=\"" + num(lx + 24) + "\" y2=\"" +
               num(ly - 4) + "\"" + stroke_attrs(it.style) + "/>\n";
      out += "<text x=\"" + num(lx + 30) + "\" y=\"" + num(ly) + "\">" + xml_escape(it.legend) + "</text>\n";
      lx += 40 + 7.0 * static_cast<double>(it.legend.size());
    }
  }
  return out + "</svg>\n";
}

}  // namespace hula::io
