#include "crossdiv/volume/marching_cubes.h"

#include <array>
#include <cmath>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

const char* to_string(AmbiguousFaceRule rule) {
    return rule == AmbiguousFaceRule::AsymptoticDecider ? "decider" : "minority";
}

AmbiguousFaceRule ambiguous_face_rule_from_string(std::string_view name) {
    if (name == "decider") return AmbiguousFaceRule::AsymptoticDecider;
    if (name == "minority") return AmbiguousFaceRule::SeparateMinority;
    throw InputError("unknown ambiguous-face rule '" + std::string(name) + "' (decider, minority)");
}

namespace {

// Cube corner c sits at offset (c & 1, c >> 1 & 1, c >> 2 & 1) from the cube's lowest sample.
constexpr int kCornerOffset[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
// The 12 cube edges by their corners (lower first): x edges, then y, then z.
constexpr int kEdgeCorners[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// The 6 faces, corners counter-clockwise seen from outside the cube: -x, +x, -y, +y, -z, +z.
constexpr int kFaceCorners[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

/// Local edge of each corner pair, and the faces (bit per face) each local edge borders.
struct CubeTables {
    int edge_of[8][8];
    int edge_faces[12];
    constexpr CubeTables() : edge_of{}, edge_faces{} {
        for (int e = 0; e < 12; ++e) {
            edge_of[kEdgeCorners[e][0]][kEdgeCorners[e][1]] = e;
            edge_of[kEdgeCorners[e][1]][kEdgeCorners[e][0]] = e;
            edge_faces[e] = 0;
        }
        for (int f = 0; f < 6; ++f)
            for (int m = 0; m < 4; ++m) edge_faces[edge_of[kFaceCorners[f][m]][kFaceCorners[f][(m + 1) % 4]]] |= 1 << f;
    }
};
constexpr CubeTables kTables;

/// Whether the inside corners of an ambiguous face are joined across it. s_in are the values
/// (minus the level, negative) at its inside diagonal, s_out at its outside one.
bool join_inside(double in0, double in1, double out0, double out1, AmbiguousFaceRule rule, int inside_corners) {
    if (rule == AmbiguousFaceRule::SeparateMinority) return inside_corners > 4;
    // The bilinear interpolant's saddle value is (in0 in1 - out0 out1) / (in0 + in1 - out0 -
    // out1), whose denominator is negative here: the saddle is inside iff in0 in1 > out0 out1.
    // Scaled by a power of two first so that the products neither overflow nor underflow;
    // both cubes of the face compute the same products of the same four numbers.
    int exponent = 0;
    std::frexp(std::max(std::max(-in0, -in1), std::max(out0, out1)), &exponent);
    const auto scaled = [exponent](double x) { return std::ldexp(x, -exponent); };
    return scaled(in0) * scaled(in1) > scaled(out0) * scaled(out1);
}

}  // namespace

Isosurface marching_cubes(const ScalarGrid& grid, const IsosurfaceOptions& options) {
    if (!std::isfinite(options.level)) throw InputError("the isosurface level must be finite");
    const int nx = grid.size[0], ny = grid.size[1], nz = grid.size[2];
    const int64_t n = grid.num_samples(), slice = int64_t{nx} * ny;
    const double sign = options.inside == InsideIs::Below ? 1.0 : -1.0;
    // s(q) < 0 is inside; a sample at the level (s == 0) is outside. Computed where used rather
    // than stored: a copy of the samples would double the memory of the largest grids.
    const auto s = [&](int64_t q) { return sign * (grid.values[q] - options.level); };
    for (int64_t q = 0; q < n; ++q)
        if (!std::isfinite(s(q)))
            throw InputError("sample (" + std::to_string(q % nx) + ", " + std::to_string(q / nx % ny) + ", " +
                             std::to_string(q / slice) + "): its value minus the level " + std::to_string(options.level) +
                             " overflows");

    Isosurface out;
    // Vertex ids of the crossed edges near the slab of cubes being traversed: x and y edges of
    // two sample slices (by slice parity) and the z edges between them.
    std::vector<int> xy_vertex[2][2], z_vertex(slice);
    for (auto& parity : xy_vertex)
        for (auto& axis : parity) axis.assign(slice, -1);

    const auto make_vertex = [&](int axis, int i, int j, int k) -> int {
        const int64_t a = grid.index(i, j, k);
        const int64_t b = a + (axis == 0 ? 1 : axis == 1 ? nx : slice);
        const double sa = s(a), sb = s(b);
        if ((sa < 0) == (sb < 0)) return -1;
        const double t = sa / (sa - sb);
        Vec3 p = grid.position(i, j, k);
        p[axis] = grid.origin[axis] + grid.spacing[axis] * ((axis == 0 ? i : axis == 1 ? j : k) + t);
        if (!p.allFinite())
            throw InputError("the crossing on the grid edge from sample (" + std::to_string(i) + ", " + std::to_string(j) +
                             ", " + std::to_string(k) + ") along axis " + std::to_string(axis) + " leaves the range of double");
        out.mesh.positions.push_back(p);
        out.vertex_edge.push_back(axis * n + a);
        return out.mesh.num_vertices() - 1;
    };
    const auto make_slice_vertices = [&](int k) {
        for (int axis = 0; axis < 2; ++axis)
            for (int j = 0; j < ny - (axis == 1); ++j)
                for (int i = 0; i < nx - (axis == 0); ++i) xy_vertex[k & 1][axis][i + int64_t{nx} * j] = make_vertex(axis, i, j, k);
    };

    make_slice_vertices(0);
    for (int k = 0; k + 1 < nz; ++k) {
        make_slice_vertices(k + 1);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) z_vertex[i + int64_t{nx} * j] = make_vertex(2, i, j, k);

        for (int j = 0; j + 1 < ny; ++j)
            for (int i = 0; i + 1 < nx; ++i) {
                double cs[8];
                int inside = 0, count = 0;
                for (int c = 0; c < 8; ++c) {
                    cs[c] = s(grid.index(i + kCornerOffset[c][0], j + kCornerOffset[c][1], k + kCornerOffset[c][2]));
                    if (cs[c] < 0) inside |= 1 << c, ++count;
                }
                if (inside == 0 || inside == 0xff) continue;

                // next[e]: the crossing after crossing e, walking the polygon so that on every face
                // (seen from outside the cube) the inside lies to the left of each segment. A
                // segment runs from a crossing where the counter-clockwise walk round the face
                // leaves the inside to one where it enters it.
                int next[12];
                for (int f = 0; f < 6; ++f) {
                    const int* fc = kFaceCorners[f];
                    int leaving[2], entering[2], nl = 0, ne = 0;
                    for (int m = 0; m < 4; ++m) {
                        const bool a = inside >> fc[m] & 1, b = inside >> fc[(m + 1) % 4] & 1;
                        if (a && !b) leaving[nl++] = m;
                        if (!a && b) entering[ne++] = m;
                    }
                    const auto edge = [&](int m) { return kTables.edge_of[fc[m]][fc[(m + 1) % 4]]; };
                    if (nl == 1) {
                        next[edge(leaving[0])] = edge(entering[0]);
                    } else if (nl == 2) {
                        // Inside corners at m and m + 2 (m = leaving[0]): joined, each leaving
                        // crossing turns to the entering one after it (cutting off an outside
                        // corner); separated, to the one before it (cutting off an inside corner).
                        ++out.ambiguous_faces;
                        const int m = leaving[0];
                        const bool join = join_inside(cs[fc[m]], cs[fc[(m + 2) % 4]], cs[fc[(m + 1) % 4]],
                                                      cs[fc[(m + 3) % 4]], options.rule, count);
                        out.joined_faces += join;
                        const int step = join ? 1 : 3;
                        next[edge(m)] = edge((m + step) % 4);
                        next[edge((m + 2) % 4)] = edge((m + 2 + step) % 4);
                    }
                }

                const auto global_vertex = [&](int e) {
                    const int* o = kCornerOffset[kEdgeCorners[e][0]];
                    const int64_t at = (i + o[0]) + int64_t{nx} * (j + o[1]);
                    return e < 4 ? xy_vertex[(k + o[2]) & 1][0][at] : e < 8 ? xy_vertex[(k + o[2]) & 1][1][at] : z_vertex[at];
                };
                // The polygon's own order turns its normal towards the inside: triangles are
                // emitted reversed, to face away from the solid.
                const auto emit_polygon = [&](const int* loop, int size) {
                    for (int r = 0; r < size; ++r) {
                        bool fan_ok = true;
                        for (int d = 2; d + 1 < size && fan_ok; ++d)
                            fan_ok = !(kTables.edge_faces[loop[r]] & kTables.edge_faces[loop[(r + d) % size]]);
                        if (!fan_ok) continue;
                        const int apex = global_vertex(loop[r]);
                        for (int d = 1; d + 1 < size; ++d)
                            out.mesh.triangles.push_back({apex, global_vertex(loop[(r + d + 1) % size]), global_vertex(loop[(r + d) % size])});
                        return;
                    }
                    Vec3 centre = Vec3::Zero();
                    for (int m = 0; m < size; ++m) centre += out.mesh.positions[global_vertex(loop[m])];
                    out.mesh.positions.push_back(centre / size);
                    out.vertex_edge.push_back(-1);
                    ++out.centred_polygons;
                    const int c = out.mesh.num_vertices() - 1;
                    for (int m = 0; m < size; ++m)
                        out.mesh.triangles.push_back({c, global_vertex(loop[(m + 1) % size]), global_vertex(loop[m])});
                };
                int visited = 0;
                for (int start = 0; start < 12; ++start) {
                    const int a = inside >> kEdgeCorners[start][0] & 1, b = inside >> kEdgeCorners[start][1] & 1;
                    if (a == b || (visited >> start & 1)) continue;
                    int loop[12], size = 0;
                    for (int e = start; !(visited >> e & 1); e = next[e]) visited |= 1 << e, loop[size++] = e;
                    emit_polygon(loop, size);
                }
            }
    }
    return out;
}

}  // namespace crossdiv
