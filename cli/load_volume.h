#pragma once
// How the subcommands read a volume: warnings as one line each on stderr, a progress line for
// long reads, errors as InputError (io/volume_reader.h).
#include <string>

#include "io/volume_reader.h"

namespace angio {

LoadedVolume loadVolumeWithProgress(const std::string& path, const std::string& labels = "");

}  // namespace angio
