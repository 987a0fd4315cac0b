#include <ivis/render/backfaces_method.h>

namespace ivis::render {
namespace {

class BackfacesMethod final : public Method {
public:
    const MethodInfo& info() const override { return backfacesMethodInfo(); }
    ParameterValues values() const override { return {}; }
    core::FaceFilter directFaces() const override { return core::FaceFilter::BackOnly; }
};

}  // namespace

const MethodInfo& backfacesMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "backfaces";
        i.help = "only the faces turned away from the camera (paper Fig. 1b)";
        i.create = [](const ParameterValues&) { return std::make_shared<const BackfacesMethod>(); };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
