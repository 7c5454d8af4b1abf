// `angioray info`: what a clinician or engineer checks first about a dataset.
#include <cstdio>
#include <functional>

#include "io/input_error.h"
#include "cli/load_volume.h"
#include "cli/commands.h"
#include "cli/progress_line.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"

namespace angio {

namespace {

// The smallest HU at or below which `fraction` of the voxels lie.
double percentileHu(const DensityHistogram& counts, std::uint64_t total, double fraction) {
  std::uint64_t seen = 0;
  for (int d = 0; d < kDensityLevels; ++d) {
    seen += counts[d];
    if (double(seen) >= fraction * double(total)) return huOfDensity(d);
  }
  return huOfDensity(kDensityLevels - 1);
}

double fractionInHuRange(const DensityHistogram& counts, std::uint64_t total, int loHu, int hiHu) {
  std::uint64_t inside = 0;
  for (int d = densityOfHu(loHu); d <= densityOfHu(hiHu); ++d) inside += counts[d];
  return 100.0 * double(inside) / double(total);
}

void printVisibleFraction(const DensityHistogram& counts, std::uint64_t total,
                          const std::string& tfName) {
  const TransferFunction tf = loadPresetOrFile(tfName);
  const TfTable table = buildTable(tf);
  std::uint64_t visible = 0;
  for (int d = 0; d < kDensityLevels; ++d) visible += table.rgba[d].a > 0.f ? counts[d] : 0;
  std::printf("visible:     %.2f%% of voxels under \"%s\"\n", 100.0 * double(visible) / double(total),
              tf.name.c_str());
}

void printHistogramSummary(const Volume& volume, const std::string& tfName) {
  const DensityHistogram counts = densityHistogram(volume);
  const std::uint64_t total = volume.voxelCount();
  const DensityRange range = densityRange(volume);
  std::printf("HU range:    %.0f .. %.0f\n", huOfDensity(range.minDensity),
              huOfDensity(range.maxDensity));
  std::printf("percentiles: 1%% %.0f, 50%% %.0f, 99%% %.0f, 99.9%% %.0f HU\n",
              percentileHu(counts, total, 0.01), percentileHu(counts, total, 0.5),
              percentileHu(counts, total, 0.99), percentileHu(counts, total, 0.999));
  std::printf(
      "classes:     air < -900: %.1f%%, fat/soft -200..150: %.1f%%, "
      "contrast 150..600: %.2f%%, calcium/bone > 700: %.2f%%\n",
      fractionInHuRange(counts, total, -1024, -901), fractionInHuRange(counts, total, -200, 150),
      fractionInHuRange(counts, total, 151, 600), fractionInHuRange(counts, total, 701, 3071));
  if (!tfName.empty()) printVisibleFraction(counts, total, tfName);
}

}  // namespace

int runInfo(const InfoOptions& options) {
  if (!options.tf.empty()) loadPresetOrFile(options.tf);  // a bad TF fails before anything is printed
  const LoadedVolume loaded = loadVolumeWithProgress(options.volume, options.labels);
  const Volume& v = loaded.volume;
  std::printf("file:        %s\n", options.volume.c_str());
  std::printf("format:      %s\n", loaded.description.c_str());
  std::printf("dimensions:  %d x %d x %d voxels (i, j, k = L, P, S)\n", v.dims.x, v.dims.y, v.dims.z);
  std::printf("spacing:     %.6g x %.6g x %.6g mm\n", v.spacing.x, v.spacing.y, v.spacing.z);
  std::printf("extent:      %.1f x %.1f x %.1f mm\n", v.dims.x * v.spacing.x, v.dims.y * v.spacing.y,
              v.dims.z * v.spacing.z);
  std::printf("origin:      (%.3f, %.3f, %.3f) mm LPS\n", v.origin.x, v.origin.y, v.origin.z);
  const glm::dmat3& d = v.direction;
  std::printf("direction:   [%.4f %.4f %.4f; %.4f %.4f %.4f; %.4f %.4f %.4f] (columns i, j, k)\n",
              d[0][0], d[0][1], d[0][2], d[1][0], d[1][1], d[1][2], d[2][0], d[2][1], d[2][2]);
  std::printf("memory:      %.1f MiB (16-bit voxels)\n", v.voxelCount() * 2.0 / (1 << 20));
  printHistogramSummary(v, options.tf);
  return 0;
}

}  // namespace angio
