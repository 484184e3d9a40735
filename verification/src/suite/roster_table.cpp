#include "crossdiv/verification/suite/roster_table.h"

#include <algorithm>

namespace crossdiv::verification {
namespace {

using nlohmann::json;

std::string string_field(const json& j, const char* key) { return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; }

/// The rule a comparison case names, as the subject record names rules.
std::string asked_rule(const CaseRecord& c) {
    return c.operation == "loop" ? "weights=" + c.weights + " boundary=" + c.boundary : c.boundary;
}

void count_rule(RosterRow& row, const std::string& rule) {
    auto it = std::find_if(row.rules.begin(), row.rules.end(), [&](const auto& r) { return r.first == rule; });
    if (it == row.rules.end()) row.rules.push_back({rule, 1});
    else ++it->second;
}

/// The row's first failing case, and its minimal input where the suite shrank it.
void set_failing_case(RosterRow& row, const CaseRecord& c) {
    row.failing_case = c.id;
    row.failing_input = c.input;
    if (!c.detail.contains("minimal") || !c.detail["minimal"].is_object()) return;
    const json& m = c.detail["minimal"];
    row.minimal_input = string_field(m, "mesh");
    row.minimal_symptom = string_field(m, "symptom");
    row.minimal_note = string_field(m, "note");
    row.minimal_faces = m.value("faces", 0);
}

std::string inputs(int n, int of) { return std::to_string(n) + " of " + std::to_string(of) + " input" + (of == 1 ? "" : "s"); }

}  // namespace

const char* to_string(RosterVerdict verdict) {
    switch (verdict) {
        case RosterVerdict::Pass: return "pass";
        case RosterVerdict::OtherRule: return "other-rule";
        case RosterVerdict::Fail: return "fail";
    }
    return "fail";
}

std::vector<RosterRow> roster_table(const std::vector<CaseRecord>& cases) {
    std::vector<RosterRow> rows;
    for (const CaseRecord& c : cases) {
        if (!c.detail.contains("subject") || !c.detail["subject"].is_object()) continue;
        const json& s = c.detail["subject"];
        const std::string name = string_field(s, "name");
        auto it = std::find_if(rows.begin(), rows.end(), [&](const RosterRow& r) { return r.subject == name && r.scheme == c.operation; });
        if (it == rows.end()) {
            rows.push_back({});
            it = rows.end() - 1;
            it->roster = string_field(s, "roster");
            it->subject = name;
            it->scheme = c.operation;
            it->asked = asked_rule(c);
        }
        RosterRow& row = *it;
        ++row.cases;
        const auto failed = [&](const std::string& how, const std::string& message) {
            ++row.failures[how];
            if (row.failing_case.empty()) {
                set_failing_case(row, c);
                row.first_failure = message;
            }
        };
        const std::string status = string_field(s, "status");
        if (status != "ok") {
            failed(status, string_field(s, "status_message"));
            continue;
        }
        if (!string_field(s, "unmatched").empty()) {
            failed("unmatched", string_field(s, "unmatched"));
            continue;
        }
        if (!string_field(s, "topology").empty()) {
            failed("topology", string_field(s, "topology"));
            continue;
        }
        ++row.ran;
        if (s.contains("match")) row.match = string_field(s["match"], "method");
        for (const RunRecord& r : c.runs) row.unexplained += r.outcome.verdict == Verdict::Diverge && r.outcome.cls == DivergenceClass::Unexplained;
        const json rules = s.value("rules", json::object());
        if (rules.contains("rule") && rules["rule"].is_string()) {
            count_rule(row, rules["rule"].get<std::string>());
            continue;
        }
        ++row.no_rule;
        if (row.failing_case.empty()) set_failing_case(row, c);
        for (const json& cls : rules.value("classes", json::array())) {
            const json fits = cls.value("fits", json::array());
            if (std::any_of(fits.begin(), fits.end(), [](const json& f) { return f.value("fits", false); })) continue;
            const int valence = cls.value("valence", 0);
            const std::string label = string_field(cls, "class") + (valence ? " " + std::to_string(valence) : "");
            if (std::find(row.unfit_classes.begin(), row.unfit_classes.end(), label) == row.unfit_classes.end())
                row.unfit_classes.push_back(label);
        }
        for (const json& o : rules.value("other_schemes", json::array()))
            if (o.value("fits", false) && row.other_scheme.empty())
                row.other_scheme = string_field(o, "scheme") + " " + string_field(o, "rule");
    }
    for (RosterRow& row : rows) {
        // The case's own rule first: a closed mesh fits several, and the one asked names it.
        std::stable_sort(row.rules.begin(), row.rules.end(), [&](const auto& a, const auto& b) {
            return (a.first == row.asked) > (b.first == row.asked);
        });
        const bool all_ran = row.ran == row.cases && row.no_rule == 0;
        const bool asked_everywhere = !row.rules.empty() && row.rules.front().first == row.asked &&
                                      row.rules.front().second == row.ran;
        row.verdict = !all_ran || row.unexplained > 0 ? RosterVerdict::Fail
                      : asked_everywhere              ? RosterVerdict::Pass
                                                      : RosterVerdict::OtherRule;
    }
    return rows;
}

std::string RosterRow::followed_rule() const {
    for (const auto& [rule, n] : rules)
        if (rule != asked) return rule;
    return rules.empty() ? "" : rules.front().first;
}

std::string RosterRow::diagnosis() const {
    std::vector<std::string> parts;
    for (const auto& [how, n] : failures) parts.push_back(how + " on " + inputs(n, cases));
    if (!failures.empty() && !first_failure.empty()) parts.back() += " (" + first_failure + ")";
    for (const auto& [rule, n] : rules)
        parts.push_back(rule + " on " + inputs(n, cases) + (rule == asked ? "" : " (the cases name " + asked + ")"));
    if (no_rule) {
        std::string classes;
        for (const std::string& c : unfit_classes) classes += (classes.empty() ? "" : ", ") + c;
        parts.push_back("no named rule on " + inputs(no_rule, cases) + (classes.empty() ? "" : " (at " + classes + ")") +
                        (other_scheme.empty() ? "" : "; at level 1 it is " + other_scheme));
    }
    if (unexplained) parts.push_back(std::to_string(unexplained) + " unexplained divergence(s) from a reference");
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : "; ") + p;
    return s;
}

json to_json(const std::vector<RosterRow>& rows) {
    json out = json::array();
    for (const RosterRow& r : rows) {
        json rules = json::array();
        for (const auto& [rule, n] : r.rules) rules.push_back({{"rule", rule}, {"cases", n}});
        out.push_back({{"roster", r.roster},
                       {"subject", r.subject},
                       {"scheme", r.scheme},
                       {"verdict", to_string(r.verdict)},
                       {"cases", r.cases},
                       {"ran", r.ran},
                       {"asked", r.asked},
                       {"rules", rules},
                       {"rule", r.followed_rule()},
                       {"no_rule", r.no_rule},
                       {"unfit_classes", r.unfit_classes},
                       {"other_scheme", r.other_scheme},
                       {"failures", r.failures},
                       {"unexplained", r.unexplained},
                       {"match", r.match},
                       {"failing_case", r.failing_case},
                       {"failing_input", r.failing_input},
                       {"minimal", r.minimal_input.empty() && r.minimal_note.empty()
                                       ? json(nullptr)
                                       : json{{"mesh", r.minimal_input}, {"faces", r.minimal_faces},
                                              {"symptom", r.minimal_symptom}, {"note", r.minimal_note}}},
                       {"diagnosis", r.diagnosis()}});
    }
    return out;
}

}  // namespace crossdiv::verification
