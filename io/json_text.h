#pragma once
// Parsing a JSON file's text, for every reader of JSON (TF, markups, sidecar, session, script):
// a bad text is one InputError naming the file, the byte and the reason, and a text nested deeper
// than any file of ours is (kMaxJsonDepth) is refused before it is parsed, so a hostile file
// cannot exhaust the stack in whatever walks the value afterwards.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace angio {

constexpr int kMaxJsonDepth = 100;

// The deepest nesting of arrays and objects in `text` (brackets inside strings do not count).
int jsonNestingDepth(const std::string& text);

nlohmann::json parseJsonText(const std::string& text, const std::filesystem::path& source);

}  // namespace angio
