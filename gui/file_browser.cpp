#include "gui/file_browser.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <imgui.h>
#include <imgui_stdlib.h>

namespace angio {

namespace fs = std::filesystem;

namespace {

// How the browser looks and chooses for each purpose.
struct PurposeLook {
  const char* title;  // "###browser": one popup whatever it is for (the id stays with the title)
  const char* hint;
  const char* accept;  // the button that chooses
  bool typedNames;     // a typed name that does not exist yet may be chosen (a file to write)
};

// By BrowserPurpose.
constexpr PurposeLook kLooks[] = {
    {"Open volume###browser",
     "volume files (.mha .mhd .nrrd .nhdr .nii .nii.gz) and folders; DICOM: open the folder", "Open",
     false},
    {"Load centerlines###browser", "centerline files (.mrk.json .vtp .csv)", "Open", false},
    {"Save centerlines###browser",
     "a centerline file (.mrk.json .vtp .csv): pick one to replace, or type a new name", "Save", true},
    {"VesselGlyph centerlines###browser", "centerline files (.mrk.json .vtp .csv)", "Open", false},
    {"Transfer function file###browser",
     "TF files (.json): pick one to load or replace, or type a new name to save to", "Choose", true},
    {"Session file###browser",
     "session files (.json): pick one to load or replace, or type a new name to save to", "Choose",
     true},
    {"Label file###browser",
     "label volumes (.seg.nrrd .nrrd .nii.gz .mha): pick one to load or replace, or type a new name",
     "Choose", true},
    {"Export image###browser",
     "images (.png .tif .exr): pick one to replace, or type a new name (the extension is the format)",
     "Choose", true},
    {"Rotation series folder###browser", "folders: the series' views and movie are written into it",
     "Choose this folder", true},
};

const PurposeLook& lookOf(BrowserPurpose purpose) { return kLooks[int(purpose)]; }

}  // namespace

bool choosesAFileToWrite(BrowserPurpose purpose) {
  return lookOf(purpose).typedNames && purpose != BrowserPurpose::seriesFolder;
}

namespace {

constexpr int kDicomProbeFiles = 8;            // files looked at per folder
constexpr std::size_t kDicomProbeLimit = 400;  // folders beyond this many are not probed

std::string lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

bool endsWith(const std::string& text, const char* suffix) {
  const std::size_t n = std::strlen(suffix);
  return text.size() > n && text.compare(text.size() - n, n, suffix) == 0;
}

bool isDicomFile(const fs::path& file) {
  if (lowered(file.extension().string()) == ".dcm") return true;
  std::ifstream in(file, std::ios::binary);
  char magic[4] = {};
  return in.seekg(128) && in.read(magic, 4) && std::memcmp(magic, "DICM", 4) == 0;
}

fs::path homeFolder() {
  const char* home = std::getenv("HOME");
  return home && *home ? fs::path(home) : fs::current_path();
}

fs::path typedFile(const FileBrowser& browser) {
  return resolveTypedPath(browser.folder, browser.typedPath, homeFolder());
}

}  // namespace

fs::path resolveTypedPath(const fs::path& folder, const std::string& typed, const fs::path& home) {
  const char* blanks = " \t\r\n";
  const std::size_t first = typed.find_first_not_of(blanks);
  if (first == std::string::npos) return folder;
  std::string path = typed.substr(first, typed.find_last_not_of(blanks) - first + 1);
  // A path copied from a file manager or a shell often comes quoted.
  if (path.size() >= 2 && (path.front() == '"' || path.front() == '\'') && path.back() == path.front())
    path = path.substr(1, path.size() - 2);
  fs::path resolved;
  if (path == "~") resolved = home;
  else if (path.rfind("~/", 0) == 0) resolved = home / path.substr(2);
  else resolved = fs::path(path).is_absolute() ? fs::path(path) : folder / path;
  return resolved.lexically_normal();
}

bool isVolumeFileName(const fs::path& path) {
  const std::string name = lowered(path.filename().string());
  for (const char* extension : {".mha", ".mhd", ".nrrd", ".nhdr", ".nii", ".nii.gz"})
    if (endsWith(name, extension)) return true;
  return false;
}

bool looksLikeDicomSeries(const fs::path& folder) {
  std::error_code error;
  int probed = 0;
  for (fs::directory_iterator it(folder, error), end; !error && it != end && probed < kDicomProbeFiles;
       it.increment(error)) {
    if (!it->is_regular_file(error)) continue;
    ++probed;
    if (isDicomFile(it->path())) return true;
  }
  return false;
}

bool isCenterlineFileName(const fs::path& path) {
  const std::string name = lowered(path.filename().string());
  for (const char* ending : {".json", ".vtp", ".csv"}) {
    const std::string e = ending;
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0) return true;
  }
  return false;
}

bool isImageFileName(const fs::path& path) {
  const std::string name = lowered(path.filename().string());
  for (const char* extension : {".png", ".tif", ".tiff", ".exr"})
    if (endsWith(name, extension)) return true;
  return false;
}

namespace {

bool isJsonFileName(const fs::path& path) {
  return endsWith(lowered(path.filename().string()), ".json");
}
bool isNoFile(const fs::path&) { return false; }

// The files a purpose lists (folders are always listed).
bool (*listedFor(BrowserPurpose purpose))(const fs::path&) {
  switch (purpose) {
    case BrowserPurpose::openVolume:
    case BrowserPurpose::labelsFile: return isVolumeFileName;
    case BrowserPurpose::loadCenterlines:
    case BrowserPurpose::saveCenterlines:
    case BrowserPurpose::glyphCenterlines: return isCenterlineFileName;
    case BrowserPurpose::tfFile:
    case BrowserPurpose::sessionFile: return isJsonFileName;
    case BrowserPurpose::exportImage: return isImageFileName;
    case BrowserPurpose::seriesFolder: return isNoFile;
  }
  return isNoFile;
}

}  // namespace

std::vector<BrowserEntry> listFolder(const fs::path& folder, BrowserPurpose purpose) {
  const auto listed = listedFor(purpose);
  std::error_code error;
  std::vector<BrowserEntry> folders, files;
  fs::directory_iterator it(folder, error);
  if (error) throw std::runtime_error(folder.string() + ": cannot be listed: " + error.message());
  for (fs::directory_iterator end; it != end; it.increment(error)) {
    if (error) throw std::runtime_error(folder.string() + ": cannot be listed: " + error.message());
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code typeError;
    if (it->is_directory(typeError)) folders.push_back({name, it->path(), true, false});
    else if (listed(it->path())) files.push_back({name, it->path(), false, false});
  }
  const auto byName = [](const BrowserEntry& a, const BrowserEntry& b) {
    const std::string la = lowered(a.name), lb = lowered(b.name);
    return la != lb ? la < lb : a.name < b.name;
  };
  std::sort(folders.begin(), folders.end(), byName);
  std::sort(files.begin(), files.end(), byName);
  if (folders.size() <= kDicomProbeLimit)
    for (BrowserEntry& entry : folders) entry.dicomSeries = looksLikeDicomSeries(entry.path);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

void FileBrowser::show(const fs::path& startFolder, BrowserPurpose forWhat) {
  requestOpen = true;
  purpose = forWhat;
  go(startFolder.empty() ? fs::current_path() : startFolder);
}

void FileBrowser::go(const fs::path& newFolder) {
  try {
    entries = listFolder(newFolder, purpose);
    folder = fs::absolute(newFolder).lexically_normal();
    if (folder.has_filename() == false && folder != folder.root_path()) folder = folder.parent_path();
    typedPath = folder.string();
    selected = -1;
    error.clear();
  } catch (const std::exception& problem) {
    error = problem.what();
  }
}

std::optional<fs::path> drawFileBrowser(FileBrowser& browser) {
  if (browser.requestOpen) {
    ImGui::OpenPopup(lookOf(browser.purpose).title);
    browser.requestOpen = false;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImVec2(std::min(640.f, display.x - 40), std::min(480.f, display.y - 40)),
                           ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(lookOf(browser.purpose).title)) return std::nullopt;
  const bool volumes = browser.purpose == BrowserPurpose::openVolume;
  const bool folders = browser.purpose == BrowserPurpose::seriesFolder;
  const PurposeLook& look = lookOf(browser.purpose);
  std::optional<fs::path> chosen;
  const auto choose = [&](const fs::path& path) {
    chosen = path;
    ImGui::CloseCurrentPopup();
  };

  if (ImGui::Button("Up")) browser.go(browser.folder.parent_path());
  ImGui::SameLine();
  if (ImGui::Button("Home")) browser.go(homeFolder());
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  if (ImGui::IsWindowAppearing() || browser.focusPath) ImGui::SetKeyboardFocusHere();
  browser.focusPath = false;
  if (ImGui::InputText("##path", &browser.typedPath, ImGuiInputTextFlags_EnterReturnsTrue)) {
    const fs::path typed = typedFile(browser);
    std::error_code error;
    if (fs::is_directory(typed, error) && !(volumes && looksLikeDicomSeries(typed))) {
      browser.go(typed);
      browser.focusPath = true;  // type on: a file name or the next folder
    } else {
      choose(typed);
    }  // a file, or a DICOM folder; a missing one fails in the loader, named
  }
  // A relative name is looked up here: shown, since the path field may say something else.
  ImGui::TextDisabled("folder: %s", browser.folder.string().c_str());
  ImGui::TextDisabled("%s", look.hint);

  const float footer = ImGui::GetFrameHeightWithSpacing() * 2 + 4;
  ImGui::BeginChild("##entries", ImVec2(0, -footer), true);
  for (int n = 0; n < int(browser.entries.size()); ++n) {
    const BrowserEntry& entry = browser.entries[n];
    const std::string label = entry.folder
                                  ? (entry.dicomSeries ? "[DICOM] " : "[dir]   ") + entry.name + "/"
                                  : "        " + entry.name;
    if (ImGui::Selectable(label.c_str(), browser.selected == n, ImGuiSelectableFlags_AllowDoubleClick)) {
      browser.selected = n;
      browser.typedPath = entry.path.string();
      if (ImGui::IsMouseDoubleClicked(0)) {
        if (entry.folder && !entry.dicomSeries) {
          browser.go(entry.path);
          break;  // entries changed
        }
        choose(entry.path);
      }
    }
  }
  if (browser.entries.empty()) ImGui::TextDisabled("(nothing to list here)");
  ImGui::EndChild();

  if (!browser.error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", browser.error.c_str());
  const BrowserEntry* selected = browser.selected >= 0 && browser.selected < int(browser.entries.size())
                                     ? &browser.entries[browser.selected]
                                     : nullptr;
  if (folders) {  // the selected folder, else the one listed
    if (ImGui::Button(look.accept))
      choose(selected && selected->folder ? selected->path : browser.folder);
  } else if (look.typedNames) {
    if (ImGui::Button(look.accept)) choose(typedFile(browser));
  } else {
    ImGui::BeginDisabled(!selected || (selected->folder && !selected->dicomSeries));
    if (ImGui::Button(look.accept)) choose(selected->path);
    ImGui::EndDisabled();
  }
  ImGui::SameLine();
  if (volumes) {
    const fs::path seriesFolder = selected && selected->folder ? selected->path : browser.folder;
    if (ImGui::Button("Open folder as DICOM series")) choose(seriesFolder);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", seriesFolder.string().c_str());
    ImGui::SameLine();
  }
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
    ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace angio
