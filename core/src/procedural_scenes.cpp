#include <ivis/core/procedural_scenes.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ivis::core {

std::vector<std::string> sceneNames() { return {"sphere", "torus", "vessel-tree"}; }

void checkSceneName(const std::string& name)
{
    const std::vector<std::string> names = sceneNames();
    if (std::find(names.begin(), names.end(), name) != names.end()) return;
    std::string known;
    for (const std::string& scene : names) known += (known.empty() ? "" : ", ") + scene;
    throw InputError("unknown scene '" + name + "' (known: " + known + ")");
}

SurfaceField makeScene(const std::string& name)
{
    checkSceneName(name);
    if (name == "sphere") return makeSphere(4);
    if (name == "torus") return makeTorus();
    return makeVesselTree();
}

}  // namespace ivis::core
