#include "crossdiv/verification/implementations/registry.h"

#include <algorithm>
#include <cctype>
#include <memory>
#include <string_view>

#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/harness/isolate.h"
#include "library_implementations.h"
#ifdef CROSSDIV_HAS_ASSIMP
#include "crossdiv/adapters/assimp.h"
#endif

namespace crossdiv::verification {
namespace {

std::vector<std::unique_ptr<Implementation>> build() {
    std::vector<std::unique_ptr<Implementation>> all;
    all.push_back(detail::make_core_implementation());
#ifdef CROSSDIV_HAS_OPENSUBDIV
    all.push_back(detail::make_opensubdiv_implementation());
#endif
#ifdef CROSSDIV_HAS_HBR
    all.push_back(detail::make_hbr_implementation());
#endif
#ifdef CROSSDIV_HAS_OPENMESH
    for (auto& i : detail::make_openmesh_implementations()) all.push_back(std::move(i));
#endif
#ifdef CROSSDIV_HAS_CGAL
    for (auto& i : detail::make_cgal_implementations()) all.push_back(std::move(i));
#endif
#ifdef CROSSDIV_HAS_VTK
    all.push_back(detail::make_vtk_implementation());
#endif
#ifdef CROSSDIV_HAS_EIGEN_SPLINES
    all.push_back(detail::make_eigen_implementation());
#endif
    // A program (adapters/skimage): always listed; a machine without scikit-image makes its
    // runs unavailable.
    all.push_back(detail::make_skimage_implementation());
    return all;
}

std::vector<std::unique_ptr<Implementation>>& owned() {
    static std::vector<std::unique_ptr<Implementation>> all = build();
    return all;
}

/// The list implementations() hands out, remade when a reference is registered.
std::vector<const Implementation*>& listed() {
    static std::vector<const Implementation*> all = [] {
        std::vector<const Implementation*> v;
        for (const auto& i : owned()) v.push_back(i.get());
        return v;
    }();
    return all;
}

std::string names(const std::vector<const Implementation*>& list) {
    std::string s;
    for (const Implementation* i : list) s += (s.empty() ? "" : ", ") + i->name();
    return s.empty() ? "none" : s;
}

template <class Keep>
std::vector<const Implementation*> references(Keep&& keep) {
    std::vector<const Implementation*> out;
    for (const Implementation* i : implementations())
        if (i->kind() != ImplementationKind::Core && keep(*i)) out.push_back(i);
    return out;
}

/// `wanted` looked up in `having` (all of `having` when empty); `unknown(name)` is the error.
template <class Message>
std::vector<const Implementation*> pick(const std::vector<const Implementation*>& having,
                                        const std::vector<std::string>& wanted, Message&& unknown) {
    if (wanted.empty()) return having;
    std::vector<const Implementation*> out;
    for (const std::string& n : wanted) {
        const auto it = std::find_if(having.begin(), having.end(), [&](const Implementation* i) { return i->name() == n; });
        if (it == having.end()) throw InputError(unknown(n));
        out.push_back(*it);
    }
    return out;
}

}  // namespace

const std::vector<const Implementation*>& implementations() { return listed(); }

void register_reference(std::unique_ptr<Implementation> reference) {
    // The same program under the same name again (a manifest read twice): already there.
    for (const Implementation* i : implementations())
        if (i->name() == reference->name() && i->kind() == reference->kind() && i->version() == reference->version()) return;
    if (is_built(reference->name()))
        throw InputError("a reference named '" + reference->name() + "' exists already (" + names(implementations()) + ")");
    listed().push_back(reference.get());
    owned().push_back(std::move(reference));
}

namespace {

/// The stand-in for core, when a ScopedCoreImplementation is alive.
const Implementation*& core_stand_in() {
    static const Implementation* stand_in = nullptr;
    return stand_in;
}

}  // namespace

const Implementation& core_implementation() { return core_stand_in() ? *core_stand_in() : *owned().front(); }

ScopedCoreImplementation::ScopedCoreImplementation(std::unique_ptr<Implementation> stand_in)
    : stand_in_(std::move(stand_in)), previous_(core_stand_in()) {
    core_stand_in() = stand_in_.get();
}

ScopedCoreImplementation::~ScopedCoreImplementation() { core_stand_in() = previous_; }

void check_subject_name(const std::string& name) {
    if (name.find_first_not_of(" \t") == std::string::npos) throw InputError("a subject needs a name (got an empty one)");
    for (const Implementation* i : implementations())
        if (i->name() == name)
            throw InputError("a subject cannot be named '" + name + "': " + (name == "core" ? "core is" : "'" + name + "' is a reference") +
                             ", and the results would attribute the subject's values to it (names taken: " +
                             names(implementations()) + ")");
}

bool is_built(std::string_view name) {
    return std::any_of(implementations().begin(), implementations().end(),
                       [&](const Implementation* i) { return i->name() == name; });
}

const Implementation& find_implementation(std::string_view name) {
    for (const Implementation* i : implementations())
        if (i->name() == name) return *i;
    throw InputError("unknown or not built implementation '" + std::string(name) + "' (built: " + names(implementations()) + ")");
}

std::vector<const Implementation*> references_for(Scheme scheme) {
    return references([&](const Implementation& i) { return i.has(scheme); });
}

std::vector<const Implementation*> references_with(bool Capabilities::*capability) {
    return references([&](const Implementation& i) { return i.capabilities().*capability; });
}

std::vector<const Implementation*> select_references(Scheme scheme, const std::vector<std::string>& wanted) {
    const std::vector<const Implementation*> having = references_for(scheme);
    return pick(having, wanted, [&](const std::string& n) {
        if (!is_built(n)) return "unknown or not built reference '" + n + "' (built: " + names(having) + ")";
        return "reference '" + n + "' has no " + to_string(scheme) + " in this build (those that have it: " + names(having) + ")";
    });
}

std::vector<const Implementation*> select_references(bool Capabilities::*capability, const std::vector<std::string>& wanted,
                                                     const char* what) {
    const std::vector<const Implementation*> having = references_with(capability);
    return pick(having, wanted, [&](const std::string& n) {
        return "unknown or unavailable " + std::string(what) + " reference '" + n + "' (this build has: " + names(having) + ")";
    });
}

namespace {

/// Whether `path` ends in `ext` (lower case, with its dot), the path's case ignored.
bool ends_in(const std::string& path, std::string_view ext) {
    return path.size() > ext.size() && std::equal(ext.rbegin(), ext.rend(), path.rbegin(), [](char a, char b) {
               return a == std::tolower(static_cast<unsigned char>(b));
           });
}

}  // namespace

std::vector<std::string> readable_mesh_extensions() {
    std::vector<std::string> all(mesh_extensions().begin(), mesh_extensions().end());
#ifdef CROSSDIV_HAS_ASSIMP
    all.insert(all.end(), adapters::assimp::extensions().begin(), adapters::assimp::extensions().end());
#endif
    return all;
}

bool readable_mesh_file(const std::string& path) {
    const std::vector<std::string> all = readable_mesh_extensions();
    return std::any_of(all.begin(), all.end(), [&](const std::string& ext) { return ends_in(path, ext); });
}

#ifdef CROSSDIV_HAS_ASSIMP
namespace {
/// How long a mesh file may take to read (a file of a corpus that makes the reader loop is
/// named, not waited for): the largest test model Assimp ships reads in under a second.
constexpr double kInputReadTimeoutSeconds = 120;
}  // namespace
#endif

std::optional<PolyMesh> read_with_input_adapter([[maybe_unused]] const std::string& path) {
#ifdef CROSSDIV_HAS_ASSIMP
    for (const std::string& ext : adapters::assimp::extensions()) {
        if (!ends_in(path, ext)) continue;
        // In a child process, as a reference runs: Debian's Assimp keeps its assertions, and a
        // file that breaks one (a broken file of a corpus) aborts the process that reads it.
        IsolatedTrace r = run_isolated([&] { return adapters::LevelTrace{adapters::assimp::read_mesh(path)}; },
                                       kInputReadTimeoutSeconds);
        if (r.outcome.status == RunStatus::Threw) throw InputError(r.outcome.message);  // read_mesh's own words
        if (r.outcome.status != RunStatus::Ok || !r.trace || r.trace->size() != 1)
            throw InputError(path + ": Assimp could not read it: " + r.outcome.summary());
        PolyMesh mesh = std::move(r.trace->front());
        mesh.source.file = path;
        return mesh;
    }
#endif
    return std::nullopt;
}

}  // namespace crossdiv::verification
