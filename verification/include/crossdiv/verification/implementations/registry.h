#pragma once
/// @file
/// Every implementation this binary has, by name: core first, then each reference library
/// it was built with (CROSSDIV_WITH_* options), in a fixed order, then the external references
/// registered at run time (programs, from a manifest's `reference` statement or the CLI's
/// --reference). The only place in the harness that knows which adapters exist; everything
/// else asks here.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

/// core, opensubdiv, openmesh, openmesh-one-call, cgal, cgal-one-call, eigen (those built),
/// then the registered external references in the order registered.
const std::vector<const Implementation*>& implementations();

/// Adds an external reference (a program) for the rest of the process; worker processes
/// forked later inherit it. The same program under the same name again is kept once.
/// @throws InputError when another implementation of that name exists.
void register_reference(std::unique_ptr<Implementation> reference);

/// Refuses a subject's name that is empty or names an implementation (core, a library, a
/// registered reference): the results would attribute its values to that one, or hide them.
/// @throws InputError naming the clash.
void check_subject_name(const std::string& name);

/// Whether an implementation of that name is built into this binary.
bool is_built(std::string_view name);

/// Core's implementation (always present), or the double a ScopedCoreImplementation put in
/// its place.
const Implementation& core_implementation();

/// Stands `stand_in` in for core's implementation for its lifetime (core_implementation()
/// returns it): how a test seeds a bug into what the comparisons and oracles call "core"
/// without editing core. Worker processes forked meanwhile inherit it.
class ScopedCoreImplementation {
public:
    explicit ScopedCoreImplementation(std::unique_ptr<Implementation> stand_in);
    ~ScopedCoreImplementation();
    ScopedCoreImplementation(const ScopedCoreImplementation&) = delete;
    ScopedCoreImplementation& operator=(const ScopedCoreImplementation&) = delete;

private:
    std::unique_ptr<Implementation> stand_in_;
    const Implementation* previous_;
};

/// @throws InputError naming the unknown or unbuilt implementation and listing those built.
const Implementation& find_implementation(std::string_view name);

/// The references (every implementation but core) that have `scheme`, in registry order.
std::vector<const Implementation*> references_for(Scheme scheme);

/// The references that declare a capability, e.g. references_with(&Capabilities::edits).
std::vector<const Implementation*> references_with(bool Capabilities::*capability);

/// `names` resolved to references that have `scheme` (all of them when `names` is empty).
/// @throws InputError for a name that is not built or lacks the scheme, listing those that have it.
std::vector<const Implementation*> select_references(Scheme scheme, const std::vector<std::string>& names);

/// `names` resolved to references that declare `capability` (all when `names` is empty).
/// @throws InputError for a name that is not built or lacks it; `what` names the capability.
std::vector<const Implementation*> select_references(bool Capabilities::*capability, const std::vector<std::string>& names,
                                                     const char* what);

/// The extensions core's readers (.obj, .off, .ply) and the input adapters of this build
/// (Assimp: .dae, .stl) take, lower case with their dot.
std::vector<std::string> readable_mesh_extensions();

/// Whether `path` ends in one of readable_mesh_extensions(), compared without case.
bool readable_mesh_file(const std::string& path);

/// Reads `path` through the input adapter built for its extension (Assimp: .dae, .ply, .stl);
/// nothing when no input adapter of this build takes it. @throws InputError naming the file.
std::optional<PolyMesh> read_with_input_adapter(const std::string& path);

}  // namespace crossdiv::verification
