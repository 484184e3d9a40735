#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

std::vector<Vec3> StencilTable::auxiliary_values(const std::vector<Vec3>& coarse) const {
    std::vector<Vec3> aux(aux_start_.size() - 1);
    for (size_t a = 0; a + 1 < aux_start_.size(); ++a) {
        Vec3 sum = Vec3::Zero();
        for (int k = aux_start_[a]; k < aux_start_[a + 1]; ++k) sum += aux_weight_[k] * coarse[aux_source_[k]];
        aux[a] = sum;
    }
    return aux;
}

std::vector<Vec3> StencilTable::apply(const std::vector<Vec3>& coarse) const {
    std::vector<Vec3> out(static_cast<size_t>(num_rows()));
    const std::vector<Vec3> aux = auxiliary_values(coarse);
    for (const bool second_pass : {false, true}) {
        for (int r = 0; r < num_rows(); ++r) {
            if (reads_refined_[r] != second_pass) continue;
            Vec3 sum = Vec3::Zero();
            for (int k = row_start_[r]; k < row_start_[r + 1]; ++k) {
                const int s = source_[k];
                sum += weight_[k] * (s < 0 ? aux[-1 - s] : s < num_coarse_ ? coarse[s] : out[s - num_coarse_]);
            }
            out[r] = sum;
        }
    }
    return out;
}

Eigen::SparseMatrix<double> StencilTable::matrix() const {
    // A referenced row or auxiliary point reads coarse vertices only, so its own terms are
    // its expansion.
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(source_.size() * 2);
    for (int r = 0; r < num_rows(); ++r) {
        for (int k = row_start_[r]; k < row_start_[r + 1]; ++k) {
            const int s = source_[k];
            if (s < 0) {
                const int a = -1 - s;
                for (int j = aux_start_[a]; j < aux_start_[a + 1]; ++j)
                    triplets.emplace_back(r, aux_source_[j], weight_[k] * aux_weight_[j]);
            } else if (s < num_coarse_) {
                triplets.emplace_back(r, s, weight_[k]);
            } else {
                const int q = s - num_coarse_;
                for (int j = row_start_[q]; j < row_start_[q + 1]; ++j)
                    triplets.emplace_back(r, source_[j], weight_[k] * weight_[j]);
            }
        }
    }
    Eigen::SparseMatrix<double> S(num_rows(), num_coarse_);
    S.setFromTriplets(triplets.begin(), triplets.end());  // sums duplicate entries
    return S;
}

PolyMesh apply_step(const RefinementStep& step, const PolyMesh& coarse) {
    PolyMesh out;
    out.positions = step.stencils.apply(coarse.positions);
    if (!coarse.colors.empty()) out.colors = step.stencils.apply(coarse.colors);
    out.face_start = step.face_start;
    out.face_vertices = step.face_vertices;
    out.creases = step.creases;
    out.derived = step.derived;
    return out;
}

}  // namespace crossdiv
