#pragma once
// The built-in file browser (Dear ImGui, no native dialog): a modal listing one folder with
// std::filesystem, folders first, then the files it is for (volume files .mha .mhd .nrrd .nhdr
// .nii .nii.gz, centerline files .mrk.json .json .vtp .csv, TF and session files .json, images
// .png .tif .tiff .exr, or no files when it picks a folder), each group sorted by name; up, home
// and a typed path (a new file's name where one is chosen to be written); a folder of DICOM slices
// can be opened as a series. Listing and filtering are plain functions, testable without a window.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace angio {

struct BrowserEntry {
  std::string name;  // file name, shown
  std::filesystem::path path;
  bool folder = false;
  bool dicomSeries = false;  // a folder holding DICOM slices
};

// By case-insensitive extension: .mha .mhd .nrrd .nhdr .nii .nii.gz.
bool isVolumeFileName(const std::filesystem::path& path);
// By case-insensitive extension: .mrk.json .json .vtp .csv.
bool isCenterlineFileName(const std::filesystem::path& path);

// By case-insensitive extension: .png .tif .tiff .exr (what an image export writes).
bool isImageFileName(const std::filesystem::path& path);

// What the browser is open for: it lists those files, and the app acts on the choice. The last
// ones fill a panel's file field ("..." beside it), which the field's own buttons then use.
enum class BrowserPurpose {
  openVolume,
  loadCenterlines,
  saveCenterlines,
  glyphCenterlines,  // the VesselGlyph section's file: loaded when chosen
  tfFile,
  sessionFile,
  labelsFile,
  exportImage,
  seriesFolder,  // a folder, not a file
};
// Whether the purpose's choice is a file to be written (a typed new name may be chosen; the browser
// starts with the field's file name typed in).
bool choosesAFileToWrite(BrowserPurpose purpose);

// Some of the first few files in `folder` are DICOM (".dcm", or "DICM" at byte 128).
bool looksLikeDicomSeries(const std::filesystem::path& folder);
// Visible (no dot-files) folders and the purpose's files of `folder`: folders first, then files,
// each sorted case-insensitively. Throws std::runtime_error (one line) if it cannot be listed.
std::vector<BrowserEntry> listFolder(const std::filesystem::path& folder,
                                     BrowserPurpose purpose = BrowserPurpose::openVolume);

// What a path typed or pasted into the browser names: surrounding blanks and quotes trimmed, "~"
// and "~/..." in the home folder (`home`), an absolute path as it is, a relative one in `folder`
// (the listed folder, shown above the list); lexically normal.
std::filesystem::path resolveTypedPath(const std::filesystem::path& folder, const std::string& typed,
                                       const std::filesystem::path& home);

struct FileBrowser {
  bool requestOpen = false;  // show() sets it; the modal opens on the next draw
  BrowserPurpose purpose = BrowserPurpose::openVolume;
  std::filesystem::path folder;
  std::string typedPath;  // the path field: a folder to go to or a file to open
  std::vector<BrowserEntry> entries;
  int selected = -1;
  std::string error;
  bool focusPath = false;  // give the path field the keyboard on the next draw

  void show(const std::filesystem::path& startFolder,
            BrowserPurpose forWhat = BrowserPurpose::openVolume);
  void go(const std::filesystem::path& newFolder);  // lists it (error kept in `error`)
};

// Draws the modal while it is open; returns the file or folder the user chose to open.
std::optional<std::filesystem::path> drawFileBrowser(FileBrowser& browser);

}  // namespace angio
