#include "phantom/phantom.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/labels.h"
#include "phantom/phantom_anatomy.h"

// The phantom is rasterised slice by slice: each axial slice gathers the few solids whose z-range
// reaches it and evaluates each only over its own bounding rectangle, into per-slice distance
// layers (one per material group, so that unions of overlapping solids blend once, not once per
// solid). A final pass per voxel layers skin, fat and muscle by the distance to the body's outline,
// paints the groups over it with partial-volume coverage and adds noise hashed from (seed, voxel
// index), so every voxel depends only on the options and its own index: same bytes for any thread
// count. The scanner table is the same in every slice, so it is rasterised once, as the background
// the body's layers are painted over. Ground-truth labels follow the same painting order: table
// outside the body, bone over it, no label where lumen or plaque is painted over bone.

namespace angio {

namespace {

using namespace phantom;

constexpr double kNoiseSigmaHu = 12;
constexpr int kSlicesPerProgressStep = 16;
constexpr float kFar = std::numeric_limits<float>::max();

// Voxel centres of one axial slice in the anatomy frame.
struct SliceGrid {
  glm::ivec2 dims{0};
  glm::dvec2 first{0.0};  // centre of voxel (0, 0)
  glm::dvec2 spacing{1.0};

  double x(int i) const { return first.x + i * spacing.x; }
  double y(int j) const { return first.y + j * spacing.y; }
};

// Half-open pixel rectangle [i0, i1) x [j0, j1).
struct PixelRect {
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;

  bool empty() const { return i0 >= i1 || j0 >= j1; }
  bool contains(int i, int j) const { return i >= i0 && i < i1 && j >= j0 && j < j1; }
  void unite(const PixelRect& other) {
    if (other.empty()) return;
    if (empty()) {
      *this = other;
      return;
    }
    i0 = std::min(i0, other.i0);
    i1 = std::max(i1, other.i1);
    j0 = std::min(j0, other.j0);
    j1 = std::max(j1, other.j1);
  }
};

// The pixels whose centres lie within the bounds' xy extent (empty for empty bounds).
PixelRect pixelsWithin(const SliceGrid& grid, const Bounds& bounds) {
  // Continuous pixel coordinates are clamped before rounding, so that far-away or empty bounds
  // convert to int safely.
  auto first = [](double lo, double origin, double step, int count) {
    return int(std::ceil(std::clamp((lo - origin) / step, 0.0, double(count))));
  };
  auto end = [](double hi, double origin, double step, int count) {
    return int(std::floor(std::clamp((hi - origin) / step, -1.0, double(count - 1)))) + 1;
  };
  PixelRect rect;
  rect.i0 = first(bounds.lo.x, grid.first.x, grid.spacing.x, grid.dims.x);
  rect.i1 = end(bounds.hi.x, grid.first.x, grid.spacing.x, grid.dims.x);
  rect.j0 = first(bounds.lo.y, grid.first.y, grid.spacing.y, grid.dims.y);
  rect.j1 = end(bounds.hi.y, grid.first.y, grid.spacing.y, grid.dims.y);
  return rect;
}

// A part with its bounds grown by the blend margin, so a slice can tell whether it matters.
template <class Part>
struct Placed {
  Part part;
  Bounds bounds;
};

template <class Part>
std::vector<Placed<Part>> place(const std::vector<Part>& parts, double marginMm) {
  std::vector<Placed<Part>> placed;
  placed.reserve(parts.size());
  for (const Part& part : parts) placed.push_back({part, boundsOf(part.solid).grown(marginMm)});
  return placed;
}

// Calls visit(pixelIndex, signedDistance) for the pixels of rect, with the solid's concrete type
// known to the inner loop.
template <class Visit>
void forEachPixel(const SliceGrid& grid, const PixelRect& rect, double z, const Solid& solid,
                  Visit&& visit) {
  std::visit(
      [&](const auto& shape) {
        for (int j = rect.j0; j < rect.j1; ++j) {
          const double y = grid.y(j);
          for (int i = rect.i0; i < rect.i1; ++i) {
            const double d = signedDistance(shape, glm::dvec3(grid.x(i), y, z));
            visit(std::size_t(j) * grid.dims.x + i, float(d));
          }
        }
      },
      solid);
}

// Union of filled parts: the nearest surface wins, with its density.
struct FilledLayer {
  std::vector<float> sd, hu, texture;
  PixelRect dirty;

  void resize(std::size_t pixels) {
    sd.assign(pixels, kFar);
    hu.assign(pixels, 0.f);
    texture.assign(pixels, 0.f);
  }
  void add(const SliceGrid& grid, double z, const Placed<FilledPart>& placed) {
    const PixelRect rect = pixelsWithin(grid, placed.bounds);
    if (rect.empty()) return;
    dirty.unite(rect);
    const float partHu = float(placed.part.hu);
    const float partTexture = float(placed.part.textureHu);
    forEachPixel(grid, rect, z, placed.part.solid, [&](std::size_t n, float d) {
      if (d < sd[n]) {
        sd[n] = d;
        hu[n] = partHu;
        texture[n] = partTexture;
      }
    });
  }
  void clear(const SliceGrid& grid) {
    for (int j = dirty.j0; j < dirty.j1; ++j) {
      std::fill_n(sd.begin() + std::size_t(j) * grid.dims.x + dirty.i0, dirty.i1 - dirty.i0, kFar);
    }
    dirty = {};
  }
};

// Union of shelled parts (bones): the outer surfaces (cortex) and the cores (surfaces moved in by
// the shell) are unions of their own, so where bones overlap a core paints over the other's cortex.
struct ShelledLayer {
  std::vector<float> outerSd, shellHu, coreSd, coreHu, coreTexture;
  std::vector<std::uint8_t> outerLabel;  // the label of the part whose outer surface is nearest
  PixelRect dirty;

  void resize(std::size_t pixels) {
    outerSd.assign(pixels, kFar);
    coreSd.assign(pixels, kFar);
    shellHu.assign(pixels, 0.f);
    coreHu.assign(pixels, 0.f);
    coreTexture.assign(pixels, 0.f);
    outerLabel.assign(pixels, 0);
  }
  void add(const SliceGrid& grid, double z, const Placed<ShelledPart>& placed) {
    const PixelRect rect = pixelsWithin(grid, placed.bounds);
    if (rect.empty()) return;
    dirty.unite(rect);
    const ShelledPart& part = placed.part;
    forEachPixel(grid, rect, z, part.solid, [&](std::size_t n, float d) {
      if (d < outerSd[n]) {
        outerSd[n] = d;
        shellHu[n] = float(part.shellHu);
        outerLabel[n] = std::uint8_t(part.label);
      }
      const float core = d + float(part.shellMm);
      if (core < coreSd[n]) {
        coreSd[n] = core;
        coreHu[n] = float(part.coreHu);
        coreTexture[n] = float(part.coreTextureHu);
      }
    });
  }
  void clear(const SliceGrid& grid) {
    for (int j = dirty.j0; j < dirty.j1; ++j) {
      const std::size_t row = std::size_t(j) * grid.dims.x;
      std::fill_n(outerSd.begin() + row + dirty.i0, dirty.i1 - dirty.i0, kFar);
      std::fill_n(coreSd.begin() + row + dirty.i0, dirty.i1 - dirty.i0, kFar);
    }
    dirty = {};
  }
};

// Per-thread scratch for one slice.
struct SliceLayers {
  FilledLayer soft, lumen, plaques;
  ShelledLayer shelled;
  std::vector<float> hu, noise, noiseRows;  // the slice's densities; its noise and scratch
  std::vector<std::uint8_t> labels;
  bool sized = false;

  void ensureSize(std::size_t pixels) {
    if (sized) return;
    soft.resize(pixels);
    lumen.resize(pixels);
    plaques.resize(pixels);
    shelled.resize(pixels);
    hu.resize(pixels);
    labels.resize(pixels);
    sized = true;
  }
};

// The table's density and ground truth per pixel of an axial slice (the same in every slice).
struct TableSlice {
  std::vector<float> hu;  // air where there is no table
  std::vector<std::uint8_t> inside;
};

// ---- Noise

std::uint64_t mix64(std::uint64_t z) {  // splitmix64 finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Approximately standard normal: the sum of four 16-bit uniforms (variance 4/12) rescaled.
float gaussianNoise(std::uint64_t seedKey, std::uint64_t voxelIndex) {
  const std::uint64_t h = mix64(seedKey ^ (voxelIndex * 0x9e3779b97f4a7c15ull));
  const double sum =
      double(h & 0xffff) + double((h >> 16) & 0xffff) + double((h >> 32) & 0xffff) + double(h >> 48);
  return float((sum / 65535.0 - 2.0) * 1.7320508075688772);
}

// Standard normal with true Gaussian tails (Box-Muller on the hash's two halves): the realistic
// style's noise, whose tails reach the vessel presets' ramp as a scanner's do.
float boxMullerNoise(std::uint64_t seedKey, std::uint64_t voxelIndex) {
  const std::uint64_t h = mix64(seedKey ^ (voxelIndex * 0x9e3779b97f4a7c15ull));
  const float u1 = (float(h >> 40) + 0.5f) * 0x1.0p-24f;  // (0, 1)
  const float u2 = float(h & 0xffffff) * 0x1.0p-24f;
  return std::sqrt(-2.f * std::log(u1)) * std::cos(6.2831853f * u2);
}

// Smooth random texture of about unit standard deviation: value noise (Gaussian values on a lattice,
// trilinearly interpolated) in two octaves, 3 mm and 1.2 mm, the scale of the mottled pattern
// unresolved trabeculae and organ perfusion give at CT resolution. Depends only on the position.
float latticeValue(std::uint64_t seedKey, glm::ivec3 cell) {
  const std::uint64_t index = (std::uint64_t(std::uint32_t(cell.x)) * 0x100000001b3ull) ^
                              (std::uint64_t(std::uint32_t(cell.y)) << 21) ^
                              (std::uint64_t(std::uint32_t(cell.z)) << 42);
  return gaussianNoise(seedKey, index);
}

float valueNoise(std::uint64_t seedKey, glm::dvec3 p) {
  const glm::dvec3 base = glm::floor(p);
  const glm::ivec3 cell(base);
  const glm::vec3 t(p - base);
  float sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 offset(corner & 1, (corner >> 1) & 1, corner >> 2);
    const glm::vec3 w = glm::mix(1.f - t, t, glm::vec3(offset));
    sum += w.x * w.y * w.z * latticeValue(seedKey, cell + offset);
  }
  return sum;
}

// Two octaves of interpolated unit Gaussians have a standard deviation of sqrt(2 (2/3)^3) = 0.77.
float texture(std::uint64_t seedKey, glm::dvec3 pMm) {
  return (valueNoise(seedKey, pMm / 3.0) + valueNoise(seedKey + 1, pMm / 1.2)) / 0.77f;
}

// In-plane correlated noise of unit standard deviation: white noise (hashed from a grid one pixel
// wider than the slice, so every value depends only on its index) blurred by the separable kernel
// (w, 1, w). Its lag-1 autocorrelation 2w / (1 + 2w^2) is 0.55 for w = 0.34, as measured on clinical
// CT reconstructed with standard kernels (0.5-0.6); blurring white noise gives the low-pass noise
// power spectrum of such kernels.
constexpr float kNoiseKernelSide = 0.34f;

void correlatedNoise(std::uint64_t seedKey, int k, glm::ivec2 dims, std::vector<float>& noise,
                     std::vector<float>& rows) {
  const int w = dims.x + 2, h = dims.y + 2;
  rows.resize(std::size_t(w) * h);
  noise.resize(std::size_t(dims.x) * dims.y);
  const std::uint64_t sliceStart = std::uint64_t(k) * w * h;
  for (std::size_t n = 0; n < rows.size(); ++n) rows[n] = boxMullerNoise(seedKey, sliceStart + n);
  const float a = kNoiseKernelSide, norm = 1.f / (1.f + 2.f * a * a);  // unit variance after both passes
  for (int j = 0; j < h; ++j) {  // along i, in place (one value behind)
    float* row = rows.data() + std::size_t(j) * w;
    float previous = row[0];
    for (int i = 1; i + 1 < w; ++i) {
      const float current = row[i];
      row[i - 1] = a * previous + current + a * row[i + 1];
      previous = current;
    }
  }
  for (int j = 0; j < dims.y; ++j) {  // along j, into the slice (columns 0 .. dims.x - 1 hold i)
    const float* up = rows.data() + std::size_t(j) * w;
    const float* mid = up + w;
    const float* down = mid + w;
    float* out = noise.data() + std::size_t(j) * dims.x;
    for (int i = 0; i < dims.x; ++i) out[i] = norm * (a * up[i] + mid[i] + a * down[i]);
  }
}

// ---- The phantom

// A voxel's density from the body's layers and its signed distance to the body's outline.
struct TissueSample {
  float hu = 0;
  float bodySd = kFar;
};

// Per style: the body's layers and the noise.
struct Look {
  bool textures = false;
  bool correlatedNoise = false;
  double noiseSigmaHu = kNoiseSigmaHu;       // in the legs (and everywhere for the simple style)
  double torsoNoiseSigmaHu = kNoiseSigmaHu;  // through the pelvis and abdomen
};

// Noise grows with the attenuation along the scanner's rays (tube current modulation only partly
// evens it out): about 17 HU through the legs and 24 HU through the pelvis and abdomen of an adult
// at CTA doses, blended between the thighs and the hips.
double noiseSigmaAt(const Look& look, double zMm) {
  const double t = std::clamp((zMm - 820.0) / 80.0, 0.0, 1.0);
  return glm::mix(look.noiseSigmaHu, look.torsoNoiseSigmaHu, t);
}

Look lookOf(PhantomStyle style) {
  // Arterial-phase CTA: 15-25 HU in soft tissue (the portal-venous phase is scanned alike).
  if (style != PhantomStyle::simple) return {true, true, 17, 24};
  return {false, false, kNoiseSigmaHu, kNoiseSigmaHu};
}

struct PhantomRasteriser {
  Volume& volume;
  std::uint64_t seedKey;
  double blendMm;  // width of the partial-volume ramp at every surface
  bool groundTruthLabels;
  Look look;
  TableSlice table;
  std::vector<FootPart> feet;
  std::vector<Placed<FilledPart>> soft, lumen, plaques;
  std::vector<Placed<ShelledPart>> shelled;

  // Fraction of a voxel inside a surface at signed distance d (ramp over blendMm).
  float coverage(float d) const { return std::clamp(0.5f - d / float(blendMm), 0.f, 1.f); }

  SliceGrid grid() const {
    const glm::dvec2 spacing(volume.spacing);
    return {glm::ivec2(volume.dims), -glm::dvec2(kBoxSizeMm) / 2.0 + spacing / 2.0, spacing};
  }
  double sliceZ(int k) const { return (k + 0.5) * volume.spacing.z; }

  template <class Layer, class Part>
  static void gather(Layer& layer, const SliceGrid& grid, double z,
                     const std::vector<Placed<Part>>& parts) {
    for (const Placed<Part>& placed : parts) {
      if (z >= placed.bounds.lo.z && z <= placed.bounds.hi.z) layer.add(grid, z, placed);
    }
  }

  TableSlice rasteriseTable(const ScannerTable& shape) const {
    const SliceGrid g = grid();
    TableSlice slice;
    slice.hu.resize(std::size_t(g.dims.x) * g.dims.y);
    slice.inside.resize(slice.hu.size());
    for (int j = 0; j < g.dims.y; ++j) {
      for (int i = 0; i < g.dims.x; ++i) {
        const std::size_t n = std::size_t(j) * g.dims.x + i;
        const glm::dvec2 p(g.x(i), g.y(j));
        const double tableSd = shape.tableDistance(p);
        float hu = glm::mix(float(kAirHu), float(shape.padHu), coverage(float(tableSd)));
        slice.hu[n] = glm::mix(hu, float(shape.shellHu), coverage(float(shape.shellDistance(p))));
        slice.inside[n] = tableSd < 0;
      }
    }
    return slice;
  }

  // Skin, fat, muscle (and in the torso, muscle wall then viscera) by depth below the outline,
  // over the background density.
  template <bool kRealistic>
  TissueSample tissue(const std::vector<BodySection>& sections,
                      const std::vector<const FootPart*>& feetHere, glm::dvec3 p,
                      float background) const {
    double sd = 1e30, fat = 0, wall = 0;
    for (const BodySection& s : sections) {
      const double d = ellipseSignedDistance(glm::dvec2(p) - s.centre, s.radii);
      if (d < sd) sd = d, fat = s.fatMm, wall = s.wallMm;
    }
    for (const FootPart* foot : feetHere) {
      const double d = signedDistance(foot->shape, p);
      if (d < sd) sd = d, fat = foot->fatMm, wall = 0;
    }
    const float d = float(sd);
    float hu = background;
    if (d > 0.5f * float(blendMm)) return {hu, d};
    // Compile-time densities: the simple style's arithmetic (and its bytes) as they always were.
    constexpr double kViscera = kRealistic ? kRealisticVisceraHu : kVisceraHu;
    constexpr double kMuscle = kRealistic ? kRealisticMuscleHu : kMuscleHu;
    hu = glm::mix(hu, float(kSkinHu), coverage(d));
    hu = glm::mix(hu, float(kFatHu), coverage(d + float(kSkinMm)));
    hu = glm::mix(hu, float(kMuscle), coverage(d + float(kSkinMm + fat)));
    if (wall > 0) hu = glm::mix(hu, float(kViscera), coverage(d + float(kSkinMm + fat + wall)));
    return {hu, d};
  }

  PixelRect bodyRect(const SliceGrid& grid, const std::vector<BodySection>& sections,
                     const std::vector<const FootPart*>& feetHere) const {
    Bounds bounds;
    for (const BodySection& s : sections) {
      bounds.add(glm::dvec3(s.centre - s.radii, 0.0));
      bounds.add(glm::dvec3(s.centre + s.radii, 0.0));
    }
    for (const FootPart* foot : feetHere) {
      const Bounds b = boundsOf(foot->shape);
      bounds.add(b.lo);
      bounds.add(b.hi);
    }
    return pixelsWithin(grid, bounds.grown(blendMm));
  }

  // The density plus its texture at p (mm), if it has one.
  float textured(float hu, float textureHu, glm::dvec3 p) const {
    return textureHu > 0 ? hu + textureHu * texture(seedKey, p) : hu;
  }

  void paintFilled(const FilledLayer& layer, std::size_t n, int i, int j, float& hu) const {
    if (!layer.dirty.contains(i, j) || layer.sd[n] >= 0.5f * float(blendMm)) return;
    hu = glm::mix(hu, layer.hu[n], coverage(layer.sd[n]));
  }

  // paintFilled with the parts' textures; a separate function, so that the simple style's code (and
  // with it how the compiler contracts its arithmetic) stays as it was: the same bytes.
  void paintTexturedFilled(const FilledLayer& layer, std::size_t n, int i, int j, glm::dvec3 p,
                           float& hu) const {
    if (!layer.dirty.contains(i, j) || layer.sd[n] >= 0.5f * float(blendMm)) return;
    hu = glm::mix(hu, textured(layer.hu[n], layer.texture[n], p), coverage(layer.sd[n]));
  }

  static bool insideFilled(const FilledLayer& layer, std::size_t n, int i, int j) {
    return layer.dirty.contains(i, j) && layer.sd[n] < 0;
  }

  // The ground truth at a voxel centre, in the painting order of its density.
  int groundTruthLabel(const SliceLayers& layers, std::size_t n, int i, int j, float bodySd) const {
    if (insideFilled(layers.lumen, n, i, j) || insideFilled(layers.plaques, n, i, j)) return 0;
    const ShelledLayer& shelled = layers.shelled;
    if (shelled.dirty.contains(i, j) && shelled.outerSd[n] < 0 && shelled.outerLabel[n] != 0)
      return shelled.outerLabel[n];
    return table.inside[n] && bodySd >= 0 ? kTableLabel : 0;
  }

  void paintShelled(const ShelledLayer& layer, std::size_t n, int i, int j, float& hu) const {
    if (!layer.dirty.contains(i, j) || layer.outerSd[n] >= 0.5f * float(blendMm)) return;
    hu = glm::mix(hu, layer.shellHu[n], coverage(layer.outerSd[n]));
    hu = glm::mix(hu, layer.coreHu[n], coverage(layer.coreSd[n]));
  }

  void paintTexturedShelled(const ShelledLayer& layer, std::size_t n, int i, int j, glm::dvec3 p,
                            float& hu) const {
    if (!layer.dirty.contains(i, j) || layer.outerSd[n] >= 0.5f * float(blendMm)) return;
    hu = glm::mix(hu, layer.shellHu[n], coverage(layer.outerSd[n]));
    const float core = coverage(layer.coreSd[n]);
    if (core > 0) hu = glm::mix(hu, textured(layer.coreHu[n], layer.coreTexture[n], p), core);
  }

  // The parts over the body's layers at pixel n (point p), in painting order.
  void paintParts(const SliceLayers& layers, std::size_t n, int i, int j, glm::dvec3 p,
                  float& hu) const {
    if (!look.textures) {
      paintFilled(layers.soft, n, i, j, hu);
      paintShelled(layers.shelled, n, i, j, hu);
      paintFilled(layers.lumen, n, i, j, hu);
      paintFilled(layers.plaques, n, i, j, hu);
      return;
    }
    paintTexturedFilled(layers.soft, n, i, j, p, hu);
    paintTexturedShelled(layers.shelled, n, i, j, p, hu);
    paintTexturedFilled(layers.lumen, n, i, j, p, hu);
    paintTexturedFilled(layers.plaques, n, i, j, p, hu);
  }

  // The slice's densities plus noise, with their labels, into the volume.
  void writeSlice(int k, SliceLayers& layers) const {
    const glm::ivec2 dims(volume.dims);
    const std::size_t pixels = std::size_t(dims.x) * dims.y;
    const std::size_t sliceStart = std::size_t(k) * pixels;
    Voxel* out = volume.voxels.data() + sliceStart;
    if (look.correlatedNoise) {
      const float sigma = float(noiseSigmaAt(look, sliceZ(k)));
      correlatedNoise(seedKey, k, dims, layers.noise, layers.noiseRows);
      for (std::size_t n = 0; n < pixels; ++n)
        out[n] = encodeVoxel(layers.hu[n] + sigma * layers.noise[n], layers.labels[n]);
      return;
    }
    for (std::size_t n = 0; n < pixels; ++n) {  // the simple style's white noise
      const float hu = layers.hu[n] + float(kNoiseSigmaHu) * gaussianNoise(seedKey, sliceStart + n);
      out[n] = encodeVoxel(hu, layers.labels[n]);
    }
  }

  void rasteriseSlice(int k, SliceLayers& layers) const {
    const SliceGrid g = grid();
    const double z = sliceZ(k);
    layers.ensureSize(std::size_t(g.dims.x) * g.dims.y);
    gather(layers.soft, g, z, soft);
    gather(layers.shelled, g, z, shelled);
    gather(layers.lumen, g, z, lumen);
    gather(layers.plaques, g, z, plaques);

    const std::vector<BodySection> sections = bodySectionsAt(z);
    std::vector<const FootPart*> feetHere;
    for (const FootPart& foot : feet) {
      const Bounds b = boundsOf(foot.shape).grown(blendMm);
      if (z >= b.lo.z && z <= b.hi.z) feetHere.push_back(&foot);
    }
    const PixelRect body = bodyRect(g, sections, feetHere);

    for (int j = 0; j < g.dims.y; ++j) {
      for (int i = 0; i < g.dims.x; ++i) {
        const std::size_t n = std::size_t(j) * g.dims.x + i;
        TissueSample sample{table.hu[n]};
        if (body.contains(i, j)) {
          const glm::dvec3 p(g.x(i), g.y(j), z);
          sample = look.textures ? tissue<true>(sections, feetHere, p, table.hu[n])
                                 : tissue<false>(sections, feetHere, p, table.hu[n]);
          paintParts(layers, n, i, j, p, sample.hu);
        }
        layers.hu[n] = sample.hu;
        layers.labels[n] =
            std::uint8_t(groundTruthLabels ? groundTruthLabel(layers, n, i, j, sample.bodySd) : 0);
      }
    }
    writeSlice(k, layers);
    layers.soft.clear(g);
    layers.shelled.clear(g);
    layers.lumen.clear(g);
    layers.plaques.clear(g);
  }
};

Volume makePhantomVolume(glm::ivec3 dims) {
  const glm::dvec3 spacing = kBoxSizeMm / glm::dvec3(dims);
  Volume volume;
  volume.dims = dims;
  volume.spacing = spacing;
  // Voxel centres sit in the middle of their cells; x, y centred on the table axis like a scanner.
  volume.origin = glm::dvec3(-kBoxSizeMm.x / 2, -kBoxSizeMm.y / 2, kPhysicalZOffsetMm) + spacing / 2.0;
  volume.direction = glm::dmat3(1.0);
  volume.voxels.resize(volume.voxelCount());
  return volume;
}

std::vector<CenterlinePath> toPhysical(std::vector<CenterlinePath> paths) {
  for (CenterlinePath& path : paths) {
    for (CenterlinePoint& point : path.points) point.positionMm.z += kPhysicalZOffsetMm;
  }
  return paths;
}

}  // namespace

std::optional<PhantomStyle> parsePhantomStyle(const std::string& name) {
  if (name == "realistic") return PhantomStyle::realistic;
  if (name == "simple") return PhantomStyle::simple;
  if (name == "portal-venous") return PhantomStyle::portalVenous;
  return std::nullopt;
}

Phantom generatePhantom(const PhantomOptions& options, const std::function<void(double)>& progress) {
  const glm::ivec3 dims = options.dims;
  if (dims.x < 1 || dims.y < 1 || dims.z < 1) {
    throw std::invalid_argument("phantom dimensions must be positive");
  }
  Phantom phantom;
  phantom.volume = makePhantomVolume(dims);
  const Anatomy anatomy = buildAnatomy(options.style);
  const glm::dvec3 spacing = phantom.volume.spacing;
  // Surfaces ramp over two voxels, about a CT scanner's point-spread: a one-voxel ramp is so sharp
  // that trilinear iso-surfaces terrace into visible rings on smooth bones.
  const double blendMm = 2.0 * std::cbrt(spacing.x * spacing.y * spacing.z);
  const double margin = blendMm;  // surfaces influence voxels up to blendMm / 2 away

  PhantomRasteriser rasteriser{phantom.volume,
                               mix64(options.seed + 0x632be59bd9b4e019ull),
                               blendMm,
                               options.groundTruthLabels,
                               lookOf(options.style),
                               {},
                               anatomy.feet,
                               place(anatomy.softParts, margin),
                               place(anatomy.lumen, margin),
                               place(anatomy.plaques, margin),
                               place(anatomy.shelled, margin)};

  rasteriser.table = rasteriser.rasteriseTable(anatomy.table);

  tbb::enumerable_thread_specific<SliceLayers> scratch;
  for (int k0 = 0; k0 < dims.z; k0 += kSlicesPerProgressStep) {
    const int k1 = std::min(dims.z, k0 + kSlicesPerProgressStep);
    tbb::parallel_for(tbb::blocked_range<int>(k0, k1, 1), [&](const tbb::blocked_range<int>& r) {
      SliceLayers& layers = scratch.local();
      for (int k = r.begin(); k != r.end(); ++k) rasteriser.rasteriseSlice(k, layers);
    });
    if (progress) progress(double(k1) / dims.z);
  }
  phantom.centerlines.source = "phantom";
  phantom.centerlines.paths = toPhysical(anatomy.paths);
  return phantom;
}

}  // namespace angio
