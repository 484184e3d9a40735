#include "crossdiv/mesh/face_varying.h"

#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

void check_face_varying(const PolyMesh& mesh) {
    for (const FaceVaryingChannel& ch : mesh.face_varying) {
        const std::string what = "face-varying channel '" + ch.name + "'";
        if (ch.dimension < 1)
            throw InputError(what + " has " + std::to_string(ch.dimension) + " components per value; it needs at least 1");
        if (ch.values.size() % static_cast<size_t>(ch.dimension) != 0)
            throw InputError(what + " has " + std::to_string(ch.values.size()) + " numbers, not a whole number of " +
                             std::to_string(ch.dimension) + "-component values");
        if (ch.corner_values.size() != mesh.face_vertices.size())
            throw InputError(what + " gives " + std::to_string(ch.corner_values.size()) + " corner values for " +
                             std::to_string(mesh.face_vertices.size()) + " face corners");
        for (size_t k = 0; k < ch.values.size(); ++k)
            if (!std::isfinite(ch.values[k]))
                throw InputError(what + ": value " + std::to_string(k / static_cast<size_t>(ch.dimension)) +
                                 " has a component that is not finite");
        const int n = ch.num_values();
        for (int f = 0; f < mesh.num_faces(); ++f)
            for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
                if (ch.corner_values[c] < 0 || ch.corner_values[c] >= n)
                    throw InputError(mesh.source.describe_face(f) + ": " + what + " index " +
                                     std::to_string(ch.corner_values[c]) + " at corner " +
                                     std::to_string(c - mesh.face_start[f]) + " is out of range (" +
                                     std::to_string(n) + " values)");
    }
}

}  // namespace crossdiv
