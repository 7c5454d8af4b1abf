#pragma once
// Timing of the slice tiles' summaries (core/slice_tiles.h), which the renderer builds after a load,
// an axis change or a label change: the whole volume without labels, then with labels (those of a
// label volume, or "bone" = every voxel above 300 HU, roughly what bone removal marks), then the
// same labels as a label change's overlay on the volume without them (what a label job builds
// ahead; about j or k only), N runs each, median, min and max of wall and process CPU time. Then
// the plain build in groups of slices as a renderer builds the tiles of a new axis ("in parts"),
// and how long such a build takes to stop once cancelled 10-90 % into it ("interrupt": the ms
// columns are the cancel-to-return latency).
#include <string>
#include <vector>

#include "core/render_params.h"
#include "core/volume.h"

namespace angio {

struct TileBenchRow {
  std::string what;  // "plain", "labelled", "ahead" (the labels as a label change's overlay),
                     // "in parts", "interrupt"
  double labelledPercent = 0;
  int runs = 0;
  double medianMs = 0, minMs = 0, maxMs = 0;
  double medianCpuMs = 0;
};

// `labelled`: the volume with labels in its voxels (label bits set); `volume` without.
std::vector<TileBenchRow> runTileBench(const Volume& volume, const Volume& labelled, Axis axis,
                                       int runs);

// Every voxel above `hu` given label 1: a stand-in for bone removal's labels.
Volume labelledAbove(const Volume& volume, double hu);

std::string formatTileBench(const std::vector<TileBenchRow>& rows);

}  // namespace angio
