#include "core/render_params.h"

#include <cmath>

namespace angio {

double wrapDegrees(double degrees) {
  const double wrapped = std::fmod(degrees, 360.0);
  return wrapped < 0 ? wrapped + 360.0 : wrapped;
}

std::string imageWindowProblem(const ImageWindow& w) {
  for (double mm : {w.leftMm, w.rightMm, w.bottomMm, w.topMm})
    if (!std::isfinite(mm)) return "the image window's bounds must be finite numbers (mm)";
  if (!(w.leftMm < w.rightMm) || !(w.bottomMm < w.topMm))
    return "the image window must have left < right and bottom < top";
  return "";
}

Sampling qualitySampling(Quality quality) {
  switch (quality) {
    case Quality::fast: return {3.0, 1.0, Filter::mean, 0.98};
    case Quality::medium: return {1.0, 1.0, Filter::nearest, 0.98};
    case Quality::high: return {0.5, 0.3, Filter::trilinear, 0.99};
  }
  return {};
}

const char* toString(Axis axis) {
  switch (axis) {
    case Axis::i: return "i";
    case Axis::j: return "j";
    case Axis::k: return "k";
  }
  return "?";
}

const char* toString(Filter filter) {
  switch (filter) {
    case Filter::nearest: return "nearest";
    case Filter::trilinear: return "trilinear";
    case Filter::mean: return "mean";
  }
  return "?";
}

const char* toString(Quality quality) {
  switch (quality) {
    case Quality::fast: return "fast";
    case Quality::medium: return "medium";
    case Quality::high: return "high";
  }
  return "?";
}

std::optional<Axis> parseAxis(const std::string& text) {
  for (Axis a : {Axis::i, Axis::j, Axis::k})
    if (text == toString(a)) return a;
  return std::nullopt;
}

std::optional<Filter> parseFilter(const std::string& text) {
  for (Filter f : {Filter::nearest, Filter::trilinear, Filter::mean})
    if (text == toString(f)) return f;
  return std::nullopt;
}

std::optional<Quality> parseQuality(const std::string& text) {
  for (Quality q : {Quality::fast, Quality::medium, Quality::high})
    if (text == toString(q)) return q;
  return std::nullopt;
}

}  // namespace angio
