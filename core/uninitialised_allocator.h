#pragma once
// An allocator like std::allocator that leaves elements made without a value uninitialised, so that
// growing a vector (resize) neither writes nor touches its memory: the pages are first touched by
// the threads that write the elements. Used for a frame's pixels (the render threads write them
// between their cancellation checks, instead of one uninterruptible zero fill before the first
// ray: a 39 MB high frame, tens of ms) and for the slice tiles' ranges (hundreds of MB written whole
// by the summarising threads right after).
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace angio {

template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A vector whose resize() leaves trivial elements (bytes, integers) unset.
template <class T>
using UninitialisedVector = std::vector<T, UninitialisedAllocator<T>>;

}  // namespace angio
