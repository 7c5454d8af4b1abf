#include "core/image_refinement.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "core/view_geometry.h"

namespace angio {

namespace {

// A cell of the refinement: the pixels [x0, x1] x [y0, y1], its four corners cast.
struct PixelCell {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// 0, step, 2 step, ... and the last index, so every pixel lies between two of them.
std::vector<int> latticeLine(int size, int step) {
  std::vector<int> line;
  for (int i = 0; i < size; i += step) line.push_back(i);
  if (line.back() != size - 1) line.push_back(size - 1);
  return line;
}

class Refiner {
 public:
  Refiner(int width, int height, const ImageRefinement& refinement, const RenderPixels& render,
          RefinementStats& stats)
      : width_(width), height_(height), tolerance_(float(refinement.tolerance)), render_(render),
        stats_(stats), cast_(std::size_t(width) * height, 0), mask_(cast_.size(), 0) {
    image_.width = width;
    image_.height = height;
    image_.pixels.resize(cast_.size());
  }

  Image run(int levels) {
    const int step = 1 << levels;
    const std::vector<int> xs = latticeLine(width_, step), ys = latticeLine(height_, step);
    std::vector<PixelCell> cells;
    for (int y : ys)
      for (int x : xs) want(x, y);
    for (std::size_t j = 0; j + 1 < ys.size(); ++j)
      for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        cells.push_back({xs[i], ys[j], xs[i + 1], ys[j + 1]});
    if (!castWanted()) return std::move(image_);
    // An image one pixel wide or high has no cells (they need two lattice lines): cast it whole.
    if (xs.size() == 1 || ys.size() == 1) return castRemaining();
    while (!cells.empty()) {
      std::vector<PixelCell> next;
      for (const PixelCell& cell : cells) refine(cell, next);
      if (!castWanted()) return std::move(image_);
      cells = std::move(next);
    }
    return std::move(image_);
  }

 private:
  glm::vec4& at(int x, int y) { return image_.pixels[index(x, y)]; }
  std::size_t index(int x, int y) const { return std::size_t(y) * width_ + x; }

  void want(int x, int y) {
    if (!cast_[index(x, y)]) mask_[index(x, y)] = 1;
  }

  // Casts the wanted pixels (if any); false if cancelled.
  bool castWanted() {
    const auto wanted = std::count(mask_.begin(), mask_.end(), std::uint8_t(1));
    if (wanted == 0) return true;
    ++stats_.passes;
    stats_.cast += std::uint64_t(wanted);
    if (!render_(mask_, image_)) {
      stats_.cancelled = true;
      return false;
    }
    for (std::size_t n = 0; n < mask_.size(); ++n) cast_[n] |= mask_[n];
    std::fill(mask_.begin(), mask_.end(), std::uint8_t(0));
    return true;
  }

  Image castRemaining() {
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) want(x, y);
    castWanted();
    return std::move(image_);
  }

  // The cell's corner pixels: top left, top right, bottom left, bottom right.
  std::array<glm::vec4, 4> corners(const PixelCell& c) {
    return {at(c.x0, c.y0), at(c.x1, c.y0), at(c.x0, c.y1), at(c.x1, c.y1)};
  }

  bool cornersAgree(const PixelCell& c) {
    const auto [a, b, d, e] = corners(c);
    const glm::vec4 lo = glm::min(glm::min(a, b), glm::min(d, e));
    const glm::vec4 hi = glm::max(glm::max(a, b), glm::max(d, e));
    const glm::vec4 spread = hi - lo;
    return std::max({spread.r, spread.g, spread.b, spread.a}) <= tolerance_;
  }

  // Bilinear interpolation of the corners into the cell's pixels not cast.
  void fill(const PixelCell& c) {
    const auto [a, b, d, e] = corners(c);
    const float w = float(c.x1 - c.x0), h = float(c.y1 - c.y0);
    for (int y = c.y0; y <= c.y1; ++y) {
      const float v = h > 0 ? float(y - c.y0) / h : 0.f;
      const glm::vec4 left = a + (d - a) * v, right = b + (e - b) * v;
      for (int x = c.x0; x <= c.x1; ++x) {
        if (cast_[index(x, y)]) continue;
        const float u = w > 0 ? float(x - c.x0) / w : 0.f;
        at(x, y) = left + (right - left) * u;
      }
    }
  }

  // Fills the cell, or wants its midpoints cast and queues its quarters.
  void refine(const PixelCell& c, std::vector<PixelCell>& next) {
    if (c.x1 - c.x0 <= 1 && c.y1 - c.y0 <= 1) return;  // no pixel inside or on an edge
    if (cornersAgree(c)) {
      fill(c);
      return;
    }
    const std::vector<int> xs = split(c.x0, c.x1), ys = split(c.y0, c.y1);
    for (int y : ys)
      for (int x : xs) want(x, y);
    for (std::size_t j = 0; j + 1 < ys.size(); ++j)
      for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        next.push_back({xs[i], ys[j], xs[i + 1], ys[j + 1]});
  }

  // An edge [lo, hi] and its midpoint, where there is one.
  static std::vector<int> split(int lo, int hi) {
    if (hi - lo < 2) return {lo, hi};
    return {lo, (lo + hi) / 2, hi};
  }

  const int width_, height_;
  const float tolerance_;
  const RenderPixels& render_;
  RefinementStats& stats_;
  std::vector<std::uint8_t> cast_;  // per pixel: rendered
  std::vector<std::uint8_t> mask_;  // per pixel: to render in the next pass
  Image image_;
};

}  // namespace

Image refineImage(int width, int height, const ImageRefinement& refinement, const RenderPixels& render,
                  RefinementStats* stats) {
  if (width < 1 || height < 1) throw std::invalid_argument("refineImage: an empty image");
  RefinementStats local;
  RefinementStats& s = stats ? *stats : local;
  s = {};
  Image image = Refiner(width, height, refinement, render, s).run(std::max(refinement.levels, 1));
  if (!s.cancelled) s.interpolated = std::uint64_t(width) * std::uint64_t(height) - s.cast;
  return image;
}

Image renderRefined(const Volume& volume, const TileClassification& classification,
                    const RegionTables& tables, const RenderParams& params,
                    const ImageRefinement& refinement, const FastRenderOptions& options,
                    FastRenderStats* stats, RefinementStats* refinementStats) {
  if (options.pixels) throw std::logic_error("renderRefined: the refinement sets the pixel mask");
  const ViewGeometry view = makeViewGeometry(volume, params);
  FastRenderStats total;
  const RenderPixels render = [&](const std::vector<std::uint8_t>& mask, Image& image) {
    FastRenderOptions pass = options;
    pass.pixels = &mask;
    pass.recycle = &image;
    pass.rowsDone = nullptr;  // rows are visited once per pass
    FastRenderStats s;
    image = renderFast(volume, classification, tables, params, pass, &s);
    total.samples += s.samples;
    total.templateMs += s.templateMs;
    total.cancelled = total.cancelled || s.cancelled;
    return !s.cancelled;
  };
  Image image = refineImage(view.width, view.height, refinement, render, refinementStats);
  if (stats) *stats = total;
  return image;
}

}  // namespace angio
