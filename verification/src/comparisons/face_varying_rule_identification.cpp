#include "crossdiv/verification/comparisons/face_varying_rule_identification.h"

#include <algorithm>
#include <cmath>

namespace crossdiv::verification {

std::vector<FaceVaryingRule> UvClassFit::fitting(double tolerance) const {
    std::vector<FaceVaryingRule> out;
    for (size_t r = 0; r < kFaceVaryingRules.size() && r < max_rel.size(); ++r)
        if (max_rel[r] <= tolerance) out.push_back(kFaceVaryingRules[r]);
    return out;
}

std::string FaceVaryingIdentification::summary() const {
    if (rule) return "the " + std::string(to_string(*rule)) + " rule";
    std::string s;
    for (const UvClassFit& row : rows) {
        const std::vector<FaceVaryingRule> fits = row.fitting(tolerance);
        s += (s.empty() ? "" : "; ") + std::string(to_string(row.cls)) + ": ";
        if (fits.empty()) s += "no rule";
        for (size_t i = 0; i < fits.size(); ++i) s += (i ? ", " : "") + std::string(to_string(fits[i]));
    }
    return "no one rule (" + s + ")";
}

std::optional<FaceVaryingIdentification> identify_face_varying_rule(const PolyMesh& subject,
                                                                    const std::vector<const PolyMesh*>& core_by_rule,
                                                                    FaceVaryingRule requested, double tolerance) {
    const PolyMesh* classified = nullptr;  // the requested rule's level: its corners' classes
    for (size_t r = 0; r < kFaceVaryingRules.size() && r < core_by_rule.size(); ++r)
        if (core_by_rule[r] && !core_by_rule[r]->face_varying.empty() && (!classified || kFaceVaryingRules[r] == requested))
            classified = core_by_rule[r];
    if (!classified || subject.face_varying.empty()) return std::nullopt;
    std::vector<int> identity(static_cast<size_t>(subject.num_vertices()));
    for (size_t v = 0; v < identity.size(); ++v) identity[v] = static_cast<int>(v);
    const std::vector<double> theirs = corner_values_in_our_order(*classified, subject, identity);
    if (theirs.empty()) return std::nullopt;

    FaceVaryingIdentification out;
    out.tolerance = tolerance;
    const std::vector<UvVertexClass> classes = uv_corner_classes(*classified);
    const double box = uv_box_diagonal(classified->face_varying.front());
    const size_t dim = static_cast<size_t>(classified->face_varying.front().dimension);
    constexpr size_t kClasses = 5;  // UvVertexClass's
    const size_t rules = kFaceVaryingRules.size();
    std::vector<double> max_rel(kClasses * rules, 0.0);
    std::vector<int> count(kClasses, 0);
    out.whole.assign(rules, 0.0);
    for (size_t r = 0; r < rules; ++r) {
        const PolyMesh* core = r < core_by_rule.size() ? core_by_rule[r] : nullptr;
        const bool usable = core && !core->face_varying.empty() && core->face_vertices.size() == classes.size();
        for (size_t c = 0; c < classes.size(); ++c) {
            const size_t k = static_cast<size_t>(classes[c]);
            if (r == 0) ++count[k];
            double d = INFINITY;
            if (usable) {
                const FaceVaryingChannel& ch = core->face_varying.front();
                const double* x = ch.value(ch.corner_values[c]);
                d = 0;
                for (size_t i = 0; i < dim; ++i) d = std::max(d, std::abs(x[i] - theirs[c * dim + i]));
                d = std::isnan(d) ? INFINITY : box > 0 ? d / box : d;
            }
            max_rel[k * rules + r] = std::max(max_rel[k * rules + r], d);
            out.whole[r] = std::max(out.whole[r], d);
        }
    }
    for (size_t k = 0; k < kClasses; ++k) {
        if (count[k] == 0) continue;
        UvClassFit row;
        row.cls = static_cast<UvVertexClass>(k);
        row.corners = count[k];
        row.max_rel.assign(max_rel.begin() + static_cast<std::ptrdiff_t>(k * rules),
                           max_rel.begin() + static_cast<std::ptrdiff_t>((k + 1) * rules));
        // The worst corner of the class under its best-fitting rule.
        const size_t best = static_cast<size_t>(std::min_element(row.max_rel.begin(), row.max_rel.end()) - row.max_rel.begin());
        const PolyMesh* core = best < core_by_rule.size() ? core_by_rule[best] : nullptr;
        double worst = -1;
        for (size_t c = 0; core && !core->face_varying.empty() && c < classes.size(); ++c) {
            if (classes[c] != row.cls) continue;
            const FaceVaryingChannel& ch = core->face_varying.front();
            double d = 0;
            for (size_t i = 0; i < dim; ++i) d = std::max(d, std::abs(ch.value(ch.corner_values[c])[i] - theirs[c * dim + i]));
            if (!(d <= worst)) {
                worst = d;
                row.worst_corner = static_cast<int>(c);
            }
        }
        out.rows.push_back(std::move(row));
    }
    const size_t asked = static_cast<size_t>(std::find(kFaceVaryingRules.begin(), kFaceVaryingRules.end(), requested) -
                                             kFaceVaryingRules.begin());
    if (asked < rules && out.whole[asked] <= tolerance) out.rule = requested;
    for (size_t r = 0; r < rules && !out.rule; ++r)
        if (out.whole[r] <= tolerance) out.rule = kFaceVaryingRules[r];
    return out;
}

}  // namespace crossdiv::verification
