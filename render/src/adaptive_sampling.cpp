#include <ivis/render/adaptive_sampling.h>

#include <ivis/render/screen_map.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace ivis::render {
namespace {

constexpr int kSide = kAdaptiveTileSize + 1;  ///< lattice points per side of a tile (its far edge included)
/// The stability rule is read off the neighbours' landings only where neighbouring pixels lie at
/// most 1 / this many probe steps apart (a picture of about 700 pixels or more of the object).
constexpr float kLeastProbeToPixelRatio = 0.6f;

/// What is known of one pixel (or lattice point beyond the tile's last row or column).
enum class PointState : std::uint8_t {
    Unknown,     ///< not sampled
    Direct,      ///< its view ray hits the surface
    Landed,      ///< its ray, as the method aims it, lands
    Missed,      ///< its ray was launched and did not land
    Refused,     ///< the method gives it no ray, near the edge of where it gives rays
    Background   ///< the method gives it no ray, clearly (no seed, or well beyond its ring)
};

/// One pixel: its state and, for a seeded ray, its start and end.
struct PixelRay {
    PointState state = PointState::Unknown;
    bool seeded = false;  ///< start.seed and start.rayParameter hold its view ray's seed
    CurvedRayStart start;
    CurvedRayEnd end;
};

/// A square block of the lattice: corner (x, y) in tile pixels and side `size` (a power of two).
struct Block {
    int x, y, size;
};

/// A lattice point to sample and, where its block's corners were seeded, a valley bottom to
/// start its seed search from (CurvedRayMap::aimedStartHinted).
struct LatticePoint {
    glm::ivec2 at;
    bool hinted = false;
    float hint = 0.0f;   ///< the bilinear map of the corners' bottoms there
    float reach = 0.0f;  ///< how far from it to seek: the corners' spread about it and the tolerance
};

/// The Lagrange weights of the three lattice points 0, 1/2 and 1 of a block side at fraction u.
std::array<float, 3> quadraticWeights(float u)
{
    return {2.0f * (u - 0.5f) * (u - 1.0f), -4.0f * u * (u - 1.0f), 2.0f * u * (u - 0.5f)};
}

/// Adaptive sampling of one tile (mapTileAdaptively).
class TileSampling {
public:
    TileSampling(const ScreenMap& screen, const CurvedRayMap& rays, const AdaptiveSampling& options,
                 const PixelTile& tile, const glm::dvec2& offset, DistanceField::Sampler& sampler,
                 PixelMapping* mappings, TileCounts& counts)
        : mScreen(screen), mRays(rays), mOptions(options), mTile(tile), mOffset(offset), mSampler(sampler),
          mMappings(mappings), mCounts(counts), mStability(rays.method().stabilityScale()),
          mBottomTolerance(options.bottomTolerance * sampler.field().voxelSize()),
          // Where the far field is the fine grid itself (volume 200) a view ray's coarse march is a
          // few dozen samples, which a hint does not measurably spare: there every lattice point
          // marches its whole view ray as the full trace does.
          mHintSeeds(sampler.field().hasFineBand())
    {
    }

    void run()
    {
        mapDirectPixels();
        std::vector<Block> level{{0, 0, kAdaptiveTileSize}}, next, background, smoothBottoms;
        while (!level.empty()) {
            sample(latticeOf(level));
            next.clear();
            for (const Block& block : level) {
                if (isClearBackground(block)) {
                    background.push_back(block);
                } else if (hasSmoothBottoms(block)) {
                    smoothBottoms.push_back(block);
                } else if (block.size > 2) {
                    const int half = block.size / 2;
                    for (int dy = 0; dy < 2; ++dy)
                        for (int dx = 0; dx < 2; ++dx) {
                            const Block child{block.x + dx * half, block.y + dy * half, half};
                            if (child.x < mTile.width && child.y < mTile.height) next.push_back(child);
                        }
                }  // else every pixel of the block is a lattice point, sampled
            }
            level.swap(next);
        }
        sampleBetween(smoothBottoms);
        for (const Block& block : background) markBackground(block);
        mapRays();
    }

private:
    PixelRay& ray(int x, int y) { return mRays_[std::size_t(y) * kSide + x]; }
    bool inTile(int x, int y) const { return x < mTile.width && y < mTile.height; }
    PixelMapping& mapping(int x, int y) { return mMappings[std::size_t(y) * mTile.width + x]; }
    glm::dvec2 position(int x, int y) const { return {mTile.x0 + x + mOffset.x, mTile.y0 + y + mOffset.y}; }

    /// Every pixel's straight view ray, exact, and the count of direct pixels above and left of each.
    void mapDirectPixels()
    {
        for (int y = 0; y < mTile.height; ++y)
            for (int x = 0; x < mTile.width; ++x) {
                const glm::dvec2 p = position(x, y);
                mapping(x, y) = mScreen.directHit(p.x, p.y);
                const int direct = mapping(x, y).region == Region::Direct;
                if (direct) ray(x, y).state = PointState::Direct;
                directBelow(x + 1, y + 1) = direct + directBelow(x + 1, y) + directBelow(x, y + 1) - directBelow(x, y);
            }
    }
    int& directBelow(int x, int y) { return mDirectBelow[std::size_t(y) * kSide + x]; }

    /// Whether some pixel of the tile in columns x0..x1 and rows y0..y1 (clipped to the tile) is direct.
    bool anyDirect(int x0, int y0, int x1, int y1)
    {
        x1 = std::min(x1, mTile.width - 1) + 1, y1 = std::min(y1, mTile.height - 1) + 1;
        return directBelow(x1, y1) - directBelow(x0, y1) - directBelow(x1, y0) + directBelow(x0, y0) > 0;
    }

    /// The points of the blocks' 3 x 3 lattices not yet sampled, each once, hinted by the bottoms of
    /// their block's corners where all four were seeded (the corners of a split block's quarters).
    std::vector<LatticePoint> latticeOf(const std::vector<Block>& blocks)
    {
        std::vector<LatticePoint> points;
        for (const Block& block : blocks) {
            const int half = block.size / 2;
            const PixelRay* corners[4] = {&ray(block.x, block.y), &ray(block.x + block.size, block.y),
                                          &ray(block.x, block.y + block.size),
                                          &ray(block.x + block.size, block.y + block.size)};
            bool hinted = mHintSeeds;
            for (const PixelRay* c : corners) hinted = hinted && c->seeded;
            const auto bottom = [&corners](int k) { return corners[k]->start.valleyBottom; };
            for (int j = 0; j <= 2; ++j)
                for (int i = 0; i <= 2; ++i) {
                    const int x = block.x + i * half, y = block.y + j * half;
                    if (ray(x, y).state != PointState::Unknown || mQueued[std::size_t(y) * kSide + x]) continue;
                    mQueued[std::size_t(y) * kSide + x] = true;
                    LatticePoint point{{x, y}};
                    if (hinted) {
                        const float u = 0.5f * float(i), v = 0.5f * float(j);
                        point.hinted = true;
                        point.hint =
                            (1.0f - v) * ((1.0f - u) * bottom(0) + u * bottom(1)) + v * ((1.0f - u) * bottom(2) + u * bottom(3));
                        for (int k = 0; k < 4; ++k) point.reach = std::max(point.reach, std::abs(bottom(k) - point.hint));
                        point.reach += mBottomTolerance;
                    }
                    points.push_back(point);
                }
        }
        return points;
    }

    /// Seeds, aims and traces the rays of @a points (lattice points: their own seeds, sought from
    /// their hints where they have one), the rays together.
    void sample(const std::vector<LatticePoint>& points)
    {
        std::vector<PixelRay*> launched;
        for (const LatticePoint& q : points) {
            PixelRay& r = ray(q.at.x, q.at.y);
            const glm::dvec2 at = position(q.at.x, q.at.y);
            if (!inTile(q.at.x, q.at.y) && mScreen.directHit(at.x, at.y).region == Region::Direct) {
                r.state = PointState::Direct;
                continue;
            }
            aimed(r,
                  q.hinted ? mRays.aimedStartHinted(at.x, at.y, q.hint, q.reach, mSampler, r.start)
                           : mRays.aimedStart(at.x, at.y, mSampler, r.start),
                  launched);
        }
        trace(launched);
    }

    /// Records an aimed start (seeded unless refused for want of a seed), queueing it for tracing when aimed.
    void aimed(PixelRay& r, bool aimedOk, std::vector<PixelRay*>& launched)
    {
        r.seeded = r.start.refusal != Refusal::NoSeed;
        if (aimedOk) {
            r.state = PointState::Missed;  // until its ray lands
            launched.push_back(&r);
        } else {
            r.state = isClearlyRefused(r.start) ? PointState::Background : PointState::Refused;
        }
    }

    /// Traces the launched rays together (CurvedRayMap::traceMany).
    void trace(const std::vector<PixelRay*>& launched)
    {
        std::vector<CurvedRayStart> starts;
        starts.reserve(launched.size());
        for (const PixelRay* r : launched) starts.push_back(r->start);
        std::vector<CurvedRayTrace> traces(starts.size());
        mRays.traceMany(starts.data(), starts.size(), mSampler, traces.data());
        for (std::size_t k = 0; k < launched.size(); ++k) {
            PixelRay& r = *launched[k];
            r.end = traces[k].end;
            if (traces[k].launch == 0) r.start.traced = r.end;  // the first launch's end, for the stability rule
            if (r.end.landed) r.state = PointState::Landed;
            mCounts.steps += std::size_t(r.end.steps);
        }
        mCounts.raysTraced += launched.size();
    }

    /// A refusal that no neighbouring pixel is likely to escape: no seed, or a seed well beyond its ring.
    bool isClearlyRefused(const CurvedRayStart& start) const
    {
        return start.refusal == Refusal::NoSeed ||
               (start.refusal == Refusal::BeyondRing && start.ring &&
                start.ring->coordinate >= 1.0f + mOptions.beyondRingMargin);
    }

    /// The block's nine lattice points (row by row).
    std::array<PixelRay*, 9> nine(const Block& block)
    {
        std::array<PixelRay*, 9> points;
        const int half = block.size / 2;
        for (int j = 0; j <= 2; ++j)
            for (int i = 0; i <= 2; ++i) points[std::size_t(3 * j + i)] = &ray(block.x + i * half, block.y + j * half);
        return points;
    }

    /// Every lattice point of the block is clearly background or its ray missed, and no pixel in it is direct.
    bool isClearBackground(const Block& block)
    {
        for (const PixelRay* r : nine(block))
            if (r->state != PointState::Background && r->state != PointState::Missed) return false;
        return !anyDirect(block.x, block.y, block.x + block.size, block.y + block.size);
    }

    /// Every lattice point of the block is seeded and the bilinear map of its corners' valley
    /// bottoms (CurvedRayStart::valleyBottom) meets the other five within the tolerance.
    bool hasSmoothBottoms(const Block& block)
    {
        const std::array<PixelRay*, 9> points = nine(block);
        for (const PixelRay* r : points)
            if (r->state == PointState::Direct || !r->seeded) return false;
        auto t = [&](int i, int j) { return points[std::size_t(3 * j + i)]->start.valleyBottom; };
        for (int j = 0; j <= 2; ++j)
            for (int i = 0; i <= 2; ++i) {
                if (i != 1 && j != 1) continue;  // a corner
                const float u = 0.5f * float(i), v = 0.5f * float(j);
                const float bilinear = (1.0f - v) * ((1.0f - u) * t(0, 0) + u * t(2, 0)) + v * ((1.0f - u) * t(0, 2) + u * t(2, 2));
                if (!(std::abs(bilinear - t(i, j)) <= mBottomTolerance)) return false;
            }
        return true;
    }

    /// The pixels of blocks with smooth valley bottoms that are not lattice points: each seeded from
    /// a bottom sought only near the one interpolated from the lattice (biquadratic through the
    /// nine), then aimed, the rays traced together.
    void sampleBetween(const std::vector<Block>& blocks)
    {
        std::vector<PixelRay*> launched;
        for (const Block& block : blocks) {
            const std::array<PixelRay*, 9> points = nine(block);
            const int x1 = std::min(block.x + block.size, mTile.width), y1 = std::min(block.y + block.size, mTile.height);
            for (int y = block.y; y < y1; ++y)
                for (int x = block.x; x < x1; ++x) {
                    PixelRay& r = ray(x, y);
                    if (r.state != PointState::Unknown) continue;  // direct, or sampled as a lattice point
                    const std::array<float, 3> wu = quadraticWeights(float(x - block.x) / float(block.size));
                    const std::array<float, 3> wv = quadraticWeights(float(y - block.y) / float(block.size));
                    float t = 0.0f;
                    for (int j = 0; j <= 2; ++j)
                        for (int i = 0; i <= 2; ++i)
                            t += wu[std::size_t(i)] * wv[std::size_t(j)] * points[std::size_t(3 * j + i)]->start.valleyBottom;
                    const glm::dvec2 at = position(x, y);
                    aimed(r, mRays.aimedStartNear(at.x, at.y, t, mBottomTolerance, mSampler, r.start), launched);
                    ++mCounts.seedsInterpolated;
                }
        }
        trace(launched);
    }

    /// The pixels of a background block that have no ray of their own: background without one.
    void markBackground(const Block& block)
    {
        const int x1 = std::min(block.x + block.size, mTile.width), y1 = std::min(block.y + block.size, mTile.height);
        for (int y = block.y; y < y1; ++y)
            for (int x = block.x; x < x1; ++x)
                if (ray(x, y).state == PointState::Unknown) {
                    ray(x, y).state = PointState::Background;
                    ++mCounts.pixelsSkipped;
                }
    }

    /// What every non-direct pixel shows: its ray's landing where the stability rule draws it (the
    ///        rule's probes traced together, for the rays whose neighbours do not show them drawn).
    void mapRays()
    {
        std::vector<glm::ivec2> judged;
        std::vector<CurvedRayStart*> starts;
        for (int y = 0; y < mTile.height; ++y)
            for (int x = 0; x < mTile.width; ++x) {
                PixelRay& r = ray(x, y);
                if (r.state != PointState::Landed && r.state != PointState::Missed) continue;
                if (r.state == PointState::Landed && isClearlyStable(x, y)) {
                    mapping(x, y) = mRays.landedAt(r.end, mSampler);
                    continue;
                }
                judged.push_back({x, y});
                starts.push_back(&r.start);
            }
        std::unique_ptr<bool[]> stable(new bool[starts.size()]);
        mRays.areStable(starts.data(), starts.size(), mSampler, stable.get());
        for (std::size_t k = 0; k < judged.size(); ++k) {
            if (!stable[k]) continue;
            const CurvedRayEnd& end = ray(judged[k].x, judged[k].y).end;
            mapping(judged[k].x, judged[k].y) = end.landed ? mRays.landedAt(end, mSampler) : launchedMiss(end.steps);
        }
    }

    /// Whether the landings of the pixel's neighbours, each row and column of three scaled to the
    /// stability rule's probe step, bend far less than the rule allows: the rule would draw it.
    bool isClearlyStable(int x, int y)
    {
        if (!mStability) return true;  // no rule: every ray that lands is drawn
        const PixelRay& r = ray(x, y);
        const float step = std::min(mStability->probeStep, r.start.seedDistance);
        const float scale = step / mRays.pixelFootprint(r.start.seed);
        // Pixels much further apart than the probes do not see what the probes see (a small picture).
        if (scale < kLeastProbeToPixelRatio) return false;
        const float allowed = mOptions.clearlyStableShare * mStability->largestBend / (scale * scale);
        // Any direction's second difference is at most the larger of the rows' and columns' plus
        // the mixed one (of a smooth map): the probes' direction across the ring is not an axis.
        return std::max(bendOfThree(x, y, 1, 0), bendOfThree(x, y, 0, 1)) + mixedBend(x, y) <= allowed;
    }

    /// |P(x+1, y+1) - P(x+1, y-1) - P(x-1, y+1) + P(x-1, y-1)| / 4 of landed neighbours (one-sided
    /// at the tile's first and last rows and columns: the far edge beyond them holds only lattice
    /// points); infinite where one does not land.
    float mixedBend(int x, int y)
    {
        const int x0 = std::clamp(x - 1, 0, kAdaptiveTileSize - 3), y0 = std::clamp(y - 1, 0, kAdaptiveTileSize - 3);
        const int x1 = x0 + 2, y1 = y0 + 2;
        const PixelRay *a = &ray(x0, y0), *b = &ray(x1, y0), *c = &ray(x0, y1), *d = &ray(x1, y1);
        for (const PixelRay* r : {a, b, c, d})
            if (r->state != PointState::Landed) return std::numeric_limits<float>::infinity();
        return 0.25f * glm::length(d->end.position - b->end.position - c->end.position + a->end.position);
    }

    /// The bend |P(a) + P(c) - 2 P(b)| of three landed pixels in a row along (dx, dy) through
    /// (x, y): centred on it, else starting at it; infinite where none lands.
    float bendOfThree(int x, int y, int dx, int dy)
    {
        auto landing = [&](int i, int j, glm::vec3& p) {
            if (i < 0 || j < 0 || i >= kSide || j >= kSide) return false;
            const PixelRay& r = ray(i, j);
            p = r.end.position;
            return r.state == PointState::Landed;
        };
        glm::vec3 a(0.0f), b(0.0f), c(0.0f);
        if ((landing(x - dx, y - dy, a) && landing(x, y, b) && landing(x + dx, y + dy, c)) ||
            (landing(x, y, a) && landing(x + dx, y + dy, b) && landing(x + 2 * dx, y + 2 * dy, c)) ||
            (landing(x - 2 * dx, y - 2 * dy, a) && landing(x - dx, y - dy, b) && landing(x, y, c)))
            return glm::length(a + c - 2.0f * b);
        return std::numeric_limits<float>::infinity();
    }


    const ScreenMap& mScreen;
    const CurvedRayMap& mRays;
    const AdaptiveSampling& mOptions;
    const PixelTile& mTile;
    glm::dvec2 mOffset;
    DistanceField::Sampler& mSampler;
    PixelMapping* mMappings;
    TileCounts& mCounts;
    std::optional<StabilityScale> mStability;
    float mBottomTolerance;  ///< normalised units along the view ray
    bool mHintSeeds;         ///< whether lattice points start their seed search from their corners' bottoms
    std::array<PixelRay, kSide * kSide> mRays_{};
    std::array<bool, kSide * kSide> mQueued{};
    std::array<int, kSide * kSide> mDirectBelow{};  ///< direct pixels above and left of each lattice point
};

}  // namespace

void mapTileAdaptively(const ScreenMap& screen, const CurvedRayMap& rays, const AdaptiveSampling& options,
                       const PixelTile& tile, const glm::dvec2& offset, DistanceField::Sampler& sampler,
                       PixelMapping* mappings, TileCounts& counts)
{
    TileSampling(screen, rays, options, tile, offset, sampler, mappings, counts).run();
}

}  // namespace ivis::render
