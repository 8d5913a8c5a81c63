// Internal: the eigen-decomposition the skeleton statistics use everywhere.
#pragma once

#include <Eigen/Core>

#include "ramus/skeleton_stats.hpp"

namespace ramus::detail {

/// Eigenvalues (descending, clamped to ≥ 0) and unit eigenvectors (columns, same order, each
/// with its largest-magnitude entry positive, so results do not depend on the solver's sign
/// choice) of a symmetric matrix. A 0×0 matrix gives empty results.
struct SortedEigen {
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
};
SortedEigen decomposeSymmetric(const Eigen::MatrixXd& matrix);

/// One random PCA coordinate for an axis with eigenvalue λ: N(0, λ) for SampleSpread::Model,
/// λ·N(0, 1) for SampleSpread::Thesis.
double sampleCoordinate(Rng& rng, double eigenvalue, SampleSpread spread);

}  // namespace ramus::detail
