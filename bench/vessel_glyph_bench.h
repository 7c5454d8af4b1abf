#pragma once
// Timing of VesselGlyph interval construction: buildRayRegions over N angles about one axis,
// median, min and max ms per view. Only the volume's geometry (dims, spacing) is used, so a
// volume without voxels will do.
#include <cstdint>
#include <string>

#include "core/render_params.h"
#include "core/volume.h"
#include "vessel/centerline.h"
#include "vessel/vessel_glyph.h"

namespace angio {

struct GlyphBenchSettings {
  int angles = 36;
  Axis axis = Axis::k;
  Quality quality = Quality::medium;
  int threads = 0;  // 0 = all cores
};

struct GlyphBenchResult {
  int width = 0, height = 0;     // the image
  std::size_t sourcePoints = 0;  // centerline points given
  std::size_t tubeVertices = 0;  // after de-duplicating trunks and simplifying
  // buildRayRegions(volume, view, centerlines, settings) per view: both parts, a new RayRegions.
  double medianMs = 0, minMs = 0, maxMs = 0;
  // RayRegionBuilder::build into a RayRegions reused from view to view (what a renderer does).
  double perViewMedianMs = 0, perViewMinMs = 0, perViewMaxMs = 0;
  double perViewMedianCpuMs = 0;  // ... its CPU time, all threads (robust on a busy machine)
  double prepareMs = 0;           // the view-independent part alone (median)
  double medianIntervals = 0;     // intervals per view
  double coveredPixels = 0;       // fraction of pixels with at least one interval (median)
  // FNV-1a of every view's rayBegin and intervals: equal before and after a speed-up = same output.
  std::uint64_t checksum = 0;
  int threads = 0;
  int views = 0;
};

// Throws what buildRayRegions throws (centerlines not in the volume frame, bad settings).
GlyphBenchResult runVesselGlyphBench(const Volume& volume, const Centerlines& inVolumeFrame,
                                     const VesselGlyphSettings& glyph,
                                     const GlyphBenchSettings& settings);

// A vessel tree in vmtk's layout: `leaves` paths from one root (an aorta at the top of the
// domain) to leaves near its bottom, each repeating the shared trunk points exactly, about
// `pointsPerPath` points each (one every domain height / pointsPerPath along the long axis k).
// Radii 10 mm (root) to 1.2 mm (leaves), wiggles of 2-8 mm. Same seed, same tree.
Centerlines syntheticVesselTree(const Volume& volume, int leaves, int pointsPerPath,
                                std::uint64_t seed = 1);

// A stress case: `paths` independent tortuous paths of `pointsPerPath` points each, in the volume
// frame, running from the top of the domain to its bottom with wiggles of 5-25 mm, radius
// 10 -> 2 mm; no shared trunks, so nothing is de-duplicated. Same seed, same paths.
Centerlines syntheticCenterlines(const Volume& volume, int paths, int pointsPerPath,
                                 std::uint64_t seed = 1);

std::string formatGlyphBench(const GlyphBenchResult& result);

}  // namespace angio
