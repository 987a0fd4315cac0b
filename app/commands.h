/// @file commands.h
/// @brief Subcommands of the `inversevis` program; each registers its options and returns what
///        to run once the command line has been parsed.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace ivis::app {

/// @brief A registered subcommand and the action to run when it was given.
struct Command {
    CLI::App* parser = nullptr;
    std::function<void()> run;
};

/// @brief `inversevis info MESH`: counts, bounds, boundary, components, scalar properties.
Command addInfoCommand(CLI::App& app);

/// @brief `inversevis sdf MESH`: builds (or reuses) the cached volume and reports it.
Command addSdfCommand(CLI::App& app);

/// @brief `inversevis render MESH`: a method's picture to PNG, EXR layers, stats and camera JSON.
Command addRenderCommand(CLI::App& app);

/// @brief `inversevis optimize MESH`: best viewpoint and parameters by simulated annealing.
Command addOptimizeCommand(CLI::App& app);

/// @brief `inversevis evaluate MESH...`: the paper's visibility and timing tables.
Command addEvaluateCommand(CLI::App& app);
/// @brief `inversevis merge PART.json...`: the tables of evaluate jobs run apart (--only).
Command addMergeCommand(CLI::App& app);
/// @brief `inversevis cache list|clear`: the volume caches of the shared cache folder.
Command addCacheCommand(CLI::App& app);

}  // namespace ivis::app
