// Face-varying refinement through Far: PrimvarRefinerReal<double>::InterpolateFaceVarying,
// level by level, under each Sdc::Options::FVarLinearInterpolation.
#include <memory>
#include <string>
#include <vector>

#include "crossdiv/adapters/opensubdiv.h"
#include "opensubdiv_far.h"

namespace crossdiv::adapters::opensubdiv {

using namespace detail;

namespace {

Sdc::Options::FVarLinearInterpolation fvar_option(FaceVaryingRule rule) {
    switch (rule) {
        case FaceVaryingRule::None: return Sdc::Options::FVAR_LINEAR_NONE;
        case FaceVaryingRule::CornersOnly: return Sdc::Options::FVAR_LINEAR_CORNERS_ONLY;
        case FaceVaryingRule::CornersPlus1: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1;
        case FaceVaryingRule::CornersPlus2: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS2;
        case FaceVaryingRule::Boundaries: return Sdc::Options::FVAR_LINEAR_BOUNDARIES;
        case FaceVaryingRule::All: return Sdc::Options::FVAR_LINEAR_ALL;
    }
    return Sdc::Options::FVAR_LINEAR_ALL;
}

/// Three components of a face-varying value (a channel of more is refined three at a time:
/// the rules weigh every component alike).
struct Value3 {
    double v[3];
    void Clear() { v[0] = v[1] = v[2] = 0.0; }
    void AddWithWeight(const Value3& src, double w) {
        v[0] += w * src.v[0];
        v[1] += w * src.v[1];
        v[2] += w * src.v[2];
    }
};

/// The levels with the channel refined; with `limit`, the last level's values replaced by
/// their limits (PrimvarRefinerReal<double>::LimitFaceVarying).
LevelTrace refine(const PolyMesh& mesh, Sdc::SchemeType scheme, Sdc::Options sdc, FaceVaryingRule rule, int levels,
                  LevelBirths* births, bool limit = false) {
    if (mesh.face_varying.empty()) throw Rejected("the mesh has no face-varying channel");
    const FaceVaryingChannel& channel = mesh.face_varying.front();
    sdc.SetFVarLinearInterpolation(fvar_option(rule));
    std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(mesh, scheme, sdc, &channel);
    refine_uniform(*refiner, levels, true);
    if (births) *births = child_births(*refiner);
    LevelTrace trace = interpolate_trace(*refiner, mesh.positions);

    Far::PrimvarRefinerReal<double> primvar(*refiner);
    const int d = channel.dimension;
    for (int level = 0; level <= levels; ++level) {
        FaceVaryingChannel& out = trace[static_cast<size_t>(level)].face_varying.emplace_back();
        out.name = channel.name;
        out.dimension = d;
        out.values.resize(static_cast<size_t>(refiner->GetLevel(level).GetNumFVarValues(0)) * d);
        const Far::TopologyLevel& l = refiner->GetLevel(level);
        for (int f = 0; f < l.GetNumFaces(); ++f) {
            Far::ConstIndexArray fv = l.GetFaceFVarValues(f, 0);
            for (int k = 0; k < fv.size(); ++k) out.corner_values.push_back(fv[k]);
        }
    }
    // Three components at a time (the rules weigh every component alike).
    for (int first = 0; first < d; first += 3) {
        const int count = std::min(3, d - first);
        std::vector<Value3> src(static_cast<size_t>(channel.num_values()), Value3{{0.0, 0.0, 0.0}});
        for (int i = 0; i < channel.num_values(); ++i)
            for (int k = 0; k < count; ++k) src[static_cast<size_t>(i)].v[k] = channel.value(i)[first + k];
        for (int level = 0; level <= levels; ++level) {
            if (level > 0) {
                std::vector<Value3> dst(static_cast<size_t>(refiner->GetLevel(level).GetNumFVarValues(0)));
                const Value3* in = src.data();
                Value3* out_values = dst.data();
                primvar.InterpolateFaceVarying(level, in, out_values, 0);
                src = std::move(dst);
            }
            if (limit && level == levels) {
                std::vector<Value3> dst(src.size());
                Value3* out_values = dst.data();
                primvar.LimitFaceVarying(src.data(), out_values, 0);
                src = std::move(dst);
            }
            std::vector<double>& values = trace[static_cast<size_t>(level)].face_varying.back().values;
            for (size_t i = 0; i < src.size(); ++i)
                for (int k = 0; k < count; ++k) values[i * static_cast<size_t>(d) + static_cast<size_t>(first + k)] = src[i].v[k];
        }
    }
    if (!g_far_errors.empty()) throw Rejected("Far reported: " + g_far_errors);
    return trace;
}

}  // namespace

LevelTrace catmull_clark_face_varying(const PolyMesh& mesh, const CatmullClarkOptions& options, FaceVaryingRule rule,
                                      int levels, LevelBirths* births) {
    return refine(mesh, Sdc::SCHEME_CATMARK, catmark_options(options), rule, levels, births);
}

LevelTrace loop_face_varying(const PolyMesh& mesh, const LoopOptions& options, FaceVaryingRule rule, int levels,
                             LevelBirths* births) {
    return refine(mesh, Sdc::SCHEME_LOOP, loop_options(options), rule, levels, births);
}

PolyMesh catmull_clark_face_varying_limit(const PolyMesh& mesh, const CatmullClarkOptions& options, FaceVaryingRule rule,
                                          int levels) {
    return refine(mesh, Sdc::SCHEME_CATMARK, catmark_options(options), rule, levels, nullptr, true).back();
}

PolyMesh loop_face_varying_limit(const PolyMesh& mesh, const LoopOptions& options, FaceVaryingRule rule, int levels) {
    return refine(mesh, Sdc::SCHEME_LOOP, loop_options(options), rule, levels, nullptr, true).back();
}

LevelTrace bilinear_face_varying(const PolyMesh& mesh, FaceVaryingRule rule, int levels, LevelBirths* births) {
    reject_crease_tags(mesh, "OpenSubdiv's bilinear scheme (as compared here)");
    return refine(mesh, Sdc::SCHEME_BILINEAR, sdc_options(false, CreaseMethod::Uniform), rule, levels, births);
}

}  // namespace crossdiv::adapters::opensubdiv
