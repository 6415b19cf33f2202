// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/line_rows.py
// through the template codegen/tripose_codegen/templates/source.cpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#include "line_rows.hpp"
#include <cmath>

namespace tripose {
namespace generated {

void lineNullSpace(const double* l1, const double* l2, const double* R12, const double* t12,
        double* qa, double* qb)
{
    // Operation count: 40 mul, 19 add, 2 div, 2 sqrt (total 63).
    const double _tmp0 = R12[0]*l2[0] + R12[3]*l2[1] + R12[6]*l2[2];
    const double _tmp1 = R12[1]*l2[0] + R12[4]*l2[1] + R12[7]*l2[2];
    const double _tmp2 = R12[2]*l2[0] + R12[5]*l2[1] + R12[8]*l2[2];
    const double _tmp3 = l2[0]*t12[0] + l2[1]*t12[1] + l2[2]*t12[2];
    const double _tmp4 = -_tmp1*l1[2] + _tmp2*l1[1];
    const double _tmp5 = _tmp0*l1[2] - _tmp2*l1[0];
    const double _tmp6 = -_tmp0*l1[1] + _tmp1*l1[0];
    const double _tmp7 = -_tmp5*l1[2] + _tmp6*l1[1];
    const double _tmp8 = _tmp4*l1[2] - _tmp6*l1[0];
    const double _tmp9 = -_tmp4*l1[1] + _tmp5*l1[0];
    const double _tmp10 = (_tmp4*_tmp4) + (_tmp5*_tmp5) + (_tmp6*_tmp6);
    const double _tmp11 = 1.0/std::sqrt(_tmp10);
    const double _tmp12 = _tmp11/std::sqrt(_tmp10 + (_tmp3*_tmp3)*((l1[0]*l1[0]) + (l1[1]*l1[1])
            + (l1[2]*l1[2])));
    const double _tmp13 = _tmp12*_tmp3;
    qa[0] = _tmp11*_tmp4;
    qa[1] = _tmp11*_tmp5;
    qa[2] = _tmp11*_tmp6;
    qa[3] = 0;
    qb[0] = _tmp13*_tmp7;
    qb[1] = _tmp13*_tmp8;
    qb[2] = _tmp13*_tmp9;
    qb[3] = _tmp10*_tmp12;
}

void lineRows(const double* qa, const double* qb, const double* l3, double* rows)
{
    // Operation count: 24 mul, 0 add, 0 div (total 24).
    rows[0] = l3[0]*qa[0];
    rows[1] = l3[1]*qa[0];
    rows[2] = l3[2]*qa[0];
    rows[3] = l3[0]*qa[1];
    rows[4] = l3[1]*qa[1];
    rows[5] = l3[2]*qa[1];
    rows[6] = l3[0]*qa[2];
    rows[7] = l3[1]*qa[2];
    rows[8] = l3[2]*qa[2];
    rows[9] = l3[0]*qa[3];
    rows[10] = l3[1]*qa[3];
    rows[11] = l3[2]*qa[3];
    rows[12] = l3[0]*qb[0];
    rows[13] = l3[1]*qb[0];
    rows[14] = l3[2]*qb[0];
    rows[15] = l3[0]*qb[1];
    rows[16] = l3[1]*qb[1];
    rows[17] = l3[2]*qb[1];
    rows[18] = l3[0]*qb[2];
    rows[19] = l3[1]*qb[2];
    rows[20] = l3[2]*qb[2];
    rows[21] = l3[0]*qb[3];
    rows[22] = l3[1]*qb[3];
    rows[23] = l3[2]*qb[3];
}

} // namespace generated
} // namespace tripose
