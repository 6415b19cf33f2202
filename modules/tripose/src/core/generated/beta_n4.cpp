// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.
//
// GENERATED FILE: do not edit by hand.
// Produced by `python3 codegen/generate.py` from the problem spec
//   codegen/tripose_codegen/specs/beta_n4.py
// through the template codegen/tripose_codegen/templates/source.cpp.in.
// Edit the spec and regenerate; `python3 codegen/generate.py --check` verifies that this file
// is up to date.

#include "beta_n4.hpp"

namespace tripose {
namespace generated {

void betaN4Matrix(const double* v, double* M)
{
    // Operation count: 261 mul, 214 add, 0 div (total 475).
    const double _tmp0 = (v[3]*v[3]);
    const double _tmp1 = (v[4]*v[4]);
    const double _tmp2 = (v[5]*v[5]);
    const double _tmp3 = (v[15]*v[15]);
    const double _tmp4 = (v[16]*v[16]);
    const double _tmp5 = (v[17]*v[17]);
    const double _tmp6 = 2*v[0];
    const double _tmp7 = 2*v[1];
    const double _tmp8 = 2*v[2];
    const double _tmp9 = 2*v[3];
    const double _tmp10 = _tmp9*v[15];
    const double _tmp11 = 2*v[4];
    const double _tmp12 = _tmp11*v[16];
    const double _tmp13 = 2*v[5];
    const double _tmp14 = _tmp13*v[17];
    const double _tmp15 = _tmp9*v[39];
    const double _tmp16 = _tmp11*v[40];
    const double _tmp17 = _tmp13*v[41];
    const double _tmp18 = _tmp9*v[27];
    const double _tmp19 = _tmp11*v[28];
    const double _tmp20 = _tmp13*v[29];
    const double _tmp21 = 2*v[12];
    const double _tmp22 = 2*v[13];
    const double _tmp23 = 2*v[14];
    const double _tmp24 = 2*v[15];
    const double _tmp25 = _tmp24*v[39];
    const double _tmp26 = 2*v[16];
    const double _tmp27 = _tmp26*v[40];
    const double _tmp28 = 2*v[17];
    const double _tmp29 = _tmp28*v[41];
    const double _tmp30 = _tmp24*v[27];
    const double _tmp31 = _tmp26*v[28];
    const double _tmp32 = _tmp28*v[29];
    const double _tmp33 = (v[39]*v[39]);
    const double _tmp34 = (v[40]*v[40]);
    const double _tmp35 = (v[41]*v[41]);
    const double _tmp36 = 2*v[27]*v[39];
    const double _tmp37 = 2*v[28]*v[40];
    const double _tmp38 = 2*v[29]*v[41];
    const double _tmp39 = (v[27]*v[27]);
    const double _tmp40 = (v[28]*v[28]);
    const double _tmp41 = (v[29]*v[29]);
    const double _tmp42 = 2*v[6];
    const double _tmp43 = 2*v[7];
    const double _tmp44 = 2*v[8];
    const double _tmp45 = 2*v[18];
    const double _tmp46 = 2*v[19];
    const double _tmp47 = 2*v[20];
    M[0] = v[0]*v[3] + v[1]*v[4] + v[2]*v[5];
    M[1] = v[12]*v[15] + v[13]*v[16] + v[14]*v[17];
    M[2] = v[0]*v[15] + v[12]*v[3] + v[13]*v[4] + v[14]*v[5] + v[16]*v[1] + v[17]*v[2];
    M[3] = v[0]*v[39] + v[1]*v[40] + v[2]*v[41] + v[36]*v[3] + v[37]*v[4] + v[38]*v[5];
    M[4] = v[0]*v[27] + v[1]*v[28] + v[24]*v[3] + v[25]*v[4] + v[26]*v[5] + v[29]*v[2];
    M[5] = v[12]*v[39] + v[13]*v[40] + v[14]*v[41] + v[15]*v[36] + v[16]*v[37] + v[17]*v[38];
    M[6] = v[12]*v[27] + v[13]*v[28] + v[14]*v[29] + v[15]*v[24] + v[16]*v[25] + v[17]*v[26];
    M[7] = v[36]*v[39] + v[37]*v[40] + v[38]*v[41];
    M[8] = v[24]*v[39] + v[25]*v[40] + v[26]*v[41] + v[27]*v[36] + v[28]*v[37] + v[29]*v[38];
    M[9] = v[24]*v[27] + v[25]*v[28] + v[26]*v[29];
    M[10] = v[3]*v[6] + v[4]*v[7] + v[5]*v[8];
    M[11] = v[15]*v[18] + v[16]*v[19] + v[17]*v[20];
    M[12] = v[15]*v[6] + v[16]*v[7] + v[17]*v[8] + v[18]*v[3] + v[19]*v[4] + v[20]*v[5];
    M[13] = v[39]*v[6] + v[3]*v[42] + v[40]*v[7] + v[41]*v[8] + v[43]*v[4] + v[44]*v[5];
    M[14] = v[27]*v[6] + v[28]*v[7] + v[29]*v[8] + v[30]*v[3] + v[31]*v[4] + v[32]*v[5];
    M[15] = v[15]*v[42] + v[16]*v[43] + v[17]*v[44] + v[18]*v[39] + v[19]*v[40] + v[20]*v[41];
    M[16] = v[15]*v[30] + v[16]*v[31] + v[17]*v[32] + v[18]*v[27] + v[19]*v[28] + v[20]*v[29];
    M[17] = v[39]*v[42] + v[40]*v[43] + v[41]*v[44];
    M[18] = v[27]*v[42] + v[28]*v[43] + v[29]*v[44] + v[30]*v[39] + v[31]*v[40] + v[32]*v[41];
    M[19] = v[27]*v[30] + v[28]*v[31] + v[29]*v[32];
    M[20] = v[0]*v[6] + v[1]*v[7] + v[2]*v[8];
    M[21] = v[12]*v[18] + v[13]*v[19] + v[14]*v[20];
    M[22] = v[0]*v[18] + v[12]*v[6] + v[13]*v[7] + v[14]*v[8] + v[19]*v[1] + v[20]*v[2];
    M[23] = v[0]*v[42] + v[1]*v[43] + v[2]*v[44] + v[36]*v[6] + v[37]*v[7] + v[38]*v[8];
    M[24] = v[0]*v[30] + v[1]*v[31] + v[24]*v[6] + v[25]*v[7] + v[26]*v[8] + v[2]*v[32];
    M[25] = v[12]*v[42] + v[13]*v[43] + v[14]*v[44] + v[18]*v[36] + v[19]*v[37] + v[20]*v[38];
    M[26] = v[12]*v[30] + v[13]*v[31] + v[14]*v[32] + v[18]*v[24] + v[19]*v[25] + v[20]*v[26];
    M[27] = v[36]*v[42] + v[37]*v[43] + v[38]*v[44];
    M[28] = v[24]*v[42] + v[25]*v[43] + v[26]*v[44] + v[30]*v[36] + v[31]*v[37] + v[32]*v[38];
    M[29] = v[24]*v[30] + v[25]*v[31] + v[26]*v[32];
    M[30] = -_tmp0 - _tmp1 - _tmp2 + (v[0]*v[0]) + (v[1]*v[1]) + (v[2]*v[2]);
    M[31] = -_tmp3 - _tmp4 - _tmp5 + (v[12]*v[12]) + (v[13]*v[13]) + (v[14]*v[14]);
    M[32] = -_tmp10 - _tmp12 - _tmp14 + _tmp6*v[12] + _tmp7*v[13] + _tmp8*v[14];
    M[33] = -_tmp15 - _tmp16 - _tmp17 + _tmp6*v[36] + _tmp7*v[37] + _tmp8*v[38];
    M[34] = -_tmp18 - _tmp19 - _tmp20 + _tmp6*v[24] + _tmp7*v[25] + _tmp8*v[26];
    M[35] = _tmp21*v[36] + _tmp22*v[37] + _tmp23*v[38] - _tmp25 - _tmp27 - _tmp29;
    M[36] = _tmp21*v[24] + _tmp22*v[25] + _tmp23*v[26] - _tmp30 - _tmp31 - _tmp32;
    M[37] = -_tmp33 - _tmp34 - _tmp35 + (v[36]*v[36]) + (v[37]*v[37]) + (v[38]*v[38]);
    M[38] = -_tmp36 - _tmp37 - _tmp38 + 2*v[24]*v[36] + 2*v[25]*v[37] + 2*v[26]*v[38];
    M[39] = -_tmp39 - _tmp40 - _tmp41 + (v[24]*v[24]) + (v[25]*v[25]) + (v[26]*v[26]);
    M[40] = _tmp0 + _tmp1 + _tmp2 - (v[6]*v[6]) - (v[7]*v[7]) - (v[8]*v[8]);
    M[41] = _tmp3 + _tmp4 + _tmp5 - (v[18]*v[18]) - (v[19]*v[19]) - (v[20]*v[20]);
    M[42] = _tmp10 + _tmp12 + _tmp14 - _tmp42*v[18] - _tmp43*v[19] - _tmp44*v[20];
    M[43] = _tmp15 + _tmp16 + _tmp17 - _tmp42*v[42] - _tmp43*v[43] - _tmp44*v[44];
    M[44] = _tmp18 + _tmp19 + _tmp20 - _tmp42*v[30] - _tmp43*v[31] - _tmp44*v[32];
    M[45] = _tmp25 + _tmp27 + _tmp29 - _tmp45*v[42] - _tmp46*v[43] - _tmp47*v[44];
    M[46] = _tmp30 + _tmp31 + _tmp32 - _tmp45*v[30] - _tmp46*v[31] - _tmp47*v[32];
    M[47] = _tmp33 + _tmp34 + _tmp35 - (v[42]*v[42]) - (v[43]*v[43]) - (v[44]*v[44]);
    M[48] = _tmp36 + _tmp37 + _tmp38 - 2*v[30]*v[42] - 2*v[31]*v[43] - 2*v[32]*v[44];
    M[49] = _tmp39 + _tmp40 + _tmp41 - (v[30]*v[30]) - (v[31]*v[31]) - (v[32]*v[32]);
}

void betaN4NullVector(const double* v, double* u)
{
    // Operation count: 1066 mul, 828 add, 0 div (total 1894).
    const double _tmp0 = (v[3]*v[3]);
    const double _tmp1 = (v[4]*v[4]);
    const double _tmp2 = (v[5]*v[5]);
    const double _tmp3 = (v[15]*v[15]);
    const double _tmp4 = (v[16]*v[16]);
    const double _tmp5 = (v[17]*v[17]);
    const double _tmp6 = 2*v[0];
    const double _tmp7 = 2*v[1];
    const double _tmp8 = 2*v[2];
    const double _tmp9 = 2*v[3];
    const double _tmp10 = _tmp9*v[15];
    const double _tmp11 = 2*v[4];
    const double _tmp12 = _tmp11*v[16];
    const double _tmp13 = 2*v[5];
    const double _tmp14 = _tmp13*v[17];
    const double _tmp15 = _tmp9*v[39];
    const double _tmp16 = _tmp11*v[40];
    const double _tmp17 = _tmp13*v[41];
    const double _tmp18 = _tmp9*v[27];
    const double _tmp19 = _tmp11*v[28];
    const double _tmp20 = _tmp13*v[29];
    const double _tmp21 = 2*v[12];
    const double _tmp22 = 2*v[13];
    const double _tmp23 = 2*v[14];
    const double _tmp24 = 2*v[15];
    const double _tmp25 = _tmp24*v[39];
    const double _tmp26 = 2*v[16];
    const double _tmp27 = _tmp26*v[40];
    const double _tmp28 = 2*v[17];
    const double _tmp29 = _tmp28*v[41];
    const double _tmp30 = _tmp24*v[27];
    const double _tmp31 = _tmp26*v[28];
    const double _tmp32 = _tmp28*v[29];
    const double _tmp33 = (v[39]*v[39]);
    const double _tmp34 = (v[40]*v[40]);
    const double _tmp35 = (v[41]*v[41]);
    const double _tmp36 = 2*v[27]*v[39];
    const double _tmp37 = 2*v[28]*v[40];
    const double _tmp38 = 2*v[29]*v[41];
    const double _tmp39 = (v[27]*v[27]);
    const double _tmp40 = (v[28]*v[28]);
    const double _tmp41 = (v[29]*v[29]);
    const double _tmp42 = 2*v[6];
    const double _tmp43 = 2*v[7];
    const double _tmp44 = 2*v[8];
    const double _tmp45 = 2*v[18];
    const double _tmp46 = 2*v[19];
    const double _tmp47 = 2*v[20];
    const double _tmp48 = v[0]*v[3] + v[1]*v[4] + v[2]*v[5];
    const double _tmp49 = v[12]*v[15] + v[13]*v[16] + v[14]*v[17];
    const double _tmp50 = v[0]*v[15] + v[12]*v[3] + v[13]*v[4] + v[14]*v[5] + v[16]*v[1]
            + v[17]*v[2];
    const double _tmp51 = v[0]*v[39] + v[1]*v[40] + v[2]*v[41] + v[36]*v[3] + v[37]*v[4]
            + v[38]*v[5];
    const double _tmp52 = v[0]*v[27] + v[1]*v[28] + v[24]*v[3] + v[25]*v[4] + v[26]*v[5]
            + v[29]*v[2];
    const double _tmp53 = v[12]*v[39] + v[13]*v[40] + v[14]*v[41] + v[15]*v[36] + v[16]*v[37]
            + v[17]*v[38];
    const double _tmp54 = v[12]*v[27] + v[13]*v[28] + v[14]*v[29] + v[15]*v[24] + v[16]*v[25]
            + v[17]*v[26];
    const double _tmp55 = v[36]*v[39] + v[37]*v[40] + v[38]*v[41];
    const double _tmp56 = v[24]*v[39] + v[25]*v[40] + v[26]*v[41] + v[27]*v[36] + v[28]*v[37]
            + v[29]*v[38];
    const double _tmp57 = v[24]*v[27] + v[25]*v[28] + v[26]*v[29];
    const double _tmp58 = v[3]*v[6] + v[4]*v[7] + v[5]*v[8];
    const double _tmp59 = v[15]*v[18] + v[16]*v[19] + v[17]*v[20];
    const double _tmp60 = v[15]*v[6] + v[16]*v[7] + v[17]*v[8] + v[18]*v[3] + v[19]*v[4]
            + v[20]*v[5];
    const double _tmp61 = v[39]*v[6] + v[3]*v[42] + v[40]*v[7] + v[41]*v[8] + v[43]*v[4]
            + v[44]*v[5];
    const double _tmp62 = v[27]*v[6] + v[28]*v[7] + v[29]*v[8] + v[30]*v[3] + v[31]*v[4]
            + v[32]*v[5];
    const double _tmp63 = v[15]*v[42] + v[16]*v[43] + v[17]*v[44] + v[18]*v[39] + v[19]*v[40]
            + v[20]*v[41];
    const double _tmp64 = v[15]*v[30] + v[16]*v[31] + v[17]*v[32] + v[18]*v[27] + v[19]*v[28]
            + v[20]*v[29];
    const double _tmp65 = v[39]*v[42] + v[40]*v[43] + v[41]*v[44];
    const double _tmp66 = v[27]*v[42] + v[28]*v[43] + v[29]*v[44] + v[30]*v[39] + v[31]*v[40]
            + v[32]*v[41];
    const double _tmp67 = v[27]*v[30] + v[28]*v[31] + v[29]*v[32];
    const double _tmp68 = v[0]*v[6] + v[1]*v[7] + v[2]*v[8];
    const double _tmp69 = v[12]*v[18] + v[13]*v[19] + v[14]*v[20];
    const double _tmp70 = v[0]*v[18] + v[12]*v[6] + v[13]*v[7] + v[14]*v[8] + v[19]*v[1]
            + v[20]*v[2];
    const double _tmp71 = v[0]*v[42] + v[1]*v[43] + v[2]*v[44] + v[36]*v[6] + v[37]*v[7]
            + v[38]*v[8];
    const double _tmp72 = v[0]*v[30] + v[1]*v[31] + v[24]*v[6] + v[25]*v[7] + v[26]*v[8]
            + v[2]*v[32];
    const double _tmp73 = v[12]*v[42] + v[13]*v[43] + v[14]*v[44] + v[18]*v[36] + v[19]*v[37]
            + v[20]*v[38];
    const double _tmp74 = v[12]*v[30] + v[13]*v[31] + v[14]*v[32] + v[18]*v[24] + v[19]*v[25]
            + v[20]*v[26];
    const double _tmp75 = v[36]*v[42] + v[37]*v[43] + v[38]*v[44];
    const double _tmp76 = v[24]*v[42] + v[25]*v[43] + v[26]*v[44] + v[30]*v[36] + v[31]*v[37]
            + v[32]*v[38];
    const double _tmp77 = v[24]*v[30] + v[25]*v[31] + v[26]*v[32];
    const double _tmp78 = -_tmp0 - _tmp1 - _tmp2 + (v[0]*v[0]) + (v[1]*v[1]) + (v[2]*v[2]);
    const double _tmp79 = -_tmp3 - _tmp4 - _tmp5 + (v[12]*v[12]) + (v[13]*v[13]) + (v[14]*v[14]);
    const double _tmp80 = -_tmp10 - _tmp12 - _tmp14 + _tmp6*v[12] + _tmp7*v[13] + _tmp8*v[14];
    const double _tmp81 = -_tmp15 - _tmp16 - _tmp17 + _tmp6*v[36] + _tmp7*v[37] + _tmp8*v[38];
    const double _tmp82 = -_tmp18 - _tmp19 - _tmp20 + _tmp6*v[24] + _tmp7*v[25] + _tmp8*v[26];
    const double _tmp83 = _tmp21*v[36] + _tmp22*v[37] + _tmp23*v[38] - _tmp25 - _tmp27 - _tmp29;
    const double _tmp84 = _tmp21*v[24] + _tmp22*v[25] + _tmp23*v[26] - _tmp30 - _tmp31 - _tmp32;
    const double _tmp85 = -_tmp33 - _tmp34 - _tmp35 + (v[36]*v[36]) + (v[37]*v[37]) + (v[38]*v[38]);
    const double _tmp86 = -_tmp36 - _tmp37 - _tmp38 + 2*v[24]*v[36] + 2*v[25]*v[37] + 2*v[26]*v[38];
    const double _tmp87 = -_tmp39 - _tmp40 - _tmp41 + (v[24]*v[24]) + (v[25]*v[25]) + (v[26]*v[26]);
    const double _tmp88 = _tmp0 + _tmp1 + _tmp2 - (v[6]*v[6]) - (v[7]*v[7]) - (v[8]*v[8]);
    const double _tmp89 = _tmp3 + _tmp4 + _tmp5 - (v[18]*v[18]) - (v[19]*v[19]) - (v[20]*v[20]);
    const double _tmp90 = _tmp10 + _tmp12 + _tmp14 - _tmp42*v[18] - _tmp43*v[19] - _tmp44*v[20];
    const double _tmp91 = _tmp15 + _tmp16 + _tmp17 - _tmp42*v[42] - _tmp43*v[43] - _tmp44*v[44];
    const double _tmp92 = _tmp18 + _tmp19 + _tmp20 - _tmp42*v[30] - _tmp43*v[31] - _tmp44*v[32];
    const double _tmp93 = _tmp25 + _tmp27 + _tmp29 - _tmp45*v[42] - _tmp46*v[43] - _tmp47*v[44];
    const double _tmp94 = _tmp30 + _tmp31 + _tmp32 - _tmp45*v[30] - _tmp46*v[31] - _tmp47*v[32];
    const double _tmp95 = _tmp33 + _tmp34 + _tmp35 - (v[42]*v[42]) - (v[43]*v[43]) - (v[44]*v[44]);
    const double _tmp96 = _tmp36 + _tmp37 + _tmp38 - 2*v[30]*v[42] - 2*v[31]*v[43] - 2*v[32]*v[44];
    const double _tmp97 = _tmp39 + _tmp40 + _tmp41 - (v[30]*v[30]) - (v[31]*v[31]) - (v[32]*v[32]);
    const double _tmp98 = _tmp79*_tmp90 - _tmp80*_tmp89;
    const double _tmp99 = _tmp69*_tmp90 - _tmp70*_tmp89;
    const double _tmp100 = _tmp69*_tmp80 - _tmp70*_tmp79;
    const double _tmp101 = _tmp100*_tmp93 + _tmp73*_tmp98 - _tmp83*_tmp99;
    const double _tmp102 = _tmp100*_tmp94 + _tmp74*_tmp98 - _tmp84*_tmp99;
    const double _tmp103 = _tmp59*_tmp90 - _tmp60*_tmp89;
    const double _tmp104 = _tmp59*_tmp80 - _tmp60*_tmp79;
    const double _tmp105 = -_tmp103*_tmp83 + _tmp104*_tmp93 + _tmp63*_tmp98;
    const double _tmp106 = -_tmp103*_tmp84 + _tmp104*_tmp94 + _tmp64*_tmp98;
    const double _tmp107 = _tmp59*_tmp70 - _tmp60*_tmp69;
    const double _tmp108 = -_tmp103*_tmp73 + _tmp107*_tmp93 + _tmp63*_tmp99;
    const double _tmp109 = -_tmp103*_tmp74 + _tmp107*_tmp94 + _tmp64*_tmp99;
    const double _tmp110 = _tmp100*_tmp63 - _tmp104*_tmp73 + _tmp107*_tmp83;
    const double _tmp111 = _tmp100*_tmp64 - _tmp104*_tmp74 + _tmp107*_tmp84;
    const double _tmp112 = _tmp101*_tmp61 - _tmp105*_tmp71 + _tmp108*_tmp81 - _tmp110*_tmp91;
    const double _tmp113 = _tmp101*_tmp62 + _tmp102*_tmp61 - _tmp105*_tmp72 - _tmp106*_tmp71
            + _tmp108*_tmp82 + _tmp109*_tmp81 - _tmp110*_tmp92 - _tmp111*_tmp91;
    const double _tmp114 = _tmp102*_tmp62 - _tmp106*_tmp72 + _tmp109*_tmp82 - _tmp111*_tmp92;
    const double _tmp115 = _tmp49*_tmp90 - _tmp50*_tmp89;
    const double _tmp116 = _tmp49*_tmp80 - _tmp50*_tmp79;
    const double _tmp117 = -_tmp115*_tmp83 + _tmp116*_tmp93 + _tmp53*_tmp98;
    const double _tmp118 = -_tmp115*_tmp84 + _tmp116*_tmp94 + _tmp54*_tmp98;
    const double _tmp119 = _tmp49*_tmp70 - _tmp50*_tmp69;
    const double _tmp120 = -_tmp115*_tmp73 + _tmp119*_tmp93 + _tmp53*_tmp99;
    const double _tmp121 = -_tmp115*_tmp74 + _tmp119*_tmp94 + _tmp54*_tmp99;
    const double _tmp122 = _tmp100*_tmp53 - _tmp116*_tmp73 + _tmp119*_tmp83;
    const double _tmp123 = _tmp100*_tmp54 - _tmp116*_tmp74 + _tmp119*_tmp84;
    const double _tmp124 = _tmp101*_tmp51 - _tmp117*_tmp71 + _tmp120*_tmp81 - _tmp122*_tmp91;
    const double _tmp125 = _tmp101*_tmp52 + _tmp102*_tmp51 - _tmp117*_tmp72 - _tmp118*_tmp71
            + _tmp120*_tmp82 + _tmp121*_tmp81 - _tmp122*_tmp92 - _tmp123*_tmp91;
    const double _tmp126 = _tmp102*_tmp52 - _tmp118*_tmp72 + _tmp121*_tmp82 - _tmp123*_tmp92;
    const double _tmp127 = _tmp49*_tmp60 - _tmp50*_tmp59;
    const double _tmp128 = _tmp103*_tmp53 - _tmp115*_tmp63 + _tmp127*_tmp93;
    const double _tmp129 = _tmp103*_tmp54 - _tmp115*_tmp64 + _tmp127*_tmp94;
    const double _tmp130 = _tmp104*_tmp53 - _tmp116*_tmp63 + _tmp127*_tmp83;
    const double _tmp131 = _tmp104*_tmp54 - _tmp116*_tmp64 + _tmp127*_tmp84;
    const double _tmp132 = _tmp105*_tmp51 - _tmp117*_tmp61 + _tmp128*_tmp81 - _tmp130*_tmp91;
    const double _tmp133 = _tmp105*_tmp52 + _tmp106*_tmp51 - _tmp117*_tmp62 - _tmp118*_tmp61
            + _tmp128*_tmp82 + _tmp129*_tmp81 - _tmp130*_tmp92 - _tmp131*_tmp91;
    const double _tmp134 = _tmp106*_tmp52 - _tmp118*_tmp62 + _tmp129*_tmp82 - _tmp131*_tmp92;
    const double _tmp135 = _tmp107*_tmp53 - _tmp119*_tmp63 + _tmp127*_tmp73;
    const double _tmp136 = _tmp107*_tmp54 - _tmp119*_tmp64 + _tmp127*_tmp74;
    const double _tmp137 = _tmp108*_tmp51 - _tmp120*_tmp61 + _tmp128*_tmp71 - _tmp135*_tmp91;
    const double _tmp138 = _tmp108*_tmp52 + _tmp109*_tmp51 - _tmp120*_tmp62 - _tmp121*_tmp61
            + _tmp128*_tmp72 + _tmp129*_tmp71 - _tmp135*_tmp92 - _tmp136*_tmp91;
    const double _tmp139 = _tmp109*_tmp52 - _tmp121*_tmp62 + _tmp129*_tmp72 - _tmp136*_tmp92;
    const double _tmp140 = _tmp110*_tmp51 - _tmp122*_tmp61 + _tmp130*_tmp71 - _tmp135*_tmp81;
    const double _tmp141 = _tmp110*_tmp52 + _tmp111*_tmp51 - _tmp122*_tmp62 - _tmp123*_tmp61
            + _tmp130*_tmp72 + _tmp131*_tmp71 - _tmp135*_tmp82 - _tmp136*_tmp81;
    const double _tmp142 = _tmp111*_tmp52 - _tmp123*_tmp62 + _tmp131*_tmp72 - _tmp136*_tmp82;
    const double _tmp143 = _tmp112*_tmp55 - _tmp124*_tmp65 + _tmp132*_tmp75 - _tmp137*_tmp85
            + _tmp140*_tmp95;
    const double _tmp144 = _tmp112*_tmp56 + _tmp113*_tmp55 - _tmp124*_tmp66 - _tmp125*_tmp65
            + _tmp132*_tmp76 + _tmp133*_tmp75 - _tmp137*_tmp86 - _tmp138*_tmp85 + _tmp140*_tmp96
            + _tmp141*_tmp95;
    const double _tmp145 = _tmp112*_tmp57 + _tmp113*_tmp56 + _tmp114*_tmp55 - _tmp124*_tmp67
            - _tmp125*_tmp66 - _tmp126*_tmp65 + _tmp132*_tmp77 + _tmp133*_tmp76 + _tmp134*_tmp75
            - _tmp137*_tmp87 - _tmp138*_tmp86 - _tmp139*_tmp85 + _tmp140*_tmp97 + _tmp141*_tmp96
            + _tmp142*_tmp95;
    const double _tmp146 = _tmp113*_tmp57 + _tmp114*_tmp56 - _tmp125*_tmp67 - _tmp126*_tmp66
            + _tmp133*_tmp77 + _tmp134*_tmp76 - _tmp138*_tmp87 - _tmp139*_tmp86 + _tmp141*_tmp97
            + _tmp142*_tmp96;
    const double _tmp147 = _tmp114*_tmp57 - _tmp126*_tmp67 + _tmp134*_tmp77 - _tmp139*_tmp87
            + _tmp142*_tmp97;
    const double _tmp148 = _tmp78*_tmp90 - _tmp80*_tmp88;
    const double _tmp149 = _tmp68*_tmp90 - _tmp70*_tmp88;
    const double _tmp150 = _tmp68*_tmp80 - _tmp70*_tmp78;
    const double _tmp151 = _tmp148*_tmp73 - _tmp149*_tmp83 + _tmp150*_tmp93;
    const double _tmp152 = _tmp148*_tmp74 - _tmp149*_tmp84 + _tmp150*_tmp94;
    const double _tmp153 = _tmp58*_tmp90 - _tmp60*_tmp88;
    const double _tmp154 = _tmp58*_tmp80 - _tmp60*_tmp78;
    const double _tmp155 = _tmp148*_tmp63 - _tmp153*_tmp83 + _tmp154*_tmp93;
    const double _tmp156 = _tmp148*_tmp64 - _tmp153*_tmp84 + _tmp154*_tmp94;
    const double _tmp157 = _tmp58*_tmp70 - _tmp60*_tmp68;
    const double _tmp158 = _tmp149*_tmp63 - _tmp153*_tmp73 + _tmp157*_tmp93;
    const double _tmp159 = _tmp149*_tmp64 - _tmp153*_tmp74 + _tmp157*_tmp94;
    const double _tmp160 = _tmp150*_tmp63 - _tmp154*_tmp73 + _tmp157*_tmp83;
    const double _tmp161 = _tmp150*_tmp64 - _tmp154*_tmp74 + _tmp157*_tmp84;
    const double _tmp162 = _tmp151*_tmp61 - _tmp155*_tmp71 + _tmp158*_tmp81 - _tmp160*_tmp91;
    const double _tmp163 = _tmp151*_tmp62 + _tmp152*_tmp61 - _tmp155*_tmp72 - _tmp156*_tmp71
            + _tmp158*_tmp82 + _tmp159*_tmp81 - _tmp160*_tmp92 - _tmp161*_tmp91;
    const double _tmp164 = _tmp152*_tmp62 - _tmp156*_tmp72 + _tmp159*_tmp82 - _tmp161*_tmp92;
    const double _tmp165 = _tmp48*_tmp90 - _tmp50*_tmp88;
    const double _tmp166 = _tmp48*_tmp80 - _tmp50*_tmp78;
    const double _tmp167 = _tmp148*_tmp53 - _tmp165*_tmp83 + _tmp166*_tmp93;
    const double _tmp168 = _tmp148*_tmp54 - _tmp165*_tmp84 + _tmp166*_tmp94;
    const double _tmp169 = _tmp48*_tmp70 - _tmp50*_tmp68;
    const double _tmp170 = _tmp149*_tmp53 - _tmp165*_tmp73 + _tmp169*_tmp93;
    const double _tmp171 = _tmp149*_tmp54 - _tmp165*_tmp74 + _tmp169*_tmp94;
    const double _tmp172 = _tmp150*_tmp53 - _tmp166*_tmp73 + _tmp169*_tmp83;
    const double _tmp173 = _tmp150*_tmp54 - _tmp166*_tmp74 + _tmp169*_tmp84;
    const double _tmp174 = _tmp151*_tmp51 - _tmp167*_tmp71 + _tmp170*_tmp81 - _tmp172*_tmp91;
    const double _tmp175 = _tmp151*_tmp52 + _tmp152*_tmp51 - _tmp167*_tmp72 - _tmp168*_tmp71
            + _tmp170*_tmp82 + _tmp171*_tmp81 - _tmp172*_tmp92 - _tmp173*_tmp91;
    const double _tmp176 = _tmp152*_tmp52 - _tmp168*_tmp72 + _tmp171*_tmp82 - _tmp173*_tmp92;
    const double _tmp177 = _tmp48*_tmp60 - _tmp50*_tmp58;
    const double _tmp178 = _tmp153*_tmp53 - _tmp165*_tmp63 + _tmp177*_tmp93;
    const double _tmp179 = _tmp153*_tmp54 - _tmp165*_tmp64 + _tmp177*_tmp94;
    const double _tmp180 = _tmp154*_tmp53 - _tmp166*_tmp63 + _tmp177*_tmp83;
    const double _tmp181 = _tmp154*_tmp54 - _tmp166*_tmp64 + _tmp177*_tmp84;
    const double _tmp182 = _tmp155*_tmp51 - _tmp167*_tmp61 + _tmp178*_tmp81 - _tmp180*_tmp91;
    const double _tmp183 = _tmp155*_tmp52 + _tmp156*_tmp51 - _tmp167*_tmp62 - _tmp168*_tmp61
            + _tmp178*_tmp82 + _tmp179*_tmp81 - _tmp180*_tmp92 - _tmp181*_tmp91;
    const double _tmp184 = _tmp156*_tmp52 - _tmp168*_tmp62 + _tmp179*_tmp82 - _tmp181*_tmp92;
    const double _tmp185 = _tmp157*_tmp53 - _tmp169*_tmp63 + _tmp177*_tmp73;
    const double _tmp186 = _tmp157*_tmp54 - _tmp169*_tmp64 + _tmp177*_tmp74;
    const double _tmp187 = _tmp158*_tmp51 - _tmp170*_tmp61 + _tmp178*_tmp71 - _tmp185*_tmp91;
    const double _tmp188 = _tmp158*_tmp52 + _tmp159*_tmp51 - _tmp170*_tmp62 - _tmp171*_tmp61
            + _tmp178*_tmp72 + _tmp179*_tmp71 - _tmp185*_tmp92 - _tmp186*_tmp91;
    const double _tmp189 = _tmp159*_tmp52 - _tmp171*_tmp62 + _tmp179*_tmp72 - _tmp186*_tmp92;
    const double _tmp190 = _tmp160*_tmp51 - _tmp172*_tmp61 + _tmp180*_tmp71 - _tmp185*_tmp81;
    const double _tmp191 = _tmp160*_tmp52 + _tmp161*_tmp51 - _tmp172*_tmp62 - _tmp173*_tmp61
            + _tmp180*_tmp72 + _tmp181*_tmp71 - _tmp185*_tmp82 - _tmp186*_tmp81;
    const double _tmp192 = _tmp161*_tmp52 - _tmp173*_tmp62 + _tmp181*_tmp72 - _tmp186*_tmp82;
    const double _tmp193 = _tmp162*_tmp55 - _tmp174*_tmp65 + _tmp182*_tmp75 - _tmp187*_tmp85
            + _tmp190*_tmp95;
    const double _tmp194 = _tmp162*_tmp56 + _tmp163*_tmp55 - _tmp174*_tmp66 - _tmp175*_tmp65
            + _tmp182*_tmp76 + _tmp183*_tmp75 - _tmp187*_tmp86 - _tmp188*_tmp85 + _tmp190*_tmp96
            + _tmp191*_tmp95;
    const double _tmp195 = _tmp162*_tmp57 + _tmp163*_tmp56 + _tmp164*_tmp55 - _tmp174*_tmp67
            - _tmp175*_tmp66 - _tmp176*_tmp65 + _tmp182*_tmp77 + _tmp183*_tmp76 + _tmp184*_tmp75
            - _tmp187*_tmp87 - _tmp188*_tmp86 - _tmp189*_tmp85 + _tmp190*_tmp97 + _tmp191*_tmp96
            + _tmp192*_tmp95;
    const double _tmp196 = _tmp163*_tmp57 + _tmp164*_tmp56 - _tmp175*_tmp67 - _tmp176*_tmp66
            + _tmp183*_tmp77 + _tmp184*_tmp76 - _tmp188*_tmp87 - _tmp189*_tmp86 + _tmp191*_tmp97
            + _tmp192*_tmp96;
    const double _tmp197 = _tmp164*_tmp57 - _tmp176*_tmp67 + _tmp184*_tmp77 - _tmp189*_tmp87
            + _tmp192*_tmp97;
    const double _tmp198 = _tmp78*_tmp89 - _tmp79*_tmp88;
    const double _tmp199 = _tmp68*_tmp89 - _tmp69*_tmp88;
    const double _tmp200 = _tmp68*_tmp79 - _tmp69*_tmp78;
    const double _tmp201 = _tmp198*_tmp73 - _tmp199*_tmp83 + _tmp200*_tmp93;
    const double _tmp202 = _tmp198*_tmp74 - _tmp199*_tmp84 + _tmp200*_tmp94;
    const double _tmp203 = _tmp58*_tmp89 - _tmp59*_tmp88;
    const double _tmp204 = _tmp58*_tmp79 - _tmp59*_tmp78;
    const double _tmp205 = _tmp198*_tmp63 - _tmp203*_tmp83 + _tmp204*_tmp93;
    const double _tmp206 = _tmp198*_tmp64 - _tmp203*_tmp84 + _tmp204*_tmp94;
    const double _tmp207 = _tmp58*_tmp69 - _tmp59*_tmp68;
    const double _tmp208 = _tmp199*_tmp63 - _tmp203*_tmp73 + _tmp207*_tmp93;
    const double _tmp209 = _tmp199*_tmp64 - _tmp203*_tmp74 + _tmp207*_tmp94;
    const double _tmp210 = _tmp200*_tmp63 - _tmp204*_tmp73 + _tmp207*_tmp83;
    const double _tmp211 = _tmp200*_tmp64 - _tmp204*_tmp74 + _tmp207*_tmp84;
    const double _tmp212 = _tmp201*_tmp61 - _tmp205*_tmp71 + _tmp208*_tmp81 - _tmp210*_tmp91;
    const double _tmp213 = _tmp201*_tmp62 + _tmp202*_tmp61 - _tmp205*_tmp72 - _tmp206*_tmp71
            + _tmp208*_tmp82 + _tmp209*_tmp81 - _tmp210*_tmp92 - _tmp211*_tmp91;
    const double _tmp214 = _tmp202*_tmp62 - _tmp206*_tmp72 + _tmp209*_tmp82 - _tmp211*_tmp92;
    const double _tmp215 = _tmp48*_tmp89 - _tmp49*_tmp88;
    const double _tmp216 = _tmp48*_tmp79 - _tmp49*_tmp78;
    const double _tmp217 = _tmp198*_tmp53 - _tmp215*_tmp83 + _tmp216*_tmp93;
    const double _tmp218 = _tmp198*_tmp54 - _tmp215*_tmp84 + _tmp216*_tmp94;
    const double _tmp219 = _tmp48*_tmp69 - _tmp49*_tmp68;
    const double _tmp220 = _tmp199*_tmp53 - _tmp215*_tmp73 + _tmp219*_tmp93;
    const double _tmp221 = _tmp199*_tmp54 - _tmp215*_tmp74 + _tmp219*_tmp94;
    const double _tmp222 = _tmp200*_tmp53 - _tmp216*_tmp73 + _tmp219*_tmp83;
    const double _tmp223 = _tmp200*_tmp54 - _tmp216*_tmp74 + _tmp219*_tmp84;
    const double _tmp224 = _tmp201*_tmp51 - _tmp217*_tmp71 + _tmp220*_tmp81 - _tmp222*_tmp91;
    const double _tmp225 = _tmp201*_tmp52 + _tmp202*_tmp51 - _tmp217*_tmp72 - _tmp218*_tmp71
            + _tmp220*_tmp82 + _tmp221*_tmp81 - _tmp222*_tmp92 - _tmp223*_tmp91;
    const double _tmp226 = _tmp202*_tmp52 - _tmp218*_tmp72 + _tmp221*_tmp82 - _tmp223*_tmp92;
    const double _tmp227 = _tmp48*_tmp59 - _tmp49*_tmp58;
    const double _tmp228 = _tmp203*_tmp53 - _tmp215*_tmp63 + _tmp227*_tmp93;
    const double _tmp229 = _tmp203*_tmp54 - _tmp215*_tmp64 + _tmp227*_tmp94;
    const double _tmp230 = _tmp204*_tmp53 - _tmp216*_tmp63 + _tmp227*_tmp83;
    const double _tmp231 = _tmp204*_tmp54 - _tmp216*_tmp64 + _tmp227*_tmp84;
    const double _tmp232 = _tmp205*_tmp51 - _tmp217*_tmp61 + _tmp228*_tmp81 - _tmp230*_tmp91;
    const double _tmp233 = _tmp205*_tmp52 + _tmp206*_tmp51 - _tmp217*_tmp62 - _tmp218*_tmp61
            + _tmp228*_tmp82 + _tmp229*_tmp81 - _tmp230*_tmp92 - _tmp231*_tmp91;
    const double _tmp234 = _tmp206*_tmp52 - _tmp218*_tmp62 + _tmp229*_tmp82 - _tmp231*_tmp92;
    const double _tmp235 = _tmp207*_tmp53 - _tmp219*_tmp63 + _tmp227*_tmp73;
    const double _tmp236 = _tmp207*_tmp54 - _tmp219*_tmp64 + _tmp227*_tmp74;
    const double _tmp237 = _tmp208*_tmp51 - _tmp220*_tmp61 + _tmp228*_tmp71 - _tmp235*_tmp91;
    const double _tmp238 = _tmp208*_tmp52 + _tmp209*_tmp51 - _tmp220*_tmp62 - _tmp221*_tmp61
            + _tmp228*_tmp72 + _tmp229*_tmp71 - _tmp235*_tmp92 - _tmp236*_tmp91;
    const double _tmp239 = _tmp209*_tmp52 - _tmp221*_tmp62 + _tmp229*_tmp72 - _tmp236*_tmp92;
    const double _tmp240 = _tmp210*_tmp51 - _tmp222*_tmp61 + _tmp230*_tmp71 - _tmp235*_tmp81;
    const double _tmp241 = _tmp210*_tmp52 + _tmp211*_tmp51 - _tmp222*_tmp62 - _tmp223*_tmp61
            + _tmp230*_tmp72 + _tmp231*_tmp71 - _tmp235*_tmp82 - _tmp236*_tmp81;
    const double _tmp242 = _tmp211*_tmp52 - _tmp223*_tmp62 + _tmp231*_tmp72 - _tmp236*_tmp82;
    const double _tmp243 = _tmp212*_tmp55 - _tmp224*_tmp65 + _tmp232*_tmp75 - _tmp237*_tmp85
            + _tmp240*_tmp95;
    const double _tmp244 = _tmp212*_tmp56 + _tmp213*_tmp55 - _tmp224*_tmp66 - _tmp225*_tmp65
            + _tmp232*_tmp76 + _tmp233*_tmp75 - _tmp237*_tmp86 - _tmp238*_tmp85 + _tmp240*_tmp96
            + _tmp241*_tmp95;
    const double _tmp245 = _tmp212*_tmp57 + _tmp213*_tmp56 + _tmp214*_tmp55 - _tmp224*_tmp67
            - _tmp225*_tmp66 - _tmp226*_tmp65 + _tmp232*_tmp77 + _tmp233*_tmp76 + _tmp234*_tmp75
            - _tmp237*_tmp87 - _tmp238*_tmp86 - _tmp239*_tmp85 + _tmp240*_tmp97 + _tmp241*_tmp96
            + _tmp242*_tmp95;
    const double _tmp246 = _tmp213*_tmp57 + _tmp214*_tmp56 - _tmp225*_tmp67 - _tmp226*_tmp66
            + _tmp233*_tmp77 + _tmp234*_tmp76 - _tmp238*_tmp87 - _tmp239*_tmp86 + _tmp241*_tmp97
            + _tmp242*_tmp96;
    const double _tmp247 = _tmp214*_tmp57 - _tmp226*_tmp67 + _tmp234*_tmp77 - _tmp239*_tmp87
            + _tmp242*_tmp97;
    const double _tmp248 = _tmp100*_tmp88 + _tmp68*_tmp98 - _tmp78*_tmp99;
    const double _tmp249 = -_tmp103*_tmp78 + _tmp104*_tmp88 + _tmp58*_tmp98;
    const double _tmp250 = -_tmp103*_tmp68 + _tmp107*_tmp88 + _tmp58*_tmp99;
    const double _tmp251 = _tmp100*_tmp58 - _tmp104*_tmp68 + _tmp107*_tmp78;
    const double _tmp252 = _tmp248*_tmp63 - _tmp249*_tmp73 + _tmp250*_tmp83 - _tmp251*_tmp93;
    const double _tmp253 = _tmp248*_tmp64 - _tmp249*_tmp74 + _tmp250*_tmp84 - _tmp251*_tmp94;
    const double _tmp254 = -_tmp115*_tmp78 + _tmp116*_tmp88 + _tmp48*_tmp98;
    const double _tmp255 = -_tmp115*_tmp68 + _tmp119*_tmp88 + _tmp48*_tmp99;
    const double _tmp256 = _tmp100*_tmp48 - _tmp116*_tmp68 + _tmp119*_tmp78;
    const double _tmp257 = _tmp248*_tmp53 - _tmp254*_tmp73 + _tmp255*_tmp83 - _tmp256*_tmp93;
    const double _tmp258 = _tmp248*_tmp54 - _tmp254*_tmp74 + _tmp255*_tmp84 - _tmp256*_tmp94;
    const double _tmp259 = _tmp103*_tmp48 - _tmp115*_tmp58 + _tmp127*_tmp88;
    const double _tmp260 = _tmp104*_tmp48 - _tmp116*_tmp58 + _tmp127*_tmp78;
    const double _tmp261 = _tmp249*_tmp53 - _tmp254*_tmp63 + _tmp259*_tmp83 - _tmp260*_tmp93;
    const double _tmp262 = _tmp249*_tmp54 - _tmp254*_tmp64 + _tmp259*_tmp84 - _tmp260*_tmp94;
    const double _tmp263 = _tmp107*_tmp48 - _tmp119*_tmp58 + _tmp127*_tmp68;
    const double _tmp264 = _tmp250*_tmp53 - _tmp255*_tmp63 + _tmp259*_tmp73 - _tmp263*_tmp93;
    const double _tmp265 = _tmp250*_tmp54 - _tmp255*_tmp64 + _tmp259*_tmp74 - _tmp263*_tmp94;
    const double _tmp266 = _tmp251*_tmp53 - _tmp256*_tmp63 + _tmp260*_tmp73 - _tmp263*_tmp83;
    const double _tmp267 = _tmp251*_tmp54 - _tmp256*_tmp64 + _tmp260*_tmp74 - _tmp263*_tmp84;
    const double _tmp268 = _tmp252*_tmp55 - _tmp257*_tmp65 + _tmp261*_tmp75 - _tmp264*_tmp85
            + _tmp266*_tmp95;
    const double _tmp269 = _tmp252*_tmp56 + _tmp253*_tmp55 - _tmp257*_tmp66 - _tmp258*_tmp65
            + _tmp261*_tmp76 + _tmp262*_tmp75 - _tmp264*_tmp86 - _tmp265*_tmp85 + _tmp266*_tmp96
            + _tmp267*_tmp95;
    const double _tmp270 = _tmp252*_tmp57 + _tmp253*_tmp56 - _tmp257*_tmp67 - _tmp258*_tmp66
            + _tmp261*_tmp77 + _tmp262*_tmp76 - _tmp264*_tmp87 - _tmp265*_tmp86 + _tmp266*_tmp97
            + _tmp267*_tmp96;
    const double _tmp271 = _tmp253*_tmp57 - _tmp258*_tmp67 + _tmp262*_tmp77 - _tmp265*_tmp87
            + _tmp267*_tmp97;
    const double _tmp272 = _tmp248*_tmp61 - _tmp249*_tmp71 + _tmp250*_tmp81 - _tmp251*_tmp91;
    const double _tmp273 = _tmp248*_tmp62 - _tmp249*_tmp72 + _tmp250*_tmp82 - _tmp251*_tmp92;
    const double _tmp274 = _tmp248*_tmp51 - _tmp254*_tmp71 + _tmp255*_tmp81 - _tmp256*_tmp91;
    const double _tmp275 = _tmp248*_tmp52 - _tmp254*_tmp72 + _tmp255*_tmp82 - _tmp256*_tmp92;
    const double _tmp276 = _tmp249*_tmp51 - _tmp254*_tmp61 + _tmp259*_tmp81 - _tmp260*_tmp91;
    const double _tmp277 = _tmp249*_tmp52 - _tmp254*_tmp62 + _tmp259*_tmp82 - _tmp260*_tmp92;
    const double _tmp278 = _tmp250*_tmp51 - _tmp255*_tmp61 + _tmp259*_tmp71 - _tmp263*_tmp91;
    const double _tmp279 = _tmp250*_tmp52 - _tmp255*_tmp62 + _tmp259*_tmp72 - _tmp263*_tmp92;
    const double _tmp280 = _tmp251*_tmp51 - _tmp256*_tmp61 + _tmp260*_tmp71 - _tmp263*_tmp81;
    const double _tmp281 = _tmp251*_tmp52 - _tmp256*_tmp62 + _tmp260*_tmp72 - _tmp263*_tmp82;
    const double _tmp282 = _tmp272*_tmp55 - _tmp274*_tmp65 + _tmp276*_tmp75 - _tmp278*_tmp85
            + _tmp280*_tmp95;
    const double _tmp283 = _tmp272*_tmp56 + _tmp273*_tmp55 - _tmp274*_tmp66 - _tmp275*_tmp65
            + _tmp276*_tmp76 + _tmp277*_tmp75 - _tmp278*_tmp86 - _tmp279*_tmp85 + _tmp280*_tmp96
            + _tmp281*_tmp95;
    const double _tmp284 = _tmp272*_tmp57 + _tmp273*_tmp56 - _tmp274*_tmp67 - _tmp275*_tmp66
            + _tmp276*_tmp77 + _tmp277*_tmp76 - _tmp278*_tmp87 - _tmp279*_tmp86 + _tmp280*_tmp97
            + _tmp281*_tmp96;
    const double _tmp285 = _tmp273*_tmp57 - _tmp275*_tmp67 + _tmp277*_tmp77 - _tmp279*_tmp87
            + _tmp281*_tmp97;
    const double _tmp286 = _tmp252*_tmp51 - _tmp257*_tmp61 + _tmp261*_tmp71 - _tmp264*_tmp81
            + _tmp266*_tmp91;
    const double _tmp287 = _tmp252*_tmp52 + _tmp253*_tmp51 - _tmp257*_tmp62 - _tmp258*_tmp61
            + _tmp261*_tmp72 + _tmp262*_tmp71 - _tmp264*_tmp82 - _tmp265*_tmp81 + _tmp266*_tmp92
            + _tmp267*_tmp91;
    const double _tmp288 = _tmp253*_tmp52 - _tmp258*_tmp62 + _tmp262*_tmp72 - _tmp265*_tmp82
            + _tmp267*_tmp92;
    u[0] = _tmp143;
    u[1] = _tmp144;
    u[2] = _tmp145;
    u[3] = _tmp146;
    u[4] = _tmp147;
    u[5] = -_tmp193;
    u[6] = -_tmp194;
    u[7] = -_tmp195;
    u[8] = -_tmp196;
    u[9] = -_tmp197;
    u[10] = _tmp243;
    u[11] = _tmp244;
    u[12] = _tmp245;
    u[13] = _tmp246;
    u[14] = _tmp247;
    u[15] = _tmp268;
    u[16] = _tmp269;
    u[17] = _tmp270;
    u[18] = _tmp271;
    u[19] = -_tmp282;
    u[20] = -_tmp283;
    u[21] = -_tmp284;
    u[22] = -_tmp285;
    u[23] = -_tmp286;
    u[24] = -_tmp287;
    u[25] = -_tmp288;
}

void betaN4Consistency(const double* u, double* f)
{
    // Operation count: 93 mul, 60 add, 0 div (total 153).
    f[0] = -u[10]*u[23] + u[15]*u[19];
    f[1] = -u[10]*u[24] - u[11]*u[23] + u[15]*u[20] + u[16]*u[19];
    f[2] = -u[10]*u[25] - u[11]*u[24] - u[12]*u[23] + u[15]*u[21] + u[16]*u[20] + u[17]*u[19];
    f[3] = -u[11]*u[25] - u[12]*u[24] - u[13]*u[23] + u[15]*u[22] + u[16]*u[21] + u[17]*u[20]
            + u[18]*u[19];
    f[4] = -u[12]*u[25] - u[13]*u[24] - u[14]*u[23] + u[16]*u[22] + u[17]*u[21] + u[18]*u[20];
    f[5] = -u[13]*u[25] - u[14]*u[24] + u[17]*u[22] + u[18]*u[21];
    f[6] = -u[14]*u[25] + u[18]*u[22];
    f[7] = -u[0]*u[23] + (u[15]*u[15]);
    f[8] = -u[0]*u[24] + 2*u[15]*u[16] - u[1]*u[23];
    f[9] = -u[0]*u[25] + 2*u[15]*u[17] + (u[16]*u[16]) - u[1]*u[24] - u[23]*u[2];
    f[10] = 2*u[15]*u[18] + 2*u[16]*u[17] - u[1]*u[25] - u[23]*u[3] - u[24]*u[2];
    f[11] = 2*u[16]*u[18] + (u[17]*u[17]) - u[23]*u[4] - u[24]*u[3] - u[25]*u[2];
    f[12] = 2*u[17]*u[18] - u[24]*u[4] - u[25]*u[3];
    f[13] = (u[18]*u[18]) - u[25]*u[4];
    f[14] = (u[19]*u[19]) - u[23]*u[5];
    f[15] = 2*u[19]*u[20] - u[23]*u[6] - u[24]*u[5];
    f[16] = 2*u[19]*u[21] + (u[20]*u[20]) - u[23]*u[7] - u[24]*u[6] - u[25]*u[5];
    f[17] = 2*u[19]*u[22] + 2*u[20]*u[21] - u[23]*u[8] - u[24]*u[7] - u[25]*u[6];
    f[18] = 2*u[20]*u[22] + (u[21]*u[21]) - u[23]*u[9] - u[24]*u[8] - u[25]*u[7];
    f[19] = 2*u[21]*u[22] - u[24]*u[9] - u[25]*u[8];
    f[20] = (u[22]*u[22]) - u[25]*u[9];
}

void betaN4Polynomial(const double* u, double* p)
{
    // Operation count: 249 mul, 129 add, 0 div (total 378).
    const double _tmp0 = -u[10]*u[23] + u[15]*u[19];
    const double _tmp1 = -u[10]*u[24] - u[11]*u[23] + u[15]*u[20] + u[16]*u[19];
    const double _tmp2 = -u[10]*u[25] - u[11]*u[24] - u[12]*u[23] + u[15]*u[21] + u[16]*u[20]
            + u[17]*u[19];
    const double _tmp3 = -u[11]*u[25] - u[12]*u[24] - u[13]*u[23] + u[15]*u[22] + u[16]*u[21]
            + u[17]*u[20] + u[18]*u[19];
    const double _tmp4 = -u[12]*u[25] - u[13]*u[24] - u[14]*u[23] + u[16]*u[22] + u[17]*u[21]
            + u[18]*u[20];
    const double _tmp5 = -u[13]*u[25] - u[14]*u[24] + u[17]*u[22] + u[18]*u[21];
    const double _tmp6 = -u[14]*u[25] + u[18]*u[22];
    const double _tmp7 = -u[0]*u[23] + (u[15]*u[15]);
    const double _tmp8 = -u[0]*u[24] + 2*u[15]*u[16] - u[1]*u[23];
    const double _tmp9 = -u[0]*u[25] + 2*u[15]*u[17] + (u[16]*u[16]) - u[1]*u[24] - u[23]*u[2];
    const double _tmp10 = 2*u[15]*u[18] + 2*u[16]*u[17] - u[1]*u[25] - u[23]*u[3] - u[24]*u[2];
    const double _tmp11 = 2*u[16]*u[18] + (u[17]*u[17]) - u[23]*u[4] - u[24]*u[3] - u[25]*u[2];
    const double _tmp12 = 2*u[17]*u[18] - u[24]*u[4] - u[25]*u[3];
    const double _tmp13 = (u[18]*u[18]) - u[25]*u[4];
    const double _tmp14 = (u[19]*u[19]) - u[23]*u[5];
    const double _tmp15 = 2*u[19]*u[20] - u[23]*u[6] - u[24]*u[5];
    const double _tmp16 = 2*u[19]*u[21] + (u[20]*u[20]) - u[23]*u[7] - u[24]*u[6] - u[25]*u[5];
    const double _tmp17 = 2*u[19]*u[22] + 2*u[20]*u[21] - u[23]*u[8] - u[24]*u[7] - u[25]*u[6];
    const double _tmp18 = 2*u[20]*u[22] + (u[21]*u[21]) - u[23]*u[9] - u[24]*u[8] - u[25]*u[7];
    const double _tmp19 = 2*u[21]*u[22] - u[24]*u[9] - u[25]*u[8];
    const double _tmp20 = (u[22]*u[22]) - u[25]*u[9];
    p[0] = _tmp0*_tmp1 + _tmp14*_tmp15 + _tmp7*_tmp8;
    p[1] = 2*_tmp0*_tmp2 + (_tmp1*_tmp1) + 2*_tmp14*_tmp16 + (_tmp15*_tmp15) + 2*_tmp7*_tmp9
            + (_tmp8*_tmp8);
    p[2] = 3*_tmp0*_tmp3 + 3*_tmp1*_tmp2 + 3*_tmp10*_tmp7 + 3*_tmp14*_tmp17 + 3*_tmp15*_tmp16
            + 3*_tmp8*_tmp9;
    p[3] = 4*_tmp0*_tmp4 + 4*_tmp1*_tmp3 + 4*_tmp10*_tmp8 + 4*_tmp11*_tmp7 + 4*_tmp14*_tmp18
            + 4*_tmp15*_tmp17 + 2*(_tmp16*_tmp16) + 2*(_tmp2*_tmp2) + 2*(_tmp9*_tmp9);
    p[4] = 5*_tmp0*_tmp5 + 5*_tmp1*_tmp4 + 5*_tmp10*_tmp9 + 5*_tmp11*_tmp8 + 5*_tmp12*_tmp7
            + 5*_tmp14*_tmp19 + 5*_tmp15*_tmp18 + 5*_tmp16*_tmp17 + 5*_tmp2*_tmp3;
    p[5] = 6*_tmp0*_tmp6 + 6*_tmp1*_tmp5 + 3*(_tmp10*_tmp10) + 6*_tmp11*_tmp9 + 6*_tmp12*_tmp8
            + 6*_tmp13*_tmp7 + 6*_tmp14*_tmp20 + 6*_tmp15*_tmp19 + 6*_tmp16*_tmp18
            + 3*(_tmp17*_tmp17) + 6*_tmp2*_tmp4 + 3*(_tmp3*_tmp3);
    p[6] = 7*_tmp1*_tmp6 + 7*_tmp10*_tmp11 + 7*_tmp12*_tmp9 + 7*_tmp13*_tmp8 + 7*_tmp15*_tmp20
            + 7*_tmp16*_tmp19 + 7*_tmp17*_tmp18 + 7*_tmp2*_tmp5 + 7*_tmp3*_tmp4;
    p[7] = 8*_tmp10*_tmp12 + 4*(_tmp11*_tmp11) + 8*_tmp13*_tmp9 + 8*_tmp16*_tmp20
            + 8*_tmp17*_tmp19 + 4*(_tmp18*_tmp18) + 8*_tmp2*_tmp6 + 8*_tmp3*_tmp5 + 4*(_tmp4*_tmp4);
    p[8] = 9*_tmp10*_tmp13 + 9*_tmp11*_tmp12 + 9*_tmp17*_tmp20 + 9*_tmp18*_tmp19 + 9*_tmp3*_tmp6
            + 9*_tmp4*_tmp5;
    p[9] = 10*_tmp11*_tmp13 + 5*(_tmp12*_tmp12) + 10*_tmp18*_tmp20 + 5*(_tmp19*_tmp19)
            + 10*_tmp4*_tmp6 + 5*(_tmp5*_tmp5);
    p[10] = 11*_tmp12*_tmp13 + 11*_tmp19*_tmp20 + 11*_tmp5*_tmp6;
    p[11] = 6*(_tmp13*_tmp13) + 6*(_tmp20*_tmp20) + 6*(_tmp6*_tmp6);
}

} // namespace generated
} // namespace tripose
