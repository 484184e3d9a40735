// libFuzzer target: one shard's results.json as `crossdiv merge` reads it (read_shard_results),
// then every record it accepts written back and read again, as the merged results.json is.
#include <nlohmann/json.hpp>

#include "crossdiv/verification/suite/shard_results.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    return fuzz::refuse_or_answer([&] {
        std::istringstream in = fuzz::stream_of(data, size);
        const verification::ShardResults shard = verification::read_shard_results(in, "results.json");
        (void)shard.suite();
        (void)shard.jobs_total();
        (void)shard.shard();
        for (const verification::CaseRecord& c : shard.cases) {
            const verification::CaseRecord again = verification::case_record_from_json(verification::to_json(c));
            if (again.job != c.job) __builtin_trap();  // a record must survive its own round trip
        }
    });
}
