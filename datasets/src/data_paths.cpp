#include "crossdiv/datasets/data_paths.h"

namespace crossdiv::datasets {

std::filesystem::path shared_data_dir() { return CROSSDIV_SHARED_DATA; }
std::filesystem::path datasets_dir() { return CROSSDIV_DATASETS_DIR; }

}  // namespace crossdiv::datasets
