#include "crossdiv/verification/harness/json_text.h"

#include <cstdio>

namespace crossdiv::verification {
namespace {

/// The length of the well-formed UTF-8 sequence at text[i], or 0.
size_t sequence_length(std::string_view text, size_t i) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) return 1;
    size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
    if (b0 >= 0xC2 && b0 <= 0xDF) n = 2;
    else if (b0 == 0xE0) n = 3, lo = 0xA0;
    else if (b0 >= 0xE1 && b0 <= 0xEC) n = 3;
    else if (b0 == 0xED) n = 3, hi = 0x9F;  // no surrogates
    else if (b0 >= 0xEE && b0 <= 0xEF) n = 3;
    else if (b0 == 0xF0) n = 4, lo = 0x90;
    else if (b0 >= 0xF1 && b0 <= 0xF3) n = 4;
    else if (b0 == 0xF4) n = 4, hi = 0x8F;  // nothing above U+10FFFF
    else return 0;
    if (i + n > text.size()) return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (size_t k = 2; k < n; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    return n;
}

nlohmann::json sanitized(const nlohmann::json& j) {
    if (j.is_string()) return valid_utf8(j.get_ref<const std::string&>());
    if (j.is_array()) {
        nlohmann::json out = nlohmann::json::array();
        for (const auto& x : j) out.push_back(sanitized(x));
        return out;
    }
    if (j.is_object()) {
        nlohmann::json out = nlohmann::json::object();
        for (auto it = j.begin(); it != j.end(); ++it) out[valid_utf8(it.key())] = sanitized(it.value());
        return out;
    }
    return j;
}

bool is_utf8(std::string_view s) {
    for (size_t i = 0, n; i < s.size(); i += n)
        if ((n = sequence_length(s, i)) == 0) return false;
    return true;
}

bool has_invalid(const nlohmann::json& j) {
    const auto bad = [](std::string_view s) { return !is_utf8(s); };
    if (j.is_string()) return bad(j.get_ref<const std::string&>());
    if (j.is_array()) {
        for (const auto& x : j)
            if (has_invalid(x)) return true;
        return false;
    }
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it)
            if (bad(it.key()) || has_invalid(it.value())) return true;
    return false;
}

}  // namespace

std::string valid_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const size_t n = sequence_length(text, i);
        if (n > 0) {
            out.append(text.substr(i, n));
            i += n;
            continue;
        }
        char escaped[5];
        std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned char>(text[i]));
        out += escaped;
        ++i;
    }
    return out;
}

std::string json_text(const nlohmann::json& j, int indent) {
    // The common case, every string already UTF-8, is written as it is.
    return has_invalid(j) ? sanitized(j).dump(indent) : j.dump(indent);
}

}  // namespace crossdiv::verification
