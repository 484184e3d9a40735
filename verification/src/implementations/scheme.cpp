#include "crossdiv/verification/implementations/scheme.h"

#include <array>

#include "crossdiv/error.h"

namespace crossdiv::verification {

const char* to_string(Scheme scheme) {
    switch (scheme) {
        case Scheme::Loop: return "loop";
        case Scheme::CatmullClark: return "catmull-clark";
        case Scheme::DooSabin: return "doo-sabin";
        case Scheme::Sqrt3: return "sqrt3";
        case Scheme::Butterfly: return "butterfly";
        case Scheme::ModifiedButterfly: return "modified-butterfly";
        case Scheme::Bilinear: return "bilinear";
        case Scheme::Midpoint: return "midpoint";
    }
    return "?";
}

std::vector<Scheme> all_schemes() {
    return {Scheme::Loop,      Scheme::CatmullClark,      Scheme::DooSabin, Scheme::Sqrt3,
            Scheme::Butterfly, Scheme::ModifiedButterfly, Scheme::Bilinear, Scheme::Midpoint};
}

std::vector<Scheme> polygon_schemes() {
    return {Scheme::CatmullClark, Scheme::DooSabin,          Scheme::Sqrt3,    Scheme::Butterfly,
            Scheme::ModifiedButterfly, Scheme::Bilinear, Scheme::Midpoint};
}

const SchemeTraits& traits(Scheme scheme) {
    //                                           primal triangles sdc_tags
    static const SchemeTraits loop{true, true, true}, catmull_clark{true, false, true}, doo_sabin{false, false, false},
        sqrt3{false, true, false}, butterfly{true, true, false}, bilinear{true, false, false}, midpoint{true, true, false};
    switch (scheme) {
        case Scheme::Loop: return loop;
        case Scheme::CatmullClark: return catmull_clark;
        case Scheme::DooSabin: return doo_sabin;
        case Scheme::Sqrt3: return sqrt3;
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: return butterfly;
        case Scheme::Bilinear: return bilinear;
        case Scheme::Midpoint: return midpoint;
    }
    return loop;
}

Scheme scheme_from_string(std::string_view name) {
    return variant_from_string<Scheme>(name, all_schemes(), "scheme");
}

namespace {

/// " creases=hbr" for Hbr's semi-sharp crease rules; nothing for OpenSubdiv's, everyone else's.
std::string crease_rules_suffix(CreaseRules t) {
    return t == CreaseRules::OpenSubdiv ? "" : " creases=" + std::string(to_string(t));
}

}  // namespace

std::string rule_name(Scheme scheme, const SchemeRule& rule) {
    switch (scheme) {
        case Scheme::Loop:
            return "weights=" + std::string(to_string(rule.loop.weights)) + " boundary=" + std::string(to_string(rule.loop.boundary)) +
                   crease_rules_suffix(rule.loop.crease_rules);
        case Scheme::CatmullClark:
            return std::string(to_string(rule.catmull_clark.boundary)) +
                   (rule.catmull_clark.smooth_triangles ? " smooth-triangles" : "") +
                   (rule.catmull_clark.vertex != CatmullClarkVertexRule::Standard
                        ? " vertex=" + std::string(to_string(rule.catmull_clark.vertex))
                        : "") +
                   crease_rules_suffix(rule.catmull_clark.crease_rules);
        case Scheme::DooSabin:
            return std::string(to_string(rule.doo_sabin.boundary)) +
                   (rule.doo_sabin.weights != DooSabinWeights::DooSabin ? " weights=" + std::string(to_string(rule.doo_sabin.weights))
                                                                         : "");
        case Scheme::Sqrt3: return std::string(to_string(rule.sqrt3.parity));
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: return std::string(to_string(rule.butterfly_wings));
        case Scheme::Bilinear:
        case Scheme::Midpoint: return "linear";
    }
    return "-";
}

std::string boundary_name(Scheme scheme, const SchemeRule& rule) {
    switch (scheme) {
        case Scheme::Loop: return std::string(to_string(rule.loop.boundary));
        default: return rule_name(scheme, rule);
    }
}

bool same_rule(Scheme scheme, const SchemeRule& a, const SchemeRule& b) {
    switch (scheme) {
        case Scheme::Loop: return a.loop == b.loop;
        case Scheme::CatmullClark:
            return a.catmull_clark.boundary == b.catmull_clark.boundary && a.catmull_clark.creasing == b.catmull_clark.creasing &&
                   a.catmull_clark.smooth_triangles == b.catmull_clark.smooth_triangles &&
                   a.catmull_clark.vertex == b.catmull_clark.vertex && a.catmull_clark.crease_rules == b.catmull_clark.crease_rules;
        default: return rule_name(scheme, a) == rule_name(scheme, b);
    }
}

SchemeRule rule_from_boundary_name(Scheme scheme, std::string_view boundary) {
    SchemeRule rule;
    if (boundary.empty()) return rule;
    const auto pick = [&](const auto& all, auto& field) {
        for (const auto v : all)
            if (to_string(v) == boundary) {
                field = v;
                return rule;
            }
        throw InputError(std::string(to_string(scheme)) + " has no boundary rule '" + std::string(boundary) + "' (" +
                         variant_names(all) + ")");
    };
    switch (scheme) {
        case Scheme::Loop: return pick(std::array{LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}, rule.loop.boundary);
        case Scheme::CatmullClark:
            return pick(std::array{CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner,
                                   CatmullClarkBoundary::MidpointAverage},
                        rule.catmull_clark.boundary);
        case Scheme::DooSabin:
            return pick(std::array{DooSabinBoundary::ChaikinBoundary, DooSabinBoundary::DropBorderFaces}, rule.doo_sabin.boundary);
        case Scheme::Sqrt3:
            return pick(std::array{Sqrt3Parity::CountFromInput, Sqrt3Parity::RestartEachLevel}, rule.sqrt3.parity);
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: return pick(kAllButterflyWings, rule.butterfly_wings);
        case Scheme::Bilinear:
        case Scheme::Midpoint:
            // Every point is an average of the corners it lies between: there is nothing a
            // boundary rule could change.
            if (boundary == "linear") return rule;
            throw InputError(std::string(to_string(scheme)) + " has no boundary rule '" + std::string(boundary) +
                             "' (its one rule is 'linear')");
    }
    throw InputError("unknown scheme");
}

}  // namespace crossdiv::verification
