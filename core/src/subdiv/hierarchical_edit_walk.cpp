#include "crossdiv/subdiv/hierarchical_edit_walk.h"

#include <algorithm>

#include "crossdiv/error.h"

namespace crossdiv {
namespace {

/// Core's slot of Hbr's slot `slot` in a face of `n` corners turned by `rotation`.
int core_slot(int slot, int rotation, int n) { return ((slot - rotation) % n + n) % n; }

float edited_sharpness(float current, const HierarchicalEdit& e) {
    const double operand = e.value[0];
    const double s = e.op == EditOperation::Set ? operand : e.op == EditOperation::Add ? current + operand : current - operand;
    return static_cast<float>(std::clamp(s, 0.0, 10.0));
}

}  // namespace

HierarchicalEditWalk::HierarchicalEditWalk(const PolyMesh& base) : edits_(base.creases.edits) {
    cursors_.reserve(edits_.size());
    for (const HierarchicalEdit& e : edits_) {
        const bool in_range = e.face >= 0 && e.face < base.num_faces();
        const std::string problem = hierarchical_edit_problem(e, base.num_faces(), in_range ? base.face_size(e.face) : 0);
        if (!problem.empty()) throw InputError("hierarchical edit " + describe(e) + ": " + problem);
        cursors_.push_back({e.face, 0});
    }
}

void HierarchicalEditWalk::descend(const PolyMesh& coarse, int level) {
    for (size_t i = 0; i < edits_.size(); ++i) {
        if (edits_[i].level() <= level) continue;
        Cursor& c = cursors_[i];
        const int n = coarse.face_size(c.face), child = edits_[i].children[static_cast<size_t>(level)];
        c.face = coarse.face_start[c.face] + core_slot(child, c.rotation, n);
        // Hbr's child i of a quad holds its corner's child in slot i; other faces' children start at slot 0.
        c.rotation = n == 4 ? child : 0;
    }
}

void HierarchicalEditWalk::apply(PolyMesh& mesh, int level) const {
    CreaseTags& tags = mesh.creases;
    for (size_t i = 0; i < edits_.size(); ++i) {
        const HierarchicalEdit& e = edits_[i];
        if (e.level() != level) continue;
        const Cursor& c = cursors_[i];
        const int n = mesh.face_size(c.face);
        if (e.target == EditTarget::Hole) {
            const auto at = std::lower_bound(tags.holes.begin(), tags.holes.end(), c.face);
            if (at == tags.holes.end() || *at != c.face) tags.holes.insert(at, c.face);
            continue;
        }
        const int slot = core_slot(e.element, c.rotation, n);
        const int v = mesh.face(c.face)[slot];
        switch (e.target) {
            case EditTarget::Position: {
                Vec3& p = mesh.positions[static_cast<size_t>(v)];
                const Vec3 operand(e.value[0], e.value[1], e.value[2]);
                p = e.op == EditOperation::Set ? operand : e.op == EditOperation::Add ? Vec3(p + operand) : Vec3(p - operand);
                break;
            }
            case EditTarget::VertexSharpness: {
                auto it = std::find_if(tags.vertices.begin(), tags.vertices.end(), [&](const SharpVertex& s) { return s.v == v; });
                if (it == tags.vertices.end()) it = tags.vertices.insert(tags.vertices.end(), SharpVertex{v, 0.0f});
                it->sharpness = edited_sharpness(it->sharpness, e);
                break;
            }
            case EditTarget::EdgeSharpness: {
                // The edge leaving Hbr's slot `element`: from core's `slot` to the next corner.
                const int w = mesh.face(c.face)[(slot + 1) % n];
                auto same = [&](const SharpEdge& s) { return (s.a == v && s.b == w) || (s.a == w && s.b == v); };
                auto it = std::find_if(tags.edges.begin(), tags.edges.end(), same);
                if (it == tags.edges.end()) it = tags.edges.insert(tags.edges.end(), SharpEdge{v, w, 0.0f});
                it->sharpness = edited_sharpness(it->sharpness, e);
                break;
            }
            case EditTarget::Hole: break;
        }
    }
}

}  // namespace crossdiv
