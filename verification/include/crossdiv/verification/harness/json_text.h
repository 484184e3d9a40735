#pragma once
/// @file
/// JSON text that is valid UTF-8 whatever its strings hold. A file name or a parse message
/// quoting a line can carry bytes that are not UTF-8; nlohmann::json refuses to write those
/// (type_error.316), which would end a run and lose its outputs. Such bytes are written as
/// the four characters \xFE instead: shown, never dropped, never fatal.

#include <cmath>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace crossdiv::verification {

/// `text` with every byte that is not part of a well-formed UTF-8 sequence (RFC 3629: no
/// overlong forms, no surrogates, nothing above U+10FFFF) replaced by "\xHH".
std::string valid_utf8(std::string_view text);

/// j.dump(indent) after valid_utf8 of every string and object key.
std::string json_text(const nlohmann::json& j, int indent = -1);

/// `x` as a JSON number, or null where it is NaN or infinite (JSON has neither).
inline nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace crossdiv::verification
