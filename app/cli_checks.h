/// @file cli_checks.h
/// @brief Value checks for command-line options that CLI11's own do not make.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace ivis::app {

/// @brief CLI::Range for floating-point options that also refuses NaN (CLI::Range compares, and
///        every comparison with NaN is false, so "--polish nan" passed it).
inline CLI::Validator finiteRange(double lo, double hi)
{
    const std::string range = "[" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]";
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            double value = 0.0;
            if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
            if (!(value >= lo && value <= hi)) return "Value " + text + " not in range " + range;
            return {};
        },
        "FLOAT in " + range);
}

}  // namespace ivis::app
