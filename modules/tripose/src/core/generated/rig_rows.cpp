// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/rig_rows.py
// through the template codegen/tripose_codegen/templates/source.cpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#include "rig_rows.hpp"

namespace tripose {
namespace generated {

void rigLineRows(const double* qa, const double* qb, const double* l4, const double* R12,
        const double* t12, double* rows, double* b)
{
    // Operation count: 38 mul, 8 add, 0 div (total 46).
    const double _tmp0 = R12[0]*l4[0] + R12[3]*l4[1] + R12[6]*l4[2];
    const double _tmp1 = R12[1]*l4[0] + R12[4]*l4[1] + R12[7]*l4[2];
    const double _tmp2 = R12[2]*l4[0] + R12[5]*l4[1] + R12[8]*l4[2];
    const double _tmp3 = l4[0]*t12[0] + l4[1]*t12[1] + l4[2]*t12[2];
    rows[0] = _tmp0*qa[0];
    rows[1] = _tmp1*qa[0];
    rows[2] = _tmp2*qa[0];
    rows[3] = _tmp0*qa[1];
    rows[4] = _tmp1*qa[1];
    rows[5] = _tmp2*qa[1];
    rows[6] = _tmp0*qa[2];
    rows[7] = _tmp1*qa[2];
    rows[8] = _tmp2*qa[2];
    rows[9] = _tmp0*qa[3];
    rows[10] = _tmp1*qa[3];
    rows[11] = _tmp2*qa[3];
    rows[12] = _tmp0*qb[0];
    rows[13] = _tmp1*qb[0];
    rows[14] = _tmp2*qb[0];
    rows[15] = _tmp0*qb[1];
    rows[16] = _tmp1*qb[1];
    rows[17] = _tmp2*qb[1];
    rows[18] = _tmp0*qb[2];
    rows[19] = _tmp1*qb[2];
    rows[20] = _tmp2*qb[2];
    rows[21] = _tmp0*qb[3];
    rows[22] = _tmp1*qb[3];
    rows[23] = _tmp2*qb[3];
    b[0] = -_tmp3*qa[3];
    b[1] = -_tmp3*qb[3];
}

void rigPointRows(const double* x1, const double* x2, const double* x4, const double* n1,
        const double* n2, const double* n4, const double* R12, const double* t12, double* rows,
        double* b)
{
    // Operation count: 88 mul, 24 add, 1 div (total 113).
    const double _tmp0 = 1.0/n1[0];
    const double _tmp1 = _tmp0*x1[0] + n1[1];
    const double _tmp2 = _tmp0*x1[1] + n1[2];
    const double _tmp3 = R12[0]*_tmp1 + R12[1]*_tmp2 + R12[2];
    const double _tmp4 = R12[3]*_tmp1 + R12[4]*_tmp2 + R12[5];
    const double _tmp5 = R12[6]*_tmp1 + R12[7]*_tmp2 + R12[8];
    const double _tmp6 = -n2[0]*n2[1] - x2[0];
    const double _tmp7 = -n2[0]*n2[2] - x2[1];
    const double _tmp8 = -n4[0]*n4[1] - x4[0];
    const double _tmp9 = -n4[0]*n4[2] - x4[1];
    const double _tmp10 = R12[0]*n4[0] + R12[6]*_tmp8;
    const double _tmp11 = R12[1]*n4[0] + R12[7]*_tmp8;
    const double _tmp12 = R12[2]*n4[0] + R12[8]*_tmp8;
    const double _tmp13 = R12[3]*n4[0] + R12[6]*_tmp9;
    const double _tmp14 = R12[4]*n4[0] + R12[7]*_tmp9;
    const double _tmp15 = R12[5]*n4[0] + R12[8]*_tmp9;
    const double _tmp16 = _tmp8*t12[2] + n4[0]*t12[0];
    const double _tmp17 = _tmp9*t12[2] + n4[0]*t12[1];
    const double _tmp18 = _tmp3*n2[0] + _tmp5*_tmp6;
    const double _tmp19 = _tmp6*t12[2] + n2[0]*t12[0];
    const double _tmp20 = _tmp10*_tmp19;
    const double _tmp21 = _tmp11*_tmp19;
    const double _tmp22 = _tmp12*_tmp19;
    const double _tmp23 = _tmp13*_tmp19;
    const double _tmp24 = _tmp14*_tmp19;
    const double _tmp25 = _tmp15*_tmp19;
    const double _tmp26 = _tmp4*n2[0] + _tmp5*_tmp7;
    const double _tmp27 = _tmp7*t12[2] + n2[0]*t12[1];
    const double _tmp28 = _tmp10*_tmp27;
    const double _tmp29 = _tmp11*_tmp27;
    const double _tmp30 = _tmp12*_tmp27;
    const double _tmp31 = _tmp13*_tmp27;
    const double _tmp32 = _tmp14*_tmp27;
    const double _tmp33 = _tmp15*_tmp27;
    rows[0] = -_tmp1*_tmp20;
    rows[1] = -_tmp1*_tmp21;
    rows[2] = -_tmp1*_tmp22;
    rows[3] = -_tmp2*_tmp20;
    rows[4] = -_tmp2*_tmp21;
    rows[5] = -_tmp2*_tmp22;
    rows[6] = -_tmp20;
    rows[7] = -_tmp21;
    rows[8] = -_tmp22;
    rows[9] = _tmp10*_tmp18;
    rows[10] = _tmp11*_tmp18;
    rows[11] = _tmp12*_tmp18;
    rows[12] = -_tmp1*_tmp23;
    rows[13] = -_tmp1*_tmp24;
    rows[14] = -_tmp1*_tmp25;
    rows[15] = -_tmp2*_tmp23;
    rows[16] = -_tmp2*_tmp24;
    rows[17] = -_tmp2*_tmp25;
    rows[18] = -_tmp23;
    rows[19] = -_tmp24;
    rows[20] = -_tmp25;
    rows[21] = _tmp13*_tmp18;
    rows[22] = _tmp14*_tmp18;
    rows[23] = _tmp15*_tmp18;
    rows[24] = -_tmp1*_tmp28;
    rows[25] = -_tmp1*_tmp29;
    rows[26] = -_tmp1*_tmp30;
    rows[27] = -_tmp2*_tmp28;
    rows[28] = -_tmp2*_tmp29;
    rows[29] = -_tmp2*_tmp30;
    rows[30] = -_tmp28;
    rows[31] = -_tmp29;
    rows[32] = -_tmp30;
    rows[33] = _tmp10*_tmp26;
    rows[34] = _tmp11*_tmp26;
    rows[35] = _tmp12*_tmp26;
    rows[36] = -_tmp1*_tmp31;
    rows[37] = -_tmp1*_tmp32;
    rows[38] = -_tmp1*_tmp33;
    rows[39] = -_tmp2*_tmp31;
    rows[40] = -_tmp2*_tmp32;
    rows[41] = -_tmp2*_tmp33;
    rows[42] = -_tmp31;
    rows[43] = -_tmp32;
    rows[44] = -_tmp33;
    rows[45] = _tmp13*_tmp26;
    rows[46] = _tmp14*_tmp26;
    rows[47] = _tmp15*_tmp26;
    b[0] = -_tmp16*_tmp18;
    b[1] = -_tmp17*_tmp18;
    b[2] = -_tmp16*_tmp26;
    b[3] = -_tmp17*_tmp26;
}

} // namespace generated
} // namespace tripose
