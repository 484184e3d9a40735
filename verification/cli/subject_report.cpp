#include "subject_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <vector>

namespace crossdiv::cli {
namespace {

using namespace crossdiv::verification;

/// A rule's column header: Loop's weights/boundary, another scheme's rule name.
std::string short_name(Scheme scheme, const RuleFit& f) {
    if (scheme != Scheme::Loop) return f.name;
    return fmt::format("{}/{}", to_string(f.rule.loop.weights), to_string(f.rule.loop.boundary));
}

/// The fit of each face-varying rule per class of UV vertex, and the rule the subject's texture
/// coordinates follow.
void print_uv_rules(const FaceVaryingIdentification& id) {
    fmt::print("  {:<22} {:>7}", "texture coordinates", "corners");
    for (FaceVaryingRule r : kFaceVaryingRules) fmt::print(" {:>14}", to_string(r));
    fmt::print("\n");
    auto cell = [&](double x) { return fmt::format("{}{:.2g}", x <= id.tolerance ? "= " : "  ", x); };
    for (const UvClassFit& row : id.rows) {
        fmt::print("  {:<22} {:>7}", to_string(row.cls), row.corners);
        for (double x : row.max_rel) fmt::print(" {:>14}", cell(x));
        fmt::print("\n");
    }
    fmt::print("  {:<22} {:>7}", "every corner", "");
    for (double x : id.whole) fmt::print(" {:>14}", cell(x));
    fmt::print("\n  texture coordinates follow {}\n", id.summary());
}

}  // namespace

/// The subject's run, its match to core and the rule fits of each vertex class.
void print_subject(const RefinementComparison& c) {
    if (c.subject_outcome.status != RunStatus::Ok) {
        fmt::print("  subject '{}' failed: {}\n", c.subject, c.subject_outcome.summary());
        return;
    }
    if (!c.subject_unmatched.empty() || !c.subject_topology.empty()) {
        fmt::print("  subject '{}': {}\n", c.subject, c.subject_unmatched.empty() ? c.subject_topology : c.subject_unmatched);
        return;
    }
    fmt::print("  subject '{}' ran in {:.3f} s; vertices matched to core's by {}\n", c.subject, c.subject_outcome.seconds,
               to_string(c.subject_match.method));
    if (c.uv_rules) print_uv_rules(*c.uv_rules);
    if (!c.rules) return;
    fmt::print("  {:<22} {:>7}", c.rules->classified_level ? fmt::format("class at level {}", c.rules->classified_level)
                                                           : std::string("whole mesh"),
               "count");
    for (const RuleFit& f : c.rules->whole) fmt::print(" {:>16}", short_name(c.scheme, f));
    fmt::print("\n");
    auto cell = [](const RuleFit& f) { return fmt::format("{}{:.2g}", f.fits ? "= " : "  ", f.max_rel); };
    for (const VertexClassRow& r : c.rules->rows) {
        const bool by_face = r.cls == VertexClass::FacePoint || r.cls == VertexClass::CornerPoint ||
                             r.cls == VertexClass::BoundaryCornerPoint;
        const char* of = by_face ? "size" : "valence";
        fmt::print("  {:<22} {:>7}", r.valence ? fmt::format("{} ({} {})", to_string(r.cls), of, r.valence) : to_string(r.cls),
                   r.count);
        for (const RuleFit& f : r.fits) fmt::print(" {:>16}", cell(f));
        fmt::print("\n");
    }
    fmt::print("  {:<22} {:>7}", "every compared level", "");
    for (const RuleFit& f : c.rules->whole) fmt::print(" {:>16}", cell(f));
    fmt::print("\n  rule: {}\n", c.rules->rule ? rule_name(c.scheme, *c.rules->rule) : std::string("no named rule fits"));
    if (c.rules->other_schemes.empty()) return;
    // The nearest rule of each scheme (and of the scheme with the tags ignored).
    std::vector<const OtherSchemeFit*> nearest;
    for (const OtherSchemeFit& f : c.rules->other_schemes) {
        auto it = std::find_if(nearest.begin(), nearest.end(), [&](const OtherSchemeFit* n) { return n->family() == f.family(); });
        if (it == nearest.end()) nearest.push_back(&f);
        else if (f.max_rel < (*it)->max_rel) *it = &f;
    }
    std::vector<std::string> others;
    for (const OtherSchemeFit* f : nearest) others.push_back(fmt::format("{} {}{:.2g}", f->label(), f->fits ? "= " : "", f->max_rel));
    const OtherSchemeFit* it = c.rules->other_scheme();
    fmt::print("  nearest rule of each scheme with its connectivity, at level 1: {}\n  {}\n", fmt::join(others, ", "),
               !it ? std::string("no rule of these schemes fits either")
               : it->tags_ignored()
                   ? fmt::format("it reads past the input's tags: it is {} {} on the mesh without them", to_string(it->scheme),
                                 it->rule.substr(0, it->rule.size() - std::string_view(", tags ignored").size()))
                   : fmt::format("it is {}, not {}", it->label(), to_string(c.scheme)));
}

bool symptom_of_subject(const RefinementComparison& c) { return c.subject_failed() || (c.rules && !c.rules->rule); }

void SubjectVerdict::add(const RefinementComparison& c) {
    ++inputs;
    if (c.subject_failed()) {
        ++failures;
        return;
    }
    if (c.rules) rules.add(*c.rules);
    for (const RefinementRun& r : c.runs) {
        // Only runs that compared the reference with the subject: a reference that refused or
        // crashed, or an input core refused, says nothing of the subject.
        if (r.verdict != Verdict::Agree && r.verdict != Verdict::Diverge) continue;
        auto& [agree, runs] = reference_agreement[r.reference];
        ++runs;
        agree += r.verdict == Verdict::Agree;
        if (r.verdict == Verdict::Diverge) classes.insert(to_string(r.divergence_class));
        unexplained += r.verdict == Verdict::Diverge && r.divergence_class == DivergenceClass::Unexplained;
        // Its texture coordinates: a verdict of their own, counted the same way.
        if (r.uv && r.uv->compared() && r.uv->outcome.verdict == Verdict::Diverge) {
            classes.insert(to_string(r.uv->outcome.cls));
            unexplained += r.uv->outcome.cls == DivergenceClass::Unexplained;
        }
    }
}

std::string SubjectVerdict::line(const std::string& name) const {
    // References it agrees with on every input first, then those it agrees with on some.
    std::vector<std::string> agreeing, partly;
    for (const auto& [ref, counts] : reference_agreement) {
        if (counts.first == counts.second && counts.second > 0) agreeing.push_back(ref);
        else if (counts.first > 0) partly.push_back(fmt::format("{} on {} of {} inputs", ref, counts.first, counts.second));
    }
    agreeing.insert(agreeing.end(), partly.begin(), partly.end());
    std::string refs = agreeing.empty() ? "agrees with no reference" : "agrees with " + fmt::format("{}", fmt::join(agreeing, ", "));
    if (!classes.empty()) refs += fmt::format(" ({})", fmt::join(classes, ", "));
    std::string s = fmt::format("subject '{}': {}; {}; {}", name, rules.rule_phrase(), refs, rules.core_phrase());
    if (failures) s += fmt::format("; failed on {} of {} inputs", failures, inputs);
    return s;
}

}  // namespace crossdiv::cli
