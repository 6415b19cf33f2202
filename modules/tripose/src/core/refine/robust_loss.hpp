// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_TRIPOSE_REFINE_ROBUST_LOSS_HPP
#define OPENCV_TRIPOSE_REFINE_ROBUST_LOSS_HPP

#include <cmath>

#include "../support/options.hpp"

namespace tripose {

/** The loss rho(s) of one observation, s its squared residual norm in px^2 (a point's two
coordinates, or a segment's two end-point distances), and the weight rho'(s) with which that
observation enters iteratively reweighted least squares.
*/
class RobustLossFunction
{
public:
    RobustLossFunction(Loss kind, double scale) : kind_(kind), c2_(scale * scale) {}

    //! rho(s); @p weight, when given, receives rho'(s).
    double evaluate(double s, double* weight = nullptr) const
    {
        double w = 1.0, rho = s;
        if (kind_ == Loss::Huber && s > c2_)
        {
            const double r = std::sqrt(s), c = std::sqrt(c2_);
            w = c / r;
            rho = 2 * c * r - c2_;
        }
        else if (kind_ == Loss::Cauchy)
        {
            w = 1.0 / (1.0 + s / c2_);
            rho = c2_ * std::log1p(s / c2_);
        }
        if (weight)
            *weight = w;
        return rho;
    }

private:
    Loss kind_;
    double c2_;
};

} // namespace tripose

#endif // OPENCV_TRIPOSE_REFINE_ROBUST_LOSS_HPP
