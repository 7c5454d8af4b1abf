#pragma once
// Timing of vessel tracing (vessel/vessel_tracing.h) on a volume with known centerlines: the lumen
// field over the whole volume (once per dataset), a trace between the two ends of each path cut
// to a length (by default 600 mm), and the 3-D pick of a click on a vessel (core/ray_pick.h) at
// many angles. Medians with min and max.
#include <string>
#include <vector>

#include "core/transfer_function.h"
#include "core/volume.h"
#include "vessel/centerline.h"

namespace angio {

struct TraceBenchSettings {
  int fieldRuns = 3;
  int traceRuns = 5;
  int pickAngles = 36;
  double pathLengthMm = 600;  // 0 = whole paths
  int threads = 0;            // 0 = all cores
};

struct Timing {
  double medianMs = 0, minMs = 0, maxMs = 0;
};

struct TraceBenchRow {
  std::string what;
  Timing timing;
  std::string detail;  // e.g. the path's length and its deviation from the given centerlines
};

// centerlines: volume frame (the ground truth or a reference); their paths' ends are the clicks.
std::vector<TraceBenchRow> runTraceBench(const Volume& volume, const Centerlines& centerlines,
                                         const TransferFunction& tf, const TraceBenchSettings& settings);

std::string formatTraceBench(const std::vector<TraceBenchRow>& rows);

}  // namespace angio
