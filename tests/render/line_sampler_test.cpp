// LineQuartic and LineSampler on the unit sphere (fine band at resolution 100, far field at 40):
// the quartic of a far cell against DenseGrid::valueAndGradient at points along the line inside
// it, its parameter range against the cells the points fall in, its lower bound against dense
// samples, and LineSampler (sampled once, marching, or skipping what lies above a bound) against
// DistanceField::Sampler::phi along lines through the band and the far field.
#include "render/scene_fixture.h"

#include <ivis/render/distance_field.h>
#include <ivis/render/line_sampler.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace ivis::render {
namespace {

/// A random unit direction.
glm::vec3 randomDirection(std::mt19937& random)
{
    std::normal_distribution<float> normal;
    return glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
}

TEST(LineQuartic, IsTheBlendAlongTheLineWithinItsCell)
{
    const DistanceField field(test::sphereWithFarField().volume);
    const DenseGrid& far = field.farGrid();
    const float voxel = far.voxelSize();
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1.6f, 1.6f);
    int cells = 0;
    for (int line = 0; line < 2000; ++line) {
        const glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random));
        const glm::vec3 direction = randomDirection(random);
        LineQuartic quartic;
        if (!far.lineQuartic(origin, direction, 0.0f, quartic)) continue;
        ++cells;
        ASSERT_TRUE(quartic.covers(0.0f));
        ASSERT_LE(quartic.hi - quartic.lo, std::sqrt(3.0f) * voxel * 1.0001f) << "no chord of a cell is longer";
        const std::ptrdiff_t cell = far.cellIndex(origin);
        for (int k = 0; k <= 20; ++k) {
            const float s = quartic.lo + (quartic.hi - quartic.lo) * float(k) / 20.0f;
            glm::vec3 gradient;
            const float blended = far.valueAndGradient(origin + s * direction, gradient);
            EXPECT_NEAR(quartic.at(s), blended, 2e-6f * (1.0f + std::abs(blended))) << "line " << line << " s " << s;
        }
        // Just inside its range the line is in the cell; just beyond it, in a neighbouring one.
        const float inside = 1e-3f * voxel;
        EXPECT_EQ(far.cellIndex(origin + (quartic.lo + inside) * direction), cell);
        EXPECT_EQ(far.cellIndex(origin + (quartic.hi - inside) * direction), cell);
        EXPECT_NE(far.cellIndex(origin + (quartic.lo - inside) * direction), cell);
        EXPECT_NE(far.cellIndex(origin + (quartic.hi + inside) * direction), cell);
    }
    EXPECT_GT(cells, 1500) << "most lines start inside the far field's box";
}

TEST(LineQuartic, LowerBoundLiesBelowTheQuarticAndTightensOnShortIntervals)
{
    std::mt19937 random(5);
    std::uniform_real_distribution<float> coefficient(-1.0f, 1.0f), position(0.0f, 1.0f);
    for (int trial = 0; trial < 2000; ++trial) {
        LineQuartic quartic;
        quartic.lo = -1.0f, quartic.hi = 2.0f, quartic.s0 = 0.5f;
        for (float& c : quartic.c) c = coefficient(random);
        const float from = position(random), to = from + position(random);
        float least = std::numeric_limits<float>::max();
        for (int k = 0; k <= 1000; ++k) least = std::min(least, quartic.at(from + (to - from) * float(k) / 1000.0f));
        EXPECT_LE(quartic.lowerBound(from, to), least + 1e-5f) << "trial " << trial;
        // On an interval a thousandth as long the bound is the quartic's value to first order.
        const float shortTo = from + 1e-3f * (to - from);
        EXPECT_NEAR(quartic.lowerBound(from, shortTo), std::min(quartic.at(from), quartic.at(shortTo)), 1e-4f);
    }
}

TEST(LineSampler, GivesTheSamplersPhiAlongALine)
{
    const DistanceField field(test::sphereWithFarField().volume);
    ASSERT_TRUE(field.hasFineBand()) << "the quartics serve only a separate far field";
    auto sampler = field.sampler();
    std::mt19937 random(11);
    const float spacing = 0.25f * field.voxelSize();
    int inBand = 0, inFarField = 0;
    for (int line = 0; line < 200; ++line) {
        // Lines from outside the hull passing the sphere at 0 to 0.6 from its surface.
        const glm::vec3 direction = randomDirection(random);
        glm::vec3 side = glm::normalize(glm::cross(direction, randomDirection(random)));
        const float pass = 1.0f + 0.6f * float(line) / 200.0f;
        const glm::vec3 origin = pass * side - 2.0f * direction;
        LineSampler samples(sampler, origin, direction), marching(sampler, origin, direction);
        for (float s = 0.0f; s < 4.0f; s += spacing) {
            const float expected = sampler.phi(origin + s * direction);
            EXPECT_NEAR(samples.phi(s), expected, 2e-6f * (1.0f + std::abs(expected))) << "line " << line << " s " << s;
            EXPECT_NEAR(marching.phiMarching(s, spacing), expected, 2e-6f * (1.0f + std::abs(expected)))
                << "line " << line << " s " << s;
            (expected > field.fineUntil() ? inFarField : inBand) += 1;
        }
    }
    EXPECT_GT(inBand, 1000);
    EXPECT_GT(inFarField, 50000);
}

TEST(LineSampler, SkipsOnlyWhatLiesAboveTheLeastSoFar)
{
    // A march from each line's start keeping the least phi: whatever skipAbove passes over, the
    // sampler's phi there (every hundredth of a voxel) is no lower than the least at that point.
    const DistanceField field(test::sphereWithFarField().volume);
    auto sampler = field.sampler();
    std::mt19937 random(13);
    const float spacing = 0.25f * field.voxelSize(), dense = 0.01f * field.voxelSize();
    int skips = 0;
    for (int line = 0; line < 200; ++line) {
        const glm::vec3 direction = randomDirection(random);
        const glm::vec3 side = glm::normalize(glm::cross(direction, randomDirection(random)));
        const glm::vec3 origin = (1.0f + 0.6f * float(line) / 200.0f) * side - 2.0f * direction;
        LineSampler samples(sampler, origin, direction);
        float best = std::numeric_limits<float>::max();
        for (float s = 0.0f, lastStep = 4.0f; s < 4.0f;) {
            const float phi = samples.phiMarching(s, lastStep);
            best = std::min(best, phi);
            const float next = s + std::max(phi - best, spacing), resumed = samples.skipAbove(s, next, best);
            ASSERT_GE(resumed, next);
            if (resumed > next) {
                ++skips;
                for (float u = next; u < resumed; u += dense)
                    ASSERT_GE(sampler.phi(origin + u * direction), best - 2e-6f * (1.0f + std::abs(best)))
                        << "line " << line << " s " << u;  // the quartic is the blend up to rounding
            }
            lastStep = resumed - s;
            s = resumed;
        }
    }
    EXPECT_GT(skips, 1000) << "the march skips the rest of many far cells";
}

}  // namespace
}  // namespace ivis::render
