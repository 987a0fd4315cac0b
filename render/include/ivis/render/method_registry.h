/// @file method_registry.h
/// @brief The registered visualisation methods, created by name from parameter values, and the
///        generic operations every method's description allows (validation, the optimised
///        parameter vector, comparison).
#pragma once

#include <ivis/render/method.h>

#include <string>
#include <vector>

namespace ivis::render {

/// @brief Every registered method's description, in the order --help lists them.
const std::vector<const MethodInfo*>& methodRegistry();

/// @brief The method a command uses when none is named: the wrapped InverseVis (inversevis-wrap) with its defaults.
MethodPtr defaultMethod();

/// @brief Names of the registered methods, in registry order.
std::vector<std::string> methodNames();

/// @brief The description of the method named @a name.
/// @throw InputError naming the known methods
const MethodInfo& methodInfo(const std::string& name);

/// @brief The method @a name with @a values; parameters not given take their defaults.
/// @throw InputError for an unknown method or a key it does not have; ValueError for a value out
///        of its bounds or with the wrong number of components
MethodPtr makeMethod(const std::string& name, const ParameterValues& values = {});

/// @brief @a method with the parameters in @a changes replaced (checked as makeMethod).
MethodPtr withValues(const Method& method, const ParameterValues& changes);

/// @brief The components of the optimised parameters, in description order.
std::vector<double> optimisedParameters(const Method& method);

/// @brief @a method with its optimised components set from @a x (as optimisedParameters orders
///        them), each clamped to its parameter's bounds.
MethodPtr withOptimisedParameters(const Method& method, const std::vector<double>& x);

/// @brief True when @a a and @a b are the same method with equal parameters that are not optimised.
bool sameFixedParameters(const Method& a, const Method& b);

/// @brief The far field's reach that @a methods' rays need (Method::reachNeeded), at least
///        @a atLeast, kept to four decimals (0.4f + 0.2f is not 0.6): equal needs give equal
///        volumes, which the volume cache tells apart by their reach.
double reachNeededBy(const std::vector<MethodPtr>& methods, double atLeast);

/// @brief The optimised parameters as text, e.g. "alpha 0.500" (for logs and the viewer).
std::string describeOptimisedParameters(const Method& method);

}  // namespace ivis::render
