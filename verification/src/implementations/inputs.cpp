#include "crossdiv/verification/implementations/inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fnmatch.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/data_paths.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/datasets/uv_layouts.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {

namespace {

/// Whether the last component of a `dir:` input is a pattern (fnmatch's * ? [).
bool is_pattern(const std::string& name) { return name.find_first_of("*?[") != std::string::npos; }

/// The mesh files of a user's folder, `dir:PATH` (every file a reader takes) or
/// `dir:PATH/PATTERN` (the files whose names match PATTERN), sorted by name, not recursive.
/// A folder the user names must exist and hold a mesh: an empty expansion would let a suite
/// pass that compared nothing.
std::vector<std::string> folder_inputs(const std::string& spec) {
    namespace fs = std::filesystem;
    const std::string path = spec.substr(4);
    if (path.empty()) throw InputError("'dir:' names no folder (dir:PATH, or dir:PATH/*.obj)");
    fs::path folder(path);
    std::string pattern;
    if (is_pattern(folder.filename().string())) {
        pattern = folder.filename().string();
        folder = folder.parent_path().empty() ? fs::path(".") : folder.parent_path();
    }
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) throw InputError(spec + ": " + folder.string() + " is not a folder");
    std::vector<std::string> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        const std::string name = it->path().filename().string();
        if (pattern.empty() ? readable_mesh_file(name) : fnmatch(pattern.c_str(), name.c_str(), 0) == 0)
            files.push_back(it->path().string());
    }
    if (ec) throw InputError(spec + ": cannot list " + folder.string() + ": " + ec.message());
    if (files.empty() && pattern.empty()) {
        std::string known;
        for (const std::string& ext : readable_mesh_extensions()) known += (known.empty() ? "" : ", ") + ext;
        throw InputError(spec + ": no mesh file (" + known + ") in " + folder.string());
    }
    if (files.empty()) throw InputError(spec + ": no file of " + folder.string() + " matches " + pattern);
    std::sort(files.begin(), files.end());
    return files;
}

/// Where Debian's assimp-testmodels installs Assimp's own test models (some 40 formats, broken
/// files among them on purpose).
constexpr const char* kAssimpTestModels = "/usr/share/assimp/models";

/// One file in this many of a corpus makes its fixed sample (corpus:assimp-sample: 52 of 414).
constexpr size_t kSampleStride = 8;

/// Every file under `root`, recursively, that a reader of crossdiv takes, sorted; empty when
/// the folder is absent (optional data, as the CGAL demo meshes).
std::vector<std::string> corpus_files(const std::string& root) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    std::error_code ec;
    if (!fs::is_directory(root, ec)) return files;
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && readable_mesh_file(it->path().string())) files.push_back(it->path().string());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

std::vector<std::string> expand_inputs(const std::vector<std::string>& specs) {
    std::vector<std::string> out;
    for (const std::string& s : specs) {
        if (s.starts_with("uv:") && s.ends_with(":all")) {
            // uv:LAYOUT:COLLECTION: each input of the collection with texture coordinates.
            const size_t colon = s.find(':', 3);
            const std::string layout = s.substr(3, colon - 3);
            (void)datasets::uv_layout_from_string(layout);  // an unknown layout is refused here
            for (std::string& in : expand_inputs({s.substr(colon + 1)})) out.push_back("uv:" + layout + ":" + in);
        } else if (s.starts_with("dir:")) {
            for (std::string& f : folder_inputs(s)) out.push_back(std::move(f));
        } else if (s == "bundled:all") {
            for (const auto& b : datasets::bundled_meshes()) out.push_back("bundled:" + b.name);
        } else if (s == "creases:all") {
            for (const auto& b : datasets::crease_meshes()) out.push_back("bundled:" + b.name);
        } else if (s == "polygons:all") {
            for (const auto& b : datasets::polygon_meshes()) out.push_back("bundled:" + b.name);
        } else if (s == "edgecases:all") {
            for (const auto& c : datasets::edge_cases()) out.push_back("edgecase:" + c.name);
        } else if (s == "polygon-edgecases:all") {
            for (const auto& c : datasets::polygon_edge_cases()) out.push_back("edgecase:" + c.name);
        } else if (s == "uv-edgecases:all") {
            for (const auto& c : datasets::uv_edge_cases()) out.push_back("edgecase:" + c.name);
        } else if (s == "uv-edgecases-tri:all") {  // their triangulations: Loop's inputs
            for (const auto& c : datasets::uv_edge_cases())
                if (c.name.ends_with("-tri")) out.push_back("edgecase:" + c.name);
        } else if (s == "course:all") {
            for (const auto& f : datasets::course_mesh_files()) out.push_back(f);
        } else if (s == "meshedit:all") {
            for (const auto& f : datasets::meshedit_mesh_files()) out.push_back(f);
        } else if (s == "cgal:all") {
            for (const auto& f : datasets::cgal_mesh_files()) out.push_back(f);
        } else if (s == "opensubdiv:all") {
            for (const auto& f : datasets::opensubdiv_shape_files()) out.push_back(f);
        } else if (s == "corpus:assimp") {
            for (std::string& f : corpus_files(kAssimpTestModels)) out.push_back(std::move(f));
        } else if (s == "corpus:sweethome3d") {
            for (std::string& f : corpus_files((datasets::datasets_dir() / "corpus" / "sweethome3d").string()))
                out.push_back(std::move(f));
        } else if (s == "corpus:all") {
            for (std::string& f : expand_inputs({"corpus:assimp", "corpus:sweethome3d"})) out.push_back(std::move(f));
        } else if (s == "corpus:assimp-sample") {
            // A fixed sample for the main job: every kSampleStride-th file in name order.
            const std::vector<std::string> all = corpus_files(kAssimpTestModels);
            for (size_t i = 0; i < all.size(); i += kSampleStride) out.push_back(all[i]);
        } else if (s.ends_with(":all")) {
            throw InputError("unknown collection '" + s + "' (known: bundled:all, polygons:all, creases:all, edgecases:all, polygon-edgecases:all, uv-edgecases:all, uv-edgecases-tri:all, course:all, meshedit:all, cgal:all, opensubdiv:all, corpus:assimp, corpus:assimp-sample, corpus:sweethome3d, corpus:all)");
        } else {
            out.push_back(s);
        }
    }
    return out;
}

namespace {

PolyMesh read_input(const std::string& spec) {
    if (spec.starts_with("uv:")) {
        // uv:LAYOUT:INPUT, the input with texture coordinates in a named layout (uv_layouts.h).
        const size_t colon = spec.find(':', 3);
        if (colon == std::string::npos)
            throw InputError("'" + spec + "': expected uv:LAYOUT:INPUT (layouts: " + variant_names(datasets::kUvLayouts) + ")");
        const datasets::UvLayout layout = datasets::uv_layout_from_string(spec.substr(3, colon - 3));
        PolyMesh m = datasets::with_uv_layout(read_input(spec.substr(colon + 1)), layout);
        m.source.file = spec;
        return m;
    }
    if (spec.starts_with("bundled:")) return datasets::bundled_mesh(spec.substr(8));
    if (spec.starts_with("edgecase:")) return datasets::edge_case(spec.substr(9)).mesh;
    if (std::optional<PolyMesh> m = read_with_input_adapter(spec)) return std::move(*m);
    // A word and a colon that is no file (cgal:fandisk) reads as a mistyped input name, not
    // as a file of unknown format.
    if (const size_t colon = spec.find(':'); colon != std::string::npos && colon > 0 &&
                                             spec.find('/') > colon && !std::filesystem::exists(spec))
        throw InputError("'" + spec + "' is neither a file nor a known input name (known: bundled:NAME, " +
                         "edgecase:NAME, uv:LAYOUT:INPUT, dir:FOLDER, and the collections bundled:all, polygons:all, creases:all, edgecases:all, " +
                         "polygon-edgecases:all, uv-edgecases:all, uv-edgecases-tri:all, " +
                         "course:all, meshedit:all, cgal:all, opensubdiv:all, corpus:assimp, corpus:assimp-sample, corpus:sweethome3d, corpus:all)");
    return read_mesh(spec);
}

}  // namespace

PolyMesh load_input(const std::string& spec, UnknownTags unknown_tags) {
    PolyMesh mesh = read_input(spec);
    // A file without a vertex reads as an empty mesh (a program's empty result is one); as an
    // input it is nothing to refine, and most often no mesh at all (the reader's note says what
    // it skipped).
    if (mesh.num_vertices() == 0)
        throw InputError(spec + ": no vertex, nothing to refine" +
                         (mesh.source.notes.empty() ? std::string() : " (" + mesh.source.notes.front() + ")"));
    std::vector<std::string>& unknown = mesh.source.unknown_tags;
    if (!unknown.empty() && unknown_tags == UnknownTags::Refuse)
        throw InputError("unknown tag " + unknown.front() + (unknown.size() > 1 ? " (and " + std::to_string(unknown.size() - 1) + " more)" : std::string()) +
                         ": refining without it would follow other rules than the file states (known: crease, "
                         "corner, hole, creasemethod, interpolateboundary, smoothtriangles, and the face-varying "
                         "tags); --ignore-unknown-tags refines without it");
    for (const std::string& t : unknown) mesh.source.notes.push_back("ignored unknown tag " + t);
    unknown.clear();
    return mesh;
}

}  // namespace crossdiv::verification
