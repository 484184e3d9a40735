#pragma once
// The message a reader's ParseError gives for a text, for the tests of the file readers'
// errors (which name the file and line).

#include <sstream>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"

namespace crossdiv::test {

/// The ParseError message `read(stream, name)` gives for `text`, or "no error".
template <class Reader>
std::string parse_error(Reader read, const std::string& text, const std::string& name) {
    std::istringstream in(text);
    try {
        read(in, name);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "no error";
}

/// read_swp's message for `text` read as file `name`.
inline std::string swp_error(const std::string& text, const std::string& name = "bad.swp") {
    return parse_error([](std::istream& in, const std::string& n) { return read_swp(in, n); }, text, name);
}

}  // namespace crossdiv::test
