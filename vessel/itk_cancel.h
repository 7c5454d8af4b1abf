#pragma once
// Running an ITK filter so that a user's cancel stops it: the filter polls the flag from its
// progress events and aborts (ITK reports that as ProcessAborted). For vessel tracing's and the
// segmentation's filters.
#include <atomic>

#include <itkCommand.h>
#include <itkProcessObject.h>

namespace angio {

// filter.Update(), or false once `cancel` (may be null) turned true.
inline bool updateUnlessCancelled(itk::ProcessObject& filter, const std::atomic<bool>* cancel) {
  if (cancel) {
    auto observer = itk::CStyleCommand::New();
    observer->SetCallback([](itk::Object* caller, const itk::EventObject&, void* flag) {
      if (static_cast<const std::atomic<bool>*>(flag)->load())
        static_cast<itk::ProcessObject*>(caller)->AbortGenerateDataOn();
    });
    observer->SetClientData(const_cast<std::atomic<bool>*>(cancel));
    filter.AddObserver(itk::ProgressEvent(), observer);
  }
  try {
    filter.Update();
  } catch (const itk::ProcessAborted&) {
    return false;
  }
  return true;
}

}  // namespace angio
