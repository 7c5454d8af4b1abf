#pragma once
// ITK and GDCM report what they meet by printing to stderr themselves, several lines at a time,
// around the one line our InputError gives. The program routes them once at start: ITK's output
// window hands every message, folded to one line, to a sink; GDCM's trace is turned off (what it
// finds wrong reaches us again as an ITK exception, which io/ turns into an InputError).
#include <functional>
#include <string>

namespace angio {

using LibraryMessageSink = std::function<void(const std::string& oneLine)>;

// ITK's output window is process-wide by ITK's design; this replaces it (call it once, from main).
void routeLibraryMessages(LibraryMessageSink sink);

}  // namespace angio
