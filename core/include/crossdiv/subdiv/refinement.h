#pragma once
/// @file
/// The generic refinement driver of the polygon schemes (Catmull-Clark, Doo-Sabin, sqrt3,
/// the Butterflies): a scheme's traversal states one level as data -- the refined faces and
/// one stencil per refined vertex -- and this driver applies it to positions and colors,
/// or turns it into the subdivision matrix S with V' = S V. Masks (the weights) live in each
/// scheme's *_mask.h; the traversal lives in the scheme's .cpp; neither knows the other's job.
/// (Loop keeps its own two-group driver, loop.h, which predates this one and is bit-identical
/// with the split-and-flip method.)
///
/// Stencils may read refined vertices, as OpenSubdiv's PrimvarRefiner does (Catmull-Clark
/// edge and vertex points read the new face points): source indices 0 .. num_coarse-1 are
/// coarse vertices, num_coarse + r is refined row r, which must itself read coarse vertices
/// only. Rows reading only coarse vertices are evaluated first, then the others, so the
/// output order (old vertices first, as every library numbers them) is free.
/// Stencils may also read auxiliary points: sums of coarse vertices that are no vertex of the
/// refined mesh, evaluated before any row. They let a rule whose every row around a vertex
/// of valence K reads all K neighbours be stated in O(K) terms instead of O(K^2) (the
/// modified Butterfly's K-point stencil, butterfly.cpp, and Doo-Sabin's corner points of a
/// polygon of many sides, doo_sabin.cpp, each through its Fourier sums).
/// Each row is summed in the order given, as sum_k w_k p_k starting from zero -- OpenSubdiv's
/// Clear/AddWithWeight -- so that a scheme that states its mask in the library's order
/// reproduces the library's rounding.

#include <Eigen/SparseCore>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// One stencil per refined vertex, in compressed-row form.
class StencilTable {
public:
    explicit StencilTable(int num_coarse) : num_coarse_(num_coarse) {}

    /// Adds a term to the row being built; `source` as described in the file comment.
    void add(int source, double weight) {
        source_.push_back(source);
        weight_.push_back(weight);
    }
    /// Adds a term reading refined row `row` (whose stencil reads coarse vertices only).
    void add_refined(int row, double weight) {
        add(num_coarse_ + row, weight);
        current_reads_refined_ = true;
    }
    /// Adds a term reading auxiliary point `point` (see add_auxiliary_term).
    void add_auxiliary(int point, double weight) { add(-1 - point, weight); }
    /// Adds a coarse vertex to the auxiliary point being built.
    void add_auxiliary_term(int coarse, double weight) {
        aux_source_.push_back(coarse);
        aux_weight_.push_back(weight);
    }
    /// Closes the auxiliary point being built; returns its index.
    int end_auxiliary() {
        aux_start_.push_back(static_cast<int>(aux_source_.size()));
        return static_cast<int>(aux_start_.size()) - 2;
    }
    /// Closes the current row; returns its index.
    int end_row() {
        row_start_.push_back(static_cast<int>(source_.size()));
        reads_refined_.push_back(current_reads_refined_);
        current_reads_refined_ = false;
        return num_rows() - 1;
    }
    void reserve(size_t rows, size_t terms) {
        row_start_.reserve(rows + 1);
        reads_refined_.reserve(rows);
        source_.reserve(terms);
        weight_.reserve(terms);
    }

    int num_coarse() const { return num_coarse_; }
    int num_rows() const { return static_cast<int>(row_start_.size()) - 1; }
    int row_begin(int r) const { return row_start_[r]; }
    int row_end(int r) const { return row_start_[r + 1]; }
    int source(int k) const { return source_[k]; }
    double weight(int k) const { return weight_[k]; }

    /// Refined values from coarse ones (positions, colors).
    std::vector<Vec3> apply(const std::vector<Vec3>& coarse) const;

    /// The subdivision matrix (rows: refined vertices, columns: coarse vertices), references
    /// to refined rows substituted by their own expansion.
    Eigen::SparseMatrix<double> matrix() const;

private:
    int num_coarse_;
    std::vector<int> row_start_{0};
    std::vector<int> source_;
    std::vector<double> weight_;
    std::vector<bool> reads_refined_;
    bool current_reads_refined_ = false;
    std::vector<int> aux_start_{0};  ///< auxiliary points in compressed-row form, coarse terms only
    std::vector<int> aux_source_;
    std::vector<double> aux_weight_;

    /// The auxiliary points' values.
    std::vector<Vec3> auxiliary_values(const std::vector<Vec3>& coarse) const;
};

/// One level of a scheme as data: the refined faces (compressed rows, as PolyMesh) and the
/// stencils of the refined vertices.
struct RefinementStep {
    StencilTable stencils;
    std::vector<int> face_start{0};
    std::vector<int> face_vertices;
    CreaseTags creases;  ///< the refined mesh's sharpness tags (schemes with crease rules)
    DerivedTopology derived;  ///< what the refined mesh inherits beyond its faces (PolyMesh::derived), or empty

    explicit RefinementStep(int num_coarse) : stencils(num_coarse) {}
    void add_face(std::initializer_list<int> corners) {
        face_vertices.insert(face_vertices.end(), corners);
        face_start.push_back(static_cast<int>(face_vertices.size()));
    }
};

/// The refined mesh: faces and crease tags of the step, positions (and colors, when the
/// coarse mesh has them) through its stencils. The source (file lines) is not carried over.
PolyMesh apply_step(const RefinementStep& step, const PolyMesh& coarse);

}  // namespace crossdiv
