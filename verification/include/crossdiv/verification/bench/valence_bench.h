#pragma once
/// @file valence_bench.h
/// The cost of a vertex of large valence, and of a polygon of many sides: each command's time
/// on such a mesh (datasets/valence_shapes.h) against its time on a regular mesh of the same
/// size. A traversal linear in the mesh keeps the ratio near 1 at every valence; one that
/// walks a vertex's ring per incident element (O(valence^2)) makes it grow with the valence.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "crossdiv/datasets/valence_shapes.h"

namespace crossdiv::verification {

/// One command on one shape at one valence, and on the shape's regular counterpart.
struct ValenceRow {
    datasets::ValenceShape shape = datasets::ValenceShape::Bicone;
    int valence = 0;      ///< the poles' valence, or the polygon's number of sides
    std::string command;  ///< "check" (the mesh and half-edge checks of `crossdiv check`) or a scheme, one level
    /// The size each time is divided by: for check the input's face corners, for a scheme the
    /// refined mesh's vertices plus faces (a polygon's every edge is on the boundary, where
    /// Doo-Sabin makes two more points per edge than inside: the same input size is not the
    /// same work).
    long long size = 0, regular_size = 0;
    double ms = 0, regular_ms = 0;  ///< median times
    /// Time per unit of size on the shape over the same on the regular mesh.
    double ratio() const { return (ms / size) / (regular_ms / regular_size); }
};

/// Goal: no row's ratio above this.
inline constexpr double kValenceRatioGoal = 2.0;

/// The valences of the default run.
inline constexpr int kBenchValences[] = {1000, 10000, 100000};

/// Every row at each valence: check, and one level of each scheme that takes the shape
/// (every scheme on triangles, Catmull-Clark and Doo-Sabin on the polygon). Each time is the
/// median of `repeats` runs after a warm-up.
std::vector<ValenceRow> run_valence_bench(const std::vector<int>& valences, int repeats);

nlohmann::json to_json(const ValenceRow& r);

}  // namespace crossdiv::verification
