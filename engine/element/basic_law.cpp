#include "element/basic_law.hpp"

namespace plastica {

Eigen::Matrix3d elastic_basic_stiffness(double EA, double EI, double L0) {
    Eigen::Matrix3d k = Eigen::Matrix3d::Zero();
    k(0, 0) = EA / L0;
    k(1, 1) = k(2, 2) = 4.0 * EI / L0;
    k(1, 2) = k(2, 1) = 2.0 * EI / L0;
    return k;
}

} // namespace plastica
