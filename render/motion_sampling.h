#pragma once
// The sampling of the first level while the user drags or spins (thesis sec. 4.4's interactive
// mode renders only the fast level): not a fixed image sampling distance but the finest one,
// between the medium level's and the fast level's, whose predicted time fits a frame budget. A
// fixed fast level is a mosaic of 4.5 mm pixels on a 1.5 mm CT even where the medium level would
// take 60 ms; the measured time decides instead.
#include <optional>

#include "render/progressive_renderer.h"

namespace angio {

// A first-level frame as rendered: its time and image sampling distance.
struct MeasuredFrame {
  double ms = 0;
  double isd = 0;
  friend bool operator==(const MeasuredFrame&, const MeasuredFrame&) = default;
};

// The first level's sampling for the next frame: levels[fast] with its isd replaced by a step of
// a ladder from levels[medium].isd to four times levels[fast].isd (ratio 2^(1/4) between steps, so the
// pixel count changes by about 1.4x per step). The time is predicted as
// `last.ms * (last.isd / isd)^2` (the pixel count); the finest step within `budgetMs` is taken,
// except that a step finer than `last`'s needs a prediction within 3/4 of the budget (no flicker
// between two steps). Steps coarser than the fast level are there for the scans where even it is
// over budget (a tall run-off, a zoomed view): a blurrier image that follows the hand beats a
// sharper one that lags it, as VTK's interactive level of detail does; the coarsest has a
// sixteenth of the fast level's pixels: on a 1024-matrix run-off a quarter of them still took
// 66-84 ms in the headless GUI. Without a measurement, or with a budget of 0 (off), levels[fast]
// as it is.
Sampling motionSampling(const LevelSamplings& levels, std::optional<MeasuredFrame> last,
                        double budgetMs);

}  // namespace angio
