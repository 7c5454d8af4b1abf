#pragma once
// Everything that decides a rendered image besides the volume and the TF (rendering model).
#include <optional>
#include <string>

#include "core/view_clipping.h"

namespace angio {

enum class Axis { i = 0, j = 1, k = 2 };
enum class Filter { nearest, trilinear, mean };
enum class Quality { fast, medium, high };
enum class Compositing { dvr, mip };

// Error-controlled adaptive integration along each ray (core/adaptive_integration.h; seed 000
// sec. 4.3) instead of samples every osd.
struct AdaptiveIntegration {
  double tolerance = 0.01;   // c_tol: stop once the ray's sum changes by at most this part of it
  double initialStep = 2.0;  // the first intervals' length, voxel units (4 misses bone cortex)
  double minStep = 0.125;    // no interval is bisected below this, voxel units

  friend bool operator==(const AdaptiveIntegration&, const AdaptiveIntegration&) = default;
};

// Adaptive sampling in three dimensions (core/adaptive_sampling.h; seed 003): an oracle's distance
// to the nearest change of the TF's opacity or colour lets samples along rays and rays across the
// image be up to 2^levels apart; skipped rays are synthesised, the segments between samples
// pre-integrated.
struct AdaptiveSampling {
  int levels = 3;           // l_max: rays at most 2^l_max apart in the image
  int rayLevels = 6;        // samples at most 2^rayLevels apart along rays (>= levels)
  double tolerance = 0.02;  // the oracle's: a block whose densities change the TF's opacity or
                            // opacity-weighted colour (per voxel unit) by more is an edge

  friend bool operator==(const AdaptiveSampling&, const AdaptiveSampling&) = default;
};

struct Sampling {
  double isd = 1.0;  // image sampling distance, voxel units
  double osd = 1.0;  // object sampling distance, voxel units
  Filter filter = Filter::nearest;
  double ert = 0.98;  // early ray termination threshold on accumulated opacity; 1 = never
  // Pre-integrated classification of the segments between samples (rendering model,
  // "Approximations"; core/preintegration.h) instead of the TF at each sample.
  bool preintegrated = false;
  std::optional<AdaptiveIntegration> adaptive;       // none: samples every osd (exact)
  std::optional<AdaptiveSampling> adaptiveSampling;  // none: every ray, every sample (exact)

  friend bool operator==(const Sampling&, const Sampling&) = default;
};

// The finest sampling distance anything may ask for (voxel units): a thousand samples per voxel,
// far past what any filter resolves; finer is a mistake that would take hours, not a better image.
constexpr double kMinSamplingDistance = 1e-3;

// The most levels adaptive sampling may use: 256 apart along rays, a band of 256 rows in the image.
constexpr int kMaxAdaptiveLevels = 8;

// Why `sampling` cannot be rendered (a distance not finite or below kMinSamplingDistance, an ERT
// threshold outside [0, 1]), or "".
std::string samplingProblem(const Sampling& sampling);

struct Shading {
  bool enabled = true;
  double ka = 0.3;  // ambient
  double kd = 0.7;  // headlight diffuse

  friend bool operator==(const Shading&, const Shading&) = default;
};

struct MipWindow {
  double window = 600;  // HU
  double level = 250;   // HU

  friend bool operator==(const MipWindow&, const MipWindow&) = default;
};

// A part of the image plane to render instead of the whole image (rendering model, View): mm
// about P0 along image right (h) and up (v). Its pixels are the whole image's (same D, same pixel
// centres), cut to the whole image: the pixels that overlap the window. So a window renders
// exactly those pixels of the whole image, and a zoomed view renders only what it shows.
struct ImageWindow {
  double leftMm = 0, rightMm = 0;  // h
  double bottomMm = 0, topMm = 0;  // v

  friend bool operator==(const ImageWindow&, const ImageWindow&) = default;
};

// Why `window` cannot be rendered (non-finite, or empty), or "".
std::string imageWindowProblem(const ImageWindow& window);

struct RenderParams;
// Why `params` cannot be rendered: a non-finite angle, shading or MIP window, samplingProblem,
// imageWindowProblem; or "". (The clipping has its own check, core/clip_interval.h.)
std::string renderParamsProblem(const RenderParams& params);

struct RenderParams {
  Axis axis = Axis::k;
  double angleDeg = 0;
  Sampling sampling;
  Shading shading;
  Compositing compositing = Compositing::dvr;
  MipWindow mip;
  ViewClipping clipping;              // crop box, clip plane, thick slab (none: the whole volume)
  std::optional<ImageWindow> window;  // none: the whole image

  friend bool operator==(const RenderParams&, const RenderParams&) = default;
};

// An angle in degrees wrapped into [0, 360) (theta of the rendering model).
double wrapDegrees(double degrees);

// The quality levels' default sampling (rendering model table).
Sampling qualitySampling(Quality quality);

const char* toString(Axis axis);
const char* toString(Filter filter);
const char* toString(Quality quality);
std::optional<Axis> parseAxis(const std::string& text);
std::optional<Filter> parseFilter(const std::string& text);
std::optional<Quality> parseQuality(const std::string& text);

}  // namespace angio
