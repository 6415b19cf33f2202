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
#include <tuple>
#include <utility>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "linear/linear_pose_solver.hpp"
#include "linear/multiview_pose_solver.hpp"
#include "linear/rig_pose_solver.hpp"
#include "pipeline/pose_pipelines.hpp"
#include "pipeline/posed_structure.hpp"
#include "problem/view_set_builder.hpp"
#include "support/error.hpp"
#include "pose_result.hpp"
#include "stereo_tracker_bindings.hpp"
#include "tracker_bindings.hpp"

namespace nb = nanobind;

namespace {

using AnyArray = nb::ndarray<nb::ro, nb::device::cpu>;

const int kMinFeatures = 4, kMinStereoFeatures = 2, kMinStereoRansacFeatures = 3, kMinRefineFeatures = 3;

[[noreturn]] void raiseType(const std::string& message)
{
    throw nb::type_error(message.c_str());
}

[[noreturn]] void raiseValue(const std::string& message)
{
    throw nb::value_error(message.c_str());
}

/** A read-only float32 or float64 array of the caller's, in any memory layout, or nested lists of
numbers (read as float64). Objects that export
the buffer protocol (numpy arrays) are read through it directly; nanobind's ndarray caster imports
numpy arrays through DLPack, a Python method call and a capsule per array, which costs more than
the rest of a small estimate's conversions. Other array types (DLPack producers) go through
nanobind. TypeError naming the argument for anything else.
*/
class ArrayView
{
public:
    ArrayView(nb::handle object, const std::string& name)
    {
        if (nb::isinstance<nb::list>(object) || nb::isinstance<nb::tuple>(object))
        {
            // Nested lists of numbers, read as numpy reads them.
            static const nb::handle asarray = nb::object(nb::module_::import_("numpy").attr("asarray")).release();
            try
            {
                converted_ = asarray(object, "float64");
            }
            catch (nb::python_error& e)
            {
                if (e.matches(PyExc_ValueError))
                    raiseValue(name + ": " + e.what());
                raiseType(name + " must be an array of numbers: " + e.what());
            }
            object = converted_;
        }
        if (PyObject_CheckBuffer(object.ptr()) && PyObject_GetBuffer(object.ptr(), &buffer_, PyBUF_RECORDS_RO) == 0)
        {
            hasBuffer_ = true;
            const char* format = buffer_.format ? buffer_.format : "B";
            if (std::strcmp(format, "d") != 0 && std::strcmp(format, "f") != 0)
                raiseType(name + " must be float32 or float64");
            single_ = format[0] == 'f';
            data_ = static_cast<const char*>(buffer_.buf);
            for (int d = 0; d < buffer_.ndim; ++d)
            {
                shape_.push_back((size_t)buffer_.shape[d]);
                strideBytes_.push_back((int64_t)buffer_.strides[d]);
            }
            return;
        }
        PyErr_Clear(); // an exporter that refused: judged by nanobind's caster below
        if (!nb::try_cast(object, fallback_, false))
            raiseType(name + " must be a numpy array of float32 or float64");
        if (fallback_.dtype() != nb::dtype<double>() && fallback_.dtype() != nb::dtype<float>())
            raiseType(name + " must be float32 or float64");
        single_ = fallback_.dtype() == nb::dtype<float>();
        data_ = static_cast<const char*>(fallback_.data());
        const int64_t itemSize = single_ ? (int64_t)sizeof(float) : (int64_t)sizeof(double);
        for (size_t d = 0; d < fallback_.ndim(); ++d)
        {
            shape_.push_back(fallback_.shape(d));
            strideBytes_.push_back(fallback_.stride(d) * itemSize); // nanobind's strides count elements
        }
    }
    ~ArrayView()
    {
        if (hasBuffer_)
            PyBuffer_Release(&buffer_);
    }
    ArrayView(const ArrayView&) = delete;
    ArrayView& operator=(const ArrayView&) = delete;

    size_t ndim() const { return shape_.size(); }
    size_t shape(size_t d) const { return shape_[d]; }
    size_t size() const
    {
        size_t n = 1;
        for (size_t s : shape_)
            n *= s;
        return n;
    }
    //! Element (r, c) of a two-dimensional array.
    double at(size_t r, size_t c) const { return value((int64_t)r * strideBytes_[0] + (int64_t)c * strideBytes_[1]); }
    //! Element @p i in row-major order, any number of dimensions.
    double flat(size_t i) const
    {
        int64_t offset = 0;
        for (size_t d = ndim(); d-- > 0;)
        {
            offset += (int64_t)(i % shape_[d]) * strideBytes_[d];
            i /= shape_[d];
        }
        return value(offset);
    }
    //! "(2, 3)", "(3,)".
    std::string shapeText() const
    {
        std::string text = "(";
        for (size_t d = 0; d < ndim(); ++d)
            text += (d ? ", " : "") + std::to_string(shape(d));
        return text + (ndim() == 1 ? ",)" : ")");
    }

private:
    double value(int64_t offsetBytes) const
    {
        return single_ ? (double)*reinterpret_cast<const float*>(data_ + offsetBytes)
                       : *reinterpret_cast<const double*>(data_ + offsetBytes);
    }

    nb::object converted_; // a list's values as an array
    Py_buffer buffer_{};
    bool hasBuffer_ = false;
    AnyArray fallback_;
    const char* data_ = nullptr;
    bool single_ = false;
    std::vector<size_t> shape_;
    std::vector<int64_t> strideBytes_;
};

//! The values of @p a (any strides) in row-major order as a @p rows x @p cols matrix named @p name,
//! which the caller has checked to hold as many values.
tripose::ArgumentMatrix copyMatrix(const ArrayView& a, const std::string& name, int rows, int cols)
{
    tripose::ArgumentMatrix m;
    m.name = name;
    m.rows = rows;
    m.cols = cols;
    m.values.resize((size_t)rows * cols);
    double* out = m.values.data();
    if (a.ndim() == 2)
    {
        for (size_t r = 0; r < a.shape(0); ++r)
            for (size_t c = 0; c < a.shape(1); ++c)
                *out++ = a.at(r, c);
    }
    else
    {
        for (size_t i = 0; i < a.size(); ++i)
            *out++ = a.flat(i);
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
    const ArrayView a(object, name);
    if (a.size() == 0)
        return m;
    const bool widthOk = a.ndim() == 2 && (lines ? (a.shape(1) == 4 || a.shape(1) == 3) : a.shape(1) == 2);
    if (!widthOk)
        raiseValue(name + (lines ? " must have shape (M, 4) (segments x0 y0 x1 y1) or (M, 3) (homogeneous lines a b c)"
                                 : " must have shape (N, 2)") + ", got " + a.shapeText());
    return copyMatrix(a, name, (int)a.shape(0), (int)a.shape(1));
}

//! A camera matrix, 3x3.
tripose::ArgumentMatrix readCameraMatrix(nb::handle object, const std::string& name)
{
    const ArrayView a(object, name);
    if (a.ndim() != 2 || a.shape(0) != 3 || a.shape(1) != 3)
        raiseValue(name + " must have shape (3, 3), got " + a.shapeText());
    return copyMatrix(a, name, 3, 3);
}

//! Distortion coefficients: a vector (OpenCV's 4, 5, 8, 12 or 14, checked by the core).
tripose::ArgumentMatrix readDistortion(nb::handle object, const std::string& name)
{
    const ArrayView a(object, name);
    if (a.ndim() > 2 || (a.ndim() == 2 && a.shape(0) != 1 && a.shape(1) != 1))
        raiseValue(name + " must be a vector of 4, 5, 8, 12 or 14 coefficients, got shape " + a.shapeText());
    return copyMatrix(a, name, 1, (int)a.size());
}

bool isSequence(nb::handle object)
{
    return nb::isinstance<nb::list>(object) || nb::isinstance<nb::tuple>(object);
}

//! K or dist given per view: a list or tuple of arrays (a list of numbers, or of lists of numbers,
//! is one array).
bool isPerViewList(nb::handle object)
{
    if (!isSequence(object) || nb::len(object) == 0)
        return false;
    const nb::object first = object[nb::int_(0)];
    return PyObject_CheckBuffer(first.ptr()) != 0;
}

/** K (one 3x3, a sequence of one per view, or an array of shape (V, 3, 3)) and dist (None, one
vector, or a sequence of one per view).
*/
void readCalibration(nb::handle K, nb::handle dist, tripose::ProblemArguments& args)
{
    args.cameraMatrixName = "K";
    args.distortionName = "dist";
    if (isPerViewList(K))
    {
        nb::sequence items = nb::borrow<nb::sequence>(K);
        const size_t n = nb::len(items);
        for (size_t v = 0; v < n; ++v)
            args.cameraMatrices.push_back(readCameraMatrix(items[v], "K[" + std::to_string(v) + "]"));
    }
    else
    {
        const ArrayView a(K, "K");
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
    if (isPerViewList(dist))
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
    const ArrayView a(object, name);
    if (!(a.size() == 9 && a.ndim() == 2 && a.shape(0) == 3) && a.size() != 3)
        raiseValue(name + " must be a 3x3 rotation matrix or a rotation vector of 3 elements, got shape " + a.shapeText());
    return a.size() == 9 ? copyMatrix(a, name, 3, 3) : copyMatrix(a, name, 3, 1);
}

tripose::ArgumentMatrix readTranslation(nb::handle object, const std::string& name)
{
    const ArrayView a(object, name);
    if (a.size() != 3)
        raiseValue(name + " must hold 3 elements, got shape " + a.shapeText());
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

/** A new float64 numpy array of @p shape holding @p values (row-major). Made by numpy.empty and
filled through the buffer protocol: exporting a C++ buffer as an ndarray through nanobind costs
several times as much, which a small estimate's result (a few 3x3 and 3-vectors) notices.
*/
nb::object newArray(std::initializer_list<size_t> shape, const double* values)
{
    // Looked up once and kept for the life of the process (never released: the interpreter may be
    // finalised before static destructors run).
    static const nb::handle numpyEmpty = nb::object(nb::module_::import_("numpy").attr("empty")).release();
    size_t n = 1;
    nb::list dims;
    for (size_t s : shape)
    {
        dims.append(s);
        n *= s;
    }
    nb::object array = numpyEmpty(nb::tuple(dims));
    Py_buffer view;
    if (PyObject_GetBuffer(array.ptr(), &view, PyBUF_WRITABLE | PyBUF_C_CONTIGUOUS) != 0)
        throw nb::python_error();
    std::memcpy(view.buf, values, n * sizeof(double));
    PyBuffer_Release(&view);
    return array;
}

nb::object rotationArray(const Eigen::Matrix3d& R)
{
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rowMajor = R;
    return newArray({ 3, 3 }, rowMajor.data());
}

nb::object vectorArray(const Eigen::Vector3d& t)
{
    return newArray({ 3 }, t.data());
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
    // Two arrays for all candidates, each (R, t) a pair of views into them: making a numpy array
    // costs far more than indexing one, and small problems return several candidates.
    const size_t n = candidates.size();
    nb::list out;
    if (n == 0)
        return out;
    std::vector<double> rotations(9 * n), translations(3 * n);
    for (size_t i = 0; i < n; ++i)
    {
        Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(&rotations[9 * i]);
        Eigen::Map<Eigen::Vector3d> t(&translations[3 * i]);
        R = candidates[i].pose.R;
        t = candidates[i].pose.t;
    }
    const nb::object Rs = newArray({ n, 3, 3 }, rotations.data());
    const nb::object ts = newArray({ n, 3 }, translations.data());
    for (size_t i = 0; i < n; ++i)
        out.append(nb::make_tuple(Rs[nb::int_(i)], ts[nb::int_(i)]));
    return out;
}

//! The pose's uncertainty into @p out: covariance (6, 6) and noise_variance, both None when not valid.
void writeCovariance(const tripose::PoseCovariance& uncertainty, PoseResult& out)
{
    if (!uncertainty.valid)
        return;
    const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> rowMajor = uncertainty.covariance;
    out.covariance = newArray({ 6, 6 }, rowMajor.data());
    out.noise_variance = nb::float_(uncertainty.noiseVariance);
}

PoseResult robustResult(bool found, const tripose::RobustEstimate& estimate, const tripose::PoseCovariance& uncertainty)
{
    PoseResult out;
    out.kind = PoseResult::Kind::Robust;
    out.hasPose = found;
    if (found)
    {
        out.rotation = estimate.pose.R;
        out.translation = estimate.pose.t;
        out.R = rotationArray(estimate.pose.R);
        out.t = vectorArray(estimate.pose.t);
    }
    out.num_inliers = nb::int_(found ? estimate.numInliers : 0);
    out.point_inliers = maskArray(estimate.pointInliers);
    out.line_inliers = maskArray(estimate.lineInliers);
    out.numPoints = (int)estimate.pointInliers.size();
    out.numLines = (int)estimate.lineInliers.size();
    for (unsigned char inlier : estimate.pointInliers)
        out.pointInliers += inlier != 0;
    for (unsigned char inlier : estimate.lineInliers)
        out.lineInliers += inlier != 0;
    out.rmsValue = found ? estimate.inlierRms : std::numeric_limits<double>::quiet_NaN();
    out.rms = nb::float_(out.rmsValue);
    writeCovariance(uncertainty, out);
    // The minima of the final refinement that the data cannot tell apart (the returned pose first).
    out.candidates = candidateList(estimate.minima);
    nb::list rms;
    for (const tripose::ScoredPose& m : estimate.minima)
        rms.append(m.rms);
    out.candidate_rms = rms;
    out.numCandidates = (int)estimate.minima.size();
    out.ambiguous = nb::bool_(estimate.minima.size() > 1);
    return out;
}

//! The refined structure as (points3d (N, 3), lines3d (M, 6): two points of each line).
std::pair<nb::object, nb::object> structureArrays(const std::vector<Eigen::Vector3d>& pointList,
                                                  const std::vector<Eigen::Vector3d>& lineEnds, int numPoints,
                                                  int numLines)
{
    std::vector<double> points(3 * (size_t)numPoints), lines(6 * (size_t)numLines);
    for (int i = 0; i < numPoints; ++i)
        for (int c = 0; c < 3; ++c)
            points[3 * i + c] = pointList[i](c);
    for (int i = 0; i < numLines; ++i)
        for (int c = 0; c < 3; ++c)
        {
            lines[6 * i + c] = lineEnds[2 * i](c);
            lines[6 * i + 3 + c] = lineEnds[2 * i + 1](c);
        }
    return { newArray({ (size_t)numPoints, 3 }, points.data()), newArray({ (size_t)numLines, 6 }, lines.data()) };
}

void writeStructure(const std::vector<Eigen::Vector3d>& pointList, const std::vector<Eigen::Vector3d>& lineEnds,
                    int numPoints, int numLines, nb::dict& out)
{
    const std::pair<nb::object, nb::object> arrays = structureArrays(pointList, lineEnds, numPoints, numLines);
    out["points3d"] = arrays.first;
    out["lines3d"] = arrays.second;
}

/** The caller's RansacOptions (the defaults for None), checked: errors name a field as
"<name>.<field>" in Python's words, or the field alone when @p name is empty (the keyword
arguments of earlier releases). */
tripose::RansacOptions ransacOptions(const tripose::RansacOptions* given, const std::string& name)
{
    const tripose::RansacOptions options = given ? *given : tripose::RansacOptions();
    tripose::RansacOptionNames names;
    names.maxIterations = "max_iterations";
    names.minInliers = "min_inliers";
    names.refineOptions = "refine_options";
    names.refine.maxIterations = "max_iterations";
    names.refine.lossValues = "'squared', 'huber' or 'cauchy'";
    names.refine.lossScale = "loss_scale";
    tripose::checkRansacOptions(options, name.c_str(), names);
    return options;
}

//! The caller's RefineOptions (the defaults for None), checked and named as ransacOptions().
tripose::RefineOptions refineOptions(const tripose::RefineOptions* given, const std::string& name)
{
    const tripose::RefineOptions options = given ? *given : tripose::RefineOptions();
    tripose::RefineOptionNames names;
    names.maxIterations = "max_iterations";
    names.lossValues = "'squared', 'huber' or 'cauchy'";
    names.lossScale = "loss_scale";
    tripose::checkRefineOptions(options, name.c_str(), names);
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

PoseResult refinedResult(const tripose::ViewSet& views, const tripose::CameraPose& pose, double rms,
                         const tripose::RefinedStructure& structure, const tripose::PoseCovariance& uncertainty)
{
    PoseResult out;
    out.kind = PoseResult::Kind::Refined;
    out.hasPose = true;
    out.rotation = pose.R;
    out.translation = pose.t;
    out.R = rotationArray(pose.R);
    out.t = vectorArray(pose.t);
    out.rmsValue = rms;
    out.rms = nb::float_(rms);
    std::tie(out.points3d, out.lines3d) = structureArrays(structure.points, structure.lineEnds, views.numPoints,
                                                          views.numLines);
    out.numPoints = views.numPoints;
    out.numLines = views.numLines;
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
PoseResult runRobust(Build build, Estimate estimate, const tripose::RansacOptions& options, bool wantCovariance)
{
    tripose::RobustEstimate result;
    tripose::PoseCovariance uncertainty;
    bool found;
    {
        nb::gil_scoped_release release;
        const tripose::ViewSet views = build();
        found = estimate(views, result);
        // Asked for only: it refines once more over the inliers, about half a RANSAC's time.
        if (wantCovariance && found && options.refine)
            uncertainty = tripose::covarianceOfEstimate(views, result.pose, options.refineOptions,
                                                        &result.pointInliers, &result.lineInliers);
    }
    return robustResult(found, result, uncertainty);
}

//! The refinement of the initial pose (@p R, @p t) over the ViewSet that @p build makes (GIL released).
template <class Build>
PoseResult runRefinement(Build build, const tripose::ArgumentMatrix& R, const tripose::ArgumentMatrix& t,
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

    bindTracker(m);
    bindPoseResult(m);
    bindStereoTracker(m);

    m.def("estimate_pose_line_point",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3, nb::handle K,
             nb::handle R12, nb::handle t12, nb::handle dist, bool refine) {
              const ThreeViewProblem problem(p1, p2, p3, l1, l2, l3, K, R12, t12, dist);
              return runCandidates<tripose::LinearPoseSolver>(problem.builder(kMinFeatures), refine);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_line_point_ransac",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3, nb::handle K,
             nb::handle R12, nb::handle t12, nb::handle dist, const tripose::RansacOptions* given,
             const std::string& optionsName, bool wantCovariance) {
              const ThreeViewProblem problem(p1, p2, p3, l1, l2, l3, K, R12, t12, dist);
              const tripose::RansacOptions options = ransacOptions(given, optionsName);
              return runRobust(problem.builder(kMinFeatures),
                               [&](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
                                   const tripose::LinearPoseSolver linear(views);
                                   return tripose::estimateRobustOnKnownStructure(views, linear, options, estimate);
                               },
                               options, wantCovariance);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"), nb::arg("covariance"));

    m.def("refine_pose_line_point",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle l1, nb::handle l2, nb::handle l3, nb::handle K,
             nb::handle R12, nb::handle t12, nb::handle R, nb::handle t, nb::handle dist,
             const tripose::RefineOptions* given, const std::string& optionsName) {
              const ThreeViewProblem problem(p1, p2, p3, l1, l2, l3, K, R12, t12, dist);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = refineOptions(given, optionsName);
              return runRefinement(problem.builder(kMinRefineFeatures), Rm, tm, options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));

    m.def("estimate_pose_line_point_stereo",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle dist, bool refine) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              return runCandidates<tripose::RigPoseSolver>(problem.builder(kMinStereoFeatures), refine);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_line_point_stereo_ransac",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle dist,
             const tripose::RansacOptions* given, const std::string& optionsName, bool wantCovariance) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              const tripose::RansacOptions options = ransacOptions(given, optionsName);
              return runRobust(problem.builder(kMinStereoRansacFeatures),
                               [options](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
                                   return tripose::estimateRobustRig(views, options, estimate);
                               },
                               options, wantCovariance);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"), nb::arg("covariance"));

    m.def("refine_pose_line_point_stereo",
          [](nb::handle p1, nb::handle p2, nb::handle p3, nb::handle p4, nb::handle l1, nb::handle l2, nb::handle l3,
             nb::handle l4, nb::handle K, nb::handle R12, nb::handle t12, nb::handle R, nb::handle t, nb::handle dist,
             const tripose::RefineOptions* given, const std::string& optionsName) {
              const StereoProblem problem(p1, p2, p3, p4, l1, l2, l3, l4, K, R12, t12, dist);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = refineOptions(given, optionsName);
              return runRefinement(problem.builder(kMinStereoFeatures), Rm, tm, options);
          },
          nb::arg("points1").none(), nb::arg("points2").none(), nb::arg("points3").none(), nb::arg("points4").none(), nb::arg("lines1").none(), nb::arg("lines2").none(), nb::arg("lines3").none(), nb::arg("lines4").none(), nb::arg("K").none(), nb::arg("R12").none(), nb::arg("t12").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));

    m.def("estimate_pose_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
             bool refine) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              return runCandidates<tripose::MultiViewPoseSolver>(problem.newViewBuilder(), refine);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("refine"));

    m.def("estimate_pose_multiview_ransac",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist,
             const tripose::RansacOptions* given, const std::string& optionsName, bool wantCovariance) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              const tripose::RansacOptions options = ransacOptions(given, optionsName);
              return runRobust(problem.newViewBuilder(),
                               [&](const tripose::ViewSet& views, tripose::RobustEstimate& estimate) {
                                   const tripose::MultiViewPoseSolver linear(views);
                                   return tripose::estimateRobustOnKnownStructure(views, linear, options, estimate);
                               },
                               options, wantCovariance);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"), nb::arg("covariance"));

    m.def("refine_pose_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle R,
             nb::handle t, nb::handle dist, const tripose::RefineOptions* given,
             const std::string& optionsName) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 1);
              const tripose::ArgumentMatrix Rm = readRotation(R, "R"), tm = readTranslation(t, "t");
              const tripose::RefineOptions options = refineOptions(given, optionsName);
              return runRefinement(problem.newViewBuilder(), Rm, tm, options);
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("R").none(), nb::arg("t").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));

    m.def("adjust_poses_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, const std::vector<int>& fixedViews, nb::handle Rs,
             nb::handle ts, nb::handle dist, const tripose::RefineOptions* given,
             const std::string& optionsName) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 0);
              const tripose::RefineOptions options = refineOptions(given, optionsName);
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
              PoseResult out;
              out.kind = PoseResult::Kind::Adjusted;
              nb::list Rout, tout;
              for (const tripose::CameraPose& pose : all)
              {
                  Rout.append(rotationArray(pose.R));
                  tout.append(vectorArray(pose.t));
              }
              out.Rs = Rout;
              out.ts = tout;
              out.numPoses = (int)all.size();
              out.rmsValue = rms;
              out.rms = nb::float_(rms);
              std::tie(out.points3d, out.lines3d) = structureArrays(structure.points, structure.lineEnds, views.numPoints,
                                                                    views.numLines);
              return out;
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("fixed_views"), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none(), nb::arg("options").none(), nb::arg("options_name"));

    m.def("triangulate_multiview",
          [](nb::handle points, nb::handle lines, nb::handle K, nb::handle Rs, nb::handle ts, nb::handle dist) {
              const MultiViewProblem problem(points, lines, K, Rs, ts, dist, 0);
              tripose::PosedStructure structure;
              tripose::ViewSet views;
              {
                  nb::gil_scoped_release release;
                  views = tripose::buildPosedViewSet(problem.arguments, problem.rotations, problem.translations);
                  structure = tripose::triangulateStructure(views);
              }
              const size_t numViews = views.views.size();
              nb::dict out;
              writeStructure(structure.points, structure.lineEnds, views.numPoints, views.numLines, out);
              out["point_errors"] = newArray({ (size_t)views.numPoints, numViews }, structure.pointErrors.data());
              out["line_errors"] = newArray({ (size_t)views.numLines, numViews }, structure.lineErrors.data());
              out["num_with_structure"] = structure.numWithStructure;
              return out;
          },
          nb::arg("points").none(), nb::arg("lines").none(), nb::arg("K").none(), nb::arg("Rs").none(), nb::arg("ts").none(), nb::arg("dist").none());
}
