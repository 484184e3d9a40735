#include "crossdiv/verification/comparisons/classification.h"

#include "crossdiv/mesh/mesh_checks.h"

namespace crossdiv::verification {

Classification classify_divergence(const DivergenceTests& tests) {
    for (const DivergenceTest* test : {&tests.isolated_vertices, &tests.rounding, &tests.reference_rule,
                                       &tests.valence_table, &tests.nonmanifold, &tests.topology})
        if (*test)
            if (std::optional<Classification> c = (*test)()) return *c;
    return {DivergenceClass::Unexplained, tests.unexplained ? tests.unexplained() : std::string()};
}

DivergenceClass rule_difference_class(Scheme scheme, const SchemeRule& applied, const SchemeRule& requested) {
    switch (scheme) {
        case Scheme::Loop: {
            const bool weights = applied.loop.weights != requested.loop.weights;
            const bool boundary = applied.loop.boundary != requested.loop.boundary;
            return weights && boundary ? DivergenceClass::WeightFamilyAndCornerRule
                   : weights           ? DivergenceClass::WeightFamily
                                       : DivergenceClass::CornerRule;
        }
        case Scheme::CatmullClark: {
            if (applied.catmull_clark.smooth_triangles != requested.catmull_clark.smooth_triangles &&
                applied.catmull_clark.boundary == requested.catmull_clark.boundary)
                return DivergenceClass::TriangleRule;
            const auto corner_only = [](CatmullClarkBoundary x) {
                return x == CatmullClarkBoundary::EdgeOnly || x == CatmullClarkBoundary::EdgeAndCorner;
            };
            return corner_only(applied.catmull_clark.boundary) && corner_only(requested.catmull_clark.boundary)
                       ? DivergenceClass::CornerRule
                       : DivergenceClass::BoundaryRule;
        }
        case Scheme::DooSabin:
            return applied.doo_sabin.boundary == DooSabinBoundary::DropBorderFaces ? DivergenceClass::BorderFacesDropped
                                                                                   : DivergenceClass::BoundaryRule;
        case Scheme::Sqrt3: return DivergenceClass::Parity;
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: return DivergenceClass::WingRule;
    }
    return DivergenceClass::BoundaryRule;
}

DivergenceClass input_handling_class(const PolyMesh& input) {
    for (const MeshIssue& issue : check_mesh(input)) {
        if (issue.severity != Severity::Error) continue;
        if (issue.kind == MeshIssueKind::NonManifoldEdge || issue.kind == MeshIssueKind::NonManifoldVertex)
            return DivergenceClass::NonManifoldHandling;
        if (issue.kind == MeshIssueKind::InconsistentOrientation) return DivergenceClass::OrientationHandling;
        if (issue.kind == MeshIssueKind::RepeatedVertex || issue.kind == MeshIssueKind::TooFewCorners)
            return DivergenceClass::DegenerateFaceHandling;
        return DivergenceClass::InvalidInputHandling;
    }
    return DivergenceClass::InvalidInputHandling;
}

}  // namespace crossdiv::verification
