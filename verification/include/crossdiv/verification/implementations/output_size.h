#pragma once
/// @file
/// The size a refinement will reach, known before any work, and the limits that keep it
/// within a 24 GB machine. Every command and suite operation that refines checks its
/// requested levels here first, so that an input too large is a clear refusal (exit 2, or
/// the suite job's recorded outcome) instead of an out-of-memory kill minutes later.

#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// A refinement refused for its size before any work: the limit the caller set (a suite's
/// max-faces, a command's option), not a refusal of the input by core.
class OverSizeLimit : public InputError {
public:
    using InputError::InputError;
};

/// Default face limit of one implementation refining alone (`crossdiv subdivide`): core
/// keeps every level, about 90 bytes per final face (measured: a tetrahedron at 12 Loop
/// levels, 67M faces, peaks at 5.7 GB), and writing the result adds the file.
inline constexpr long long kMaxRefinedFaces = 64LL << 20;

/// Default face limit of a comparison (`crossdiv compare`, `diff`, the suite's loop
/// operation): core, up to three references and the correspondence side by side, about
/// 410 bytes per final face (measured: fandisk at 6 Loop levels, 53M faces, peaks at
/// 21.8 GB). 16M faces is about 7 GB, so two suite workers fit a 24 GB machine.
inline constexpr long long kMaxComparedFaces = 16LL << 20;

/// Faces of the final level after `levels` levels of `scheme` on `mesh`, saturating at
/// the largest long long. The first level makes 4 per triangle (Loop, the Butterflies),
/// one per corner (Catmull-Clark), faces + edges + vertices <= 2 corners (Doo-Sabin, an
/// upper bound) or at most 3 per triangle (sqrt3); later levels multiply by 3 (sqrt3) or 4.
long long refined_face_count(const PolyMesh& mesh, Scheme scheme, int levels);

/// @throws InputError naming `name`, the levels, the predicted count and `limit_option`
///   (the flag or manifest statement that moves the limit) when `faces` > `limit`.
void require_refined_size(long long faces, long long limit, int levels, const std::string& name,
                          const std::string& limit_option);

/// refined_face_count then require_refined_size.
void require_refined_size(const PolyMesh& mesh, Scheme scheme, int levels, long long limit, const std::string& name,
                          const std::string& limit_option);

}  // namespace crossdiv::verification
