#include <ivis/core/procedural_scenes.h>

#include <ivis/core/errors.h>

#include <string>
#include <vector>

namespace ivis::core {

std::vector<std::string> sceneNames() { return {"sphere", "torus", "vessel-tree"}; }

SurfaceField makeScene(const std::string& name)
{
    if (name == "sphere") return makeSphere(4);
    if (name == "torus") return makeTorus();
    if (name == "vessel-tree") return makeVesselTree();
    std::string known;
    for (const std::string& scene : sceneNames()) known += (known.empty() ? "" : ", ") + scene;
    throw InputError("unknown scene '" + name + "' (known: " + known + ")");
}

}  // namespace ivis::core
