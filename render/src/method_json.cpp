#include <ivis/render/method_json.h>

#include <ivis/core/errors.h>
#include <ivis/core/json_numbers.h>
#include <ivis/render/method_registry.h>

namespace ivis::render {

nlohmann::json methodToJson(const Method& method)
{
    nlohmann::json json = {{"method", method.name()}};
    const ParameterValues values = method.values();
    for (const ParameterSpec& spec : method.info().parameters) {
        const std::vector<float>& v = values.at(spec.key);
        nlohmann::json value = nlohmann::json::array();
        for (float component : v) value.push_back(spec.integer ? nlohmann::json(int(component)) : nlohmann::json(component));
        json[spec.key] = v.size() == 1 ? value[0] : value;
    }
    return json;
}

MethodPtr methodFromJson(const nlohmann::json& json)
{
    if (!json.is_object() || !json.contains("method") || !json["method"].is_string())
        throw InputError("method JSON needs a \"method\" name");
    ParameterValues values;
    for (const auto& [key, value] : json.items()) {
        if (key == "method") continue;
        std::vector<float>& v = values[key];
        for (const auto& component : value.is_array() ? value : nlohmann::json::array({value})) {
            if (!core::isFiniteFloat(component))
                throw InputError("method parameter '" + key + "' is not a finite number");
            v.push_back(component.get<float>());
        }
    }
    return makeMethod(json["method"].get<std::string>(), values);
}

}  // namespace ivis::render
