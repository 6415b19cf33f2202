// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/beta_constraints.py
// through the template codegen/tripose_codegen/templates/source.cpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#include "beta_constraints.hpp"

namespace tripose {
namespace generated {

void betaConstraintsN2(const double* v1, const double* v2, double* C)
{
    // Operation count: 72 mul, 57 add, 0 div (total 129).
    const double _tmp0 = (v1[3]*v1[3]);
    const double _tmp1 = (v1[4]*v1[4]);
    const double _tmp2 = (v1[5]*v1[5]);
    const double _tmp3 = (v2[3]*v2[3]);
    const double _tmp4 = (v2[4]*v2[4]);
    const double _tmp5 = (v2[5]*v2[5]);
    const double _tmp6 = 2*v1[3]*v2[3];
    const double _tmp7 = 2*v1[4]*v2[4];
    const double _tmp8 = 2*v1[5]*v2[5];
    C[0] = v1[0]*v1[3] + v1[1]*v1[4] + v1[2]*v1[5];
    C[1] = v2[0]*v2[3] + v2[1]*v2[4] + v2[2]*v2[5];
    C[2] = v1[0]*v2[3] + v1[1]*v2[4] + v1[2]*v2[5] + v1[3]*v2[0] + v1[4]*v2[1] + v1[5]*v2[2];
    C[3] = v1[3]*v1[6] + v1[4]*v1[7] + v1[5]*v1[8];
    C[4] = v2[3]*v2[6] + v2[4]*v2[7] + v2[5]*v2[8];
    C[5] = v1[3]*v2[6] + v1[4]*v2[7] + v1[5]*v2[8] + v1[6]*v2[3] + v1[7]*v2[4] + v1[8]*v2[5];
    C[6] = v1[0]*v1[6] + v1[1]*v1[7] + v1[2]*v1[8];
    C[7] = v2[0]*v2[6] + v2[1]*v2[7] + v2[2]*v2[8];
    C[8] = v1[0]*v2[6] + v1[1]*v2[7] + v1[2]*v2[8] + v1[6]*v2[0] + v1[7]*v2[1] + v1[8]*v2[2];
    C[9] = -_tmp0 - _tmp1 - _tmp2 + (v1[0]*v1[0]) + (v1[1]*v1[1]) + (v1[2]*v1[2]);
    C[10] = -_tmp3 - _tmp4 - _tmp5 + (v2[0]*v2[0]) + (v2[1]*v2[1]) + (v2[2]*v2[2]);
    C[11] = -_tmp6 - _tmp7 - _tmp8 + 2*v1[0]*v2[0] + 2*v1[1]*v2[1] + 2*v1[2]*v2[2];
    C[12] = _tmp0 + _tmp1 + _tmp2 - (v1[6]*v1[6]) - (v1[7]*v1[7]) - (v1[8]*v1[8]);
    C[13] = _tmp3 + _tmp4 + _tmp5 - (v2[6]*v2[6]) - (v2[7]*v2[7]) - (v2[8]*v2[8]);
    C[14] = _tmp6 + _tmp7 + _tmp8 - 2*v1[6]*v2[6] - 2*v1[7]*v2[7] - 2*v1[8]*v2[8];
}

void betaConstraintsN3(const double* v1, const double* v2, const double* v3, double* C)
{
    // Operation count: 153 mul, 99 add, 0 div (total 252).
    const double _tmp0 = 2*v1[0];
    const double _tmp1 = 2*v1[1];
    const double _tmp2 = 2*v1[2];
    const double _tmp3 = 2*v1[3];
    const double _tmp4 = 2*v1[4];
    const double _tmp5 = 2*v1[5];
    const double _tmp6 = 2*v1[6];
    const double _tmp7 = 2*v1[7];
    const double _tmp8 = 2*v1[8];
    C[0] = v1[0]*v1[3] + v1[1]*v1[4] + v1[2]*v1[5];
    C[1] = v2[0]*v2[3] + v2[1]*v2[4] + v2[2]*v2[5];
    C[2] = v3[0]*v3[3] + v3[1]*v3[4] + v3[2]*v3[5];
    C[3] = v1[0]*v2[3] + v1[1]*v2[4] + v1[2]*v2[5] + v1[3]*v2[0] + v1[4]*v2[1] + v1[5]*v2[2];
    C[4] = v1[0]*v3[3] + v1[1]*v3[4] + v1[2]*v3[5] + v1[3]*v3[0] + v1[4]*v3[1] + v1[5]*v3[2];
    C[5] = v2[0]*v3[3] + v2[1]*v3[4] + v2[2]*v3[5] + v2[3]*v3[0] + v2[4]*v3[1] + v2[5]*v3[2];
    C[6] = v1[3]*v1[6] + v1[4]*v1[7] + v1[5]*v1[8];
    C[7] = v2[3]*v2[6] + v2[4]*v2[7] + v2[5]*v2[8];
    C[8] = v3[3]*v3[6] + v3[4]*v3[7] + v3[5]*v3[8];
    C[9] = v1[3]*v2[6] + v1[4]*v2[7] + v1[5]*v2[8] + v1[6]*v2[3] + v1[7]*v2[4] + v1[8]*v2[5];
    C[10] = v1[3]*v3[6] + v1[4]*v3[7] + v1[5]*v3[8] + v1[6]*v3[3] + v1[7]*v3[4] + v1[8]*v3[5];
    C[11] = v2[3]*v3[6] + v2[4]*v3[7] + v2[5]*v3[8] + v2[6]*v3[3] + v2[7]*v3[4] + v2[8]*v3[5];
    C[12] = v1[0]*v1[6] + v1[1]*v1[7] + v1[2]*v1[8];
    C[13] = v2[0]*v2[6] + v2[1]*v2[7] + v2[2]*v2[8];
    C[14] = v3[0]*v3[6] + v3[1]*v3[7] + v3[2]*v3[8];
    C[15] = v1[0]*v2[6] + v1[1]*v2[7] + v1[2]*v2[8] + v1[6]*v2[0] + v1[7]*v2[1] + v1[8]*v2[2];
    C[16] = v1[0]*v3[6] + v1[1]*v3[7] + v1[2]*v3[8] + v1[6]*v3[0] + v1[7]*v3[1] + v1[8]*v3[2];
    C[17] = v2[0]*v3[6] + v2[1]*v3[7] + v2[2]*v3[8] + v2[6]*v3[0] + v2[7]*v3[1] + v2[8]*v3[2];
    C[18] = (v1[0]*v1[0]) + (v1[1]*v1[1]) + (v1[2]*v1[2]);
    C[19] = (v2[0]*v2[0]) + (v2[1]*v2[1]) + (v2[2]*v2[2]);
    C[20] = (v3[0]*v3[0]) + (v3[1]*v3[1]) + (v3[2]*v3[2]);
    C[21] = _tmp0*v2[0] + _tmp1*v2[1] + _tmp2*v2[2];
    C[22] = _tmp0*v3[0] + _tmp1*v3[1] + _tmp2*v3[2];
    C[23] = 2*v2[0]*v3[0] + 2*v2[1]*v3[1] + 2*v2[2]*v3[2];
    C[24] = (v1[3]*v1[3]) + (v1[4]*v1[4]) + (v1[5]*v1[5]);
    C[25] = (v2[3]*v2[3]) + (v2[4]*v2[4]) + (v2[5]*v2[5]);
    C[26] = (v3[3]*v3[3]) + (v3[4]*v3[4]) + (v3[5]*v3[5]);
    C[27] = _tmp3*v2[3] + _tmp4*v2[4] + _tmp5*v2[5];
    C[28] = _tmp3*v3[3] + _tmp4*v3[4] + _tmp5*v3[5];
    C[29] = 2*v2[3]*v3[3] + 2*v2[4]*v3[4] + 2*v2[5]*v3[5];
    C[30] = (v1[6]*v1[6]) + (v1[7]*v1[7]) + (v1[8]*v1[8]);
    C[31] = (v2[6]*v2[6]) + (v2[7]*v2[7]) + (v2[8]*v2[8]);
    C[32] = (v3[6]*v3[6]) + (v3[7]*v3[7]) + (v3[8]*v3[8]);
    C[33] = _tmp6*v2[6] + _tmp7*v2[7] + _tmp8*v2[8];
    C[34] = _tmp6*v3[6] + _tmp7*v3[7] + _tmp8*v3[8];
    C[35] = 2*v2[6]*v3[6] + 2*v2[7]*v3[7] + 2*v2[8]*v3[8];
}

} // namespace generated
} // namespace tripose
