#include "vessel/vessel_glyph.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <memory>
#include <new>
#include <limits>
#include <span>
#include <stdexcept>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include "vessel/capsule_intersection.h"

namespace angio {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Rows are handed out to threads in bands; segments are binned per band, not per row, which keeps
// the binning small while a band's rows still see few irrelevant segments.
constexpr int kRowsPerBand = 8;

bool isFinite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// --- Preparation (view-independent) -------------------------------------------------------------

// How many leading points `path` shares (same position and radius) with an earlier path.
std::size_t sharedTrunkLength(const Centerlines& centerlines, std::size_t pathIndex) {
  constexpr double kSameMm = 1e-6;
  const CenterlinePath& path = centerlines.paths[pathIndex];
  std::size_t longest = 0;
  for (std::size_t earlier = 0; earlier < pathIndex; ++earlier) {
    const CenterlinePath& other = centerlines.paths[earlier];
    std::size_t n = sharedPrefixLength(other, path, kSameMm);
    for (std::size_t k = 0; k < n; ++k) {
      if (std::abs(other.points[k].radiusMm - path.points[k].radiusMm) > kSameMm) n = k;
    }
    longest = std::max(longest, n);
  }
  return longest;
}

GlyphTubes::Vertex tubeVertex(const CenterlinePoint& point, const VesselGlyphSettings& settings) {
  const double vesselRadius = point.radiusMm > 0 ? point.radiusMm : settings.unknownVesselRadiusMm;
  GlyphTubes::Vertex vertex;
  vertex.positionMm = point.positionMm;
  vertex.focusRadiusMm = settings.focus.at(vesselRadius);
  if (settings.context == ContextShape::tube) {
    vertex.contextRadiusMm = settings.contextTube.at(vesselRadius);
  }
  return vertex;
}

// The path's points from `first` on as chains of finite vertices (split at non-finite points).
void appendChains(const CenterlinePath& path, std::size_t first, const VesselGlyphSettings& settings,
                  GlyphTubes& tubes) {
  std::vector<GlyphTubes::Vertex> chain;
  for (std::size_t n = first; n < path.points.size(); ++n) {
    const CenterlinePoint& point = path.points[n];
    if (isFinite(point.positionMm) && std::isfinite(point.radiusMm)) {
      chain.push_back(tubeVertex(point, settings));
    } else if (!chain.empty()) {
      tubes.chains.push_back(std::move(chain));
      chain.clear();
    }
  }
  if (!chain.empty()) tubes.chains.push_back(std::move(chain));
}

// How far vertex n's balls are from the merged segment [a, b] at n's arc-length parameter:
// |position offset| + the larger |radius offset|. When every merged vertex is within e, each
// exact ball lies inside a merged ball grown by e and vice versa, and so do the convex
// combinations between them (the round cones), hence the tolerance guarantee in the header.
double deviation(const std::vector<GlyphTubes::Vertex>& chain, const std::vector<double>& arc,
                 std::size_t a, std::size_t b, std::size_t n) {
  const double span = arc[b] - arc[a];
  const double s = span > 0 ? (arc[n] - arc[a]) / span : 0.0;
  const GlyphTubes::Vertex& va = chain[a];
  const GlyphTubes::Vertex& vb = chain[b];
  const GlyphTubes::Vertex& vn = chain[n];
  const double offset = glm::distance(vn.positionMm, glm::mix(va.positionMm, vb.positionMm, s));
  const double focus =
      std::abs(vn.focusRadiusMm - (va.focusRadiusMm + s * (vb.focusRadiusMm - va.focusRadiusMm)));
  const double context = std::abs(vn.contextRadiusMm -
                                  (va.contextRadiusMm + s * (vb.contextRadiusMm - va.contextRadiusMm)));
  return offset + std::max(focus, context);
}

// Douglas-Peucker with the deviation above, then every radius grown by the tolerance. Run on
// pieces of at most kSimplifyPiece points, which bounds its worst case (quadratic in the piece)
// for paths of any length; their ends are kept.
constexpr std::size_t kSimplifyPiece = 256;

std::vector<GlyphTubes::Vertex> simplified(const std::vector<GlyphTubes::Vertex>& chain,
                                           double toleranceMm) {
  if (toleranceMm <= 0) return chain;
  const std::size_t count = chain.size();
  std::vector<double> arc(count, 0.0);
  for (std::size_t n = 1; n < count; ++n) {
    arc[n] = arc[n - 1] + glm::distance(chain[n - 1].positionMm, chain[n].positionMm);
  }
  std::vector<bool> keep(count, false);
  keep.back() = true;
  std::vector<std::pair<std::size_t, std::size_t>> pending;
  for (std::size_t first = 0; first + 1 < count; first += kSimplifyPiece - 1) {
    keep[first] = true;
    pending.push_back({first, std::min(first + kSimplifyPiece - 1, count - 1)});
  }
  while (!pending.empty()) {
    const auto [a, b] = pending.back();
    pending.pop_back();
    std::size_t worst = a;
    double worstDeviation = toleranceMm;
    for (std::size_t n = a + 1; n < b; ++n) {
      const double d = deviation(chain, arc, a, b, n);
      if (d > worstDeviation) worstDeviation = d, worst = n;
    }
    if (worst == a) continue;
    keep[worst] = true;
    pending.push_back({a, worst});
    pending.push_back({worst, b});
  }
  std::vector<GlyphTubes::Vertex> result;
  for (std::size_t n = 0; n < count; ++n) {
    if (!keep[n]) continue;
    GlyphTubes::Vertex vertex = chain[n];
    vertex.focusRadiusMm += toleranceMm;
    vertex.contextRadiusMm += toleranceMm;
    result.push_back(vertex);
  }
  return result;
}

// --- Per view: segments in view coordinates -----------------------------------------------------

// View coordinates (h, v, t): image right, image up, depth along the view direction, relative to
// P0. The ray of pixel (x, y) is the line (h_x, v_y, t), t its depth in the rendering model.
glm::dvec3 toView(const ViewGeometry& view, glm::dvec3 positionMm) {
  const glm::dvec3 p = positionMm - view.centre;
  return {glm::dot(p, view.right), glm::dot(p, view.up), glm::dot(p, view.viewDir)};
}

struct SRange {  // parameters s along a segment
  double lo = 0;
  double hi = 1;
  bool empty() const { return lo > hi; }
};

// Narrows `range` to the s with k s <= c.
void requireAtMost(SRange& range, double k, double c) {
  if (k > 0) {
    range.hi = std::min(range.hi, c / k);
  } else if (k < 0) {
    range.lo = std::max(range.lo, c / k);
  } else if (c < 0) {
    range = {1, 0};
  }
}

struct Tube {  // one segment's piece of a tube, prepared for this view's rays
  DepthRayRoundCone cone;
  double radius0, radius1;
  double vLo, vHi;  // the heights its round cone reaches
};

struct ViewSegment {
  glm::dvec3 a, b;  // endpoints in view coordinates
  Tube focus;
  std::optional<Tube> contextTube;
  std::size_t chain;  // which chain of GlyphTubes

  glm::dvec3 at(double s) const { return a + s * (b - a); }
};

Tube makeTube(glm::dvec3 a, glm::dvec3 b, double radius0, double radius1, bool withEndBall) {
  return {DepthRayRoundCone({a, b, radius0, radius1}, withEndBall), radius0, radius1,
          std::min(a.y - radius0, b.y - radius1), std::max(a.y + radius0, b.y + radius1)};
}

std::vector<ViewSegment> viewSegments(const ViewGeometry& view, const GlyphTubes& tubes,
                                      const VesselGlyphSettings& settings) {
  std::vector<ViewSegment> segments;
  const bool withTube = settings.context == ContextShape::tube;
  for (std::size_t c = 0; c < tubes.chains.size(); ++c) {
    const auto& chain = tubes.chains[c];
    // A chain of one point is a ball: a segment of zero length.
    const std::size_t count = std::max<std::size_t>(chain.size(), 2) - 1;
    for (std::size_t n = 0; n < count; ++n) {
      const GlyphTubes::Vertex& v0 = chain[n];
      const GlyphTubes::Vertex& v1 = chain[std::min(n + 1, chain.size() - 1)];
      const glm::dvec3 a = toView(view, v0.positionMm), b = toView(view, v1.positionMm);
      const bool last = n + 1 == count;  // the inner balls come with the following segment
      ViewSegment segment{a, b, makeTube(a, b, v0.focusRadiusMm, v1.focusRadiusMm, last), std::nullopt,
                          c};
      if (withTube) {
        segment.contextTube = makeTube(a, b, v0.contextRadiusMm, v1.contextRadiusMm, last);
      }
      segments.push_back(std::move(segment));
    }
  }
  return segments;
}

// --- Per view: slab end caps -------------------------------------------------------------------

// The slab's sideways reach is along image rows whatever the path's direction (thesis 5.3.3: the
// row-wise sweep assumes vessels run vertically). Where a path runs sideways, its points lie in a
// few rows and reach the half width along the path, so past its ends that slab would stick out as
// a needle of one to a few rows. A cap ends the chain's slab at each end instead: the chain's slab
// leaves out the rectangle beyond the end, up to the half width along the path's image-space
// direction there and to either side of it.
struct SlabCap {
  glm::dvec2 end{0.0};      // the chain's end in image space (h, v)
  glm::dvec2 outward{0.0};  // unit: the path's image-space direction at the end, pointing out
};

struct ChainCaps {
  std::optional<SlabCap> first, last;
};

// The cap at *end, the next vertices inward from `next` to `stop`; none for a chain seen end-on.
template <class Iterator>
std::optional<SlabCap> capAt(const ViewGeometry& view, Iterator end, Iterator stop) {
  constexpr double kEndOnMm = 1e-9;
  const glm::dvec2 endPoint(toView(view, end->positionMm));
  for (Iterator next = std::next(end); next != stop; ++next) {
    const glm::dvec2 outward = endPoint - glm::dvec2(toView(view, next->positionMm));
    if (glm::length(outward) > kEndOnMm) return SlabCap{endPoint, glm::normalize(outward)};
  }
  return std::nullopt;
}

std::vector<ChainCaps> slabCaps(const ViewGeometry& view, const GlyphTubes& tubes,
                                const VesselGlyphSettings& settings) {
  std::vector<ChainCaps> caps(tubes.chains.size());
  if (settings.context != ContextShape::slab) return caps;
  for (std::size_t c = 0; c < tubes.chains.size(); ++c) {
    const auto& chain = tubes.chains[c];
    caps[c] = {capAt(view, chain.begin(), chain.end()), capAt(view, chain.rbegin(), chain.rend())};
  }
  return caps;
}

// Narrows [lo, hi] to the h with min <= k h + c <= max.
void requireBetween(double& lo, double& hi, double k, double c, double min, double max) {
  if (k == 0) {
    if (c < min || c > max) lo = kInfinity, hi = -kInfinity;
    return;
  }
  const double a = (min - c) / k, b = (max - c) / k;
  lo = std::max(lo, std::min(a, b));
  hi = std::min(hi, std::max(a, b));
}

// --- Per view: rows -----------------------------------------------------------------------------

struct RowGeometry {
  int width = 0, height = 0;
  double pixelMm = 0;
  double rowV(int y) const { return (height * 0.5 - y - 0.5) * pixelMm; }
  double columnH(int x) const { return (x + 0.5 - width * 0.5) * pixelMm; }
  // The columns whose h lies in [hLo, hHi], clamped to the image (first > last when none).
  std::pair<int, int> columns(double hLo, double hHi) const {
    const double first = std::ceil(hLo / pixelMm + width * 0.5 - 0.5);
    const double last = std::floor(hHi / pixelMm + width * 0.5 - 0.5);
    return {int(std::clamp(first, 0.0, double(width))), int(std::clamp(last, -1.0, width - 1.0))};
  }
  // The rows whose v lies in [vLo, vHi], clamped likewise.
  std::pair<int, int> rows(double vLo, double vHi) const {
    const double first = std::ceil(height * 0.5 - 0.5 - vHi / pixelMm);
    const double last = std::floor(height * 0.5 - 0.5 - vLo / pixelMm);
    return {int(std::clamp(first, 0.0, double(height))), int(std::clamp(last, -1.0, height - 1.0))};
  }
};

struct ColumnRange {  // columns first..last; none when first > last
  int first = 0, last = -1;
  bool contains(int x) const { return first <= x && x <= last; }
};

// The columns of row v inside the cap's rectangle (see SlabCap).
ColumnRange cappedColumns(const RowGeometry& rows, const SlabCap& cap, double v, double halfWidthMm) {
  const glm::dvec2 o = cap.outward;
  const double dv = v - cap.end.y;
  double lo = -kInfinity, hi = kInfinity;
  // along = (h - end.h) o.x + dv o.y in [0, w]; across = -(h - end.h) o.y + dv o.x in [-w, w]
  requireBetween(lo, hi, o.x, dv * o.y - cap.end.x * o.x, 0, halfWidthMm);
  requireBetween(lo, hi, -o.y, dv * o.x + cap.end.x * o.y, -halfWidthMm, halfWidthMm);
  if (lo > hi) return {};
  const auto [first, last] = rows.columns(lo, hi);
  return {first, last};
}

using SlabCuts = std::array<ColumnRange, 2>;  // a chain's capped columns in one row

// Calls piece(first, last) for each run of columns of [first, last] outside the cuts, in order.
template <class Piece>
void forEachPieceOutside(int first, int last, SlabCuts cuts, Piece piece) {
  if (cuts[1].first < cuts[0].first) std::swap(cuts[0], cuts[1]);
  for (const ColumnRange& cut : cuts) {
    if (cut.first > cut.last || cut.last < first) continue;
    if (cut.first > last) break;
    if (cut.first > first) piece(first, cut.first - 1);
    first = std::max(first, cut.last + 1);
  }
  if (first <= last) piece(first, last);
}

// The heights v a segment's regions reach.
std::pair<double, double> verticalReach(const ViewSegment& segment, const VesselGlyphSettings& settings,
                                        double pixelMm) {
  double lo = segment.focus.vLo, hi = segment.focus.vHi;
  if (segment.contextTube) {
    lo = std::min(lo, segment.contextTube->vLo);
    hi = std::max(hi, segment.contextTube->vHi);
  }
  if (settings.context == ContextShape::slab) {
    lo = std::min({lo, segment.a.y - pixelMm / 2, segment.b.y - pixelMm / 2});
    hi = std::max({hi, segment.a.y + pixelMm / 2, segment.b.y + pixelMm / 2});
  }
  return {lo, hi};
}

// Segment indices per band of rows (compressed rows: band n owns [first[n], first[n + 1])).
struct BandBins {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> segments;
};

BandBins binByBand(const std::vector<ViewSegment>& segments, const RowGeometry& rows,
                   const VesselGlyphSettings& settings, int bands) {
  std::vector<std::pair<int, int>> bandRange(segments.size());
  BandBins bins;
  bins.first.assign(bands + 1, 0);
  for (std::size_t n = 0; n < segments.size(); ++n) {
    const auto [vLo, vHi] = verticalReach(segments[n], settings, rows.pixelMm);
    const auto [y0, y1] = rows.rows(vLo, vHi);
    bandRange[n] = y0 <= y1 ? std::pair{y0 / kRowsPerBand, y1 / kRowsPerBand} : std::pair{1, 0};
    for (int band = bandRange[n].first; band <= bandRange[n].second; ++band) ++bins.first[band + 1];
  }
  for (int band = 0; band < bands; ++band) bins.first[band + 1] += bins.first[band];
  bins.segments.resize(bins.first[bands]);
  std::vector<std::uint32_t> cursor(bins.first.begin(), bins.first.end() - 1);
  for (std::size_t n = 0; n < segments.size(); ++n) {
    for (int band = bandRange[n].first; band <= bandRange[n].second; ++band) {
      bins.segments[cursor[band]++] = std::uint32_t(n);
    }
  }
  return bins;
}

// The depth of the segment's axis line under pixel (h, v): at the point of the line whose
// projection is nearest to (h, v), not clamped to the segment, so collinear segments share one
// cut plane and a straight vessel is cut cleanly at its joints. A segment seen end-on has no
// such point; its middle is taken.
double axisDepthUnder(const ViewSegment& segment, double h, double v) {
  const glm::dvec2 a(segment.a), along = glm::dvec2(segment.b) - a;
  const double lengthSquared = glm::dot(along, along);
  const double s = lengthSquared > 1e-12 ? glm::dot(glm::dvec2(h, v) - a, along) / lengthSquared : 0.5;
  return segment.at(s).z;
}

struct RunSpan {  // the same depth span on the rays of columns x0..x1 (a slab's interior)
  int x0, x1;
  double begin, end;
};

// Inserts `span` into the sorted, disjoint spans[0, count), merging it with those it overlaps or
// touches; `spans` has room for count + 1. Returns the new count.
std::size_t insertMerged(DepthSpan* spans, std::size_t count, DepthSpan span) {
  // Common cases first: an empty list, or a span meeting only the last one.
  if (count == 0 || span.begin > spans[count - 1].end) {
    spans[count] = span;
    return count + 1;
  }
  std::size_t first = 0;
  while (first < count && spans[first].end < span.begin) ++first;
  std::size_t last = first;
  for (; last < count && spans[last].begin <= span.end; ++last) {
    span = {std::min(span.begin, spans[last].begin), std::max(span.end, spans[last].end)};
  }
  if (first == last) {  // between two: make room
    std::copy_backward(spans + first, spans + count, spans + count + 1);
    spans[first] = span;
    return count + 1;
  }
  spans[first] = span;
  std::copy(spans + last, spans + count, spans + first + 1);
  return count - (last - first - 1);
}

void insertMerged(std::vector<DepthSpan>& spans, DepthSpan span) {
  spans.emplace_back();
  spans.resize(insertMerged(spans.data(), spans.size() - 1, span));
}

// A column's sorted, merged spans: a few inline (one cache line), more in a spill vector.
class SpanList {
 public:
  const DepthSpan* begin() const { return spilled_ ? spill_.data() : local_; }
  const DepthSpan* end() const { return begin() + count_; }
  bool empty() const { return count_ == 0; }

  void add(const DepthSpan& span) {  // by reference: a copy on the stack stalled its load
    if (count_ == 0) {  // the most common case by far, inline (an empty list is never spilled)
      local_[0] = span;
      count_ = 1;
      return;
    }
    DepthSpan* spans = spilled_ ? spill_.data() : local_;
    DepthSpan& last = spans[count_ - 1];  // most often the span meets the last one only: join in place
    if (span.begin <= last.end && span.end >= last.begin &&
        (count_ == 1 || span.begin > spans[count_ - 2].end)) {
      last = {std::min(span.begin, last.begin), std::max(span.end, last.end)};
      return;
    }
    if (!spilled_ && count_ < kLocal) {
      count_ = insertMerged(local_, count_, span);
      return;
    }
    if (!spilled_) {
      spill_.assign(local_, local_ + count_);
      spilled_ = true;
    }
    spill_.resize(count_ + 1);
    count_ = insertMerged(spill_.data(), count_, span);
  }
  void clear() {
    count_ = 0;
    spilled_ = false;
  }

 private:
  static constexpr std::size_t kLocal = 3;
  DepthSpan local_[kLocal];
  std::size_t count_ = 0;
  bool spilled_ = false;
  std::vector<DepthSpan> spill_;
};

// The focus and context spans of every column of a row, each list kept sorted and merged as spans
// arrive (union is order-independent, so the result does not depend on the order of segments).
class ColumnSpans {
 public:
  explicit ColumnSpans(int width)
      : focus_(std::size_t(width)), context_(std::size_t(width)),
        used_((std::size_t(width) + 63) / 64, 0) {}

  void add(Region region, int x, const DepthSpan& span) {
    const std::size_t word = std::size_t(x) / 64;
    const std::uint64_t bit = std::uint64_t(1) << (x % 64);
    if (!(used_[word] & bit)) {
      used_[word] |= bit;
      touched_.push_back(x);
      first_ = std::min(first_, x);
      last_ = std::max(last_, x);
    }
    (region == Region::focus ? focus_ : context_)[std::size_t(x)].add(span);
  }
  const SpanList& focus(int x) const { return focus_[std::size_t(x)]; }
  const SpanList& context(int x) const { return context_[std::size_t(x)]; }
  int first() const { return first_; }
  int last() const { return last_; }

  // The first column >= x with spans, or INT_MAX.
  int nextUsed(int x) const {
    std::size_t word = std::size_t(x) / 64;
    if (word >= used_.size()) return std::numeric_limits<int>::max();
    std::uint64_t bits = used_[word] & (~std::uint64_t(0) << (x % 64));
    while (bits == 0) {
      if (++word == used_.size()) return std::numeric_limits<int>::max();
      bits = used_[word];
    }
    return int(word * 64) + std::countr_zero(bits);
  }

  void clear() {
    for (int x : touched_) {
      focus_[std::size_t(x)].clear();
      context_[std::size_t(x)].clear();
      used_[std::size_t(x) / 64] = 0;
    }
    touched_.clear();
    first_ = std::numeric_limits<int>::max();
    last_ = -1;
  }

 private:
  std::vector<SpanList> focus_, context_;
  std::vector<std::uint64_t> used_;  // one bit per column with spans
  std::vector<int> touched_;
  int first_ = std::numeric_limits<int>::max(), last_ = -1;
};

// One pending span per column while the pieces of one chain are added: a piece's span that
// overlaps the pending one joins it (the union of overlapping spans is their hull), any other
// sends the pending one on. Consecutive pieces of a chain overlap, so a column gets one span per
// chain instead of one per piece.
class ChainAccumulator {
 public:
  ChainAccumulator(int width, Region region) : pending_(std::size_t(width)), region_(region) {}

  void add(int x, DepthSpan span, ColumnSpans& columns) {
    DepthSpan& pending = pending_[std::size_t(x)];
    if (pending.empty()) {
      pending = span;
      touched_.push_back(x);
    } else if (span.begin <= pending.end && pending.begin <= span.end) {
      pending = {std::min(pending.begin, span.begin), std::max(pending.end, span.end)};
    } else {
      columns.add(region_, x, pending);
      pending = span;
    }
  }
  void flush(ColumnSpans& columns) {
    for (int x : touched_) {
      DepthSpan& pending = pending_[std::size_t(x)];
      columns.add(region_, x, pending);
      pending = {};
    }
    touched_.clear();
  }

 private:
  std::vector<DepthSpan> pending_;
  std::vector<int> touched_;
  Region region_;
};

// `context` minus the (merged) `focus` spans, and not before `notBefore`, into `out`.
void subtract(std::span<const DepthSpan> context, const std::vector<DepthSpan>& focus, double notBefore,
              std::vector<DepthSpan>& out) {
  out.clear();
  std::size_t f = 0;
  for (DepthSpan piece : context) {
    piece.begin = std::max(piece.begin, notBefore);
    while (f < focus.size() && focus[f].end <= piece.begin) ++f;
    for (std::size_t g = f; g < focus.size() && focus[g].begin < piece.end && !piece.empty(); ++g) {
      if (focus[g].begin > piece.begin) out.push_back({piece.begin, focus[g].begin});
      piece.begin = std::max(piece.begin, focus[g].end);
    }
    if (piece.end > piece.begin) out.push_back(piece);
  }
}

bool emptyInFloat(const DepthSpan& span) { return !(float(span.end) > float(span.begin)); }

// Appends a span to a pixel's intervals [first, end) as float, returning the new end. Spans come
// sorted and disjoint, and rounding is monotone, so they stay so; rounding can only close a gap,
// and then two intervals of one region are joined.
inline RegionInterval* appendInterval(RegionInterval* first, RegionInterval* end, const DepthSpan& span,
                                      Region region) {
  const float begin = float(span.begin), stop = float(span.end);
  if (!(stop > begin)) return end;
  if (end > first && end[-1].region == region && end[-1].end >= begin) {
    end[-1].end = std::max(end[-1].end, stop);
    return end;
  }
  *end = {begin, stop, region};
  return end + 1;
}

// A band's intervals, written through raw pointers: room is made before each column, so the
// per-interval cost is a store. Uninitialised storage (RegionInterval is an implicit-lifetime
// aggregate), grown by doubling.
class IntervalBuffer {
 public:
  std::size_t size() const { return size_; }
  // Room for `count` more intervals at the end.
  RegionInterval* room(std::size_t count) {
    if (size_ + count > capacity_) grow(std::max(2 * capacity_, size_ + count + 1024));
    return data_.get() + size_;
  }
  void commit(RegionInterval* end) { size_ = std::size_t(end - data_.get()); }
  void clear() { size_ = 0; }
  const RegionInterval* data() const { return data_.get(); }

 private:
  struct Free {
    void operator()(RegionInterval* p) const { std::free(p); }
  };
  void grow(std::size_t capacity) {
    auto* bigger = static_cast<RegionInterval*>(std::malloc(capacity * sizeof(RegionInterval)));
    if (bigger == nullptr) throw std::bad_alloc();
    if (size_ > 0) std::memcpy(bigger, data_.get(), size_ * sizeof(RegionInterval));
    data_.reset(bigger);
    capacity_ = capacity;
  }

  std::unique_ptr<RegionInterval, Free> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

// Builds rows one at a time. Its per-column storage is kept from band to band and view to view
// (one builder per thread, vessel_glyph's Scratch), so it is not allocated again for every band.
class RowBuilder {
 public:
  RowBuilder() : columns_(0), focusChain_(0, Region::focus), contextChain_(0, Region::context) {}

  // Before the rows of a view; `settings` and `caps` (per chain) must outlive them.
  void startView(const RowGeometry& rows, const VesselGlyphSettings& settings,
                 const std::vector<ChainCaps>& caps) {
    if (rows.width != rows_.width) {
      columns_ = ColumnSpans(rows.width);
      focusChain_ = ChainAccumulator(rows.width, Region::focus);
      contextChain_ = ChainAccumulator(rows.width, Region::context);
    }
    rows_ = rows;
    settings_ = &settings;
    caps_ = &caps;
  }

  // Appends row y's intervals to `out`; rowStarts[x] = the offset in `out` of column x's first.
  void build(int y, const std::vector<ViewSegment>& segments, const std::uint32_t* candidates,
             std::size_t candidateCount, IntervalBuffer& out, std::uint32_t* rowStarts);

 private:
  void addTube(const ViewSegment& segment, const Tube& tube, double v, ChainAccumulator& chain,
               bool cut);
  SlabCuts slabCuts(std::size_t chain, double v) const;
  void addSlab(const ViewSegment& segment, double v, const SlabCuts& cuts);
  void emitColumns(int xFirst, int xLast, IntervalBuffer& out, std::uint32_t* rowStarts);
  void advanceRuns(int x);
  void emitMixed(int x, IntervalBuffer& out);

  RowGeometry rows_;
  const VesselGlyphSettings* settings_ = nullptr;
  const std::vector<ChainCaps>* caps_ = nullptr;
  ColumnSpans columns_;
  ChainAccumulator focusChain_, contextChain_;
  std::vector<RunSpan> runs_, activeRuns_;
  std::size_t nextRun_ = 0;
  int nextRunChange_ = 0;                     // the first column where the active runs change
  std::vector<DepthSpan> runUnion_;           // the active runs' merged spans
  std::vector<RegionInterval> runIntervals_;  // the same as output
  std::vector<DepthSpan> focus_, context_, contextLeft_, spans_;
};

void RowBuilder::build(int y, const std::vector<ViewSegment>& segments, const std::uint32_t* candidates,
                       std::size_t candidateCount, IntervalBuffer& out, std::uint32_t* rowStarts) {
  const double v = rows_.rowV(y);
  const bool slab = settings_->context == ContextShape::slab;
  runs_.clear();
  SlabCuts cuts;
  for (std::size_t n = 0; n < candidateCount; ++n) {
    const ViewSegment& segment = segments[candidates[n]];
    const bool newChain = n == 0 || segments[candidates[n - 1]].chain != segment.chain;
    if (newChain && n > 0) {
      focusChain_.flush(columns_);
      contextChain_.flush(columns_);
    }
    if (newChain && slab) cuts = slabCuts(segment.chain, v);
    addTube(segment, segment.focus, v, focusChain_, settings_->halfVessel);
    if (segment.contextTube) addTube(segment, *segment.contextTube, v, contextChain_, false);
    if (slab) addSlab(segment, v, cuts);
  }
  focusChain_.flush(columns_);
  contextChain_.flush(columns_);
  int xFirst = columns_.first(), xLast = columns_.last();
  for (const RunSpan& run : runs_) xFirst = std::min(xFirst, run.x0), xLast = std::max(xLast, run.x1);
  if (xFirst > xLast) {
    std::fill_n(rowStarts, rows_.width, std::uint32_t(out.size()));
    return;
  }
  std::fill_n(rowStarts, xFirst, std::uint32_t(out.size()));
  emitColumns(xFirst, xLast, out, rowStarts);
  std::fill_n(rowStarts + xLast + 1, rows_.width - 1 - xLast, std::uint32_t(out.size()));
  columns_.clear();
}

// Rays against the segment's piece of the tube, part by part, each only for the columns it can
// reach in this row; `cut`: the half-vessel cut, spans start at the axis depth.
void RowBuilder::addTube(const ViewSegment& segment, const Tube& tube, double v, ChainAccumulator& chain,
                         bool cut) {
  if (v < tube.vLo || v > tube.vHi) return;  // the band's other rows
  const DepthRayRoundCone::Row row = tube.cone.row(v);
  if (row.partCount == 0) return;
  // The columns of each part, and of all (columns() is monotone: the hull's are min and max).
  std::pair<int, int> partColumns[3];
  int x0 = rows_.width, x1 = -1;
  for (int p = 0; p < row.partCount; ++p) {
    partColumns[p] = rows_.columns(row.parts[p].hLo, row.parts[p].hHi);
    x0 = std::min(x0, partColumns[p].first);
    x1 = std::max(x1, partColumns[p].second);
  }
  if (x0 > x1) return;
  spans_.assign(std::size_t(x1 - x0 + 1), DepthSpan{});
  for (int p = 0; p < row.partCount; ++p) {
    const auto [first, last] = partColumns[p];
    if (first > last) continue;
    tube.cone.addPartSpans(row, row.parts[p], rows_.columnH(first), rows_.pixelMm, last - first + 1,
                           spans_.data() + (first - x0));
  }
  for (int x = x0; x <= x1; ++x) {
    DepthSpan span = spans_[std::size_t(x - x0)];
    if (span.empty()) continue;
    if (cut) span.begin = std::max(span.begin, axisDepthUnder(segment, rows_.columnH(x), v));
    if (span.end > span.begin) chain.add(x, span, columns_);
  }
}

// The columns of row v the chain's end caps take from its slab.
SlabCuts RowBuilder::slabCuts(std::size_t chain, double v) const {
  const ChainCaps& caps = (*caps_)[chain];
  const double w = settings_->slab.halfWidthMm;
  return {caps.first ? cappedColumns(rows_, *caps.first, v, w) : ColumnRange{},
          caps.last ? cappedColumns(rows_, *caps.last, v, w) : ColumnRange{}};
}

// The slab of the segment's points inside the row's band |v(s) - v| <= D/2: pixel h gets the
// depths of those with |h(s) - h| <= half width, widened by front and back. Where all of them
// are within the half width (the interior) the span is the same for every column: one run (or a
// run on each side of a cut). The chain's end caps' columns are left out.
void RowBuilder::addSlab(const ViewSegment& segment, double v, const SlabCuts& cuts) {
  const SlabContext& slab = settings_->slab;
  const double halfRow = rows_.pixelMm / 2;
  const glm::dvec3 along = segment.b - segment.a;
  SRange inRow;
  requireAtMost(inRow, along.y, v + halfRow - segment.a.y);
  requireAtMost(inRow, -along.y, segment.a.y - (v - halfRow));
  if (inRow.empty()) return;
  const glm::dvec3 p = segment.at(inRow.lo), q = segment.at(inRow.hi);
  const double hMin = std::min(p.x, q.x), hMax = std::max(p.x, q.x);
  const auto [x0, x1] = rows_.columns(hMin - slab.halfWidthMm, hMax + slab.halfWidthMm);
  auto [i0, i1] = rows_.columns(hMax - slab.halfWidthMm, hMin + slab.halfWidthMm);
  if (i0 <= i1) {
    const double begin = std::min(p.z, q.z) - slab.frontMm, end = std::max(p.z, q.z) + slab.backMm;
    forEachPieceOutside(i0, i1, cuts, [&](int first, int last) {
      runs_.push_back({first, last, begin, end});
    });
  } else {
    i0 = x1 + 1, i1 = x1;  // no interior: every column on its own
  }
  for (int x = x0; x <= x1; ++x) {
    if (x == i0) x = i1 + 1;
    if (x > x1) break;
    if (cuts[0].contains(x) || cuts[1].contains(x)) continue;
    const double h = rows_.columnH(x);
    SRange s = inRow;
    requireAtMost(s, along.x, slab.halfWidthMm + h - segment.a.x);   // h(s) - h <= w
    requireAtMost(s, -along.x, slab.halfWidthMm - h + segment.a.x);  // h - h(s) <= w
    if (s.empty()) continue;
    const double tA = segment.at(s.lo).z, tB = segment.at(s.hi).z;
    const double begin = std::min(tA, tB) - slab.frontMm, end = std::max(tA, tB) + slab.backMm;
    if (end > begin) columns_.add(Region::context, x, {begin, end});
  }
}

// Keeps activeRuns_ = the runs covering column x (runs_ sorted by x0), itself sorted by depth,
// and their union current.
void RowBuilder::advanceRuns(int x) {
  if (x < nextRunChange_) return;
  std::erase_if(activeRuns_, [x](const RunSpan& run) { return run.x1 < x; });
  for (; nextRun_ < runs_.size() && runs_[nextRun_].x0 <= x; ++nextRun_) {
    const RunSpan& run = runs_[nextRun_];
    const auto at =
        std::upper_bound(activeRuns_.begin(), activeRuns_.end(), run.begin,
                         [](double begin, const RunSpan& other) { return begin < other.begin; });
    activeRuns_.insert(at, run);
  }
  nextRunChange_ = nextRun_ < runs_.size() ? runs_[nextRun_].x0 : std::numeric_limits<int>::max();
  runUnion_.clear();
  for (const RunSpan& run : activeRuns_) {
    nextRunChange_ = std::min(nextRunChange_, run.x1 + 1);
    if (!runUnion_.empty() && run.begin <= runUnion_.back().end) {
      runUnion_.back().end = std::max(runUnion_.back().end, run.end);
    } else {
      runUnion_.push_back({run.begin, run.end});
    }
  }
  runIntervals_.resize(runUnion_.size());
  RegionInterval* end = runIntervals_.data();
  for (const DepthSpan& span : runUnion_)
    end = appendInterval(runIntervals_.data(), end, span, Region::context);
  runIntervals_.resize(std::size_t(end - runIntervals_.data()));
}

void RowBuilder::emitColumns(int xFirst, int xLast, IntervalBuffer& out, std::uint32_t* rowStarts) {
  std::sort(runs_.begin(), runs_.end(), [](const RunSpan& a, const RunSpan& b) {
    return a.x0 != b.x0 ? a.x0 < b.x0 : a.begin < b.begin;
  });
  nextRun_ = 0;
  nextRunChange_ = xFirst;
  activeRuns_.clear();
  for (int x = xFirst; x <= xLast;) {
    advanceRuns(x);
    const int nextUsed = columns_.nextUsed(x);
    if (nextUsed == x) {
      rowStarts[x] = std::uint32_t(out.size());
      emitMixed(x, out);
      ++x;
      continue;
    }
    // Columns without tube hits up to the next one or a change of runs: the runs' union alone.
    const int stop = std::min({nextUsed, nextRunChange_, xLast + 1});
    const std::size_t perColumn = runIntervals_.size(), count = std::size_t(stop - x);
    const std::uint32_t start = std::uint32_t(out.size());
    for (std::size_t column = 0; column < count; ++column) {
      rowStarts[std::size_t(x) + column] = start + std::uint32_t(column * perColumn);
    }
    RegionInterval* end = out.room(perColumn * count);
    if (perColumn == 1) {
      end = std::fill_n(end, count, runIntervals_.front());
    } else {
      for (std::size_t column = 0; column < count; ++column) {
        for (const RegionInterval& interval : runIntervals_) *end++ = interval;
      }
    }
    out.commit(end);
    x = stop;
  }
}

// A column with tube or slab-edge spans: focus wins over context, the cleft is cut, and both are
// interleaved by depth.
void RowBuilder::emitMixed(int x, IntervalBuffer& out) {
  // A ray grazing a tube can leave a span too short for float; it must neither split the context
  // nor open a cleft that the output does not show.
  focus_.clear();
  for (const DepthSpan& span : columns_.focus(x)) {
    if (!emptyInFloat(span)) focus_.push_back(span);
  }
  const SpanList& columnContext = columns_.context(x);
  // At most: every focus span, plus every context span split once by each focus span.
  RegionInterval* const first = out.room(2 * focus_.size() + runUnion_.size() +
                                         std::size_t(columnContext.end() - columnContext.begin()) + 1);
  RegionInterval* end = first;
  if (columnContext.empty() && runUnion_.empty()) {
    for (const DepthSpan& span : focus_) end = appendInterval(first, end, span, Region::focus);
    out.commit(end);
    return;
  }
  // The context: the runs' union, the column's own spans, or both merged.
  std::span<const DepthSpan> context = runUnion_;
  if (runUnion_.empty()) {
    context = {columnContext.begin(), columnContext.end()};
  } else if (!columnContext.empty()) {
    context_.assign(runUnion_.begin(), runUnion_.end());
    for (const DepthSpan& span : columnContext) insertMerged(context_, span);
    context = context_;
  }
  const double notBefore = settings_->cleft && !focus_.empty() ? focus_.front().begin : -kInfinity;
  subtract(context, focus_, notBefore, contextLeft_);
  // Both lists are sorted and disjoint from each other: merge them by begin.
  std::size_t f = 0, c = 0;
  while (f < focus_.size() || c < contextLeft_.size()) {
    const bool takeFocus =
        c == contextLeft_.size() || (f < focus_.size() && focus_[f].begin < contextLeft_[c].begin);
    const DepthSpan& span = takeFocus ? focus_[f++] : contextLeft_[c++];
    end = appendInterval(first, end, span, takeFocus ? Region::focus : Region::context);
  }
  out.commit(end);
}

// Appends a finished band to `regions` (bands arrive in order): its intervals, and its rows'
// offsets in regions.rayBegin turned from band-local into global ones.
void appendBand(const RowGeometry& rows, int band, const IntervalBuffer& buffer, RayRegions& regions) {
  const std::uint32_t base = std::uint32_t(regions.intervals.size());
  const std::size_t pixels = std::size_t(rows.width) * rows.height;
  const std::size_t pixelsPerBand = std::size_t(rows.width) * kRowsPerBand;
  std::uint32_t* begin = regions.rayBegin.data() + std::size_t(band) * pixelsPerBand;
  std::uint32_t* end =
      regions.rayBegin.data() + std::min(pixels, (std::size_t(band) + 1) * pixelsPerBand);
  for (std::uint32_t* start = begin; start != end; ++start) *start += base;
  regions.intervals.insert(regions.intervals.end(), buffer.data(), buffer.data() + buffer.size());
}

bool finiteAndNonNegative(double value) { return std::isfinite(value) && value >= 0; }

}  // namespace

double TubeRadius::at(double vesselRadiusMm) const {
  const double base = mode == RadiusMode::constant ? value : value * vesselRadiusMm;
  return std::max(0.0, base + marginMm);
}

std::optional<std::string> settingsProblem(const VesselGlyphSettings& settings) {
  const auto tubeProblem = [](const TubeRadius& tube,
                              const std::string& name) -> std::optional<std::string> {
    if (!finiteAndNonNegative(tube.value)) return name + " radius must be finite and >= 0";
    if (!std::isfinite(tube.marginMm)) return name + " margin must be finite";
    return std::nullopt;
  };
  if (auto problem = tubeProblem(settings.focus, "focus")) return problem;
  if (auto problem = tubeProblem(settings.contextTube, "context tube")) return problem;
  const SlabContext& slab = settings.slab;
  if (!finiteAndNonNegative(slab.frontMm)) return "context slab front must be finite and >= 0 mm";
  if (!finiteAndNonNegative(slab.backMm)) return "context slab back must be finite and >= 0 mm";
  if (std::isnan(slab.halfWidthMm) || slab.halfWidthMm < 0) {
    return "context slab half width must be >= 0 mm";
  }
  if (!finiteAndNonNegative(settings.unknownVesselRadiusMm)) {
    return "unknown vessel radius must be finite and >= 0 mm";
  }
  if (!finiteAndNonNegative(settings.simplifyToleranceMm)) {
    return "simplification tolerance must be finite and >= 0 mm";
  }
  return std::nullopt;
}

GlyphTubes prepareGlyphTubes(const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings) {
  if (inVolumeFrame.frame != CenterlineFrame::volume) {
    throw std::logic_error("VesselGlyph regions need centerlines in the volume frame");
  }
  if (const auto problem = settingsProblem(settings)) throw std::invalid_argument(*problem);
  GlyphTubes tubes;
  for (std::size_t n = 0; n < inVolumeFrame.paths.size(); ++n) {
    const CenterlinePath& path = inVolumeFrame.paths[n];
    tubes.sourcePoints += path.points.size();
    const std::size_t shared = sharedTrunkLength(inVolumeFrame, n);
    if (shared == path.points.size()) continue;  // all of it is in an earlier path
    // The segment from the last shared point on is this path's own.
    appendChains(path, shared > 0 ? shared - 1 : 0, settings, tubes);
  }
  for (auto& chain : tubes.chains) chain = simplified(chain, settings.simplifyToleranceMm);
  return tubes;
}

namespace {

// Band `band`'s rows into `buffer` (cleared first), their band-local offsets into rayBegin.
void buildBand(int band, const RowGeometry& rows, const std::vector<ViewSegment>& segments,
               const BandBins& bins, RowBuilder& builder, IntervalBuffer& buffer,
               std::vector<std::uint32_t>& rayBegin) {
  buffer.clear();
  buffer.room(std::size_t(rows.width) * kRowsPerBand);  // about one interval per pixel
  const std::uint32_t* candidates = bins.segments.data() + bins.first[band];
  const std::size_t candidateCount = bins.first[band + 1] - bins.first[band];
  const int yEnd = std::min(rows.height, (band + 1) * kRowsPerBand);
  for (int y = band * kRowsPerBand; y < yEnd; ++y) {
    builder.build(y, segments, candidates, candidateCount, buffer,
                  rayBegin.data() + std::size_t(y) * rows.width);
  }
}

// What the per-view work keeps from view to view: the bands' intervals and a row builder per thread.
struct BuildScratch {
  std::vector<IntervalBuffer> bands;
  tbb::enumerable_thread_specific<RowBuilder> builders;
};

// The per-view work, into `out` (both reused if they have room).
void buildInto(const ViewGeometry& view, const GlyphTubes& tubes, const VesselGlyphSettings& settings,
               RayRegions& out, BuildScratch& scratch) {
  std::vector<IntervalBuffer>& bands = scratch.bands;
  if (const auto problem = settingsProblem(settings)) throw std::invalid_argument(*problem);
  const RowGeometry rows{view.width, view.height, view.pixelMm};
  const std::vector<ViewSegment> segments = viewSegments(view, tubes, settings);
  const std::vector<ChainCaps> caps = slabCaps(view, tubes, settings);
  const int bandCount = (rows.height + kRowsPerBand - 1) / kRowsPerBand;
  const BandBins bins = binByBand(segments, rows, settings, bandCount);
  out.width = rows.width;
  out.height = rows.height;
  out.rayBegin.resize(std::size_t(rows.width) * rows.height + 1);
  out.intervals.clear();
  // A pipeline: bands are built in parallel, each into a buffer of its own, and appended to `out`
  // in order as soon as they are done, while their intervals are still in cache (appending them
  // all at the end would read them back from memory). Band n's buffer is n % tokens: at most
  // `tokens` bands are in flight and they leave in order, so band n + tokens starts after n has
  // left.
  const int tokens = 4 * tbb::this_task_arena::max_concurrency();
  bands.resize(std::size_t(tokens));
  int nextBand = 0;
  tbb::parallel_pipeline(
      std::size_t(tokens),
      tbb::make_filter<void, int>(tbb::filter_mode::serial_in_order, [&](tbb::flow_control& control) {
        if (nextBand == bandCount) control.stop();
        return nextBand++;
      }) & tbb::make_filter<int, int>(tbb::filter_mode::parallel, [&](int band) {
        RowBuilder& builder = scratch.builders.local();
        builder.startView(rows, settings, caps);
        buildBand(band, rows, segments, bins, builder, bands[std::size_t(band % tokens)], out.rayBegin);
        return band;
      }) & tbb::make_filter<int, void>(tbb::filter_mode::serial_in_order, [&](int band) {
        appendBand(rows, band, bands[std::size_t(band % tokens)], out);
      }));
  out.rayBegin.back() = std::uint32_t(out.intervals.size());
}

}  // namespace

RayRegions buildRayRegions(const ViewGeometry& view, const GlyphTubes& tubes,
                           const VesselGlyphSettings& settings) {
  RayRegions regions;
  BuildScratch scratch;
  buildInto(view, tubes, settings, regions, scratch);
  return regions;
}

struct RayRegionBuilder::Scratch : BuildScratch {};

RayRegionBuilder::RayRegionBuilder(const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings)
    : settings_(settings), tubes_(prepareGlyphTubes(inVolumeFrame, settings)),
      scratch_(std::make_unique<Scratch>()) {}

RayRegionBuilder::~RayRegionBuilder() = default;
RayRegionBuilder::RayRegionBuilder(RayRegionBuilder&&) noexcept = default;
RayRegionBuilder& RayRegionBuilder::operator=(RayRegionBuilder&&) noexcept = default;

void RayRegionBuilder::build(const ViewGeometry& view, RayRegions& out) {
  buildInto(view, tubes_, settings_, out, *scratch_);
}

RayRegions buildRayRegions(const Volume& volume, const ViewGeometry& view,
                           const Centerlines& inVolumeFrame, const VesselGlyphSettings& settings) {
  const glm::dvec3 extent = domainExtent(volume);
  if (glm::any(glm::greaterThan(glm::abs(extent - view.extent),
                                glm::dvec3(1e-9 * (1 + glm::length(extent)))))) {
    throw std::invalid_argument("VesselGlyph: the view was made for another volume");
  }
  return buildRayRegions(view, prepareGlyphTubes(inVolumeFrame, settings), settings);
}

}  // namespace angio
