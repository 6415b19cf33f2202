// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The Python package's extension: numpy arrays in, the core's problems built and solved, numpy
// arrays out. Conversions only; every algorithm and every check of a value is the core's, so that
// Python and C++ report the same errors and return the same poses. The Python layer
// (python/tripose/__init__.py) gives the functions their documented signatures.

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "linear/linear_pose_solver.hpp"
#include "linear/multiview_pose_solver.hpp"
#include "linear/rig_pose_solver.hpp"
#include "pipeline/pose_pipelines.hpp"
#include "problem/view_set_builder.hpp"
#include "robust/hybrid_pose_solver.hpp"
#include "support/error.hpp"

namespace nb = nanobind;

namespace {

using AnyArray = nb::ndarray<nb::ro, nb::device::cpu>;
using OutArray = nb::ndarray<nb::numpy, double>;

const int kMinFeatures = 4, kMinStereoFeatures = 2, kMinStereoRansacFeatures = 3, kMinRefineFeatures = 3;

[[noreturn]] void raiseType(const std::string& message)
{
    throw nb::type_error(message.c_str());
}

[[noreturn]] void raiseValue(const std::string& message)
{
    throw nb::value_error(message.c_str());
}

std::string shapeText(const AnyArray& a)
{
    std::string text = "(";
    for (size_t d = 0; d < a.ndim(); ++d)
        text += (d ? ", " : "") + std::to_string(a.shape(d));
    return text + (a.ndim() == 1 ? ",)" : ")");
}

//! A numpy array of float32 or float64 (any memory layout); TypeError naming @p name otherwise.
AnyArray asArray(nb::handle object, const std::string& name)
{
    AnyArray a;
    if (!nb::try_cast(object, a, false))
        raiseType(name + " must be a numpy array of float32 or float64");
    if (a.dtype() != nb::dtype<double>() && a.dtype() != nb::dtype<float>())
        raiseType(name + " must be float32 or float64");
    return a;
}

//! The values of @p a (one or two dimensions, any strides) in row-major order as a @p rows x @p cols
//! matrix named @p name.
tripose::ArgumentMatrix copyMatrix(const AnyArray& a, const std::string& name, int rows, int cols)
{
    tripose::ArgumentMatrix m;
    m.name = name;
    m.rows = rows;
    m.cols = cols;
    m.singlePrecision = a.dtype() == nb::dtype<float>();
    m.values.resize((size_t)rows * cols);
    // numpy strides are in elements here; a vector is read as one row.
    const size_t outer = a.ndim() == 2 ? a.shape(0) : 1, inner = a.ndim() == 2 ? a.shape(1) : a.size();
    const int64_t outerStride = a.ndim() == 2 ? a.stride(0) : 0, innerStride = a.stride(a.ndim() - 1);
    double* out = m.values.data();
    for (size_t r = 0; r < outer; ++r)
        for (size_t c = 0; c < inner; ++c)
        {
            const int64_t offset = (int64_t)r * outerStride + (int64_t)c * innerStride;
            *out++ = m.singlePrecision ? (double)static_cast<const float*>(a.data())[offset]
                                       : static_cast<const double*>(a.data())[offset];
        }
    return m;
}

//! Points (Nx2) or lines (Mx4 segments / Mx3 homogeneous); None or an empty array: none.
tripose::ArgumentMatrix readFeatures(nb::handle object, const std::string& name, bool lines)
{
    tripose::ArgumentMatrix m;
    m.name = name;
    if (object.is_none())
        return m;
    const AnyArray a = asArray(object, name);
    if (a.size() == 0)
        return m;
    const bool widthOk = a.ndim() == 2 && (lines ? (a.shape(1) == 4 || a.shape(1) == 3) : a.shape(1) == 2);
    if (!widthOk)
        raiseValue(name + (lines ? " must have shape (M, 4) (segments x0 y0 x1 y1) or (M, 3) (homogeneous lines a b c)"
                                 : " must have shape (N, 2)") + ", got " + shapeText(a));
    return copyMatrix(a, name, (int)a.shape(0), (int)a.shape(1));
}

//! A camera matrix, 3x3.
tripose::ArgumentMatrix readCameraMatrix(nb::handle object, const std::string& name)
{
    const AnyArray a = asArray(object, name);
    if (a.ndim() != 2 || a.shape(0) != 3 || a.shape(1) != 3)
        raiseValue(name + " must have shape (3, 3), got " + shapeText(a));
    return copyMatrix(a, name, 3, 3);
}

//! Distortion coefficients: a vector (OpenCV's 4, 5, 8, 12 or 14, checked by the core).
tripose::ArgumentMatrix readDistortion(nb::handle object, const std::string& name)
{
    const AnyArray a = asArray(object, name);
    if (a.ndim() > 2 || (a.ndim() == 2 && a.shape(0) != 1 && a.shape(1) != 1))
        raiseValue(name + " must be a vector of 4, 5, 8, 12 or 14 coefficients, got shape " + shapeText(a));
    return copyMatrix(a, name, 1, (int)a.size());
}

bool isSequence(nb::handle object)
{
    return nb::isinstance<nb::list>(object) || nb::isinstance<nb::tuple>(object);
}

/** K (one 3x3, a sequence of one per view, or an array of shape (V, 3, 3)) and dist (None, one
vector, or a sequence of one per view).
*/
void readCalibration(nb::handle K, nb::handle dist, tripose::ProblemArguments& args)
{
    args.cameraMatrixName = "K";
    args.distortionName = "dist";
    if (isSequence(K))
    {
        nb::sequence items = nb::borrow<nb::sequence>(K);
        const size_t n = nb::len(items);
        for (size_t v = 0; v < n; ++v)
            args.cameraMatrices.push_back(readCameraMatrix(items[v], "K[" + std::to_string(v) + "]"));
    }
    else
    {
        const AnyArray a = asArray(K, "K");
        if (a.ndim() == 3 && a.shape(1) == 3 && a.shape(2) == 3)
        {
            nb::object array = nb::borrow(K);
            for (size_t v = 0; v < a.shape(0); ++v)
                args.cameraMatrices.push_back(readCameraMatrix(array[nb::int_(v)], "K[" + std::to_string(v) + "]"));
        }
        else
            args.cameraMatrices.push_back(readCameraMatrix(K, "K"));
    }
    if (dist.is_none())
        return;
    if (isSequence(dist))
    {
        nb::sequence items = nb::borrow<nb::sequence>(dist);
        const size_t n = nb::len(items);
        for (size_t v = 0; v < n; ++v)
            args.distortions.push_back(readDistortion(items[v], "dist[" + std::to_string(v) + "]"));
    }
    else
        args.distortions.push_back(readDistortion(dist, "dist"));
}

tripose::ArgumentMatrix readRotation(nb::handle object, const std::string& name)
{
    const AnyArray a = asArray(object, name);
    if (!(a.size() == 9 && a.ndim() == 2 && a.shape(0) == 3) && a.size() != 3)
        raiseValue(name + " must be a 3x3 rotation matrix or a rotation vector of 3 elements, got shape " + shapeText(a));
    return a.size() == 9 ? copyMatrix(a, name, 3, 3) : copyMatrix(a, name, 3, 1);
}

tripose::ArgumentMatrix readTranslation(nb::handle object, const std::string& name)
{
    const AnyArray a = asArray(object, name);
    if (a.size() != 3)
        raiseValue(name + " must hold 3 elements, got shape " + shapeText(a));
    return copyMatrix(a, name, 3, 1);
}

tripose::ViewArguments readView(nb::handle points, nb::handle lines, const std::string& pointsName,
                                const std::string& linesName, bool mayMiss)
{
    tripose::ViewArguments view;
    view.points = readFeatures(points, pointsName, false);
    view.lines = readFeatures(lines, linesName, true);
    view.mayMiss = mayMiss;
    return view;
}

//! A list of one array per view (or None: no feature of that kind in any view).
std::vector<nb::object> readViewList(nb::handle object, const char* name, size_t numViews)
{
    std::vector<nb::object> out(numViews, nb::none());
    if (object.is_none())
        return out;
    if (!isSequence(object))
        raiseType(std::string(name) + " must be a list of arrays, one per view");
    nb::sequence items = nb::borrow<nb::sequence>(object);
    if (nb::len(items) != numViews)
        raiseValue(std::string(name) + " must hold " + std::to_string(numViews) + " arrays, one per view, got " +
                   std::to_string(nb::len(items)));
    for (size_t v = 0; v < numViews; ++v)
        out[v] = items[v];
    return out;
}

std::vector<tripose::ArgumentMatrix> readPoseList(nb::handle object, const char* name, bool rotations)
{
    if (!isSequence(object))
        raiseType(std::string(name) + " must be a list of " + (rotations ? "rotations" : "translations"));
    nb::sequence items = nb::borrow<nb::sequence>(object);
    std::vector<tripose::ArgumentMatrix> out;
    for (size_t k = 0; k < nb::len(items); ++k)
    {
        const std::string element = std::string(name) + "[" + std::to_string(k) + "]";
        out.push_back(rotations ? readRotation(items[k], element) : readTranslation(items[k], element));
    }
    return out;
}

//! Views that each may miss features: @p numViews of them, the arrays named points[v], lines[v].
tripose::ProblemArguments readPosedViews(nb::handle points, nb::handle lines, nb::handle K, nb::handle dist,
                                         size_t numViews)
{
    if (points.is_none() && lines.is_none())
        raiseValue("points and lines are both None: at least four features are required");
    const std::vector<nb::object> pointArrays = readViewList(points, "points", numViews);
    const std::vector<nb::object> lineArrays = readViewList(lines, "lines", numViews);
    tripose::ProblemArguments args;
    for (size_t v = 0; v < numViews; ++v)
        args.views.push_back(readView(pointArrays[v], lineArrays[v], "points[" + std::to_string(v) + "]",
                                      "lines[" + std::to_string(v) + "]", true));
    readCalibration(K, dist, args);
    return args;
}

OutArray newArray(std::initializer_list<size_t> shape, const double* values)
{
    size_t n = 1;
    for (size_t s : shape)
        n *= s;
    double* data = new double[n];
    std::memcpy(data, values, n * sizeof(double));
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<double*>(p); });
    return OutArray(data, shape.size(), shape.begin(), owner);
}

nb::object rotationArray(const Eigen::Matrix3d& R)
{
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMajor = R;
    return newArray({ 3, 3 }, rowMajor.data()).cast();
}

nb::object vectorArray(const Eigen::Vector3d& t)
{
    return newArray({ 3 }, t.data()).cast();
}

nb::object maskArray(const std::vector<unsigned char>& mask)
{
    bool* data = new bool[mask.size() ? mask.size() : 1];
    for (size_t i = 0; i < mask.size(); ++i)
        data[i] = mask[i] != 0;
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    const size_t shape[1] = { mask.size() };
    return nb::ndarray<nb::numpy, bool>(data, 1, shape, owner).cast();
}

nb::list candidateList(const std::vector<tripose::ScoredPose>& candidates)
{
    nb::list out;
    for (const tripose::ScoredPose& c : candidates)
        out.append(nb::make_tuple(rotationArray(c.pose.R), vectorArray(c.pose.t)));
    return out;
}

//! The pose's uncertainty into @p out: covariance (6, 6) and noise_variance, both None when not valid.
void writeCovariance(const tripose::PoseCovariance& uncertainty, nb::dict& out)
{
    if (!uncertainty.valid)
    {
        out["covariance"] = nb::none();
        out["noise_variance"] = nb::none();
        return;
    }
    const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> rowMajor = uncertainty.covariance;
    out["covariance"] = newArray({ 6, 6 }, rowMajor.data()).cast();
    out["noise_variance"] = uncertainty.noiseVariance;
}

nb::dict robustResult(bool found, const tripose::RobustEstimate& estimate, const tripose::PoseCovariance& uncertainty)
{
    nb::dict out;
    out["R"] = found ? rotationArray(estimate.pose.R) : nb::none();
    out["t"] = found ? vectorArray(estimate.pose.t) : nb::none();
    out["num_inliers"] = found ? estimate.numInliers : 0;
    out["point_inliers"] = maskArray(estimate.pointInliers);
    out["line_inliers"] = maskArray(estimate.lineInliers);
    out["rms"] = found ? estimate.inlierRms : std::numeric_limits<double>::quiet_NaN();
    writeCovariance(uncertainty, out);
    return out;
}

void writeStructure(const tripose::RefinedStructure& s, int numPoints, int numLines, nb::dict& out)
{
    std::vector<double> points(3 * (size_t)numPoints), lines(6 * (size_t)numLines);
    for (int i = 0; i < numPoints; ++i)
        for (int c = 0; c < 3; ++c)
            points[3 * i + c] = s.points[i](c);
    for (int i = 0; i < numLines; ++i)
        for (int c = 0; c < 3; ++c)
        {
            lines[6 * i + c] = s.lineEnds[2 * i](c);
            lines[6 * i + 3 + c] = s.lineEnds[2 * i + 1](c);
        }
    out["points3d"] = newArray({ (size_t)numPoints, 3 }, points.data()).cast();
    out["lines3d"] = newArray({ (size_t)numLines, 6 }, lines.data()).cast();
}

tripose::RansacOptions ransacOptions(double threshold, double confidence, int maxIterations, bool refine,
                                     uint64_t seed)
{
    tripose::RansacOptions options;
    options.threshold = threshold;
    options.confidence = confidence;
    options.maxIterations = maxIterations;
    options.refine = refine;
    options.seed = seed;
    tripose::RansacOptionNames names;
    names.maxIterations = "max_iterations";
    tripose::checkRansacOptions(options, "", names);
    return options;
}

tripose::RefineOptions refineOptions(int maxIterations, const std::string& loss, double lossScale, double tolerance)
{
    tripose::RefineOptions options;
    options.maxIterations = maxIterations;
    options.lossScale = lossScale;
    options.tolerance = tolerance;
    if (loss == "squared")
        options.loss = tripose::Loss::Squared;
    else if (loss == "huber")
        options.loss = tripose::Loss::Huber;
    else if (loss == "cauchy")
        options.loss = tripose::Loss::Cauchy;
    else
        raiseValue("loss must be 'squared', 'huber' or 'cauchy', got '" + loss + "'");
    tripose::RefineOptionNames names;
    names.maxIterations = "max_iterations";
    names.lossScale = "loss_scale";
    tripose::checkRefineOptions(options, "", names);
    return options;
}

/** The arguments of a three-view problem, converted while the GIL is held; builder() makes its
ViewSet (the core validates) without touching a Python object.
*/
struct ThreeViewProblem
{
    tripose::ProblemArguments arguments;
    tripose::ArgumentMatrix R12, t12;

    ThreeViewProblem(nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3,
                     nb::handle K, nb::handle R12in, nb::handle t12in, nb::handle dist)
    {
        arguments.views.push_back(readView(p1, l1, "points1", "lines1", false));
        arguments.views.push_back(readView(p2, l2, "points2", "lines2", false));
        arguments.views.push_back(readView(p3, l3, "points3", "lines3", false));
        readCalibration(K, dist, arguments);
        R12 = readRotation(R12in, "R12");
        t12 = readTranslation(t12in, "t12");
    }

    std::function<tripose::ViewSet()> builder(int minFeatures) const
    {
        return [this, minFeatures] { return tripose::buildThreeViewSet(arguments, R12, t12, minFeatures); };
    }
};

//! The stereo rig's arguments (views 3 and 4 may miss features), as ThreeViewProblem.
struct StereoProblem
{
    tripose::ProblemArguments arguments;
    tripose::ArgumentMatrix R12, t12;

    StereoProblem(nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2,
                  nb::handle l3, nb::handle l4, nb::handle K, nb::handle R12in, nb::handle t12in, nb::handle dist)
    {
        arguments.views.push_back(readView(p1, l1, "points1", "lines1", false));
        arguments.views.push_back(readView(p2, l2, "points2", "lines2", false));
        arguments.views.push_back(readView(p3, l3, "points3", "lines3", true));
        arguments.views.push_back(readView(p4, l4, "points4", "lines4", true));
        readCalibration(K, dist, arguments);
        R12 = readRotation(R12in, "R12");
        t12 = readTranslation(t12in, "t12");
    }

    std::function<tripose::ViewSet()> builder(int minFeatures) const
    {
        return [this, minFeatures] { return tripose::buildStereoRigSet(arguments, R12, t12, minFeatures); };
    }
};

//! Views at the world poses Rs, ts, plus @p unposedViews new views, every view free to miss features.
struct MultiViewProblem
{
    std::vector<tripose::ArgumentMatrix> rotations, translations;
    tripose::ProblemArguments arguments;

    MultiViewProblem(nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
                     size_t unposedViews)
        : rotations(readPoseList(Rs, "Rs", true)), translations(readPoseList(ts, "ts", false)),
          arguments(readPosedViews(points, lines, K, dist, rotations.size() + unposedViews))
    {
    }

    //! The registration of one new view (estimatePoseMultiView's layout).
    std::function<tripose::ViewSet()> newViewBuilder() const
    {
        return [this] { return tripose::buildMultiViewSet(arguments, rotations, translations, kMinFeatures); };
    }
};

//! The robust estimator of an arrangement whose scorer is built from its views (stereo, multi-view).
template <class Solver>
std::function<bool(const tripose::ViewSet&, tripose::RobustEstimate&)> robustWith(const tripose::RansacOptions& options)
{
    return [options](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
        const Solver solver(views);
        return tripose::estimateRobust(views, solver, options, estimate);
    };
}

nb::dict refinedResult(const tripose::ViewSet& views, const tripose::CameraPose& pose, double rms,
                       const tripose::RefinedStructure& structure, const tripose::PoseCovariance& uncertainty)
{
    nb::dict out;
    out["R"] = rotationArray(pose.R);
    out["t"] = vectorArray(pose.t);
    out["rms"] = rms;
    writeStructure(structure, views.numPoints, views.numLines, out);
    writeCovariance(uncertainty, out);
    return out;
}

//! The candidates of a problem: @p build makes its ViewSet, Solver is its PoseSolver; the GIL is
//! released while they run.
template <class Solver, class Build>
nb::list runCandidates(Build build, bool refine)
{
    std::vector<tripose::ScoredPose> candidates;
    {
        nb::gil_scoped_release release;
        const tripose::ViewSet views = build();
        const Solver solver(views);
        candidates = tripose::estimateCandidates(views, solver, refine);
    }
    return candidateList(candidates);
}

//! The robust estimate of a problem: @p estimate runs the estimator of its arrangement, with
//! @p options, on the ViewSet that @p build makes (GIL released); with refinement, the uncertainty
//! of the refined pose over the inliers.
template <class Build, class Estimate>
nb::dict runRobust(Build build, Estimate estimate, const tripose::RansacOptions& options)
{
    tripose::RobustEstimate result;
    tripose::PoseCovariance uncertainty;
    bool found;
    {
        nb::gil_scoped_release release;
        const tripose::ViewSet views = build();
        found = estimate(views, result);
        if (found && options.refine)
            uncertainty = tripose::covarianceOfEstimate(views, result.pose, options.refineOptions,
                                                        &result.pointInliers, &result.lineInliers);
    }
    return robustResult(found, result, uncertainty);
}

//! The refinement of the initial pose (@p R, @p t) over the ViewSet that @p build makes (GIL released).
template <class Build>
nb::dict runRefinement(Build build, const tripose::ArgumentMatrix& R, const tripose::ArgumentMatrix& t,
                       const tripose::RefineOptions& options)
{
    tripose::RefinedStructure structure;
    tripose::PoseCovariance uncertainty;
    tripose::CameraPose pose;
    double rms;
    tripose::ViewSet views;
    {
        nb::gil_scoped_release release;
        views = build();
        pose.R = tripose::readRotation(R);
        pose.t = tripose::readTranslation(t, false);
        rms = tripose::refineInitialPose(views, pose, options, &structure, &uncertainty);
    }
    return refinedResult(views, pose, rms, structure, uncertainty);
}

} // namespace

NB_MODULE(_tripose_ext, m)
{
    m.doc() = "tripose's extension; use the functions of the tripose package, which document them.";

    nb::register_exception_translator([](const std::exception_ptr& p, void*) {
        try
        {
            std::rethrow_exception(p);
        }
        catch (const tripose::Error& e)
        {
            PyErr_SetString(e.code() == tripose::ErrorCode::Internal ? PyExc_RuntimeError : PyExc_ValueError, e.what());
        }
    });

    m.def("estimate_pose_line_point",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3, nb::handle K,
             nb::handle R12, nb::handle t12, nb::handle dist, bool refine) {
              const ThreeViewProblem problem(p1, p2, p3, l1, l2, l3, K, R12, t12, dist);
              return runCandidates<tripose::LinearPoseSolver>(problem.builder(kMinFeatures), refine);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_line_point_ransac",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3, nb::handle K,
             nb::handle R12, nb::handle t12, nb::handle dist, double threshold, double confidence, int maxIterations,
             bool refine, uint64_t seed) {
              const ThreeViewProblem problem(p1, p2, p3, l1, l2, l3, K, R12, t12, dist);
              const tripose::RansacOptions options = ransacOptions(threshold, confidence, maxIterations, refine, seed);
              return runRobust(problem.builder(kMinFeatures),
                               [&](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
                                   // The scorer's structure from views 1-2 is also what the minimal samples solve on.
                                   const tripose::PoseScorer scorer(views);
                                   const tripose::LinearPoseSolver linear(views);
                                   const tripose::HybridPoseSolver solver(views, scorer, linear);
                                   return tripose::estimateRobust(views, scorer, solver, options, estimate);
                               },
                               options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("threshold"), nb::arg("confidence"), nb::arg("max_iterations"), nb::arg("refine"), nb::arg("seed"));

    m.def("refine_pose_line_point",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3, nb::handle K,
             nb::handle R12, nb::handle t12, nb::handle R, nb::handle t, nb::handle dist, int maxIterations,
             const std::string& loss, double lossScale, double tolerance) {
              const ThreeViewProblem problem(p1, p2, p3, l1, l2, l3, K, R12, t12, dist);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = refineOptions(maxIterations, loss, lossScale, tolerance);
              return runRefinement(problem.builder(kMinRefineFeatures), Rm, tm, options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("max_iterations"), nb::arg("loss"), nb::arg("loss_scale"), nb::arg("tolerance"));

    m.def("estimate_pose_line_point_stereo",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle dist, bool refine) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              return runCandidates<tripose::RigPoseSolver>(problem.builder(kMinStereoFeatures), refine);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_line_point_stereo_ransac",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle dist, double threshold,
             double confidence, int maxIterations, bool refine, uint64_t seed) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              const tripose::RansacOptions options = ransacOptions(threshold, confidence, maxIterations, refine, seed);
              return runRobust(problem.builder(kMinStereoRansacFeatures), robustWith<tripose::RigPoseSolver>(options), options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("threshold"), nb::arg("confidence"), nb::arg("max_iterations"), nb::arg("refine"), nb::arg("seed"));

    m.def("refine_pose_line_point_stereo",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle R, nb::handle t, nb::handle dist,
             int maxIterations, const std::string& loss, double lossScale, double tolerance) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = refineOptions(maxIterations, loss, lossScale, tolerance);
              return runRefinement(problem.builder(kMinStereoFeatures), Rm, tm, options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("max_iterations"), nb::arg("loss"), nb::arg("loss_scale"), nb::arg("tolerance"));

    m.def("estimate_pose_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
             bool refine) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              return runCandidates<tripose::MultiViewPoseSolver>(problem.newViewBuilder(), refine);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_multiview_ransac",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
             double threshold, double confidence, int maxIterations, bool refine, uint64_t seed) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              const tripose::RansacOptions options = ransacOptions(threshold, confidence, maxIterations, refine, seed);
              return runRobust(problem.newViewBuilder(), robustWith<tripose::MultiViewPoseSolver>(options), options);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("threshold"), nb::arg("confidence"), nb::arg("max_iterations"), nb::arg("refine"), nb::arg("seed"));

    m.def("refine_pose_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle R,
             nb::handle t, nb::handle dist, int maxIterations, const std::string& loss, double lossScale,
             double tolerance) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = refineOptions(maxIterations, loss, lossScale, tolerance);
              return runRefinement(problem.newViewBuilder(), Rm, tm, options);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("max_iterations"), nb::arg("loss"), nb::arg("loss_scale"), nb::arg("tolerance"));

    m.def("refine_poses_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts,
             const std::vector<int>& fixedViews, nb::handle dist, int maxIterations, const std::string& loss,
             double lossScale, double tolerance) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 0);
              const tripose::RefineOptions options = refineOptions(maxIterations, loss, lossScale, tolerance);
              tripose::RefinedStructure structure;
              std::vector<tripose::CameraPose> all;
              double rms;
              tripose::ViewSet views;
              {
                  nb::gil_scoped_release release;
                  std::vector<int> poseOfView;
                  std::vector<tripose::CameraPose> poses;
                  views = tripose::buildSeveralPosesSet(problem.arguments, problem.rotations, problem.translations,
                                                        fixedViews, "fixed_views", poseOfView, poses);
                  rms = tripose::refineSeveralPoses(views, poseOfView, poses, options, &structure);
                  all = tripose::allViewPoses(views, poseOfView, poses);
              }
              nb::dict out;
              nb::list Rout, tout;
              for (const tripose::CameraPose& pose : all)
              {
                  Rout.append(rotationArray(pose.R));
                  tout.append(vectorArray(pose.t));
              }
              out["Rs"] = Rout;
              out["ts"] = tout;
              out["rms"] = rms;
              writeStructure(structure, views.numPoints, views.numLines, out);
              return out;
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("fixed_views"), nb::arg("dist").none(), nb::arg("max_iterations"), nb::arg("loss"), nb::arg("loss_scale"), nb::arg("tolerance"));
}
