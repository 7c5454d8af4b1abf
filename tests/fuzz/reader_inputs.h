#pragma once
// How each fuzz target hands its input to a reader, shared by the targets (tests/fuzz/fuzz_*.cpp)
// and the tests that replay saved crashers (tests/io/fuzz_regression_test.cpp), so both read the
// bytes the same way. A reader of text gets the bytes and a made-up file name; one that takes a
// path gets the bytes written to a file of that name in `scratch`, a folder the caller owns.
// A reader must return or throw an std::exception whose message is one line naming the input
// (readerMessageProblem); its warnings must be one line each.
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "io/centerline_csv.h"
#include "io/centerline_markups.h"
#include "io/centerline_vtp.h"
#include "io/metaimage_header.h"
#include "io/nifti_header.h"
#include "io/tf_file.h"
#include "io/volume_reader.h"
#include "render/recipe_json.h"
#include "tests/fuzz/gdcm_agreement.h"
#include "tests/fuzz/metaio_agreement.h"
#include "tests/fuzz/nifti_agreement.h"
#include "tests/fuzz/teem_agreement.h"

namespace angio::fuzz {

struct FuzzInput {
  std::string bytes;
  std::filesystem::path scratch;      // an existing folder the reader's files may be written to
  std::vector<std::string> warnings;  // what the reader warned about
  std::vector<std::string>
      caughtErrors;  // messages of errors caught on the way (checked as thrown ones)
};

struct ReaderTarget {
  const char* name;       // the target: fuzz_<name>, corpus and regression folders <name>/
  const char* inputName;  // the file or folder the input becomes; error messages must name it
  void (*read)(FuzzInput& input);
};

// Separates the slices of a dicom_series input (the files of the folder, in order).
constexpr std::string_view kSliceSeparator = "\n--angioray-next-slice--\n";
constexpr int kMaxSeriesSlices = 16;
// The voxel file every volume_mhd input may name (ElementDataFile = input.raw): 8x8x4 int16.
constexpr std::size_t kMhdRawBytes = 8 * 8 * 4 * 2;

inline std::filesystem::path writeInputFile(const std::filesystem::path& file, std::string_view bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), std::streamsize(bytes.size()));
  return file;
}

inline CenterlineLoadOptions collectingCenterlineWarnings(FuzzInput& input) {
  return {[&input](const std::string& warning) { input.warnings.push_back(warning); }};
}

inline ReadOptions collectingReadWarnings(FuzzInput& input) {
  ReadOptions options;
  options.warn = [&input](const std::string& warning) { input.warnings.push_back(warning); };
  return options;
}

inline void readVolumeFile(FuzzInput& input, const char* name) {
  readVolume(writeInputFile(input.scratch / name, input.bytes), collectingReadWarnings(input));
}

// An empty folder `name` in the scratch folder.
inline std::filesystem::path emptyFolder(const FuzzInput& input, const char* name) {
  const std::filesystem::path folder = input.scratch / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

inline const ReaderTarget kIoReaderTargets[] = {
    {"tf", "input.json", [](FuzzInput& input) { parseTransferFunction(input.bytes, "input.json"); }},
    {"centerline_csv", "input.csv",
     [](FuzzInput& input) {
       parseCenterlinesCsv(input.bytes, "input.csv", collectingCenterlineWarnings(input));
     }},
    {"centerline_vtp", "input.vtp",
     [](FuzzInput& input) {
       parseCenterlinesVtp(input.bytes, "input.vtp", collectingCenterlineWarnings(input));
     }},
    {"centerline_markups", "input.mrk.json",
     [](FuzzInput& input) {
       parseCenterlinesMarkups(input.bytes, "input.mrk.json", collectingCenterlineWarnings(input));
     }},
    {"render_sidecar", "input.png.json",
     [](FuzzInput& input) { parseRenderSidecar(input.bytes, "input.png.json"); }},
    {"metaimage_header", "input.mhd",
     [](FuzzInput& input) {
       writeInputFile(input.scratch / "input.raw", std::string(kMhdRawBytes, '\0'));  // as volume_mhd's
       const std::filesystem::path file = writeInputFile(input.scratch / "input.mhd", input.bytes);
       requireMetaIoAgrees(file, readMetaImageHeader(file));
     }},
    {"nifti_header", "input.nii",
     [](FuzzInput& input) {
       const std::filesystem::path file = writeInputFile(input.scratch / "input.nii", input.bytes);
       if (const auto header = readNiftiHeader(file)) requireNiftiLibraryAgrees(file, *header);
     }},
    {"volume_mha", "input.mha", [](FuzzInput& input) { readVolumeFile(input, "input.mha"); }},
    {"volume_mhd", "input.mhd",
     [](FuzzInput& input) {
       std::string raw(kMhdRawBytes, '\0');
       for (std::size_t n = 0; n < raw.size(); ++n) raw[n] = char(n * 7);
       writeInputFile(input.scratch / "input.raw", raw);
       readVolumeFile(input, "input.mhd");
     }},
    {"volume_nrrd", "input.nrrd",
     [](FuzzInput& input) {
       requireTeemAgrees(writeInputFile(input.scratch / "input.nrrd", input.bytes));
       readVolumeFile(input, "input.nrrd");
     }},
    {"volume_nii", "input.nii", [](FuzzInput& input) { readVolumeFile(input, "input.nii"); }},
    // One slice as a file (the header checks) and as a folder of one (the series reader).
    {"dicom_slice", "input",
     [](FuzzInput& input) {
       const std::filesystem::path folder = emptyFolder(input, "input-slice");
       const std::filesystem::path file = writeInputFile(folder / "input.dcm", input.bytes);
       requireGdcmAgrees(file);
       try {
         readVolume(file, collectingReadWarnings(input));
       } catch (const std::exception& error) {
         input.caughtErrors.push_back(error.what());  // expected: a slice is not a volume
       }
       readVolume(folder, collectingReadWarnings(input));
     }},
    {"dicom_series", "input-series",
     [](FuzzInput& input) {
       const std::filesystem::path folder = emptyFolder(input, "input-series");
       std::string_view rest = input.bytes;
       for (int slice = 0; slice < kMaxSeriesSlices && !rest.empty(); ++slice) {
         const std::size_t end = rest.find(kSliceSeparator);
         writeInputFile(folder / ("IM" + std::to_string(slice) + ".dcm"), rest.substr(0, end));
         rest = end == std::string_view::npos ? std::string_view()
                                              : rest.substr(end + kSliceSeparator.size());
       }
       readVolume(folder, collectingReadWarnings(input));
     }},
};

// Empty if `message` is one non-empty line (naming `inputName` unless that is empty); otherwise
// what is wrong with it.
inline std::string messageProblem(const std::string& message, const std::string& inputName) {
  if (message.empty()) return "empty message";
  if (message.find_first_of("\n\r") != std::string::npos) return "message of several lines";
  if (message.find(inputName) == std::string::npos) return "message does not name " + inputName;
  return {};
}

// Feeds `input` to the target's reader: empty if it returned, or threw an std::exception whose
// message is one line naming the input, and warned in one line each; otherwise the problem.
// Crashes, hangs and sanitizer reports are the caller's to notice.
inline std::string readerProblem(const ReaderTarget& target, FuzzInput& input) {
  std::string problem;
  try {
    target.read(input);
  } catch (const std::exception& error) {
    if (const std::string bad = messageProblem(error.what(), target.inputName); !bad.empty())
      problem = bad + ": \"" + error.what() + "\"";
  }
  for (const std::string& error : input.caughtErrors) {
    if (const std::string bad = messageProblem(error, target.inputName); !bad.empty())
      problem = bad + ": \"" + error + "\"";
  }
  for (const std::string& warning : input.warnings) {
    if (const std::string bad = messageProblem(warning, ""); !bad.empty())
      problem = "warning: " + bad + ": \"" + warning + "\"";
  }
  return problem;
}

}  // namespace angio::fuzz
