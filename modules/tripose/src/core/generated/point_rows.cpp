// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/point_rows.py
// through the template codegen/tripose_codegen/templates/source.cpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#include "point_rows.hpp"

namespace tripose {
namespace generated {

void pointRows(const double* x1, const double* x2, const double* x3, const double* n1,
        const double* n2, const double* n3, const double* R12, const double* t12, double* rows)
{
    // Operation count: 44 mul, 16 add, 1 div (total 61).
    const double _tmp0 = 1.0/n1[0];
    const double _tmp1 = _tmp0*x1[0] + n1[1];
    const double _tmp2 = _tmp0*x1[1] + n1[2];
    const double _tmp3 = R12[0]*_tmp1 + R12[1]*_tmp2 + R12[2];
    const double _tmp4 = R12[3]*_tmp1 + R12[4]*_tmp2 + R12[5];
    const double _tmp5 = R12[6]*_tmp1 + R12[7]*_tmp2 + R12[8];
    const double _tmp6 = -n2[0]*n2[1] - x2[0];
    const double _tmp7 = -n2[0]*n2[2] - x2[1];
    const double _tmp8 = -n3[0]*n3[1] - x3[0];
    const double _tmp9 = -n3[0]*n3[2] - x3[1];
    const double _tmp10 = _tmp3*n2[0] + _tmp5*_tmp6;
    const double _tmp11 = _tmp10*n3[0];
    const double _tmp12 = _tmp6*t12[2] + n2[0]*t12[0];
    const double _tmp13 = _tmp12*n3[0];
    const double _tmp14 = -_tmp1*_tmp13;
    const double _tmp15 = _tmp12*_tmp8;
    const double _tmp16 = -_tmp13*_tmp2;
    const double _tmp17 = -_tmp13;
    const double _tmp18 = _tmp12*_tmp9;
    const double _tmp19 = _tmp4*n2[0] + _tmp5*_tmp7;
    const double _tmp20 = _tmp19*n3[0];
    const double _tmp21 = _tmp7*t12[2] + n2[0]*t12[1];
    const double _tmp22 = _tmp21*n3[0];
    const double _tmp23 = -_tmp1*_tmp22;
    const double _tmp24 = _tmp21*_tmp8;
    const double _tmp25 = -_tmp2*_tmp22;
    const double _tmp26 = -_tmp22;
    const double _tmp27 = _tmp21*_tmp9;
    rows[0] = _tmp14;
    rows[1] = 0;
    rows[2] = -_tmp1*_tmp15;
    rows[3] = _tmp16;
    rows[4] = 0;
    rows[5] = -_tmp15*_tmp2;
    rows[6] = _tmp17;
    rows[7] = 0;
    rows[8] = -_tmp15;
    rows[9] = _tmp11;
    rows[10] = 0;
    rows[11] = _tmp10*_tmp8;
    rows[12] = 0;
    rows[13] = _tmp14;
    rows[14] = -_tmp1*_tmp18;
    rows[15] = 0;
    rows[16] = _tmp16;
    rows[17] = -_tmp18*_tmp2;
    rows[18] = 0;
    rows[19] = _tmp17;
    rows[20] = -_tmp18;
    rows[21] = 0;
    rows[22] = _tmp11;
    rows[23] = _tmp10*_tmp9;
    rows[24] = _tmp23;
    rows[25] = 0;
    rows[26] = -_tmp1*_tmp24;
    rows[27] = _tmp25;
    rows[28] = 0;
    rows[29] = -_tmp2*_tmp24;
    rows[30] = _tmp26;
    rows[31] = 0;
    rows[32] = -_tmp24;
    rows[33] = _tmp20;
    rows[34] = 0;
    rows[35] = _tmp19*_tmp8;
    rows[36] = 0;
    rows[37] = _tmp23;
    rows[38] = -_tmp1*_tmp27;
    rows[39] = 0;
    rows[40] = _tmp25;
    rows[41] = -_tmp2*_tmp27;
    rows[42] = 0;
    rows[43] = _tmp26;
    rows[44] = -_tmp27;
    rows[45] = 0;
    rows[46] = _tmp20;
    rows[47] = _tmp19*_tmp9;
}

} // namespace generated
} // namespace tripose
