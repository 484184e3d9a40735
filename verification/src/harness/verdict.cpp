#include "crossdiv/verification/harness/verdict.h"

#include <array>
#include <utility>

#include "crossdiv/error.h"

namespace crossdiv::verification {
namespace {

constexpr std::array kVerdicts = {
    std::pair{Verdict::Agree, "agree"},
    std::pair{Verdict::Diverge, "diverge"},
    std::pair{Verdict::RefRejected, "ref-rejected"},
    std::pair{Verdict::RefCrashed, "ref-crashed"},
    std::pair{Verdict::RefInvalidOutput, "ref-invalid-output"},
    std::pair{Verdict::RefUnavailable, "ref-unavailable"},
    std::pair{Verdict::OursRejected, "ours-rejected"},
    std::pair{Verdict::RefNondeterministic, "ref-nondeterministic"},
    std::pair{Verdict::NotCompared, "not-compared"},
};

constexpr std::array kClasses = {
    std::pair{DivergenceClass::None, ""},
    std::pair{DivergenceClass::WeightFamily, "weight-family"},
    std::pair{DivergenceClass::CornerRule, "corner-rule"},
    std::pair{DivergenceClass::WeightFamilyAndCornerRule, "weight-family+corner-rule"},
    std::pair{DivergenceClass::BoundaryRule, "boundary-rule"},
    std::pair{DivergenceClass::BorderFacesDropped, "border-faces-dropped"},
    std::pair{DivergenceClass::Parity, "parity"},
    std::pair{DivergenceClass::WingRule, "wing-rule"},
    std::pair{DivergenceClass::TriangleRule, "triangle-rule"},
    std::pair{DivergenceClass::CreaseRules, "crease-rules"},
    std::pair{DivergenceClass::FaceVaryingRule, "fvar-rule"},
    std::pair{DivergenceClass::LegacyFaceVaryingRules, "legacy-fvar-rules"},
    std::pair{DivergenceClass::NormalRule, "normal-rule"},
    std::pair{DivergenceClass::Convention, "convention"},
    std::pair{DivergenceClass::FaceOrderDependence, "face-order-dependence"},
    std::pair{DivergenceClass::Rounding, "rounding"},
    std::pair{DivergenceClass::IsolatedVertexHandling, "isolated-vertex-handling"},
    std::pair{DivergenceClass::ValenceLimit, "valence-limit"},
    std::pair{DivergenceClass::ShortBoundaryLoop, "short-boundary-loop"},
    std::pair{DivergenceClass::FanWalk, "fan-walk"},
    std::pair{DivergenceClass::Topology, "topology"},
    std::pair{DivergenceClass::Triangulation, "triangulation"},
    std::pair{DivergenceClass::Unexplained, "unexplained"},
    std::pair{DivergenceClass::NonManifoldHandling, "non-manifold-handling"},
    std::pair{DivergenceClass::OrientationHandling, "orientation-handling"},
    std::pair{DivergenceClass::DegenerateFaceHandling, "degenerate-face-handling"},
    std::pair{DivergenceClass::InvalidInputHandling, "invalid-input-handling"},
};

template <class Table>
auto parse(const Table& table, std::string_view name, const char* what) {
    std::string known;
    for (const auto& [value, text] : table) {
        if (name == text) return value;
        if (*text) known += (known.empty() ? "" : ", ") + std::string(text);
    }
    throw InputError("unknown " + std::string(what) + " '" + std::string(name) + "' (known: " + known + ")");
}

template <class Table, class Value>
const char* name_of(const Table& table, Value v) {
    for (const auto& [value, text] : table)
        if (value == v) return text;
    return "?";
}

}  // namespace

const char* to_string(Verdict verdict) { return name_of(kVerdicts, verdict); }
Verdict verdict_from_string(std::string_view name) { return parse(kVerdicts, name, "verdict"); }

const char* to_string(DivergenceClass cls) { return name_of(kClasses, cls); }
DivergenceClass divergence_class_from_string(std::string_view name) { return parse(kClasses, name, "divergence class"); }

std::string to_string(const Outcome& o) {
    const bool classed =
        o.verdict == Verdict::Diverge || o.verdict == Verdict::OursRejected || o.verdict == Verdict::RefNondeterministic;
    if (classed && o.cls != DivergenceClass::None) return std::string(to_string(o.verdict)) + " (" + to_string(o.cls) + ")";
    return to_string(o.verdict);
}

}  // namespace crossdiv::verification
