// The dense decompositions the program needs, instantiated once (linear_algebra.cpp): Eigen's
// SVD is a heavy template, and each file that instantiated its own paid ~20 s of compile time.
#pragma once

#include <Eigen/Core>

namespace accelcal {

struct SingularValueDecomposition {
  Eigen::VectorXd values;  // descending, min(rows, cols) of them
  Eigen::MatrixXd v;       // the right singular vectors, one per column (cols x cols)
};

// The singular values of `a`, descending.
Eigen::VectorXd SingularValues(const Eigen::MatrixXd& a);
// The singular values and the full set of right singular vectors of `a`.
SingularValueDecomposition DecomposeSvd(const Eigen::MatrixXd& a);

}  // namespace accelcal
