#include <ivis/render/front_method.h>

namespace ivis::render {
namespace {

class FrontMethod final : public Method {
public:
    const MethodInfo& info() const override { return frontMethodInfo(); }
    ParameterValues values() const override { return {}; }
};

}  // namespace

const MethodInfo& frontMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "front";
        i.help = "plain rendering (paper Fig. 1a)";
        i.create = [](const ParameterValues&) { return std::make_shared<const FrontMethod>(); };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
