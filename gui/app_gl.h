#pragma once
// The few OpenGL calls the app makes itself (the rendered image as a texture), looked up at run
// time through the context's own getProcAddress: the windowed app runs on GLX through GLFW, the
// headless twin on OSMesa, and one binary holds both, so calling gl* symbols directly would reach
// whichever library the linker picked, not the current context's.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <imgui.h>

#include "gui/display_image.h"

namespace angio {

struct GlApi {
  using GetProc = std::function<void*(const char* name)>;
  // Fails (throws std::runtime_error) when a required entry point is missing.
  static GlApi load(const GetProc& getProc);

  void (*genTextures)(int, unsigned*) = nullptr;
  void (*deleteTextures)(int, const unsigned*) = nullptr;
  void (*bindTexture)(unsigned, unsigned) = nullptr;
  void (*texParameteri)(unsigned, unsigned, int) = nullptr;
  void (*pixelStorei)(unsigned, int) = nullptr;
  void (*texImage2D)(unsigned, int, int, int, int, int, unsigned, unsigned, const void*) = nullptr;
  void (*texSubImage2D)(unsigned, int, int, int, int, int, unsigned, unsigned, const void*) = nullptr;
  void (*getIntegerv)(unsigned, int*) = nullptr;
  // The platform's frame: clear the framebuffer before ImGui draws.
  void (*viewport)(int, int, int, int) = nullptr;
  void (*clearColor)(float, float, float, float) = nullptr;
  void (*clear)(unsigned) = nullptr;
  void (*finish)() = nullptr;
  void (*readPixels)(int, int, int, int, unsigned, unsigned, void*) = nullptr;

  void clearFrame(int width, int height) const;
  // The framebuffer's RGB pixels, row 0 at the top (OpenGL's row 0 is the bottom).
  std::vector<std::uint8_t> readFrameRgb(int width, int height) const;
};

// A display image (gui/display_image.h) as a mipmapped RGB8 texture, its own levels uploaded.
// A new image is uploaded in row strips over several UI frames into a second texture, which is
// shown once complete: the UI frame never stalls on a large upload (tens of ms in software GL).
class StreamedTexture {
 public:
  explicit StreamedTexture(const GlApi& gl) : gl_(gl) {}
  ~StreamedTexture();
  StreamedTexture(const StreamedTexture&) = delete;
  StreamedTexture& operator=(const StreamedTexture&) = delete;

  // Starts uploading `image` (replacing any upload in progress).
  void begin(std::shared_ptr<const DisplayImage> image);
  // Uploads up to `byteBudget` more bytes (at least one strip); true when the upload completed
  // this call and the new image is now the one shown.
  bool step(std::size_t byteBudget);
  bool uploading() const { return incoming_ != nullptr; }

  ImTextureID id() const { return reinterpret_cast<ImTextureID>(std::uintptr_t(front_)); }
  bool empty() const { return front_ == 0; }

 private:
  void bind(unsigned texture);
  void restoreBinding();

  GlApi gl_;
  unsigned front_ = 0, back_ = 0;
  std::shared_ptr<const DisplayImage> incoming_;
  int level_ = 0;    // mip level being uploaded (0 = the image itself)
  int nextRow_ = 0;  // first row of that level not yet uploaded
  int previousBinding_ = 0;
};

}  // namespace angio
