#pragma once
// Where a frame's samples go, counted by the fast raycaster when asked (FastRenderOptions::profile,
// `angioray bench --profile`): of the samples the reference would take inside the volume, how many
// each skipping level removed, how many early ray termination saved, how many were reconstructed,
// and of those how many the TF shows, faintly or not. Plain DVR only (one TF, no regions, labels
// or MIP); every other frame leaves it empty.
#include <cstdint>

namespace angio {

struct RayProfile {
  // Samples of every ray inside the volume's domain, as the reference takes them (before clipping).
  std::uint64_t domainSamples = 0;
  std::uint64_t skippedByGroups = 0;  // in tile groups no ray of the row sees
  std::uint64_t skippedByTiles = 0;   // in tiles the row's classification hides
  std::uint64_t skippedByCells = 0;   // in cells whose corners the TF hides (leaps within a tile)
  std::uint64_t evaluated = 0;        // reconstructed and classified
  std::uint64_t visible = 0;          // evaluated with opacity > 0
  std::uint64_t faint = 0;            // visible with opacity below kFaintOpacity
  std::uint64_t rays = 0;             // rays that reached a visible tile
  std::uint64_t terminatedRays = 0;   // of those, ended by early ray termination
  std::uint64_t terminatedDepth = 0;  // samples from their first to their last evaluated one

  // A sample's opacity (after the osd correction) below this is faint material: at 1 % a ray
  // needs about 460 of them to reach the default ERT threshold (0.99).
  static constexpr float kFaintOpacity = 0.01f;

  // Samples after early ray termination, and what clipping removed: what the counts above leave.
  std::uint64_t savedByTermination() const {
    const std::uint64_t accounted = skippedByGroups + skippedByTiles + skippedByCells + evaluated;
    return domainSamples > accounted ? domainSamples - accounted : 0;
  }

  RayProfile& operator+=(const RayProfile& other) {
    domainSamples += other.domainSamples;
    skippedByGroups += other.skippedByGroups;
    skippedByTiles += other.skippedByTiles;
    skippedByCells += other.skippedByCells;
    evaluated += other.evaluated;
    visible += other.visible;
    faint += other.faint;
    rays += other.rays;
    terminatedRays += other.terminatedRays;
    terminatedDepth += other.terminatedDepth;
    return *this;
  }
  bool operator==(const RayProfile&) const = default;
};

}  // namespace angio
