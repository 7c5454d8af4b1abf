#pragma once
// One segmentation run's progress over a known number of steps and its cancel flag, honoured
// between steps, inside ITK filters (told to abort from their progress events) and in the run's own
// loops (which call throwIfCancelled now and then).
#include <itkProcessObject.h>

#include "segment/bone_removal.h"

namespace angio::segment {

// Thrown inside a run once its cancel flag is set; removeBoneAndTable turns it into a result.
struct Cancelled {};

class SegmentationRun {
 public:
  SegmentationRun(const SegmentationProgress& progress, int steps);

  void throwIfCancelled() const;
  void stepDone();
  // filter.Update() as one step, aborted when cancel is requested.
  void update(itk::ProcessObject& filter);

 private:
  bool cancelRequested() const;
  void report(double stepFraction) const;

  const SegmentationProgress& progress_;
  int steps_;
  int done_ = 0;
};

}  // namespace angio::segment
