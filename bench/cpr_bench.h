#pragma once
// Timing of the CPR: lay out and resample the same CPR N times (by default a straightened CPR of a
// 400 mm path at 0.5 mm pixels), report median, min and max.
#include <string>

#include "core/render_params.h"
#include "core/volume.h"
#include "vessel/centerline.h"
#include "vessel/cpr.h"

namespace angio {

struct CprBenchSettings {
  int runs = 50;
  CprMode mode = CprMode::straightened;
  double pixelMm = 0.5;
  double widthMm = kDefaultCprWidthMm;
  double pathLengthMm = 400;  // the path is cut to this arc length; 0 = the whole path
  Axis axis = Axis::k;
  double angleDeg = 0;
  CprResampler resampler = CprResampler::trilinear;
  bool display = false;  // also time the window/level display (marker and ruler included)
  int threads = 0;       // 0 = all cores
};

struct CprBenchReport {
  std::string path;
  std::string mode;
  std::string resampler;
  double pathLengthMm = 0;
  int width = 0, height = 0;
  int threads = 0;
  int runs = 0;
  double medianMs = 0, minMs = 0, maxMs = 0;  // the whole CPR
  double medianLayoutMs = 0;                  // of which the geometry
};

// path: in the volume frame. Throws std::invalid_argument for a path the CPR refuses.
CprBenchReport runCprBench(const Volume& volume, const CenterlinePath& path,
                           const CprBenchSettings& settings);

// The first `lengthMm` of arc length of a path (the end point interpolated); the whole path if
// it is shorter.
CenterlinePath truncatePath(const CenterlinePath& path, double lengthMm);

std::string formatCprBench(const CprBenchReport& report);

}  // namespace angio
