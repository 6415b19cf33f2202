// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

#include "core/pipeline/posed_structure.hpp"
#include "opencv/argument_reading.hpp"
#include "opencv/result_writing.hpp"

namespace cv {
namespace tripose {

int triangulateMultiView(InputArrayOfArrays points, InputArrayOfArrays lines, InputArrayOfArrays cameraMatrix,
                         InputArrayOfArrays distCoeffs, InputArrayOfArrays Rs, InputArrayOfArrays ts,
                         OutputArray points3d, OutputArray lines3d, OutputArray pointErrors, OutputArray lineErrors)
{
    CV_INSTRUMENT_REGION();
    return TRIPOSE_CALL_CORE([&] {
        const detail::core::ViewSet views = detail::readPosedViewsInput(points, lines, cameraMatrix, distCoeffs, Rs, ts);
        const detail::core::PosedStructure structure = detail::core::triangulateStructure(views);
        const int numViews = (int)views.views.size();
        detail::writeStructure(structure.points, structure.lineEnds, views.numPoints, views.numLines, points3d,
                               lines3d);
        detail::writeFeatureViewMatrix(structure.pointErrors, views.numPoints, numViews, pointErrors);
        detail::writeFeatureViewMatrix(structure.lineErrors, views.numLines, numViews, lineErrors);
        return structure.numWithStructure;
    });
}

} // namespace tripose
} // namespace cv
