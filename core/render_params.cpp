#include "core/render_params.h"

#include <cmath>
#include <cstdio>

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

std::string samplingProblem(const Sampling& s) {
  if (!std::isfinite(s.isd) || !std::isfinite(s.osd) || !std::isfinite(s.ert))
    return "the sampling's isd, osd and ert must be finite numbers";
  if (s.isd < kMinSamplingDistance || s.osd < kMinSamplingDistance) {
    char text[64];
    std::snprintf(text, sizeof text, "isd and osd must be at least %g voxel", kMinSamplingDistance);
    return text;
  }
  if (s.ert < 0 || s.ert > 1) return "ert must be in [0, 1]";
  if (const auto& a = s.adaptive) {
    if (!(std::isfinite(a->tolerance) && a->tolerance > 0 && a->tolerance <= 1))
      return "the adaptive integration's tolerance must be in (0, 1]";
    // The bisections go down to minStep: a pass per halving, 2^passes intervals per initial one.
    if (!(std::isfinite(a->minStep) && a->minStep >= kMinSamplingDistance) ||
        !(std::isfinite(a->initialStep) && a->initialStep >= a->minStep && a->initialStep <= 64))
      return "the adaptive integration's steps must satisfy 0.001 <= min step <= initial step <= 64 "
             "voxels";
  }
  if (const auto& a = s.adaptiveSampling) {
    if (s.adaptive) return "adaptive sampling and adaptive integration exclude each other";
    if (a->levels < 0 || a->levels > kMaxAdaptiveLevels || a->rayLevels < a->levels ||
        a->rayLevels > kMaxAdaptiveLevels)
      return "the adaptive sampling's levels must satisfy 0 <= levels <= ray levels <= " +
             std::to_string(kMaxAdaptiveLevels);
    if (!(std::isfinite(a->tolerance) && a->tolerance >= 0))
      return "the adaptive sampling's tolerance must be a number >= 0";
  }
  return "";
}

std::string renderParamsProblem(const RenderParams& p) {
  if (!std::isfinite(p.angleDeg)) return "the view angle must be a finite number";
  if (!std::isfinite(p.shading.ka) || !std::isfinite(p.shading.kd))
    return "the shading's ka and kd must be finite numbers";
  if (!std::isfinite(p.mip.window) || !std::isfinite(p.mip.level))
    return "the MIP window and level must be finite numbers";
  if (!(p.mip.window > 0)) return "the MIP window must be > 0 HU";
  if (std::string problem = samplingProblem(p.sampling); !problem.empty()) return problem;
  if (p.window) return imageWindowProblem(*p.window);
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
