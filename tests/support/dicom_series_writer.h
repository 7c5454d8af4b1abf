#pragma once
// Writing small CT series as DICOM slices (GDCM through ITK) for the readers' and the app's tests:
// 16x16 slices with a rescale, positions, shuffled file names and instance numbers, and any tags.
#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <itkGDCMImageIO.h>
#include <itkImage.h>
#include <itkImageFileWriter.h>
#include <itkMetaDataObject.h>

namespace angio::test_support {

struct DicomSlice {
  std::string fileName;
  glm::dvec3 position{0.0};  // ImagePositionPatient
  int instanceNumber = 0;
  std::string seriesUid = "1.2.826.0.1.3680043.2.1125.777.1";
  std::string orientation = "1\\0\\0\\0\\1\\0";
  std::function<short(int, int)> hu;        // real-world HU at column i, row j
  std::map<std::string, std::string> tags;  // more, e.g. the patient's
};

// Writes a 16x16 CT slice with rescale slope 2, intercept -1024 (stored = (HU + 1024) / 2).
inline void writeDicomSlice(const std::filesystem::path& folder, const DicomSlice& slice) {
  using Slice = itk::Image<short, 2>;
  auto image = Slice::New();
  Slice::RegionType region;
  region.SetSize(0, 16);
  region.SetSize(1, 16);
  image->SetRegions(region);
  Slice::SpacingType spacing;
  spacing[0] = spacing[1] = 0.7;
  image->SetSpacing(spacing);
  image->Allocate();
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) image->SetPixel({{i, j}}, slice.hu(i, j));
  itk::MetaDataDictionary& tags = image->GetMetaDataDictionary();
  const auto set = [&](const char* tag, const std::string& value) {
    itk::EncapsulateMetaData<std::string>(tags, tag, value);
  };
  set("0008|0016", "1.2.840.10008.5.1.4.1.1.2");  // CT Image Storage
  set("0008|0018", slice.seriesUid + "." + std::to_string(slice.instanceNumber));
  set("0008|0060", "CT");
  set("0028|0004", "MONOCHROME2");
  set("0020|000d", "1.2.826.0.1.3680043.2.1125.777");
  set("0020|000e", slice.seriesUid);
  set("0020|0052", "1.2.826.0.1.3680043.2.1125.777.9");
  set("0020|0013", std::to_string(slice.instanceNumber));
  set("0020|0032", std::to_string(slice.position.x) + "\\" + std::to_string(slice.position.y) + "\\" +
                       std::to_string(slice.position.z));
  set("0020|0037", slice.orientation);
  set("0028|1052", "-1024");
  set("0028|1053", "2");
  for (const auto& [tag, value] : slice.tags) set(tag.c_str(), value);
  auto io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn();
  auto writer = itk::ImageFileWriter<Slice>::New();
  writer->SetImageIO(io);
  writer->SetFileName((folder / slice.fileName).string());
  writer->SetInput(image);
  writer->Update();
}

// HU of slice k at (i, j): even values, so the slope-2 rescale round-trips exactly.
inline short sliceHu(int k, int i, int j) { return short(100 * k - 300 + 2 * i + 40 * (j == 0)); }

// Slices at z = 5 + 2.5 k for k in `positions`, with shuffled file names and instance numbers.
inline void writeDicomSeries(const std::filesystem::path& folder, const std::vector<int>& positions,
                             const std::string& uid, unsigned seed,
                             const std::map<std::string, std::string>& tags = {}) {
  std::vector<int> names(positions.size()), instances(positions.size());
  std::iota(names.begin(), names.end(), 0);
  std::iota(instances.begin(), instances.end(), 1);
  std::mt19937 random(seed);
  std::shuffle(names.begin(), names.end(), random);
  std::shuffle(instances.begin(), instances.end(), random);
  for (std::size_t n = 0; n < positions.size(); ++n) {
    const int k = positions[n];
    DicomSlice slice;
    slice.fileName = "IM" + std::to_string(names[n]) + "-" + uid.substr(uid.size() - 1) + ".dcm";
    slice.position = {-12.0, 30.5, 5.0 + 2.5 * k};
    slice.instanceNumber = instances[n];
    slice.seriesUid = uid;
    slice.hu = [k](int i, int j) { return sliceHu(k, i, j); };
    slice.tags = tags;
    writeDicomSlice(folder, slice);
  }
}

}  // namespace angio::test_support
