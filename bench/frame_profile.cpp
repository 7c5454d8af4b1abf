#include "bench/frame_profile.h"

#include <cstdio>
#include <sstream>

namespace angio {

namespace {

double percentOf(std::uint64_t part, std::uint64_t whole) {
  return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0;
}

}  // namespace

std::string formatProfiles(const std::vector<LevelProfile>& profiles) {
  std::ostringstream out;
  char line[320];
  out << "where the samples go (% of the samples in the domain; visible and faint: % of the "
         "evaluated; faint: opacity below 1 %)\n";
  std::snprintf(line, sizeof line, "%-17s %12s %7s %7s %7s %9s %7s %8s %7s %8s %9s %9s %12s\n", "level",
                "domain/frame", "groups", "tiles", "cells", "evaluated", "ERT", "visible", "faint",
                "ERT rays", "ERT depth", "ns/sample", "templates ms");
  out << line;
  for (const LevelProfile& l : profiles) {
    const RayProfile& p = l.total;
    const double frames = l.frames > 0 ? l.frames : 1;
    const double depth = p.terminatedRays > 0 ? double(p.terminatedDepth) / p.terminatedRays : 0.0;
    std::snprintf(
        line, sizeof line,
        "%-17s %12.3g %6.1f%% %6.1f%% %6.1f%% %8.1f%% %6.1f%% %7.1f%% %6.1f%% %7.1f%% "
        "%9.0f %9.2f %12.2f\n",
        l.level.c_str(), double(p.domainSamples) / frames, percentOf(p.skippedByGroups, p.domainSamples),
        percentOf(p.skippedByTiles, p.domainSamples), percentOf(p.skippedByCells, p.domainSamples),
        percentOf(p.evaluated, p.domainSamples), percentOf(p.savedByTermination(), p.domainSamples),
        percentOf(p.visible, p.evaluated), percentOf(p.faint, p.evaluated),
        percentOf(p.terminatedRays, p.rays), depth, l.nsPerEvaluatedSample, l.templateMs);
    out << line;
  }
  return out.str();
}

}  // namespace angio
