#pragma once
// The geometry of a curved planar reformation (CPR): which point of the volume each CPR pixel
// shows. Kanitsar et al., "CPR - Curved Planar Reformation", IEEE Vis 2002, sec. 3; thesis
// sec. 1.3.2 and 5.2.2. Everything is in the volume frame (mm; vessel/centerline.h): pass
// centerlines through toVolumeFrame first.
//
// Every CPR row is sampled along straight lines (Kanitsar's "line of interest"), so a layout is a
// list of spans: pixel x of span [x0, x1) in row `row` shows originMm + x * stepMm. The three
// projections differ only in where the lines go (D = pixel size, r / e_a / d / P0 = the view's
// image right, up, viewing direction and domain centre; core/view_geometry.h):
//
// - projected: the surface swept by the image-horizontal r through the centerline, seen in the
//   view's parallel projection. The image is the DVR image (W x H, same D); row y is the plane
//   v = (H/2 - y - 0.5) D. Where a path crosses that plane at point P (image column
//   x_P = dot(P - P0, r) / D + W/2 - 0.5), the row shows P + (x - x_P) D r: exactly the point
//   at P's depth on the ray of pixel (x, y), so the CPR registers pixel for pixel with the DVR.
//   A row crossed more than once (the vessel turns back, or several paths) is split between the
//   crossings at the midpoints in x: each pixel shows the crossing nearest to it in the image
//   (Kanitsar's multi-path rule). Rows no path crosses stay empty.
// - stretched: the same surface, developed into the plane (it is a cylinder with rulings along r,
//   so the development is isometric): columns keep the projected image's h (column x is DVR
//   column x + columnOffset), and rows advance by the centerline's length orthogonal to r,
//   sigma = integral |c' - (c' . r) r| ds, row y at sigma = (y + 0.5) D. A centerline without a
//   component along r (e.g. one that runs along the image's up axis) has sigma = arc length, so
//   the image is arc length / D rows high; in general the centerline drawn in the image keeps its
//   true length. Rows are split between crossings as in the projected CPR, so all paths of a tree
//   share one image and the trunk (the same points in every path) is drawn once.
// - straightened: the centerline straight down the image's centre column, row y at arc length
//   s = (y + 0.5) D (clamped to the path's end) from the path's first point, columns along the
//   vector of interest v(s): c(s) + (x - x_c) D v(s). v comes from a rotation-minimising frame
//   (double reflection, Wang et al., ACM TOG 27(1) 2008) started from the view's r at angle 0
//   (e_b, projected normal to the first tangent) and turned about the tangent by the view angle,
//   so v = r for a vessel along the up axis and rotating the view rotates the CPR without twist.
//   Several paths: one panel of `width` per path side by side; rows where paths still share their
//   trunk are one span across their panels, the centerline in their middle column (the tree
//   reads as a "Y").
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/view_geometry.h"
#include "vessel/centerline.h"

namespace angio {

enum class CprMode { projected, stretched, straightened };

const char* toString(CprMode mode);
std::optional<CprMode> parseCprMode(const std::string& text);

// Straightened: image width; stretched: the margin around the centerline's columns (width / 2 on
// each side); projected: if set, only pixels within width / 2 of a crossing are sampled.
constexpr double kDefaultCprWidthMm = 60;
// More pixels than this is a mistake (a tiny --pixel): an error, not an allocation failure.
constexpr long kMaxCprPixels = 64L * 1024 * 1024;

// A problem with the centerline paths themselves (the caller can name their file); other bad
// input (width, pixel size) is a plain std::invalid_argument.
class CprPathError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct CprSettings {
  CprMode mode = CprMode::straightened;
  std::optional<double> widthMm;  // default: kDefaultCprWidthMm, or whole rows for projected
};

// Pixels [x0, x1) of row `row` show originMm + x * stepMm (volume frame, mm). Spans are clipped to
// the volume's domain box, so every pixel of a span is a point inside it.
struct CprSpan {
  int row = 0;
  int x0 = 0;
  int x1 = 0;
  glm::dvec3 originMm{0.0};
  glm::dvec3 stepMm{0.0};
  int path = 0;        // the path whose centerline this line passes through
  double centreX = 0;  // the image column (continuous) where it passes the centerline
  double arcMm = 0;    // arc length of that centerline point from the path's first point

  glm::dvec3 pointMm(int x) const { return originMm + double(x) * stepMm; }
};

// A path's centerline in image coordinates (x right, y down, pixel centres at integers) with the
// arc length (mm from the path's first point) at each vertex: the marker line and ruler. Where a
// path shares its trunk with an earlier path, its curve starts at the end of the shared part.
struct CprCurve {
  int path = 0;
  std::vector<glm::dvec2> pixels;
  std::vector<double> arcMm;
};

struct CprLayout {
  CprMode mode = CprMode::straightened;
  int width = 0;
  int height = 0;
  double pixelMm = 0;          // D, along rows and columns
  int columnOffset = 0;        // stretched: image column 0 is this column of the DVR image
  double widthMm = 0;          // the lateral extent used (straightened: a panel's width, odd pixels)
  std::vector<CprSpan> spans;  // row by row
  std::vector<CprCurve> curves;
  std::vector<std::string> warnings;  // one line each, naming the path
};

// The layout of a CPR of `paths` (volume frame) for the view. Throws CprPathError with a one-line
// message naming the path for: no paths, a path with fewer than 2 points or zero length,
// non-finite coordinates, a path entirely outside the volume; std::invalid_argument for a bad
// width or pixel size or an image of more than kMaxCprPixels. Paths partly outside the volume
// give a warning; the CPR is clipped to the volume (pixels outside it are not sampled).
CprLayout layoutCpr(const std::vector<CenterlinePath>& paths, const ViewGeometry& view,
                    const CprSettings& settings);

// The rotation-minimising frame's normals at `points` (double reflection), starting from
// `initialNormal` (made orthogonal to the first tangent). Tangents must be unit vectors.
std::vector<glm::dvec3> rotationMinimizingNormals(const std::vector<glm::dvec3>& points,
                                                  const std::vector<glm::dvec3>& tangents,
                                                  glm::dvec3 initialNormal);

// The paths a "--path" selection names: "all", or one index. Throws CprPathError naming the index
// and how many paths there are.
std::vector<CenterlinePath> selectPaths(const Centerlines& centerlines, const std::string& which);

}  // namespace angio
