#pragma once
/// @file
/// Typed errors for bad input. Every error says what was wrong and where: the file and
/// line when the element came from a file, otherwise the element (vertex, face, edge) by
/// index. The CLI turns an InputError into exit code 2.

#include <stdexcept>
#include <string>

namespace crossdiv {

/// Bad input from a user: a malformed file, a mesh a scheme cannot take, a bad option.
/// Never a bug of ours; those are std::logic_error.
class InputError : public std::runtime_error {
public:
    /// @param message what is wrong, already naming the element and location.
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// A mesh that is not a manifold, consistently oriented one, in a way OpenSubdiv's
/// non-manifold rules refine (nonmanifold.h): an edge of more than two faces, two faces
/// traversing an edge in the same direction (a duplicate face), a vertex whose faces form
/// several fans, a face naming a vertex twice. The
/// manifold refinements throw it; Loop and Catmull-Clark then take those rules when asked to.
class NonManifoldInput : public InputError {
public:
    using InputError::InputError;
};

/// An input file could not be parsed; the message is prefixed with `file:line: `.
class ParseError : public InputError {
public:
    ParseError(const std::string& file, int line, const std::string& what)
        : InputError(file + ":" + std::to_string(line) + ": " + what), file_(file), line_(line) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }

private:
    std::string file_;
    int line_;
};

/// A number in an input file reads as NaN or infinity: a ParseError of its own kind, so
/// that a harness reading another program's output can name it as a non-finite result.
class NonFiniteNumber : public ParseError {
public:
    using ParseError::ParseError;
};

}  // namespace crossdiv
