#pragma once
// The command line's checks of numbers. CLI11's own ranges let NaN through (every comparison with
// it is false) and print their unbounded ends as 300-digit numbers; these refuse NaN and the
// infinities wherever a number enters and say what is wanted in a few words.
#include <CLI/CLI.hpp>

namespace angio {

CLI::Validator finiteNumber();                       // any finite number
CLI::Validator numberAbove(double bound);            // finite and > bound
CLI::Validator numberAtLeast(double bound);          // finite and >= bound
CLI::Validator numberBetween(double lo, double hi);  // finite and in [lo, hi]

// Adds finiteNumber() to every floating-point option of `app` and its subcommands (also each
// element of a list), so an option without a range of its own still refuses NaN.
void requireFiniteNumbers(CLI::App& app);

// CLI11's parse errors as one line, as the other errors: "angioray: error: --isd: ...".
std::string oneLineFailure(const CLI::App* app, const CLI::Error& error);

}  // namespace angio
