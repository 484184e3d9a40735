#pragma once
/// @file
/// Where crossdiv's own files are: the suite manifests, the report script and the program
/// adapters (MeshLab's). An installed crossdiv finds them beside itself, under
/// PREFIX/share/crossdiv/ for PREFIX/bin/crossdiv (the executable's own path, from
/// /proc/self/exe); a crossdiv run from its build tree, which has no such folder, uses the
/// source tree it was configured from.

#include <string>

namespace crossdiv::verification {

/// The folder of the suite manifests (default.suite): share/crossdiv/suites, else
/// verification/suites of the source tree.
std::string suites_dir();
/// The folder of the report script (make_report.py): share/crossdiv/reports, else reports/.
std::string reports_dir();
/// The folder of the program adapters (meshlab/meshlab_subdivide.py), the {adapters} of a
/// command template: share/crossdiv/adapters, else adapters/ of the source tree.
std::string adapters_dir();

}  // namespace crossdiv::verification
