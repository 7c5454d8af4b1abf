#include "render/render_threads.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <thread>

#include <tbb/task_scheduler_observer.h>

namespace angio {

namespace {

// Below the process's own priority, in nice steps.
constexpr int kFastNiceSteps = 5;
constexpr int kBackgroundNiceSteps = 10;

id_t thisThread() { return id_t(syscall(SYS_gettid)); }

}  // namespace

// A oneTBB arena whose threads (oneTBB's and whoever executes in it) run at `nice` while in it.
struct RenderThreads::PriorityArena {
  struct Observer : tbb::task_scheduler_observer {
    Observer(tbb::task_arena& arena, int nice) : tbb::task_scheduler_observer(arena), nice(nice) {
      observe(true);
    }
    ~Observer() override { observe(false); }
    void on_scheduler_entry(bool) override {
      if (getpriority(PRIO_PROCESS, thisThread()) != nice) setpriority(PRIO_PROCESS, thisThread(), nice);
    }
    int nice;
  };
  explicit PriorityArena(int nice) : observer(arena, nice) {}
  tbb::task_arena arena;
  Observer observer;
};

RenderThreads::RenderThreads() {
  const int process = getpriority(PRIO_PROCESS, thisThread());
  fastNice_ = backgroundNice_ = std::min(process + kFastNiceSteps, 19);
  const int lowered = std::min(process + kBackgroundNiceSteps, 19);
  bool restorable = false;
  std::thread([&] {  // a throw-away thread: lowering it is harmless if raising fails
    restorable = setpriority(PRIO_PROCESS, thisThread(), lowered) == 0 &&
                 setpriority(PRIO_PROCESS, thisThread(), fastNice_) == 0;
  })
      .join();
  if (restorable) backgroundNice_ = lowered;
  foreground_ = std::make_unique<PriorityArena>(fastNice_);
  background_ = std::make_unique<PriorityArena>(backgroundNice_);
}

RenderThreads::~RenderThreads() = default;

tbb::task_arena& RenderThreads::arenaFor(Quality level) {
  return (level == Quality::fast ? foreground_ : background_)->arena;
}

}  // namespace angio
