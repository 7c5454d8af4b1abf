#include "io/plugin_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#ifndef ANGIORAY_PLUGIN_DIR
#define ANGIORAY_PLUGIN_DIR ""
#endif

namespace angio {

namespace fs = std::filesystem;

namespace {

// Beside the executable first (a copied or installed angioray with its modules), then the build
// tree (the test executables live in a folder of their own).
std::vector<fs::path> moduleFolders() {
  std::vector<fs::path> folders;
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) folders.push_back(executable.parent_path());
  if (const fs::path built = ANGIORAY_PLUGIN_DIR; !built.empty()) folders.push_back(built);
  return folders;
}

void* openModule(const std::string& moduleName) {
  std::string tried;
  for (const fs::path& folder : moduleFolders()) {
    const fs::path file = folder / moduleName;
    if (!fs::exists(file)) {
      tried += (tried.empty() ? "" : ", ") + file.string();
      continue;
    }
    // dlopen counts the opens of a module and keeps one copy; it is never closed.
    if (void* module = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL)) return module;
    throw std::runtime_error("cannot load " + file.string() + ": " + dlerror());
  }
  throw std::runtime_error("cannot find angioray's module " + moduleName + " (looked for " + tried +
                           ")");
}

}  // namespace

void* pluginSymbol(const std::string& moduleName, const char* symbol) {
  void* module = openModule(moduleName);
  if (void* address = dlsym(module, symbol)) return address;
  throw std::runtime_error("module " + moduleName + " has no " + symbol);
}

}  // namespace angio
