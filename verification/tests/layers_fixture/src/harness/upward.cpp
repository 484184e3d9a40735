// A harness source that reaches up into the suite: what cmake/check_layers.cmake must refuse
// (the layers test runs the check on this folder). Never compiled.
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/suite/manifest.h"
