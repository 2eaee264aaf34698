// chart.hpp.
#include "oracle/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "oracle/raster.hpp"

namespace relpos::detail::oracle {

namespace {

enum Colour : std::uint8_t { kWhite, kBlack, kAxis, kGrid, kBaseline0, kBaseline1, kBaseline2, kFirstFamily };

const std::vector<std::array<std::uint8_t, 3>>& palette() {
  static const std::vector<std::array<std::uint8_t, 3>> p = {
      {255, 255, 255},
      {0, 0, 0},
      {80, 80, 80},
      {222, 222, 222},
      {120, 120, 120},
      {160, 160, 160},
      {190, 190, 190},
      // families: a categorical palette (Tableau 10) and two more
      {31, 119, 180},
      {255, 127, 14},
      {44, 160, 44},
      {214, 39, 40},
      {148, 103, 189},
      {140, 86, 75},
      {227, 119, 194},
      {188, 189, 34},
      {23, 190, 207},
      {127, 127, 127},
      {0, 90, 50},
      {120, 0, 90}};
  return p;
}
constexpr int kFamilyColours = 12;

constexpr int kWidth = 1000, kHeight = 620, kLeft = 80, kRight = kWidth - 290, kTop = 60, kBottom = kHeight - 80;

std::string decade_label(int e) { return e == 0 ? std::string("1") : "1e" + std::to_string(e); }

/// The axes: decades d0 to d1 of the positive eps on a log scale, a slot for eps = 0 at the left when
/// there is one, the error rate from 0 to 1 upwards.
struct Frame {
  bool zero = false;
  int d0 = -12, d1 = 0, axis_left = kLeft + 10;
  double x_of(double eps) const {
    if (eps == 0) return kLeft + 25;
    return axis_left + (std::log10(eps) - d0) / (d1 - d0) * (kRight - 10 - axis_left);
  }
  static double y_of(double rate) { return kBottom - rate * (kBottom - kTop); }
};

Frame frame_of(const JudgeReport& r) {
  Frame f;
  double lo = 1e300, hi = 0;
  for (const Curve& curve : r.curves)
    for (const CurvePoint& p : curve.points) {
      if (p.eps == 0)
        f.zero = true;
      else
        lo = std::min(lo, p.eps), hi = std::max(hi, p.eps);
    }
  if (hi > 0) {
    f.d0 = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
    f.d1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
    if (f.d1 <= f.d0) f.d1 = f.d0 + 1;
  }
  if (f.zero) f.axis_left = kLeft + 100;
  return f;
}

/// The title, the grid, the axes, their ticks and labels.
void draw_axes(Canvas& c, const Frame& f, const JudgeReport& r) {
  char title[160];
  std::snprintf(title, sizeof title, "error rate against eps  (truth %s, %zu cases)", truth_name(r.options.truth),
                r.total.counts.cases);
  c.text(kLeft, 18, title, kBlack, 2);
  for (int k = 0; k <= 4; ++k) {
    const double y = Frame::y_of(k / 4.0);
    c.line(kLeft, y, kRight, y, k == 0 ? kAxis : kGrid);
    const std::string label = std::to_string(25 * k) + "%";
    c.text(kLeft - 8 - Canvas::text_width(label, 2), static_cast<int>(y) - 7, label, kBlack, 2);
  }
  c.line(kLeft, kTop, kLeft, kBottom, kAxis);
  const int step = f.d1 - f.d0 > 8 ? 2 : 1;
  for (int e = f.d0; e <= f.d1; e += step) {
    const double x = f.x_of(std::pow(10.0, e));
    c.line(x, kTop, x, kBottom, kGrid);
    c.line(x, kBottom, x, kBottom + 5, kAxis);
    const std::string label = decade_label(e);
    c.text(static_cast<int>(x) - Canvas::text_width(label, 2) / 2, kBottom + 10, label, kBlack, 2);
  }
  if (f.zero) {
    const double x = f.x_of(0);
    c.line(x, kBottom, x, kBottom + 5, kAxis);
    c.text(static_cast<int>(x) - 5, kBottom + 10, "0", kBlack, 2);
  }
  c.text(kLeft, kBottom + 40, "eps: the ellipsoid scaled by 1 +- eps touches (log scale; 0: tangent)", kAxis, 2);
  c.text(kLeft, kTop - 18, "error rate (wrong, undecided, missing)", kAxis, 1);
}

/// A curve's points joined (not across the gap between eps = 0 and the log axis), with markers.
template <class Rate, class Has>
void draw_curve(Canvas& c, const Frame& f, const Curve& curve, Rate rate, Has has, std::uint8_t colour, int thickness,
                int dash) {
  double px = 0, py = 0;
  bool first = true;
  for (const CurvePoint& p : curve.points) {
    if (!has(p)) continue;
    const double x = f.x_of(p.eps), y = Frame::y_of(rate(p));
    if (!first && !(p.eps > 0 && px == f.x_of(0))) c.line(px, py, x, y, colour, thickness, dash);
    c.fill(static_cast<int>(x) - thickness - 1, static_cast<int>(y) - thickness - 1,
           static_cast<int>(x) + thickness + 1, static_cast<int>(y) + thickness + 1, colour);
    px = x, py = y, first = false;
  }
}

/// A legend entry at the right, one below the other.
struct Legend {
  Canvas& c;
  int y = kTop;
  void add(const std::string& name, std::uint8_t colour, int thickness, int dash) {
    c.line(kRight + 20, y + 6, kRight + 50, y + 6, colour, thickness, dash);
    c.text(kRight + 58, y, name, kBlack, 2);
    y += 22;
  }
};

}  // namespace

std::string chart_png(const JudgeReport& r) {
  Canvas c(kWidth, kHeight, kWhite);
  const Frame f = frame_of(r);
  draw_axes(c, f, r);
  // The baselines first (dashed), then the families, then all of them on top.
  Legend legend{c};
  const auto answered = [](const CurvePoint& p) { return p.counts.judged() > 0; };
  const auto error_rate = [](const CurvePoint& p) { return p.counts.error_rate(); };
  const Curve* all = nullptr;
  for (const Curve& curve : r.curves)
    if (curve.family.empty()) all = &curve;
  if (all && r.options.baselines) {
    legend.add("float baselines:", kWhite, 1, 0);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint8_t colour = static_cast<std::uint8_t>(kBaseline0 + k);
      draw_curve(
          c, f, *all, [k](const CurvePoint& p) { return p.baselines.error_rate(k); },
          [](const CurvePoint& p) { return p.baselines.cases > 0; }, colour, 2, 6 + 4 * static_cast<int>(k));
      legend.add(kBaselineNames[k], colour, 2, 4 + 2 * static_cast<int>(k));
    }
    legend.y += 8;
  }
  legend.add("the answers:", kWhite, 1, 0);
  int k = 0;
  for (const Curve& curve : r.curves) {
    if (curve.family.empty()) continue;
    const std::uint8_t colour = static_cast<std::uint8_t>(kFirstFamily + k++ % kFamilyColours);
    draw_curve(c, f, curve, error_rate, answered, colour, 1, 0);
    legend.add(curve.family, colour, 2, 0);
  }
  if (all) {
    draw_curve(c, f, *all, error_rate, answered, kBlack, 3, 0);
    legend.add("all families", kBlack, 3, 0);
  } else {
    c.text(kLeft + 20, kTop + 20, "no eps in the cases' meta: nothing to draw", kBlack, 2);
  }
  return c.png(palette());
}

}  // namespace relpos::detail::oracle
