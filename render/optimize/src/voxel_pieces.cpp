#include <ivis/optimize/voxel_pieces.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {
namespace {

using Visit = std::function<void(const glm::ivec3&, const ConvexPiece&)>;

/// Appends @a p to @a piece (the capacity holds every cut of a triangle by a voxel's planes).
void append(ConvexPiece& piece, const glm::dvec3& p)
{
    if (piece.size < int(piece.corners.size())) piece.corners[std::size_t(piece.size++)] = p;
}

/// Splits @a piece at the plane where coordinate @a axis equals @a value into the part below and the part above.
void split(const ConvexPiece& piece, int axis, double value, ConvexPiece& below, ConvexPiece& above)
{
    below.size = above.size = 0;
    for (int i = 0; i < piece.size; ++i) {
        const glm::dvec3& p = piece.corners[std::size_t(i)];
        const glm::dvec3& q = piece.corners[std::size_t((i + 1) % piece.size)];
        const double dp = p[axis] - value, dq = q[axis] - value;
        if (dp <= 0.0) append(below, p);
        if (dp >= 0.0) append(above, p);
        if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
            glm::dvec3 crossing = p + (dp / (dp - dq)) * (q - p);
            crossing[axis] = value;  // exactly on the plane, whatever the rounding
            append(below, crossing);
            append(above, crossing);
        }
    }
}

/// Cuts @a piece along the integer planes of @a axis and of the axes after it; @a voxel holds
/// the voxel's coordinates on the axes before.
void cutAlong(const ConvexPiece& piece, int axis, glm::ivec3 voxel, const Visit& visit)
{
    if (axis == 3) {
        visit(voxel, piece);
        return;
    }
    double lo = piece.corners[0][axis], hi = lo;
    for (int i = 1; i < piece.size; ++i) {
        lo = std::min(lo, piece.corners[std::size_t(i)][axis]);
        hi = std::max(hi, piece.corners[std::size_t(i)][axis]);
    }
    const int first = int(std::floor(lo)), last = std::max(first, int(std::ceil(hi)) - 1);
    ConvexPiece rest = piece, below, above;
    for (int cell = first; cell < last; ++cell) {
        split(rest, axis, double(cell + 1), below, above);
        voxel[axis] = cell;
        if (below.size >= 3) cutAlong(below, axis + 1, voxel, visit);
        rest = above;
        if (rest.size < 3) return;
    }
    voxel[axis] = last;
    cutAlong(rest, axis + 1, voxel, visit);
}

}  // namespace

double pieceArea(const ConvexPiece& piece)
{
    glm::dvec3 sum(0.0);
    for (int i = 1; i + 1 < piece.size; ++i)
        sum += glm::cross(piece.corners[std::size_t(i)] - piece.corners[0], piece.corners[std::size_t(i + 1)] - piece.corners[0]);
    return 0.5 * glm::length(sum);
}

void cutIntoVoxels(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const Visit& visit)
{
    ConvexPiece triangle;
    triangle.corners[0] = a;
    triangle.corners[1] = b;
    triangle.corners[2] = c;
    triangle.size = 3;
    if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z)) return;
    cutAlong(triangle, 0, glm::ivec3(0), visit);
}

}  // namespace ivis::optimize
