// The viewpoint annealing: determinism for a seed and its rules (the cube views, the compass search,
// the Metropolis rate, the framing of each view, the coarse ascent, the finalists).
#include "optimization_fixture.h"
#include "render/scene_fixture.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/parameter_optimizer.h>
#include <ivis/optimize/curved_ray_gradient.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_registry.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <utility>

namespace ivis::optimize {
namespace {

using namespace render;

TEST(ViewpointAnnealing, IsDeterministicForASeedAndFollowsItsRules)
{
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(32));
    AnnealingOptions options;
    options.steps = 12;
    const MethodPtr start = makeMethod("neugebauer");  // nothing optimised: the test is about the view search
    const AnnealingResult a = annealViewpoint(evaluator, start, options);
    const AnnealingResult b = annealViewpoint(evaluator, start, options);
    options.seed = 2;
    const AnnealingResult c = annealViewpoint(evaluator, start, options);
    ASSERT_EQ(a.visited.size(), 13u);
    bool differs = false;
    for (std::size_t i = 0; i < a.visited.size(); ++i) {
        EXPECT_EQ(a.visited[i].thetaDeg, b.visited[i].thetaDeg);
        EXPECT_EQ(a.visited[i].phiDeg, b.visited[i].phiDeg);
        EXPECT_EQ(a.visited[i].value.energy, b.visited[i].value.energy);
        differs |= a.visited[i].thetaDeg != c.visited[i].thetaDeg;
    }
    EXPECT_TRUE(differs) << "another seed proposes other views";
    double best = 0.0;
    const VisitedView* current = &a.visited[0];
    for (std::size_t i = 0; i < a.visited.size(); ++i) {
        const VisitedView& view = a.visited[i];
        EXPECT_GE(view.thetaDeg, 0.0);
        EXPECT_LE(view.thetaDeg, 180.0);
        best = std::max(best, view.value.energy);
        if (i == 0) continue;
        // Neighbours lie within 60 degrees in theta (before reflection at a pole) of the current view.
        const bool nearPole = current->thetaDeg < 60.0 || current->thetaDeg > 120.0;
        if (!nearPole) {
            EXPECT_LE(std::abs(view.thetaDeg - current->thetaDeg), 60.0 + 1e-9);
        }
        if (view.value.energy > current->value.energy) {
            EXPECT_TRUE(view.accepted) << "better views are always accepted";
        }
        if (view.accepted) current = &view;
    }
    EXPECT_EQ(a.bestView().value.energy, best);
}

TEST(ViewpointAnnealing, CubeViewsLookFromEveryFaceEdgeAndCornerOfACube)
{
    const std::vector<std::array<double, 2>> views = cubeViews();
    ASSERT_EQ(views.size(), 26u);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(views[i][0], kAxisViews[i][0]);
        EXPECT_EQ(views[i][1], kAxisViews[i][1]);
    }
    // Brute force: every direction (x, y, z) in {-1, 0, 1}^3 but the zero one is the eye direction
    // of exactly one view.
    std::vector<int> hits(views.size(), 0);
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                if (x == 0 && y == 0 && z == 0) continue;
                const glm::dvec3 direction = glm::normalize(glm::dvec3(x, y, z));
                int found = 0;
                for (std::size_t i = 0; i < views.size(); ++i) {
                    const glm::dvec3 eye = core::Camera::fromAngles(views[i][0], views[i][1], 1.0).eye;
                    if (glm::length(eye - direction) < 1e-9) {
                        ++found;
                        ++hits[i];
                    }
                }
                EXPECT_EQ(found, 1) << "direction " << x << ", " << y << ", " << z;
            }
    for (std::size_t i = 0; i < views.size(); ++i) EXPECT_EQ(hits[i], 1) << "view " << i;
}

TEST(ViewpointAnnealing, StartsAtTheBestOfTheCubeViews)
{
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(32));
    AnnealingOptions options;
    options.steps = 3;
    options.startAtBestCubeView = true;
    const MethodPtr start = makeMethod("neugebauer");
    const AnnealingResult run = annealViewpoint(evaluator, start, options);
    const std::vector<std::array<double, 2>> views = cubeViews();
    ASSERT_EQ(run.visited.size(), views.size() + 3);
    std::size_t best = 0;
    for (std::size_t i = 0; i < views.size(); ++i) {
        const VisitedView& view = run.visited[i];
        EXPECT_EQ(view.thetaDeg, views[i][0]);
        EXPECT_EQ(view.phiDeg, views[i][1]);
        const core::Camera camera = render::frameView(*fixture.scene, core::Camera::fromAngles(view.thetaDeg, view.phiDeg), *start, 1.0);
        EXPECT_EQ(view.value.energy, evaluator.evaluate(camera, start).energy) << "cube view " << i;
        if (view.value.energy > run.visited[best].value.energy) best = i;
    }
    EXPECT_NE(best, 2u) << "the test needs a best cube view other than the fixed start (90, 0)";
    for (std::size_t i = 0; i < views.size(); ++i) EXPECT_EQ(run.visited[i].accepted, i == best) << "cube view " << i;
    // Every proposal is a neighbour of the view accepted before it: within 60 degrees in theta
    // unless a step that long could cross a pole (and be reflected there).
    const VisitedView* current = &run.visited[best];
    for (std::size_t i = views.size(); i < run.visited.size(); ++i) {
        const VisitedView& proposal = run.visited[i];
        const double theta = current->thetaDeg;
        const bool mayCrossAPole = theta < 60.0 || theta > 120.0;
        if (!mayCrossAPole) {
            EXPECT_LE(std::abs(proposal.thetaDeg - theta), 60.0 + 1e-9) << "proposal " << i;
        }
        if (proposal.accepted) current = &proposal;
    }
}

TEST(ViewpointAnnealing, CompassSearchVisitsTheBestViewsNeighboursAtHalvingSteps)
{
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(32));
    AnnealingOptions options;
    options.steps = 4;
    const MethodPtr start = makeMethod("neugebauer");
    const AnnealingResult plain = annealViewpoint(evaluator, start, options);
    options.polishDeg = 16.0;
    const AnnealingResult run = annealViewpoint(evaluator, start, options);
    ASSERT_EQ(run.visited.size(), plain.visited.size() + 12);
    for (std::size_t i = 0; i < plain.visited.size(); ++i) {
        EXPECT_EQ(run.visited[i].value.energy, plain.visited[i].value.energy) << "the annealing itself is unchanged";
        EXPECT_FALSE(run.visited[i].polish);
    }
    double step = 16.0;
    for (std::size_t round = 0; round < 3; ++round, step *= 0.5) {
        const std::size_t first = plain.visited.size() + 4 * round;
        // The centre: the best of every view before this round.
        std::size_t centre = 0;
        for (std::size_t i = 0; i < first; ++i)
            if (run.visited[i].value.energy > run.visited[centre].value.energy) centre = i;
        for (std::size_t k = 0; k < 4; ++k) {
            const VisitedView& view = run.visited[first + k];
            EXPECT_TRUE(view.polish);
            const double dTheta = std::abs(view.thetaDeg - run.visited[centre].thetaDeg);
            const double dPhi = std::abs(std::remainder(view.phiDeg - run.visited[centre].phiDeg, 360.0));
            EXPECT_NEAR(dTheta + dPhi, step, 1e-9) << "round " << round << ", neighbour " << k;
            EXPECT_TRUE(dTheta == 0.0 || dPhi < 1e-9) << "one angle moves at a time";
        }
    }
    double best = 0.0;
    for (const VisitedView& view : run.visited) best = std::max(best, view.value.energy);
    EXPECT_EQ(run.bestView().value.energy, best);
    EXPECT_GE(best, plain.bestView().value.energy);
}

TEST(ViewpointAnnealing, AcceptsAWorseProposalWithProbabilityExpOfTenGainOverT)
{
    std::mt19937_64 random(7);
    const int draws = 20000;
    for (const auto& [gain, temperature] : {std::pair{-0.01, 1.0}, {-0.05, 1.0}, {-0.05, 0.5}, {-0.2, 1.0}}) {
        int accepted = 0;
        for (int i = 0; i < draws; ++i)
            accepted += acceptsProposal(gain, temperature, 10.0, double(random() >> 11) * 0x1.0p-53) ? 1 : 0;
        const double expected = std::exp(10.0 * gain / temperature);
        const double sigma = std::sqrt(expected * (1.0 - expected) / draws);
        EXPECT_NEAR(double(accepted) / draws, expected, 5.0 * sigma)
            << "gain " << gain << " at temperature " << temperature;
    }
    EXPECT_TRUE(acceptsProposal(1e-9, 1.0, 10.0, 1.0)) << "a gain is always accepted";
    EXPECT_TRUE(acceptsProposal(0.0, 1.0, 10.0, 0.999)) << "an equal energy is accepted (exp(0) = 1)";
}

TEST(ViewpointAnnealing, AcceptsWorseViewsAtTheMetropolisRate)
{
    // At a constant temperature every worse proposal is accepted with probability exp(10 dE / T):
    // the accepted count over a run must match the sum of those probabilities (binomial z-score).
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(16));
    AnnealingOptions options;
    options.steps = 200;
    options.cooling = 1.0;
    options.startTemperature = 0.15;
    const AnnealingResult run = annealViewpoint(evaluator, makeMethod("neugebauer"), options);
    double expected = 0.0, variance = 0.0;
    int accepted = 0, worse = 0;
    const VisitedView* current = &run.visited[0];
    for (std::size_t i = 1; i < run.visited.size(); ++i) {
        const VisitedView& view = run.visited[i];
        const double gain = view.value.energy - current->value.energy;
        if (gain <= 0.0) {
            const double p = std::exp(10.0 * gain / options.startTemperature);
            expected += p;
            variance += p * (1.0 - p);
            accepted += view.accepted ? 1 : 0;
            ++worse;
        }
        if (view.accepted) current = &view;
    }
    ASSERT_GE(variance, 4.0) << "the run must offer enough uncertain proposals to test the rule";
    EXPECT_LT(std::abs(accepted - expected), 4.0 * std::sqrt(variance))
        << accepted << " of " << worse << " worse views accepted, " << expected << " expected";
}

// The mirror's footprint moves with w: each view is measured at the framing of the parameters its
// ascent ends with, and its energy is that of the picture shown there; a fixed field of view is
// kept for every view.
TEST(ViewpointAnnealing, EachViewIsMeasuredAtTheFramingOfItsFinalParameters)
{
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(16));
    AnnealingOptions options;
    options.steps = 3;
    AscentOptions ascent;
    ascent.maxIterations = 1;
    const AnnealingResult run = annealViewpoint(evaluator, makeMethod("mirror"), options, ascent);
    int moved = 0;
    for (std::size_t i = 0; i < run.visited.size(); ++i) {
        const VisitedView& view = run.visited[i];
        const core::Camera framed =
            render::frameView(*fixture.scene, core::Camera::fromAngles(view.thetaDeg, view.phiDeg), *view.method, 1.0);
        EXPECT_EQ(view.camera.fovYDeg, framed.fovYDeg) << "view " << i;
        EXPECT_EQ(view.value.energy, evaluator.evaluate(view.camera, view.method).energy) << "view " << i;
        const core::Camera before =
            render::frameView(*fixture.scene, core::Camera::fromAngles(view.thetaDeg, view.phiDeg), *makeMethod("mirror"), 1.0);
        moved += view.camera.fovYDeg != before.fovYDeg;
    }
    EXPECT_GT(moved, 0) << "w must move the framing for the test to mean anything";
    options.fovYDeg = 50.0;
    for (const VisitedView& view : annealViewpoint(evaluator, makeMethod("mirror"), options, ascent).visited)
        EXPECT_EQ(view.camera.fovYDeg, 50.0);
}

TEST(ViewpointAnnealing, CoarseAscentIsMeasuredOnTheFullEnergyAndTheWinnerAscendedThere)
{
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(48));
    const EnergyEvaluator ascentEvaluator(*fixture.scene, visibilityOptions(16));
    AnnealingOptions options;
    options.steps = 4;
    const AnnealingResult run = annealViewpoint(evaluator, faithful(), options, {}, &ascentEvaluator);
    ASSERT_EQ(run.visited.size(), 5u);
    // Each proposal ascends from the current view's coarse parameters (the winner's are replaced
    // by its final ascent afterwards, so they are recomputed here).
    MethodPtr from = faithful();
    for (std::size_t i = 0; i < run.visited.size(); ++i) {
        const VisitedView& view = run.visited[i];
        // Framed for the method (InverseVis: the framing does not move with alpha).
        const core::Camera camera = render::frameView(*fixture.scene, core::Camera::fromAngles(view.thetaDeg, view.phiDeg), *from, 1.0);
        EXPECT_EQ(view.camera.fovYDeg, camera.fovYDeg) << "view " << i << " is framed";
        const AscentResult ascended = optimizeParameters(ascentEvaluator, camera, from);
        const EnergyValue measured = evaluator.evaluate(camera, view.method);
        EXPECT_EQ(view.value.energy, measured.energy) << "view " << i << " is measured on the full energy";
        if (i == run.best) {
            EXPECT_GE(view.value.energy, evaluator.evaluate(camera, ascended.method).energy) << "the winner's ascent";
        } else {
            EXPECT_EQ(view.method->values(), ascended.method->values()) << "view " << i << " ascends coarsely";
        }
        EXPECT_LE(view.value.energy, run.bestView().value.energy);
        if (i == 0 || view.accepted) from = ascended.method;
    }
}

TEST(ViewpointAnnealing, FinalistsAreTheBestViewsAndTheFinerEnergyPicksAmongThem)
{
    const auto& fixture = test::vesselScene();
    const EnergyEvaluator evaluator(*fixture.scene, visibilityOptions(8));
    const EnergyEvaluator finer(*fixture.scene, visibilityOptions(64));
    AnnealingOptions options;
    options.steps = 12;
    const MethodPtr start = makeMethod("neugebauer");  // nothing optimised: the test is about the view search
    const AnnealingResult plain = annealViewpoint(evaluator, start, options);
    options.finalists = 4;
    const AnnealingResult run = annealViewpoint(evaluator, start, options, {}, nullptr, nullptr, &finer);
    ASSERT_EQ(run.visited.size(), plain.visited.size());
    double lowestFinalist = 1.0, highestOther = 0.0, bestFinal = 0.0;
    int finalists = 0;
    for (std::size_t i = 0; i < run.visited.size(); ++i) {
        const VisitedView& view = run.visited[i];
        EXPECT_EQ(view.value.energy, plain.visited[i].value.energy) << "the annealing itself is unchanged";
        if (!view.finalValue) {
            highestOther = std::max(highestOther, view.value.energy);
            continue;
        }
        ++finalists;
        lowestFinalist = std::min(lowestFinalist, view.value.energy);
        EXPECT_EQ(view.finalValue->energy, finer.evaluate(view.camera, view.method).energy);
        bestFinal = std::max(bestFinal, view.finalValue->energy);
    }
    EXPECT_EQ(finalists, 4);
    EXPECT_GE(lowestFinalist, highestOther) << "the finalists are the views of highest energy";
    ASSERT_TRUE(run.bestView().finalValue);
    EXPECT_EQ(run.bestView().finalValue->energy, bestFinal);
    EXPECT_GT(bestFinal, finer.evaluate(plain.bestView().camera, plain.bestView().method).energy)
        << "on 8 rays per side the annealing's best is not the best of its finalists on 64";
}

}  // namespace
}  // namespace ivis::optimize
