#pragma once
// The fuzz targets of the GUI's readers (session files, headless scripts), as reader_inputs.h's;
// kept apart because they link the GUI library (tests/gui replays their crashers).
#include "gui/app_script.h"
#include "gui/session_file.h"
#include "tests/fuzz/reader_inputs.h"

namespace angio::fuzz {

inline const ReaderTarget kGuiReaderTargets[] = {
    {"session", "input-session.json",
     [](FuzzInput& input) { parseSession(input.bytes, "input-session.json"); }},
    {"script", "input-script.json",
     [](FuzzInput& input) { parseScript(input.bytes, "input-script.json"); }},
};

}  // namespace angio::fuzz
