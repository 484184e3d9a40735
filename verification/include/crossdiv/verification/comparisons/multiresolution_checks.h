#pragma once
/// @file
/// Multiresolution editing (subdiv/multiresolution.h) measured the way the command and the
/// study report it: the round trip, a rigid motion against decompose and recompose, and which
/// vertices an edit of a base vertex moves against the predicted reach and the subdivision support.

#include <vector>

#include "crossdiv/subdiv/multiresolution.h"

namespace crossdiv::verification {

/// The hierarchy's pure subdivision surface of `base_positions`, each finest vertex moved along
/// its angle-weighted normal by amplitude * diagonal * sin(k x) sin(k y) sin(k z), k = waves /
/// diagonal: a detailed surface with subdivision connectivity that needs no file.
std::vector<Vec3> detailed_surface(const LoopMultiresolution& m, const std::vector<Vec3>& base_positions, double amplitude,
                                   double waves);

struct MultiresolutionMeasures {
    double diagonal = 0;
    double round_trip = 0;    ///< largest |recompose(decompose(P)) - P| / diagonal
    double rigid_motion = 0;  ///< largest |recompose(decompose(M P)) - M P| and detail difference, / diagonal
    std::vector<double> detail_rms;  ///< per level 1 .. L, / diagonal
    int moved = 0;            ///< finest vertices the edit moved
    int reach = 0;            ///< predicted by edit_reach (stencils and frames)
    int support = 0;          ///< the subdivision support (stencils alone)
    int outside_reach = 0;    ///< moved but not predicted: must be 0
    int smooth_moved = 0;     ///< the same edit with zero details: vertices moved
    int smooth_mismatch = 0;  ///< ... against the subdivision support (nothing for a zero edit), either way: must be 0
    std::vector<Vec3> edited;  ///< the finest positions after the edit
};

/// Decomposes `finest`, measures the round trip and a fixed rigid motion, then moves base
/// vertex `vertex` by `edit` and recomposes, with the details and with zero details.
/// @throws InputError as LoopMultiresolution, or for a vertex out of range.
MultiresolutionMeasures measure_multiresolution(const LoopMultiresolution& m, const std::vector<Vec3>& finest, int vertex,
                                                const Vec3& edit);

}  // namespace crossdiv::verification
