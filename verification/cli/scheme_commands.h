#pragma once
// The subcommands of the polygon schemes and of limit behaviour: subdivide and compare with
// --scheme catmull-clark (Loop stays in main.cpp), limit and spectrum.

#include <string>
#include <vector>

namespace crossdiv::cli {

/// What `subdivide`/`compare` were given, for a scheme other than Loop.
struct PolySchemeArgs {
    std::string scheme, boundary;
    int levels = 1;
};

/// `crossdiv subdivide IN --scheme catmull-clark --impl core|opensubdiv|openmesh|cgal -o OUT`.
int run_scheme_subdivide(const std::string& in, const PolySchemeArgs& s, const std::string& impl, const std::string& out);

/// `crossdiv compare INPUTS --scheme catmull-clark`: a table per input, exit 0 when every
/// reference agrees, 1 otherwise (each divergence printed with its class).
int run_scheme_compare(const std::vector<std::string>& specs, const PolySchemeArgs& s, const std::string& against,
                       const std::string& json_path, double timeout, bool no_isolate);

}  // namespace crossdiv::cli
