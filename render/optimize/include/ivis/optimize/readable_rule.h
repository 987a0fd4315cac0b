/// @file readable_rule.h
/// @brief The optimisation's readable rule (beyond the paper, docs/optimisation.md, "The readable
///        rule"): a method whose rule for drawing its rays trades completeness for coherence
///        (MethodInfo::readableRuleParameter) gets, at the optimised view, the loosest setting
///        whose picture keeps the mapping coherence a reader needs.
#pragma once

#include <ivis/optimize/coherence.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <vector>

namespace ivis::optimize {

/// @brief The coherence a picture a person can read needs at least (docs/measures.md): the
///        readable rule's default minimum.
inline constexpr double kDefaultMinCoherence = 0.99;

/// @brief What the readable rule chose.
struct ReadableSetting {
    render::MethodPtr method;  ///< the method with the chosen setting
    Coherence coherence;       ///< its picture's coherence, estimated on sampled pairs
    glm::ivec2 size{0, 0};     ///< the size (width, height) of the picture it was estimated on
    bool keepsMinimum = true;  ///< false when even the ladder's tightest rung falls short of the minimum
};

/// @brief Lower end of the about 95% interval of the coherence estimated from @a coherence's pairs:
///        value - 2 sqrt(value (1 - value) / pairs).
double coherenceLowerBound(const Coherence& coherence);

/// @brief The mapping coherence of @a method's picture from @a camera at @a size pixels (width,
///        height) with its readable rule's parameter at each of @a values, from one tracing of its rays
///        at the largest value (a ray is drawn at a value when its CurvedRayStart::bend is at most
///        that): on the pairs of every @a stride-th row and column (mappingCoherence's stride;
///        stride 1 is measureCoherence of the method at that value).
/// @throw ValueError for a method without a readable rule's parameter, no value, a size or stride below 1
std::vector<Coherence> coherenceAtSettings(const render::RenderScene& scene, const core::Camera& camera,
                                           const render::Method& method, const glm::ivec2& size, int stride,
                                           const std::vector<float>& values);

/// @brief The size the readable rule judges a @a width x @a height picture at, whatever its
///        own: the coherence measure's kCoherenceResolution rows (docs/measures.md, 2)
///        and as many columns as the picture's aspect gives (at most 4 times as many). The rule
///        then draws the same rays at every size (the wrap's rule judges each view ray alone), and
///        a small picture, whose neighbouring pixels land further apart, does not get a tighter
///        rule that scatters its outer rings into dust.
/// @throw ValueError for a size below 1
glm::ivec2 readableRulePictureSize(int width, int height);

/// @brief The settings the readable rule chooses among, tightest first: the readable rule's
///        parameter of @a method at its own value v times 2^(k/2), k = -6..6 (v/8 to 8v), within the parameter's
///        bounds; empty for a method without such a parameter.
std::vector<float> readableRuleLadder(const render::Method& method);

/// @brief Of readableRuleLadder(@a method), the loosest rung reached from the tightest before a rung
///        whose picture from @a camera at @a size pixels (width, height) has a coherence lower
///        bound below @a minCoherence (the tightest when the next one falls short, and
///        keepsMinimum false when it falls short itself), estimated on
///        the pairs of every (height / 200)-th row and column: the method's own rule is loosened
///        where its picture has room in coherence and tightened where it has none. A method without such a
///        parameter is returned as it is, nothing measured; a method at the chosen value itself.
/// @param keeps if given, a rung looser than the method's own must also pass it: asked of the
///        chosen rung, and where that fails, the loosest rung that passes is found by bisection
///        between it and the method's own value (which needs not pass), taking `keeps` to fail on
///        every rung looser than one that fails
/// @throw ValueError for a size below 1 or a minimum coherence outside (0, 1]
ReadableSetting loosestReadable(const render::RenderScene& scene, const core::Camera& camera,
                                const render::MethodPtr& method, const glm::ivec2& size, double minCoherence,
                                const std::function<bool(const render::MethodPtr&)>& keeps = {});

/// @brief What the readable rule chose, as --stats-json reports it: {"parameter", "value",
///        "estimated_coherence", "sampled_pairs", "picture_size", "keeps_min_coherence"}.
nlohmann::json readableSettingJson(const ReadableSetting& setting);

}  // namespace ivis::optimize
