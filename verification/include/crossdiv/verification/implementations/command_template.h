#pragma once
/// @file
/// A command line with placeholders, as a user writes it for an implementation that is a
/// program: `python3 loop.py {in} {levels} {out}`. It is split into words once, the way a
/// shell would split it for the simple cases (whitespace; '...' and "..." group; a backslash
/// outside single quotes escapes the next character) and never given to a shell: each word
/// becomes one argument, so a file name with spaces or `;` is just a name.
///
/// The program runs in a temporary folder; words naming files relative to where crossdiv was
/// started are made absolute first (anchor_relative_paths).
///
/// Placeholders, each inside any word:
///   {in} {in.obj}    the input, written as OBJ with 17 significant digits, with its tags
///                    (OpenSubdiv's 't crease', 't corner', 't interpolateboundary', ... lines):
///                    a command that names it declares it honours them
///   {in.untagged}    the same OBJ without the tag lines, for a program that cannot read them;
///                    it, like OFF and PLY, is refused a tagged input
///   {in.off}         the input as OFF
///   {in.ply}         the input as ASCII PLY
///   {out} {out.obj}  where the program writes its result as OBJ
///   {out.off}        ... as OFF
///   {out.ply}        ... as PLY (ASCII or binary; binary floats read back exactly)
///   {adapters}       the folder of crossdiv's program adapters (install_paths.h)
///   {ops}            the edit task's list of operations (crossdiv edit --subject)
///   {dir}            the submission folder of a roster's subject (a manifest's `subjects`
///                    statement), absolute
///   {levels}         the number of levels asked of this run
///   {scheme}         loop, catmull-clark, doo-sabin, sqrt3, butterfly, modified-butterfly
///   {weights}        loop | warren (Loop's weight family)
///   {boundary}       the boundary rule's name (edge-only, edge-and-corner, ...)
///   {{ and }}        literal braces

#include <string>
#include <vector>

#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// The mesh file formats a program can read or write.
enum class MeshFormat { Obj, Off, Ply };
/// "obj", "off", "ply" (also the file extension).
const char* to_string(MeshFormat format);

/// The values of one run's placeholders.
struct TemplateValues {
    std::string in_obj, in_off, in_ply;  ///< paths of the input in each format (written only when used)
    std::string out;             ///< the output path, with the extension of output_format()
    RefineRequest request;
    std::string in_untagged;  ///< the path of the OBJ without tag lines
    std::string dir;          ///< the program's submission folder ({dir}; empty outside a roster)
    std::string ops;          ///< the edit task's operations file ({ops}; empty elsewhere)
};

class CommandTemplate {
public:
    /// @param needs_output false for a command that makes no mesh (a program's setup check).
    /// @throws InputError naming the template and the problem: an unknown placeholder, an
    ///         unclosed quote or brace, no output placeholder, two output formats, no words.
    explicit CommandTemplate(std::string text, bool needs_output = true);

    const std::string& text() const { return text_; }
    /// The formats of the input the command reads (one file is written per format used).
    bool reads(MeshFormat format) const;
    /// Whether it reads the OBJ with tag lines ({in}, {in.obj}): the program honours tags.
    bool reads_tags() const;
    /// Whether it reads the OBJ without them ({in.untagged}).
    bool reads_untagged_obj() const;
    MeshFormat output_format() const { return output_format_; }
    /// Makes each word without placeholders that names an existing file or folder relative
    /// to `base` (the current folder when empty) absolute, so that the command means what it
    /// means in the user's shell, or beside the manifest that names it, although it runs in a
    /// folder of its own.
    void anchor_relative_paths(const std::string& base = "");
    /// The template as text again, after anchor_relative_paths: the command that means the
    /// same from any folder.
    std::string anchored_text() const;
    /// The argument vector for one run.
    std::vector<std::string> expand(const TemplateValues& values) const;
    /// How many leading words this template and `other` have in common, placeholders and all:
    /// the words that start a serving program (ProgramSpec::serve) and its one-run command
    /// alike, after which the command's words are one run's arguments.
    size_t shared_words(const CommandTemplate& other) const;
    /// Whether a word names a value of one run ({in}, {out}, {levels}, {scheme}, ...): anything
    /// but {adapters} and {dir}, which are the same for every run.
    bool names_run_values() const;

private:
    /// A word is a sequence of literal text and placeholders.
    struct Piece {
        bool placeholder = false;
        std::string text;  ///< literal text, or the placeholder's name
        friend bool operator==(const Piece&, const Piece&) = default;
    };
    std::string text_;
    std::vector<std::vector<Piece>> words_;
    bool reads_obj_ = false, reads_off_ = false, reads_ply_ = false, reads_untagged_ = false;
    MeshFormat output_format_ = MeshFormat::Obj;
};

}  // namespace crossdiv::verification
