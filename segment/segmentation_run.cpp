#include "segment/segmentation_run.h"

#include <algorithm>

#include <itkCommand.h>

namespace angio::segment {

SegmentationRun::SegmentationRun(const SegmentationProgress& progress, int steps)
    : progress_(progress), steps_(std::max(steps, 1)) {}

bool SegmentationRun::cancelRequested() const {
  return progress_.cancel && progress_.cancel->load(std::memory_order_relaxed);
}

void SegmentationRun::throwIfCancelled() const {
  if (cancelRequested()) throw Cancelled{};
}

void SegmentationRun::report(double stepFraction) const {
  if (progress_.progress) progress_.progress(std::min(1.0, (done_ + stepFraction) / steps_));
}

void SegmentationRun::stepDone() {
  ++done_;
  report(0.0);
  throwIfCancelled();
}

void SegmentationRun::update(itk::ProcessObject& filter) {
  throwIfCancelled();
  // ITK filters check their abort flag as they report progress and then throw ProcessAborted.
  const unsigned long observer = filter.AddObserver(itk::ProgressEvent(), [&](const itk::EventObject&) {
    if (cancelRequested()) filter.AbortGenerateDataOn();
  });
  try {
    filter.Update();
  } catch (const itk::ProcessAborted&) {
    filter.RemoveObserver(observer);
    throw Cancelled{};
  }
  filter.RemoveObserver(observer);
  stepDone();
}

}  // namespace angio::segment
