#pragma once
// Line-oriented tokenizing shared by the text mesh readers: strict number parsing with
// std::from_chars (no locale, no silent partial parses) and messages that carry file:line.

#include <charconv>
#include <limits>
#include <cmath>
#include <istream>
#include <string>
#include <string_view>

#include "crossdiv/error.h"

namespace crossdiv::io_detail {

class LineReader {
public:
    LineReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}

    /// Next line with its comment (from '#') stripped; false at end of file.
    bool next() {
        if (!std::getline(in_, line_)) return false;
        ++number_;
        // UTF-16 or UTF-32 text, and binary data, have NUL bytes; read as ASCII they would be
        // lines of unknown statements, and the file an empty mesh.
        if (line_.find('\0') != std::string::npos)
            fail("a NUL byte: not a text file in ASCII or UTF-8 (UTF-16 or UTF-32 text, or binary data)");
        if (!line_.empty() && line_.back() == '\r') line_.pop_back();
        if (auto hash = line_.find('#'); hash != std::string::npos) line_.erase(hash);
        rest_ = line_;
        return true;
    }
    /// Next whitespace-separated token of the current line, empty at its end.
    std::string_view token() {
        size_t b = rest_.find_first_not_of(" \t");
        if (b == std::string_view::npos) { rest_ = {}; return {}; }
        size_t e = rest_.find_first_of(" \t", b);
        std::string_view t = rest_.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b);
        rest_ = e == std::string_view::npos ? std::string_view{} : rest_.substr(e);
        return t;
    }
    bool at_end_of_line() const { return rest_.find_first_not_of(" \t") == std::string_view::npos; }

    /// Parses the next token as a finite double; `what` names it in the message.
    double real(const char* what) {
        std::string_view t = token();
        if (t.empty()) fail(std::string("missing ") + what);
        if (t.size() > 1 && t[0] == '+') t.remove_prefix(1);  // from_chars rejects a leading '+'
        double x = 0;
        auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
        if (ec != std::errc() || p != t.data() + t.size())
            fail(std::string("'") + std::string(t) + "' is not a number (" + what + ")");
        if (!std::isfinite(x))
            throw NonFiniteNumber(name_, number_, std::string(what) + " is " + std::string(t) + "; numbers must be finite");
        return x;
    }
    /// Parses a whole token as an integer.
    long integer(std::string_view t, const char* what) {
        long x = 0;
        auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
        if (!t.empty() && ec == std::errc::result_out_of_range && p == t.data() + t.size())
            fail(std::string("'") + std::string(t) + "' is out of the range of a 64-bit integer (" + what + ")");
        if (t.empty() || ec != std::errc() || p != t.data() + t.size())
            fail(std::string("'") + std::string(t) + "' is not an integer (" + what + ")");
        return x;
    }
    /// An element index or count that 32-bit indices address: 0 <= x <= INT_MAX, else the
    /// failure names the file's value.
    int index(long x, const char* what) const {
        if (x < 0 || x > std::numeric_limits<int>::max())
            fail(std::string(what) + " " + std::to_string(x) + " is out of range: 32-bit indices address 0.." +
                 std::to_string(std::numeric_limits<int>::max()));
        return static_cast<int>(x);
    }
    long integer(const char* what) {
        std::string_view t = token();
        if (t.empty()) fail(std::string("missing ") + what);
        return integer(t, what);
    }

    [[noreturn]] void fail(const std::string& what) const { throw ParseError(name_, number_, what); }
    [[noreturn]] void fail_at(int line, const std::string& what) const { throw ParseError(name_, line, what); }
    int line_number() const { return number_; }
    const std::string& name() const { return name_; }

private:
    std::istream& in_;
    std::string name_;
    std::string line_;
    std::string_view rest_;
    int number_ = 0;
};

}  // namespace crossdiv::io_detail

namespace crossdiv::io_detail {

/// Appends x with 17 significant digits: every double reads back bit-identical.
inline void append_real(std::string& out, double x) {
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
    out.append(buf, p);
}
inline void append_int(std::string& out, long x) {
    char buf[24];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, x);
    out.append(buf, p);
}

}  // namespace crossdiv::io_detail
