// The absolute paths of this build, compiled here alone (see test_inputs.h).
#include "test_inputs.h"

namespace crossdiv::verification::test {

const std::string& source_dir() {
    static const std::string dir = CROSSDIV_SOURCE_DIR;
    return dir;
}

const std::string& crossdiv_cli() {
    static const std::string cli = CROSSDIV_CLI;
    return cli;
}

}  // namespace crossdiv::verification::test
