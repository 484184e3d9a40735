#include "nearest_name.h"

#include <algorithm>

namespace crossdiv::cli {

int edit_distance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic programme: the transposition reads two rows back.
    const size_t m = b.size();
    std::vector<int> before(m + 1), previous(m + 1), current(m + 1);
    for (size_t j = 0; j <= m; ++j) previous[j] = static_cast<int>(j);
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = static_cast<int>(i);
        for (size_t j = 1; j <= m; ++j) {
            const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            int best = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) best = std::min(best, before[j - 2] + 1);
            current[j] = best;
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[m];
}

std::optional<std::string> nearest_name(std::string_view typed, const std::vector<std::string>& names) {
    std::optional<std::string> best;
    int best_distance = 0;
    for (const std::string& name : names) {
        const int d = edit_distance(typed, name);
        if (d <= 2 && 3 * d <= static_cast<int>(typed.size()) && (!best || d < best_distance)) {
            best = name;
            best_distance = d;
        }
    }
    if (best) return best;
    std::optional<std::string> prefix_of;
    for (const std::string& name : names)
        if (!typed.empty() && name.starts_with(typed)) {
            if (prefix_of) return std::nullopt;  // the start of two names: no guess
            prefix_of = name;
        }
    return prefix_of;
}

}  // namespace crossdiv::cli
