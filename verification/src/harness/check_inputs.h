#pragma once
// How the check operations (curves, surfaces) name their inputs: files, a bundled item
// `ITEM:NAME`, and collections `FAMILY:bundled`, `FAMILY:course`, `FAMILY:synthetic`; one
// expansion for both families.

#include <cctype>
#include <string>
#include <vector>

#include "crossdiv/error.h"

namespace crossdiv::verification::detail {

struct CheckInputFamily {
    std::string family;                     ///< "curves": collections are "curves:..."
    std::string item;                       ///< "curve": bundled items are "curve:NAME"
    std::vector<std::string> extensions;    ///< file extensions taken, lower case (".swp", ...)
    std::vector<std::string> (*bundled)();  ///< names of the bundled items
    std::vector<std::string> (*course)();   ///< the course files present (reads the folder: only when asked)
};

inline bool is_check_input(const CheckInputFamily& f, const std::string& spec) {
    if (spec.starts_with(f.item + ":") || spec.starts_with(f.family + ":")) return true;
    for (const std::string& ext : f.extensions) {
        std::string upper = ext;
        for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (spec.ends_with(ext) || spec.ends_with(upper)) return true;
    }
    return false;
}

/// Expands the collections (`:synthetic` stays one input, run as a whole).
/// @throws InputError for an unknown collection or a name that is not an input of the family.
inline std::vector<std::string> expand_check_inputs(const CheckInputFamily& f, const std::vector<std::string>& specs) {
    const std::string collections = f.family + ":bundled, " + f.family + ":course, " + f.family + ":synthetic";
    std::vector<std::string> out;
    for (const std::string& s : specs) {
        if (s == f.family + ":bundled") {
            for (const std::string& name : f.bundled()) out.push_back(f.item + ":" + name);
        } else if (s == f.family + ":course") {
            for (const std::string& file : f.course()) out.push_back(file);
        } else if (s == f.family + ":synthetic" || !s.starts_with(f.family + ":")) {
            if (!is_check_input(f, s)) {
                std::string files;
                for (const std::string& ext : f.extensions) files += (files.empty() ? "a " : " or ") + ext;
                throw InputError("'" + s + "' is not a " + f.item + " input (" + files + " file, " + f.item + ":NAME, " + collections + ")");
            }
            out.push_back(s);
        } else {
            throw InputError("unknown " + f.item + " collection '" + s + "' (known: " + collections + ")");
        }
    }
    return out;
}

}  // namespace crossdiv::verification::detail
