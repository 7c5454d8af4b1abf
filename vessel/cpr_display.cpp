#include "vessel/cpr_display.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/voxel.h"

namespace angio {

namespace {

static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "Image pixels must be packed RGBA floats");

const glm::vec4 kMarkerColor{1.0f, 0.85f, 0.1f, 1.0f};
constexpr float kMarkerOpacity = 0.7f;  // the lumen stays visible under the marker

// The image's pixels as an OpenCV canvas (no copy), for lines and text.
cv::Mat canvasOf(Image& image) {
  return cv::Mat(image.height, image.width, CV_32FC4, image.pixels.data());
}

cv::Scalar scalarOf(glm::vec4 c) { return cv::Scalar(c.r, c.g, c.b, c.a); }

// A dashed line along each curve (6 pixels on, 3 off), blended over the CPR.
void drawMarker(Image& image, const std::vector<CprCurve>& curves) {
  std::vector<char> marked(image.pixels.size(), 0);
  constexpr double kStep = 0.25, kDash = 6, kPeriod = 9;
  for (const CprCurve& curve : curves) {
    double travelled = 0;
    for (std::size_t n = 0; n + 1 < curve.pixels.size(); ++n) {
      const glm::dvec2 a = curve.pixels[n], b = curve.pixels[n + 1];
      const double length = glm::distance(a, b);
      for (double t = 0; t < length; t += kStep, travelled += kStep) {
        if (std::fmod(travelled, kPeriod) >= kDash) continue;
        const glm::dvec2 p = glm::mix(a, b, t / length);
        const int x = int(std::floor(p.x + 0.5)), y = int(std::floor(p.y + 0.5));
        if (x >= 0 && y >= 0 && x < image.width && y < image.height) {
          marked[std::size_t(y) * image.width + x] = 1;
        }
      }
    }
  }
  for (std::size_t n = 0; n < marked.size(); ++n) {
    if (marked[n]) image.pixels[n] = glm::mix(image.pixels[n], kMarkerColor, kMarkerOpacity);
  }
}

// Ticks across the centerline every rulerStepMm of arc length, labelled (in mm) every fifth.
void drawRuler(Image& image, const std::vector<CprCurve>& curves, double stepMm) {
  cv::Mat canvas = canvasOf(image);
  for (const CprRulerTick& tick : cprRulerTicks(curves, stepMm)) {
    const double half = tick.major ? 6 : 3;
    const glm::dvec2 a = tick.pixel - half * tick.across, b = tick.pixel + half * tick.across;
    cv::line(canvas, cv::Point(int(std::lround(a.x)), int(std::lround(a.y))),
             cv::Point(int(std::lround(b.x)), int(std::lround(b.y))), scalarOf(kMarkerColor), 1,
             cv::LINE_8);
    if (!tick.major) continue;
    const glm::dvec2 label = tick.pixel + (half + 3) * (tick.across.x >= 0 ? tick.across : -tick.across);
    cv::putText(canvas, std::to_string(long(std::lround(tick.arcMm))),
                cv::Point(int(std::lround(label.x)), int(std::lround(label.y + 4))),
                cv::FONT_HERSHEY_PLAIN, 0.8, scalarOf(kMarkerColor), 1, cv::LINE_8);
  }
}

}  // namespace

std::vector<CprRulerTick> cprRulerTicks(const std::vector<CprCurve>& curves, double stepMm) {
  std::vector<CprRulerTick> ticks;
  if (!(stepMm > 0)) return ticks;
  for (const CprCurve& curve : curves) {
    if (curve.pixels.size() < 2) continue;
    // A curve that starts at a junction continues a trunk whose ticks are already there.
    const bool continues = curve.arcMm.front() > 0;
    long k = long(std::ceil(curve.arcMm.front() / stepMm));
    if (continues && k * stepMm <= curve.arcMm.front()) ++k;
    std::size_t n = 0;
    for (; k * stepMm <= curve.arcMm.back(); ++k) {
      const double s = k * stepMm;
      while (n + 2 < curve.pixels.size() && curve.arcMm[n + 1] < s) ++n;
      const double span = curve.arcMm[n + 1] - curve.arcMm[n];
      const double t = span > 0 ? std::clamp((s - curve.arcMm[n]) / span, 0.0, 1.0) : 0.0;
      glm::dvec2 along = curve.pixels[n + 1] - curve.pixels[n];
      along = glm::length(along) > 0 ? glm::normalize(along) : glm::dvec2(0, 1);
      ticks.push_back({glm::mix(curve.pixels[n], curve.pixels[n + 1], t),
                       {-along.y, along.x},
                       s,
                       k % 5 == 0,
                       curve.path});
    }
  }
  return ticks;
}

std::optional<WindowLevel> windowPreset(const std::string& name) {
  if (name == "cta-lumen") return kCtaLumenWindow;
  if (name == "calcium") return kCalciumWindow;
  return std::nullopt;
}

float windowGrey(float hu, WindowLevel windowLevel) {
  const double low = windowLevel.level - 0.5 * windowLevel.window;
  return float(std::clamp((hu - low) / windowLevel.window, 0.0, 1.0));
}

glm::vec4 cprColor(float hu, const CprDisplay& display, const TfTable* table) {
  if (table) return glm::vec4(glm::vec3(table->rgba[densityOfHu(hu)]), 1.0f);
  const float g = windowGrey(hu, display.windowLevel);
  return {g, g, g, 1.0f};
}

Image coloredHu(int width, int height, const std::vector<float>& hu, const CprDisplay& display) {
  const std::optional<TfTable> table =
      display.tf ? std::optional<TfTable>(buildTable(*display.tf)) : std::nullopt;
  Image image = makeImage(width, height);
  for (std::size_t n = 0; n < hu.size(); ++n) {
    if (std::isnan(hu[n])) continue;  // stays transparent black
    image.pixels[n] = cprColor(hu[n], display, table ? &*table : nullptr);
  }
  return image;
}

Image displayCpr(const CprLayout& layout, const std::vector<float>& hu, const CprDisplay& display) {
  Image image = coloredHu(layout.width, layout.height, hu, display);
  if (display.centerlineMarker) drawMarker(image, layout.curves);
  if (display.ruler && display.rulerStepMm > 0) drawRuler(image, layout.curves, display.rulerStepMm);
  return image;
}

}  // namespace angio
