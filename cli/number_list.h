#pragma once
// A flag's value that is a comma-separated list of numbers ("10,20,5.5").
#include <cstddef>
#include <string>
#include <vector>

namespace angio {

// Exactly `count` finite numbers separated by commas; else std::invalid_argument with one line
// naming `flag`, what it needs (`form`) and what it got.
std::vector<double> parseNumberList(const std::string& text, std::size_t count, const std::string& flag,
                                    const std::string& form);

}  // namespace angio
