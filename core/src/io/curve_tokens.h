#pragma once
// Tokens of the curve formats (SWP, BZC): brackets are tokens of their own, so "[3 0]" and
// "[ 3 0 ]" read the same; '#' starts a comment. The parser's errors carry file:line.

#include <charconv>
#include <limits>
#include <cmath>
#include <istream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::io_detail {

struct Token {
    std::string text;
    int line;
};

inline std::vector<Token> lex(std::istream& in) {
    std::vector<Token> out;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        size_t i = 0;
        while (i < line.size()) {
            const char c = line[i];
            if (c == ' ' || c == '\t' || c == '\r') {
                ++i;
            } else if (c == '[' || c == ']') {
                out.push_back({std::string(1, c), number});
                ++i;
            } else {
                const size_t e = line.find_first_of(" \t\r[]", i);
                out.push_back({line.substr(i, e == std::string::npos ? std::string::npos : e - i), number});
                i = e == std::string::npos ? line.size() : e;
            }
        }
    }
    return out;
}

class Parser {
public:
    Parser(std::vector<Token> tokens, std::string file) : t_(std::move(tokens)), file_(std::move(file)) {}

    bool done() const { return pos_ >= t_.size(); }
    const Token& peek() const { return t_[pos_]; }

    const Token& next(const char* what) {
        if (done()) fail(std::string("unexpected end of file: expected ") + what);
        return t_[pos_++];
    }
    std::string word(const char* what) {
        const Token& tok = next(what);
        if (tok.text == "[" || tok.text == "]") fail_at(tok.line, std::string("expected ") + what + ", got '" + tok.text + "'");
        return tok.text;
    }
    double real(const char* what) {
        const Token& tok = next(what);
        std::string_view s = tok.text;
        if (s.size() > 1 && s[0] == '+') s.remove_prefix(1);
        double x = 0;
        auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
        if (ec != std::errc() || p != s.data() + s.size())
            fail_at(tok.line, "'" + tok.text + "' is not a number (" + what + ")");
        if (!std::isfinite(x)) fail_at(tok.line, std::string(what) + " is " + tok.text + "; numbers must be finite");
        return x;
    }
    /// An integer in [min, max], else a failure at its line naming the file's text.
    long integer(const char* what, long min, long max = std::numeric_limits<int>::max()) {
        const Token& tok = next(what);
        long x = 0;
        auto [p, ec] = std::from_chars(tok.text.data(), tok.text.data() + tok.text.size(), x);
        const bool whole = p == tok.text.data() + tok.text.size();
        if (ec == std::errc::result_out_of_range && whole)
            fail_at(tok.line, std::string(what) + " " + tok.text + " is out of range: at most " + std::to_string(max));
        if (ec != std::errc() || !whole) fail_at(tok.line, "'" + tok.text + "' is not an integer (" + what + ")");
        if (x < min) fail_at(tok.line, std::string(what) + " must be at least " + std::to_string(min) + ", got " + tok.text);
        if (x > max) fail_at(tok.line, std::string(what) + " " + tok.text + " is out of range: at most " + std::to_string(max));
        return x;
    }
    /// One bracketed point with `dim` coordinates.
    Vec3 point(int dim, int index, long count) { return point_with_extras(dim, 0, index, count).first; }

    /// One bracketed point with `dim` coordinates, then `extras` more numbers or none:
    /// `[x y]` or `[x y e1 .. ek]`. The extras are empty when the point has none.
    std::pair<Vec3, std::vector<double>> point_with_extras(int dim, int extras, int index, long count) {
        const std::string which = "point " + std::to_string(index + 1) + " of " + std::to_string(count);
        const Token& open = next(("'[' opening " + which).c_str());
        if (open.text != "[")
            fail_at(open.line, "expected '[' opening " + which + ", got '" + open.text + "' (too few points?)");
        Vec3 p = Vec3::Zero();
        for (int c = 0; c < dim; ++c) {
            if (!done() && (peek().text == "]" || peek().text == "["))
                fail_at(peek().line, which + " has " + std::to_string(c) + " coordinates, expected " + std::to_string(dim));
            p[c] = real("a coordinate");
        }
        std::vector<double> more;
        if (extras > 0 && !done() && peek().text != "]" && peek().text != "[") {
            for (int e = 0; e < extras; ++e) {
                if (!done() && (peek().text == "]" || peek().text == "["))
                    fail_at(peek().line, which + " has " + std::to_string(dim + e) + " numbers, expected " +
                                             std::to_string(dim) + " or " + std::to_string(dim + extras));
                more.push_back(real("a number"));
            }
        }
        const Token& close = next(("']' closing " + which).c_str());
        if (close.text == "[") fail_at(close.line, "unbalanced bracket: '[' inside " + which);
        if (close.text != "]")
            fail_at(close.line, which + " has more than " + std::to_string(dim + extras) +
                                    (extras > 0 ? " numbers" : " coordinates") + " (or an unclosed '[')");
        return {p, std::move(more)};
    }
    int line() const { return done() ? (t_.empty() ? 1 : t_.back().line) : peek().line; }
    [[noreturn]] void fail(const std::string& what) const { throw ParseError(file_, line(), what); }
    [[noreturn]] void fail_at(int line, const std::string& what) const { throw ParseError(file_, line, what); }

private:
    std::vector<Token> t_;
    size_t pos_ = 0;
    std::string file_;
};

}  // namespace crossdiv::io_detail
