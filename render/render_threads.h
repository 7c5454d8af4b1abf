#pragma once
// The thread policy of interactive rendering: an object the program makes once (the `gui`
// subcommand) and hands to the renderers that use it, instead of process-wide statics.
//
// The fast level is what a hand on the mouse waits for; its threads run a few nice steps below
// the process: the UI's own drawing (software GL rasterises on threads of the UI's priority)
// finishes first when both want the cores, but the render is not starved by other work on the
// machine (relative steps, so under `nice -n -10` the gaps stay). The levels above fast are
// background work, lower still - but only where a thread can be raised back (RLIMIT_NICE or
// CAP_SYS_NICE): oneTBB threads move between the two arenas, and a thread left lowered would
// render the next fast level at background priority. Without that right both levels render at
// the fast level's priority; a high render still yields to input, which cancels it within a row.
// Linux: nice is per thread.
#include <memory>

#include <tbb/task_arena.h>

#include "core/render_params.h"

namespace angio {

class RenderThreads {
 public:
  RenderThreads();  // probes what the OS allows (a throw-away thread), makes the two arenas
  ~RenderThreads();
  RenderThreads(const RenderThreads&) = delete;
  RenderThreads& operator=(const RenderThreads&) = delete;

  // Where a level renders: fast just below the UI, medium and high in the background.
  tbb::task_arena& arenaFor(Quality level);

  int fastNice() const { return fastNice_; }
  int backgroundNice() const { return backgroundNice_; }

 private:
  struct PriorityArena;
  int fastNice_ = 0, backgroundNice_ = 0;
  std::unique_ptr<PriorityArena> foreground_, background_;
};

}  // namespace angio
