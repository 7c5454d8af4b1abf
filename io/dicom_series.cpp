#include "io/dicom_series.h"

#include <algorithm>
#include <functional>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <itkGDCMImageIO.h>

#include "io/dicom_file_walk.h"
#include "io/shown_text.h"
#include "io/dicom_slice_check.h"
#include "io/input_error.h"
#include "io/slices_in_child.h"
#include "io/volume_conversion.h"
#include "io/volume_formats.h"
#include "io/volume_memory.h"

namespace angio {

namespace {

struct Series {
  std::string uid;
  std::vector<std::string> files;
};

// One slice's header: where it sits (from checkDicomSlice, before any pixel is read).
struct Slice {
  std::string file;
  DicomSliceTags tags;
  double along = 0.0;  // position along the slice normal
};

// A UID as the user reads it in a message (it comes from the file: printable characters only).
std::string shownUid(const std::string& uid) {
  return uid.empty() ? "(no SeriesInstanceUID)" : shownText(uid);
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// "12.5", "15.0": two decimals at most, one at least.
std::string millimetres(double value) {
  char text[48];
  std::snprintf(text, sizeof text, "%.2f", value);
  std::string s = text;
  while (s.size() > 1 && s.back() == '0' && s[s.size() - 2] != '.') s.pop_back();
  return s == "-0.0" ? "0.0" : s;
}

// The image files of the folder grouped by SeriesInstanceUID alone (a series that mixes
// orientations or sizes is reported as such later instead of being split silently), from our own
// walk of every file: GDCM's series scan would read each file whole, and assert on damaged ones.
// Files that are not DICOM, and DICOM files without pixel data (a DICOMDIR, a report), are skipped.
std::vector<Series> seriesInFolder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.is_regular_file(error)) files.push_back(entry.path());
  if (error) throw InputError(folder, "cannot list the folder: " + error.message());
  std::sort(files.begin(), files.end());
  std::vector<Series> all;
  for (const std::filesystem::path& file : files) {
    const std::optional<DicomFileFacts> facts = walkDicomFile(folder, file);
    if (!facts || !facts->hasPixelData) continue;
    const auto known = std::find_if(
        all.begin(), all.end(), [&](const Series& series) { return series.uid == facts->seriesUid; });
    if (known == all.end()) all.push_back({facts->seriesUid, {file.string()}});
    else known->files.push_back(file.string());
  }
  return all;
}

Series chooseSeries(const std::filesystem::path& folder, const ReadOptions& options) {
  std::vector<Series> all = seriesInFolder(folder);
  if (all.empty()) throw InputError(folder, "no DICOM series found in the folder");
  std::stable_sort(all.begin(), all.end(),
                   [](const Series& a, const Series& b) { return a.files.size() > b.files.size(); });
  if (all.size() > 1 && options.warn) {
    std::ostringstream text;
    text << folder.string() << ": " << all.size() << " DICOM series in the folder; loading "
         << shownUid(all[0].uid) << " (" << all[0].files.size() << " slices), ignoring";
    for (std::size_t n = 1; n < all.size(); ++n)
      text << (n > 1 ? ", " : " ") << shownUid(all[n].uid) << " (" << all[n].files.size() << " slices)";
    options.warn(text.str());
  }
  return all.front();
}

itk::GDCMImageIO::Pointer readSliceHeader(const std::filesystem::path& folder, const std::string& file) {
  checkDicomSlice(folder, file, true);  // before GDCM sees a tag it would assert on
  auto io = itk::GDCMImageIO::New();
  io->SetFileName(file);
  io->ReadImageInformation();
  if (io->GetNumberOfComponents() != 1)
    throw InputError(folder, "slice " + fileName(file) + " is not greyscale; need CT slices");
  if (io->GetDimensions(2) != 1)
    throw InputError(folder,
                     "slice " + fileName(file) + " is a multi-frame image inside a series of slices");
  return io;
}

// Reads a slice's pixels (rescale slope/intercept applied by GDCM) as encoded voxels into `out`
// (columns x rows of them); returns the NaN/Inf pixel values (float pixel data) it met.
std::size_t readSlicePixels(const std::filesystem::path& folder, const std::string& file,
                            glm::ivec2 size, std::vector<double>& scratch, Voxel* out) {
  const itk::GDCMImageIO::Pointer io = readSliceHeader(folder, file);
  if (int(io->GetDimensions(0)) != size.x || int(io->GetDimensions(1)) != size.y)
    throw InputError(folder, "slice " + fileName(file) + " changed while it was read");
  scratch.resize((io->GetImageSizeInBytes() + sizeof(double) - 1) / sizeof(double));
  io->Read(scratch.data());
  const int voxels = size.x * size.y;
  return withComponentType(io->GetComponentType(), [&](auto type) {
    using T = typename decltype(type)::type;
    return HuToVoxels{}(reinterpret_cast<const T*>(scratch.data()), 1, voxels, out);
  });
}

glm::dvec3 sliceNormal(const std::filesystem::path& folder, const Slice& slice) {
  const glm::dvec3 normal = glm::cross(slice.tags.row, slice.tags.column);
  const double length = glm::length(normal);
  if (!(length > 0.5))  // the cosines should be orthonormal; tolerate rounding only
    throw InputError(folder,
                     "slice " + fileName(slice.file) + " has an invalid ImageOrientationPatient");
  return normal / length;
}

void requireSameOrientationAndSize(const std::filesystem::path& folder,
                                   const std::vector<Slice>& slices) {
  const Slice& first = slices.front();
  for (const Slice& slice : slices) {
    const double difference = std::max(glm::length(slice.tags.row - first.tags.row),
                                       glm::length(slice.tags.column - first.tags.column));
    if (difference > 1e-3)
      throw InputError(folder, "mixed slice orientations in one series (" + fileName(first.file) +
                                   " vs " + fileName(slice.file) + ")");
    if (slice.tags.rows != first.tags.rows || slice.tags.columns != first.tags.columns)
      throw InputError(folder, "slices of different sizes in one series (" + fileName(first.file) +
                                   " vs " + fileName(slice.file) + ")");
  }
}

// The LPS coordinate (x, y or z) a slice normal runs along, for messages.
int dominantAxis(glm::dvec3 normal) {
  const glm::dvec3 a = glm::abs(normal);
  return a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
}

// Slices of a tilted gantry are stacked along a direction off their normal (sheared). Placing them
// along the normal would move the far slices sideways by the drift; refused when that is more than
// half a pixel, as resampling the shear onto a straight grid is not done here.
void requireUnsheared(const std::filesystem::path& folder, const std::vector<Slice>& slices,
                      glm::dvec3 normal) {
  const glm::dvec3 offset = slices.back().tags.position - slices.front().tags.position;
  const double along = glm::dot(offset, normal);
  const double sideways = glm::length(offset - along * normal);
  const double pixel = std::min(slices.front().tags.pixelSpacing.x, slices.front().tags.pixelSpacing.y);
  if (sideways <= 0.5 * pixel) return;
  const double tiltDeg = glm::degrees(std::atan2(sideways, std::abs(along)));
  throw InputError(folder, "slices are sheared (gantry tilt of " + millimetres(tiltDeg) +
                               " degrees: they drift " + millimetres(sideways) + " mm sideways over " +
                               millimetres(std::abs(along)) +
                               " mm); tilted series are not resampled, reconstruct it without tilt");
}

double uniformSpacing(const std::filesystem::path& folder, const std::vector<Slice>& slices,
                      glm::dvec3 normal) {
  std::vector<double> along;
  for (const Slice& slice : slices) along.push_back(slice.along);
  std::vector<double> missing;
  try {
    missing = missingSlicePositions(along);
  } catch (const std::invalid_argument& problem) {
    throw InputError(folder, problem.what());
  }
  if (!missing.empty()) {
    const int axis = dominantAxis(normal);
    std::string list;
    const std::size_t shown = std::min<std::size_t>(missing.size(), 10);
    for (std::size_t n = 0; n < shown; ++n) {
      const glm::dvec3 point = slices.front().tags.position + normal * (missing[n] - along.front());
      list += (n ? ", " : "") + millimetres(point[axis]);
    }
    if (shown < missing.size()) list += ", ... (" + std::to_string(missing.size()) + " in all)";
    throw InputError(
        folder, std::string("gap in slice positions: missing ") + "xyz"[axis] + " = " + list + " mm");
  }
  return (along.back() - along.front()) / double(along.size() - 1);
}

}  // namespace

std::vector<double> missingSlicePositions(const std::vector<double>& sorted) {
  if (sorted.size() < 2) return {};
  std::vector<double> steps;
  for (std::size_t n = 1; n < sorted.size(); ++n) steps.push_back(sorted[n] - sorted[n - 1]);
  const double smallest = *std::min_element(steps.begin(), steps.end());
  if (smallest < 1e-3) {
    const std::size_t at = std::min_element(steps.begin(), steps.end()) - steps.begin();
    throw std::invalid_argument("two slices at the same position (" + millimetres(sorted[at]) +
                                " mm along the slice normal)");
  }
  // The common step: the median of the steps near the smallest (missing slices make larger ones).
  std::vector<double> common;
  for (double step : steps)
    if (step <= 1.5 * smallest) common.push_back(step);
  std::nth_element(common.begin(), common.begin() + common.size() / 2, common.end());
  const double base = common[common.size() / 2];
  const double tolerance = 0.05 * base;  // scanners jitter by far less than this
  std::vector<double> missing;
  for (std::size_t n = 0; n < steps.size(); ++n) {
    const double multiple = std::round(steps[n] / base);
    if (multiple < 1 || std::abs(steps[n] - multiple * base) > tolerance * multiple)
      throw std::invalid_argument("non-uniform slice spacing: step of " + millimetres(steps[n]) +
                                  " mm after " + millimetres(sorted[n]) + " mm (common step " +
                                  millimetres(base) + " mm)");
    for (int t = 1; t < int(multiple); ++t) missing.push_back(sorted[n] + t * steps[n] / multiple);
  }
  return missing;
}

DicomSeries scanDicomSeries(const std::filesystem::path& folder, const ReadOptions& options) {
  try {
    const Series series = chooseSeries(folder, options);
    if (series.files.size() < 2)
      throw InputError(folder, "the DICOM series has a single slice; need a 3-D volume");
    // Every slice's header first: a series that cannot be stacked is refused before any pixel
    // is read, and the pixels then go straight to their place.
    std::vector<Slice> slices;
    for (const std::string& file : series.files) {
      slices.push_back({file, checkDicomSlice(folder, file, true)});
      if (options.progress) options.progress(0.1 * double(slices.size()) / double(series.files.size()));
    }
    requireSameOrientationAndSize(folder, slices);
    const glm::dvec3 normal = sliceNormal(folder, slices.front());
    for (Slice& slice : slices) slice.along = glm::dot(slice.tags.position, normal);
    std::sort(slices.begin(), slices.end(),
              [](const Slice& a, const Slice& b) { return a.along < b.along; });
    requireUnsheared(folder, slices, normal);

    DicomSeries result;
    const DicomSliceTags& first = slices.front().tags;
    VolumeGeometry& geometry = result.geometry;
    geometry.dims = {first.columns, first.rows, int(slices.size())};
    geometry.spacing = {first.pixelSpacing.x, first.pixelSpacing.y,
                        uniformSpacing(folder, slices, normal)};
    geometry.origin = first.position;
    geometry.direction = glm::dmat3(glm::normalize(first.row), glm::normalize(first.column), normal);
    for (const Slice& slice : slices) result.files.push_back(slice.file);
    result.study = slices.front().tags.study;
    result.compressed = std::any_of(slices.begin(), slices.end(),
                                    [](const Slice& slice) { return slice.tags.encapsulated; });
    result.description =
        "DICOM series " + shownUid(series.uid) + " (" + std::to_string(slices.size()) + " slices)";
    return result;
  } catch (const itk::ExceptionObject& error) {
    throw InputError(folder, "cannot read the DICOM series: " + oneLine(error));
  }
}

std::size_t readDicomSlices(const std::filesystem::path& folder, const DicomSeries& series,
                            const std::function<void(int, const Voxel*)>& slice,
                            const ReadOptions& options) {
  const glm::ivec3 dims = series.geometry.dims;
  std::vector<double> scratch;
  const SliceDecode decode = [&](int k, Voxel* voxels) {
    try {
      return readSlicePixels(folder, series.files[k], dims, scratch, voxels);
    } catch (const itk::ExceptionObject& error) {
      throw InputError(folder, "cannot read the DICOM series: " + oneLine(error));
    }
  };
  const SliceTake take = [&](int k, const Voxel* voxels) {
    slice(k, voxels);
    if (options.progress) options.progress(0.1 + 0.85 * double(k + 1) / double(dims.z));
  };
  if (series.compressed)
    return decodeSlicesInChild(folder, series.files, std::size_t(dims.x) * dims.y, decode, take);
  std::vector<Voxel> voxels(std::size_t(dims.x) * dims.y);
  std::size_t nonFinite = 0;
  for (int k = 0; k < dims.z; ++k) {
    nonFinite += decode(k, voxels.data());
    take(k, voxels.data());
  }
  return nonFinite;
}

}  // namespace angio
