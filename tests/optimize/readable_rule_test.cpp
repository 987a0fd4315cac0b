// The readable rule: the loosest setting of a method's drawing rule whose picture stays
// coherent, chosen on the ladder v/8 ... 8v in steps of sqrt(2); and the annealing applying it to its best view.
#include "render/scene_fixture.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/readable_rule.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ivis::optimize {
namespace {

constexpr int kResolution = 400;  // pixels per side of the pictures kept coherent (stride 2)
const glm::ivec2 kSize(kResolution, kResolution);

float stableShift(const render::Method& method) { return method.values().at("stable_shift").at(0); }

TEST(ReadableRule, LowerBoundIsTheEstimateLessTwoStandardErrors)
{
    Coherence c;
    c.pairs = 10000;
    c.coherent = 9900;
    EXPECT_NEAR(coherenceLowerBound(c), 0.99 - 2.0 * std::sqrt(0.99 * 0.01 / 10000.0), 1e-12);
    c.coherent = c.pairs;
    EXPECT_DOUBLE_EQ(coherenceLowerBound(c), 1.0) << "no tear among the pairs";
    EXPECT_DOUBLE_EQ(coherenceLowerBound(Coherence{}), 1.0) << "no pair, nothing torn";
}

TEST(ReadableRule, CoherenceAtSettingsIsTheMeasureOfEachSetting)
{
    // Brute force: the method made with each value and its picture measured pixel by pixel.
    const auto& fixture = test::vesselScene();
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    const std::vector<float> values = {0.005f, 0.02f, 0.08f};
    const int size = 150;
    const std::vector<Coherence> all = coherenceAtSettings(*fixture.scene, camera, *wrap, {size, size}, 1, values);
    ASSERT_EQ(all.size(), values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
        const render::MethodPtr method = render::withValues(*wrap, {{"stable_shift", {values[k]}}});
        const Coherence measured = measureCoherence(*fixture.scene, camera, method, size);
        EXPECT_EQ(all[k].pairs, measured.pairs) << values[k];
        EXPECT_EQ(all[k].coherent, measured.coherent) << values[k];
    }
    EXPECT_GT(all[2].pairs, all[0].pairs) << "a looser rule draws more rays";
    EXPECT_LT(all[2].value(), 1.0) << "and the tree's picture has tears to count";
    const std::vector<Coherence> sampled = coherenceAtSettings(*fixture.scene, camera, *wrap, {size, size}, 3, values);
    EXPECT_LT(sampled[0].pairs, all[0].pairs / 4);
    EXPECT_THROW(coherenceAtSettings(*fixture.scene, camera, *render::makeMethod("inversevis"), {size, size}, 1, values),
                 ValueError);
    EXPECT_THROW(coherenceAtSettings(*fixture.scene, camera, *wrap, {size, size}, 1, {}), ValueError);
    EXPECT_THROW(coherenceAtSettings(*fixture.scene, camera, *wrap, {size, 0}, 1, values), ValueError);
}

TEST(ReadableRule, CoherenceAtSettingsMeasuresAWidePictureAsItsRender)
{
    // Brute force: a 150 x 90 picture rendered with each value, every ray traced (the rule judges
    // each view ray alone), its coherence counted on its layers.
    const auto& fixture = test::vesselScene();
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    const std::vector<float> values = {0.005f, 0.08f};
    const std::vector<Coherence> all = coherenceAtSettings(*fixture.scene, camera, *wrap, {150, 90}, 1, values);
    for (std::size_t k = 0; k < values.size(); ++k) {
        render::RenderOptions options;
        options.width = 150;
        options.height = 90;
        options.adaptive.enabled = false;
        options.method = render::withValues(*wrap, {{"stable_shift", {values[k]}}});
        const Coherence rendered = mappingCoherence(render::renderImage(*fixture.scene, camera, options).layers);
        EXPECT_GT(rendered.pairs, 1000u);
        EXPECT_EQ(all[k].pairs, rendered.pairs) << values[k];
        EXPECT_EQ(all[k].coherent, rendered.coherent) << values[k];
    }
}

TEST(ReadableRule, JudgesEveryPictureAtTheMeasuresRowsInItsOwnAspect)
{
    EXPECT_EQ(readableRulePictureSize(480, 480), glm::ivec2(kCoherenceResolution, kCoherenceResolution));
    EXPECT_EQ(readableRulePictureSize(4000, 4000), glm::ivec2(kCoherenceResolution, kCoherenceResolution));
    EXPECT_EQ(readableRulePictureSize(1600, 900), glm::ivec2(1778, kCoherenceResolution));
    EXPECT_EQ(readableRulePictureSize(300, 1200), glm::ivec2(250, kCoherenceResolution));
    EXPECT_EQ(readableRulePictureSize(100000, 10), glm::ivec2(4 * kCoherenceResolution, kCoherenceResolution))
        << "a very wide picture judged on its middle";
    EXPECT_EQ(readableRulePictureSize(1, 100000), glm::ivec2(1, kCoherenceResolution));
    EXPECT_THROW(readableRulePictureSize(0, 10), ValueError);
    EXPECT_THROW(readableRulePictureSize(10, 0), ValueError);
}

TEST(ReadableRule, TheLadderRunsFromAnEighthToEightTimesTheOwnValueInStepsOfRootTwo)
{
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    const float own = stableShift(*wrap);
    const std::vector<float> ladder = readableRuleLadder(*wrap);
    ASSERT_EQ(ladder.size(), 13u);
    EXPECT_FLOAT_EQ(ladder.front(), own / 8.0f);
    EXPECT_EQ(ladder[6], own) << "the method's own value is the middle rung";
    EXPECT_FLOAT_EQ(ladder.back(), 8.0f * own);
    for (std::size_t k = 1; k < ladder.size(); ++k) EXPECT_NEAR(ladder[k] / ladder[k - 1], std::sqrt(2.0f), 1e-5f) << k;
    // Within the parameter's bounds: a method near its upper bound gets fewer, clamped rungs.
    const float hi = wrap->info().parameter("stable_shift")->hi;
    const std::vector<float> high = readableRuleLadder(*render::withValues(*wrap, {{"stable_shift", {hi / 2.0f}}}));
    EXPECT_EQ(high.back(), hi);
    EXPECT_EQ(high.size(), 9u) << "hi/2 * sqrt(2) and hi, then nothing looser";
    EXPECT_TRUE(readableRuleLadder(*render::makeMethod("inversevis")).empty());
}

TEST(ReadableRule, KeepsTheLoosestSettingBeforeTheCoherenceFallsShort)
{
    const auto& fixture = test::vesselScene();
    const render::RenderScene& scene = *fixture.scene;
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    const std::vector<float> ladder = readableRuleLadder(*wrap);
    const std::size_t own = 6;
    const std::vector<Coherence> coherence =
        coherenceAtSettings(scene, camera, *wrap, kSize, kResolution / 200, ladder);
    // Every rung from the tightest up to the chosen one holds the bound, the next one does not.
    auto expectChosenRung = [&](const ReadableSetting& chosen, double minCoherence) {
        const auto rung = std::find(ladder.begin(), ladder.end(), stableShift(*chosen.method));
        ASSERT_NE(rung, ladder.end()) << "a rung of the ladder";
        const std::size_t k = std::size_t(rung - ladder.begin());
        for (std::size_t i = 1; i <= k; ++i) EXPECT_GE(coherenceLowerBound(coherence[i]), minCoherence) << ladder[i];
        if (k + 1 < ladder.size()) {
            EXPECT_LT(coherenceLowerBound(coherence[k + 1]), minCoherence) << ladder[k + 1];
        }
        EXPECT_EQ(chosen.coherence.pairs, coherence[k].pairs);
        EXPECT_EQ(chosen.coherence.coherent, coherence[k].coherent);
    };

    // Any coherence will do: the loosest rung.
    EXPECT_FLOAT_EQ(stableShift(*loosestReadable(scene, camera, wrap, kSize, 1e-6).method), ladder.back());
    // At 0.99.
    const ReadableSetting chosen = loosestReadable(scene, camera, wrap, kSize, 0.99);
    expectChosenRung(chosen, 0.99);
    EXPECT_EQ(chosen.size, kSize) << "the size it was judged at";
    // Looser draws more: the chosen picture shows at least as much of the surface as the tightest.
    EnergyOptions options;
    options.resolution = 200;
    const EnergyEvaluator evaluator(scene, options);
    const render::MethodPtr tightest = render::withValues(*wrap, {{"stable_shift", {ladder.front()}}});
    EXPECT_GE(evaluator.evaluate(camera, chosen.method).energy, evaluator.evaluate(camera, tightest).energy);
    // Where the method's own rule leaves the picture less coherent than asked, a tighter rule.
    const double between = 0.5 * (coherenceLowerBound(coherence[0]) + coherenceLowerBound(coherence[own]));
    ASSERT_GT(coherenceLowerBound(coherence[0]), coherenceLowerBound(coherence[own])) << "the tree's own rule tears";
    const ReadableSetting tighter = loosestReadable(scene, camera, wrap, kSize, between);
    EXPECT_LT(stableShift(*tighter.method), ladder[own]);
    expectChosenRung(tighter, between);
    // A rung looser than the method's own must also pass `keeps`: the chosen rung is asked first,
    // then the rest by bisection, so that where every rung up to some one keeps, that one is taken
    // after at most 1 + log2 of the looser rungs asked; the own rung and tighter ones are never asked.
    // Any coherence: the loosest rung that keeps.
    std::vector<float> asked;
    const auto keepsUpTo = [&](float limit) {
        return [&asked, limit](const render::MethodPtr& method) {
            asked.push_back(stableShift(*method));
            return stableShift(*method) <= limit;
        };
    };
    const std::size_t looser = ladder.size() - own - 1;
    ASSERT_GE(looser, 4u);
    for (std::size_t limit = own; limit < ladder.size(); ++limit) {
        asked.clear();
        EXPECT_FLOAT_EQ(stableShift(*loosestReadable(scene, camera, wrap, kSize, 1e-6, keepsUpTo(ladder[limit])).method),
                        ladder[limit])
            << limit;
        ASSERT_FALSE(asked.empty());
        EXPECT_EQ(asked.front(), ladder.back()) << "the chosen rung first";
        EXPECT_LE(asked.size(), 1 + std::size_t(std::ceil(std::log2(double(looser))))) << limit;
        for (const float value : asked) EXPECT_GT(value, ladder[own]);
    }
    asked.clear();
    EXPECT_EQ(loosestReadable(scene, camera, wrap, kSize, 1e-6, keepsUpTo(0.0f)).method, wrap) << "its own rung";
    asked.clear();
    EXPECT_LT(stableShift(*loosestReadable(scene, camera, wrap, kSize, between, keepsUpTo(0.0f)).method), ladder[own]);
    EXPECT_TRUE(asked.empty()) << "a rung at or below its own is not asked";
    // Perfect coherence is more than the tree's picture has one rung up: the tightest rung.
    ASSERT_LT(coherenceLowerBound(coherence[1]), 1.0);
    EXPECT_EQ(stableShift(*loosestReadable(scene, camera, wrap, kSize, 1.0).method), ladder.front());
    // The method's own value chosen (here the loosest, the parameter's upper bound): the method itself.
    const render::MethodPtr loosest =
        render::withValues(*wrap, {{"stable_shift", {wrap->info().parameter("stable_shift")->hi}}});
    EXPECT_EQ(loosestReadable(scene, camera, loosest, kSize, 1e-6).method, loosest);

    // A method without a readable rule's parameter is left as it is; bad arguments are refused.
    const render::MethodPtr faithful = render::makeMethod("inversevis");
    EXPECT_EQ(loosestReadable(scene, camera, faithful, kSize, 0.99).method, faithful);
    EXPECT_THROW(loosestReadable(scene, camera, wrap, {0, kResolution}, 0.99), ValueError);
    EXPECT_THROW(loosestReadable(scene, camera, wrap, kSize, 0.0), ValueError);
    EXPECT_THROW(loosestReadable(scene, camera, wrap, kSize, 1.5), ValueError);
}

TEST(ReadableRule, TheAnnealingsBestViewIsMeasuredWithTheChosenSetting)
{
    const auto& fixture = test::vesselScene();
    EnergyOptions energy;
    energy.resolution = 24;
    const EnergyEvaluator evaluator(*fixture.scene, energy);
    AnnealingOptions options;
    options.steps = 2;
    AscentOptions ascent;
    ascent.maxIterations = 1;
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    const AnnealingResult plain = annealViewpoint(evaluator, wrap, options, ascent);
    EXPECT_FALSE(plain.readable.has_value());
    EXPECT_FLOAT_EQ(stableShift(*plain.bestView().method), stableShift(*wrap));

    options.readableResolution = kResolution;
    options.minCoherence = 1e-6;  // any: the loosest rung
    const AnnealingResult readable = annealViewpoint(evaluator, wrap, options, ascent);
    ASSERT_TRUE(readable.readable.has_value());
    const VisitedView& best = readable.bestView();
    EXPECT_EQ(best.method, readable.readable->method);
    EXPECT_FLOAT_EQ(stableShift(*best.method), 8.0f * stableShift(*wrap));
    EXPECT_DOUBLE_EQ(best.value.energy, evaluator.evaluate(best.camera, best.method).energy)
        << "the best view is measured again with its new rule";
    EXPECT_EQ(readable.evaluations, plain.evaluations + 1);
}

}  // namespace
}  // namespace ivis::optimize
