// The file browser of App (gui/file_browser.h): one modal behind the Data section's Open, the
// Vessels section's Save as / Open and every file field's "...". A choice opens or loads where
// the button said so, else it fills the field, whose own buttons then use it.
#include <filesystem>
#include <system_error>

#include "gui/app.h"

namespace angio {

namespace fs = std::filesystem;

// Starts in the folder of `current` (a file or folder, absolute or relative), else the working
// folder; where the choice is a file to write, its name is typed in already, to keep or type over.
void App::browseFor(BrowserPurpose purpose, const std::string& current) {
  std::error_code error;
  const fs::path given = fs::absolute(current.empty() ? fs::path(".") : fs::path(current), error);
  const bool isFolder = fs::is_directory(given, error);
  const fs::path folder = isFolder ? given : given.parent_path();
  browser_.show(fs::is_directory(folder, error) ? folder : fs::current_path(), purpose);
  if (choosesAFileToWrite(purpose) && !isFolder && !current.empty())
    browser_.typedPath = (browser_.folder / given.filename()).string();
}

void App::chooseBrowsed(const fs::path& chosen) {
  const std::string path = chosen.string();
  switch (browser_.purpose) {
    case BrowserPurpose::openVolume: openDataset(path); break;
    case BrowserPurpose::loadCenterlines:
    case BrowserPurpose::saveCenterlines: chooseVesselFile(chosen); break;
    case BrowserPurpose::glyphCenterlines:
      vessel_.ui.path = path;
      loadVesselCenterlines({path, "", CenterlineLoad::From::panel});
      break;
    case BrowserPurpose::tfFile: tfPanel_.path = path; break;
    case BrowserPurpose::sessionFile: sessionPanel_.path = path; break;
    case BrowserPurpose::labelsFile: labels_.ui.path = path; break;
    case BrowserPurpose::exportImage: export_.ui.path = path; break;
    case BrowserPurpose::seriesFolder: series_.folder = path; break;
  }
}

void App::drawBrowser() {
  if (const auto chosen = drawFileBrowser(browser_)) chooseBrowsed(*chosen);
}

}  // namespace angio
