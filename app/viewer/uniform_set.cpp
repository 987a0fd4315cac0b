#include "uniform_set.h"

namespace ivis::app {

void UniformSet::applyTo(GlProgram& program) const
{
    for (const auto& [name, value] : mValues)
        std::visit([&program, &name = name](const auto& v) { program.set(name.c_str(), v); }, value);
}

}  // namespace ivis::app
