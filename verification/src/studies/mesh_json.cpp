#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {

using nlohmann::json;

json mesh_json(const PolyMesh& m) {
    json pos = json::array(), faces = json::array();
    for (const Vec3& p : m.positions) pos.push_back({p.x(), p.y(), p.z()});
    for (int f = 0; f < m.num_faces(); ++f) faces.push_back(std::vector<int>(m.face(f), m.face(f) + m.face_size(f)));
    return {{"positions", pos}, {"faces", faces}};
}

}  // namespace crossdiv::verification
