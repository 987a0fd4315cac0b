/// @file number_text.h
/// @brief Numbers as the program's messages and reports write them.
#pragma once

#include <cstdio>
#include <string>

namespace ivis::core {

/// @brief @a value to six significant digits in its shortest form, as printf's %g writes it
///        ("2", "0.5", "1e-06", "inf"): the form of every number a message or a report names.
inline std::string shortNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace ivis::core
