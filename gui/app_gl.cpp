#include "gui/app_gl.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace angio {

namespace {

// Constants from the OpenGL specification (no GL header: it would declare the functions too).
constexpr unsigned kTexture2D = 0x0DE1;
constexpr unsigned kTextureMinFilter = 0x2801, kTextureMagFilter = 0x2800;
constexpr unsigned kTextureWrapS = 0x2802, kTextureWrapT = 0x2803;
constexpr unsigned kTextureBaseLevel = 0x813C, kTextureMaxLevel = 0x813D;
constexpr int kLinear = 0x2601, kLinearMipmapLinear = 0x2703, kClampToEdge = 0x812F;
constexpr unsigned kUnpackAlignment = 0x0CF5, kUnpackRowLength = 0x0CF2;
constexpr unsigned kRgb = 0x1907, kRgb8 = 0x8051, kUnsignedByte = 0x1401;
constexpr unsigned kTextureBinding2D = 0x8069;
constexpr unsigned kColorBufferBit = 0x00004000;

template <typename Function>
void resolve(Function& function, const GlApi::GetProc& getProc, const char* name) {
  function = reinterpret_cast<Function>(getProc(name));
  if (!function) throw std::runtime_error(std::string("OpenGL has no ") + name);
}

struct LevelView {
  int width, height;
  const std::uint8_t* rgb;
};

LevelView levelOf(const DisplayImage& image, int level) {
  const Rgb8Image& pixels = image.levels[level];
  return {pixels.width, pixels.height, pixels.rgb.data()};
}

}  // namespace

GlApi GlApi::load(const GetProc& getProc) {
  GlApi gl;
  resolve(gl.genTextures, getProc, "glGenTextures");
  resolve(gl.deleteTextures, getProc, "glDeleteTextures");
  resolve(gl.bindTexture, getProc, "glBindTexture");
  resolve(gl.texParameteri, getProc, "glTexParameteri");
  resolve(gl.pixelStorei, getProc, "glPixelStorei");
  resolve(gl.texImage2D, getProc, "glTexImage2D");
  resolve(gl.texSubImage2D, getProc, "glTexSubImage2D");
  resolve(gl.getIntegerv, getProc, "glGetIntegerv");
  resolve(gl.viewport, getProc, "glViewport");
  resolve(gl.clearColor, getProc, "glClearColor");
  resolve(gl.clear, getProc, "glClear");
  resolve(gl.finish, getProc, "glFinish");
  resolve(gl.readPixels, getProc, "glReadPixels");
  return gl;
}

void GlApi::clearFrame(int width, int height) const {
  viewport(0, 0, width, height);
  clearColor(0.08f, 0.08f, 0.09f, 1.f);
  clear(kColorBufferBit);
}

std::vector<std::uint8_t> GlApi::readFrameRgb(int width, int height) const {
  constexpr unsigned kPackAlignment = 0x0D05;
  std::vector<std::uint8_t> bottomUp(std::size_t(width) * height * 3), rgb(bottomUp.size());
  pixelStorei(kPackAlignment, 1);
  readPixels(0, 0, width, height, kRgb, kUnsignedByte, bottomUp.data());
  const std::size_t row = std::size_t(width) * 3;
  for (int y = 0; y < height; ++y) std::copy_n(&bottomUp[row * (height - 1 - y)], row, &rgb[row * y]);
  return rgb;
}

StreamedTexture::~StreamedTexture() {
  for (unsigned texture : {front_, back_})
    if (texture) gl_.deleteTextures(1, &texture);
}

void StreamedTexture::bind(unsigned texture) {
  gl_.getIntegerv(kTextureBinding2D, &previousBinding_);  // the ImGui backend's, left as it was
  gl_.bindTexture(kTexture2D, texture);
  gl_.pixelStorei(kUnpackAlignment, 1);  // RGB rows are not 4-byte aligned
  gl_.pixelStorei(kUnpackRowLength, 0);
}

void StreamedTexture::restoreBinding() { gl_.bindTexture(kTexture2D, unsigned(previousBinding_)); }

void StreamedTexture::begin(std::shared_ptr<const DisplayImage> image) {
  if (!back_) gl_.genTextures(1, &back_);
  incoming_ = std::move(image);
  level_ = 0;
  nextRow_ = 0;
  // Storage for every level first (contents follow in strips).
  bind(back_);
  const int levels = int(incoming_->levels.size());
  gl_.texParameteri(kTexture2D, kTextureBaseLevel, 0);
  gl_.texParameteri(kTexture2D, kTextureMaxLevel, levels - 1);
  gl_.texParameteri(kTexture2D, kTextureMinFilter, kLinearMipmapLinear);
  gl_.texParameteri(kTexture2D, kTextureMagFilter, kLinear);
  gl_.texParameteri(kTexture2D, kTextureWrapS, kClampToEdge);
  gl_.texParameteri(kTexture2D, kTextureWrapT, kClampToEdge);
  for (int level = 0; level < levels; ++level) {
    const LevelView view = levelOf(*incoming_, level);
    gl_.texImage2D(kTexture2D, level, int(kRgb8), view.width, view.height, 0, kRgb, kUnsignedByte,
                   nullptr);
  }
  restoreBinding();
}

bool StreamedTexture::step(std::size_t byteBudget) {
  if (!incoming_) return false;
  const int levels = int(incoming_->levels.size());
  bind(back_);
  std::size_t spent = 0;
  while (level_ < levels && (spent == 0 || spent < byteBudget)) {
    const LevelView view = levelOf(*incoming_, level_);
    const std::size_t rowBytes = std::size_t(view.width) * 3;
    const int rows = std::clamp(int((byteBudget - std::min(spent, byteBudget)) / rowBytes), 1,
                                view.height - nextRow_);
    gl_.texSubImage2D(kTexture2D, level_, 0, nextRow_, view.width, rows, kRgb, kUnsignedByte,
                      view.rgb + rowBytes * nextRow_);
    spent += rowBytes * rows;
    nextRow_ += rows;
    if (nextRow_ == view.height) ++level_, nextRow_ = 0;
  }
  restoreBinding();
  if (level_ < levels) return false;
  std::swap(front_, back_);
  incoming_.reset();
  return true;
}

}  // namespace angio
