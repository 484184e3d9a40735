#pragma once
// The tessellation of whatever a curve reader accepts: every record in each mode, with the
// work of one input bounded (records whose uniform samples would exceed kMaxSamples are
// tessellated by the adaptive modes only).

#include <cmath>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/curves/tessellation.h"
#include "fuzz_input.h"

namespace crossdiv::fuzz {

inline constexpr long long kMaxSamples = 20'000;

inline void tessellate_what_parses(const CurveFile& file) {
    for (const CurveRecord& r : file.curves) {
        long long segments = 1;
        if (r.type != CurveType::Primitive) refuse_or_answer([&] { segments = r.chain().num_segments(); });
        if (segments * r.steps <= kMaxSamples)
            refuse_or_answer([&] { (void)tessellate_record(r, {}); });
        TessellationOptions angle;
        angle.mode = TessellationMode::Angle;
        angle.angle_tol = 0.3;
        refuse_or_answer([&] { (void)tessellate_record(r, angle); });
    }
}

}  // namespace crossdiv::fuzz
