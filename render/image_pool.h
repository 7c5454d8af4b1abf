#pragma once
// Recycled frame memory for the progressive renderer. A fresh 39 MB high-quality frame costs
// ~25 ms of page faults, uninterruptible, before the first ray; frames the UI no longer shows
// give their memory back here instead, and the next render takes it (FastRenderOptions::recycle).
#include <memory>
#include <mutex>
#include <vector>

#include "core/image.h"

namespace angio {

class ImagePool : public std::enable_shared_from_this<ImagePool> {
 public:
  static constexpr std::size_t kKept = 3;  // one per quality level

  // The largest image returned so far (empty if none).
  Image take() {
    std::lock_guard lock(mutex_);
    if (free_.empty()) return {};
    auto largest = free_.begin();
    for (auto it = free_.begin(); it != free_.end(); ++it)
      if (it->pixels.capacity() > largest->pixels.capacity()) largest = it;
    Image image = std::move(*largest);
    free_.erase(largest);
    return image;
  }

  void giveBack(Image image) {
    std::lock_guard lock(mutex_);
    if (free_.size() < kKept) free_.push_back(std::move(image));
  }

  // A shared image that comes back to this pool when its last user lets go (the pool may be gone
  // by then: the deleter holds it alive).
  std::shared_ptr<const Image> share(Image image) {
    return std::shared_ptr<const Image>(new Image(std::move(image)),
                                        [pool = shared_from_this()](const Image* shared) {
                                          std::unique_ptr<Image> owned(const_cast<Image*>(shared));
                                          pool->giveBack(std::move(*owned));
                                        });
  }

 private:
  std::mutex mutex_;
  std::vector<Image> free_;
};

}  // namespace angio
