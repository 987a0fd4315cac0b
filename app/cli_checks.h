/// @file cli_checks.h
/// @brief Value checks for command-line options that CLI11's own do not make.
#pragma once

#include <ivis/core/errors.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>

namespace ivis::app {

namespace detail {

/// The check of finiteRange and positiveUpTo: a number from @a lo (or above it) to @a hi.
inline CLI::Validator numberRange(double lo, double hi, bool loIncluded)
{
    const std::string range =
        (loIncluded ? "[" : "(") + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]";
    return CLI::Validator(
        [lo, hi, loIncluded, range](std::string& text) -> std::string {
            double value = 0.0;
            // Hexadecimal ("0x10", which strtod reads as 16) is no angle or length a user means.
            if (text.find_first_of("xX") != std::string::npos || !CLI::detail::lexical_cast(text, value))
                return "'" + text + "' is not a number";
            if (!((loIncluded ? value >= lo : value > lo) && value <= hi))
                return "Value " + text + " not in range " + range;
            return {};
        },
        "FLOAT in " + range);
}

}  // namespace detail

/// @brief CLI::Range for floating-point options that also refuses NaN (CLI::Range compares, and
///        every comparison with NaN is false, so "--polish nan" passed it).
inline CLI::Validator finiteRange(double lo, double hi) { return detail::numberRange(lo, hi, true); }

/// @brief finiteRange(0, hi) without 0 itself: a length that must not vanish.
inline CLI::Validator positiveUpTo(double hi) { return detail::numberRange(0.0, hi, false); }

/// @brief A whole number from 0 to 2^64 - 1 written in digits (CLI11 read "-1" as 2^64 - 1 and
///        2^64 as 2^64 - 1, so three seeds gave one run).
inline CLI::Validator unsigned64()
{
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const std::string expected = "is not a whole number from 0 to 18446744073709551615";
            if (text.empty() || text.size() > 20 || text.find_first_not_of("0123456789") != std::string::npos ||
                (text.size() == 20 && text > "18446744073709551615"))
                return "'" + text + "' " + expected;
            return {};
        },
        "");
}

/// @brief A file that must exist (--camera, --view): "PATH: file not found" or "PATH: a folder, not
///        a file" (CLI11's CLI::ExistingFile said "File does not exist: PATH").
inline CLI::Validator existingFile()
{
    return CLI::Validator(
        [](std::string& path) -> std::string {
            std::error_code error;
            if (std::filesystem::is_directory(path, error)) return path + ": a folder, not a file";
            if (!std::filesystem::exists(path, error)) return path + ": file not found";
            return {};
        },
        "FILE");
}

/// @brief The one line a parse error @a e of @a app prints: a value that is no number of its
///        option's type in words ("--step: 'abc' is not a number", "--spp: '1.5' is not a whole
///        number from 1 to 1024") where CLI11 said "Could not convert: --step = abc" or "--spp:
///        Value 1.5 not in range 1 to 1024"; anything else as CLI11 words it.
inline std::string parseErrorText(const CLI::App& app, const CLI::ParseError& e)
{
    const std::string message = e.what();
    std::string name, value, range;
    if (const std::string prefix = "Could not convert: "; e.get_name() == "ConversionError" && message.rfind(prefix, 0) == 0) {
        const std::size_t equals = message.find(" = ");
        if (equals == std::string::npos) return message;
        name = message.substr(prefix.size(), equals - prefix.size()), value = message.substr(equals + 3);
    } else if (const std::size_t at = message.find(": Value "), in = message.find(" not in range ");
               e.get_name() == "ValidationError" && at != std::string::npos && in != std::string::npos && at < in) {
        name = message.substr(0, at), value = message.substr(at + 8, in - at - 8), range = message.substr(in + 14);
    } else {
        return message;
    }
    std::string type;
    for (const CLI::App* command : app.get_subcommands())
        if (const CLI::Option* option = command->get_option_no_throw(name)) type = option->get_type_name();
    if (const CLI::Option* option = app.get_option_no_throw(name); type.empty() && option) type = option->get_type_name();
    const bool whole = type.find("INT") != std::string::npos;
    double number = 0.0;
    const bool numeric = CLI::detail::lexical_cast(value, number) && std::isfinite(number);
    if (!range.empty() && numeric && (!whole || number == std::floor(number))) return message;  // a number, out of range
    return name + ": '" + value + "' is not " + (whole ? "a whole number" : "a number") +
           (range.empty() ? "" : " from " + range);
}

/// @brief Refuses an empty value ("--cache-dir $DIR" with DIR unset would name the default folder).
inline CLI::Validator nonEmpty()
{
    return CLI::Validator(
        [](std::string& text) -> std::string { return text.empty() ? "empty (an unset shell variable?)" : ""; }, "");
}

/// @brief Refuses an option's value made of commas only ("--opt-res ,," or "--methods=,"): CLI11
///        drops a comma-separated list's empty items, so such an option took the next argument.
/// @throw InputError naming the option
inline void rejectEmptyLists(int argc, const char* const* argv)
{
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        const std::size_t equals = argument.rfind("--", 0) == 0 ? argument.find('=') : std::string::npos;
        const bool value = equals != std::string::npos || (i > 1 && argv[i - 1][0] == '-');
        const std::string text = equals != std::string::npos ? argument.substr(equals + 1) : argument;
        if (value && !text.empty() && text.find_first_not_of(',') == std::string::npos)
            throw InputError((equals != std::string::npos ? argument.substr(0, equals) : std::string(argv[i - 1])) +
                             ": '" + text + "' lists nothing (give the items comma-separated, e.g. 100,1000)");
    }
}

}  // namespace ivis::app
