/// @file method_options.h
/// @brief The --method option and every registered method's parameters as options, read from the
///        method registry: an option of a parameter the chosen method lacks is rejected.
#pragma once

#include <ivis/render/method_registry.h>
#include <ivis/vdb/surface_volume.h>

#include <CLI/CLI.hpp>

#include <map>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief The method and its parameters as given on the command line.
/// @note CLI11 writes into the object addTo() registered: copy it only after parsing, and call
///       create() while the CLI::App lives (it asks the options which were given).
struct MethodOptions {
    std::string method = render::defaultMethod()->name();
    std::map<std::string, std::vector<float>> values;  ///< by parameter key, as given

    /// @brief Registers --method and one option per parameter key of any registered method.
    void addTo(CLI::App& command);
    /// @brief The chosen method (--method, or @a base's when --method is not given) with the given
    ///        parameters over @a base's values when it is @a base's method, over its defaults else.
    /// @param base the method a view file gives, or null
    /// @throw InputError for an unknown method or an option its method does not take; ValueError
    ///        for a value out of bounds
    render::MethodPtr create(const render::Method* base = nullptr) const;
    /// @brief True when create(@a base) keeps @a base's method (and so its values).
    bool keeps(const render::Method& base) const;
    /// @brief True when the option of parameter @a key was given on the command line.
    bool givenParameter(const std::string& key) const;

private:
    std::map<std::string, CLI::Option*> mOptions;
    std::map<std::string, std::string> mFirstMethod;  ///< by key: the first method with the parameter (its default leads the help)
    CLI::Option* mMethodOption = nullptr;
};

/// @brief Checks that the distances of @a method that must stay below the volume's reach (the
///        curved rays' hull offset) do so for a volume built with @a volume.
/// @throw ValueError naming both values
void checkMethodFitsVolume(const render::Method& method, const vdb::VolumeOptions& volume);

}  // namespace ivis::app
