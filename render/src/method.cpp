#include <ivis/render/method.h>

#include <ivis/core/errors.h>

namespace ivis::render {

std::vector<std::string> methodNames()
{
    return {"front", "backfaces", "neugebauer", "mirror", "inversevis", "inversevis-adaptive"};
}

const char* toString(Method method)
{
    switch (method) {
    case Method::Front: return "front";
    case Method::Backfaces: return "backfaces";
    case Method::Neugebauer: return "neugebauer";
    case Method::Mirror: return "mirror";
    case Method::InverseVis: return "inversevis";
    case Method::InverseVisAdaptive: return "inversevis-adaptive";
    }
    return "unknown";
}

Method parseMethod(const std::string& name)
{
    const std::vector<std::string> names = methodNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return Method(i);
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw InputError("unknown method '" + name + "' (known: " + known + ")");
}

}  // namespace ivis::render
