#pragma once
// Transfer-function files (JSON, schema in the rendering model) and the shipped presets.
#include <filesystem>
#include <string>
#include <vector>

#include "core/transfer_function.h"

namespace angio {

// Throws InputError (file + problem) for missing/unreadable files, bad JSON, missing keys,
// NaN/out-of-range values, fewer than one point.
TransferFunction loadTransferFunction(const std::filesystem::path& path);
TransferFunction parseTransferFunction(const std::string& json, const std::filesystem::path& source);
// Atomic write (temp + rename). Keeps name, points, modulators and MIP window/level.
void saveTransferFunction(const TransferFunction& tf, const std::filesystem::path& path);
std::string toJson(const TransferFunction& tf);

struct Preset {
  std::string id;  // file stem, e.g. "cta-vessels"
  std::filesystem::path file;
};
// Presets shipped in the preset directory (ANGIORAY_PRESET_DIR or next to the executable).
std::vector<Preset> listPresets();
// A preset by id or display name, or else a TF file path. Throws InputError if neither.
TransferFunction loadPresetOrFile(const std::string& presetOrPath);

}  // namespace angio
