#include "accelcal/base/linear_algebra.h"

#include <Eigen/SVD>

namespace accelcal {

Eigen::VectorXd SingularValues(const Eigen::MatrixXd& a) {
  return Eigen::JacobiSVD<Eigen::MatrixXd>(a).singularValues();
}

SingularValueDecomposition DecomposeSvd(const Eigen::MatrixXd& a) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  return {svd.singularValues(), svd.matrixV()};
}

}  // namespace accelcal
