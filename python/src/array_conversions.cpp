// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "array_conversions.hpp"

#include <cstring>
#include <string>
#include <vector>

#include <nanobind/ndarray.h>

namespace array_conversions {

namespace {

using AnyArray = nb::ndarray<nb::ro, nb::device::cpu>;

[[noreturn]] void raiseType(const std::string& message)
{
    throw nb::type_error(message.c_str());
}

[[noreturn]] void raiseValue(const std::string& message)
{
    throw nb::value_error(message.c_str());
}

/** The fields at the start of every numpy array object (numpy's PyArrayObject_fields, the same in
numpy 1 and 2): read directly, an exact ndarray of a builtin dtype gives its data pointer, shape and
strides without exporting a buffer, which numpy does by building and looking up a format string per
call. */
struct NumpyArrayHead
{
    PyObject_HEAD
    char* data;
    int nd;
    const Py_ssize_t* dimensions;
    const Py_ssize_t* strides;
    PyObject* base;
    PyObject* descr;
};

//! numpy's ndarray type and its builtin float64 and float32 dtypes, looked up once for the process.
struct NumpyTypes
{
    PyTypeObject* ndarray;
    PyObject* float64;
    PyObject* float32;
};

const NumpyTypes& numpyTypes()
{
    // Never released: the interpreter may be finalised before static destructors run.
    static const NumpyTypes types = [] {
        const nb::module_ numpy = nb::module_::import_("numpy");
        return NumpyTypes{ (PyTypeObject*)nb::object(numpy.attr("ndarray")).release().ptr(),
                           nb::object(numpy.attr("dtype")("float64")).release().ptr(),
                           nb::object(numpy.attr("dtype")("float32")).release().ptr() };
    }();
    return types;
}

/** A read-only float32 or float64 array of the caller's, in any memory layout, or nested lists of
numbers (read as float64). A numpy array of numpy's own float64 or float32 dtype is read from its
fields (NumpyArrayHead); other objects that export the buffer protocol through it; nanobind's
ndarray caster imports arrays through DLPack, a Python method call and a capsule per array, so only
other array types (DLPack producers) go through nanobind. TypeError naming the argument for
anything else.
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
        const NumpyTypes& numpy = numpyTypes();
        if (Py_TYPE(object.ptr()) == numpy.ndarray)
        {
            const NumpyArrayHead* head = reinterpret_cast<const NumpyArrayHead*>(object.ptr());
            if (head->descr == numpy.float64 || head->descr == numpy.float32)
            {
                single_ = head->descr == numpy.float32;
                data_ = head->data;
                ndim_ = (size_t)head->nd;
                shape_ = head->dimensions;
                strideBytes_ = head->strides;
                return;
            }
        }
        if (PyObject_CheckBuffer(object.ptr()) && PyObject_GetBuffer(object.ptr(), &buffer_, PyBUF_RECORDS_RO) == 0)
        {
            hasBuffer_ = true;
            const char* format = buffer_.format ? buffer_.format : "B";
            if (std::strcmp(format, "d") != 0 && std::strcmp(format, "f") != 0)
                raiseType(name + " must be float32 or float64");
            single_ = format[0] == 'f';
            data_ = static_cast<const char*>(buffer_.buf);
            ndim_ = (size_t)buffer_.ndim;
            shape_ = buffer_.shape;
            strideBytes_ = buffer_.strides;
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
        ndim_ = fallback_.ndim();
        for (size_t d = 0; d < ndim_; ++d)
        {
            fallbackShape_.push_back((Py_ssize_t)fallback_.shape(d));
            fallbackStrides_.push_back((Py_ssize_t)(fallback_.stride(d) * itemSize)); // nanobind's count elements
        }
        shape_ = fallbackShape_.data();
        strideBytes_ = fallbackStrides_.data();
    }
    ~ArrayView()
    {
        if (hasBuffer_)
            PyBuffer_Release(&buffer_);
    }
    ArrayView(const ArrayView&) = delete;
    ArrayView& operator=(const ArrayView&) = delete;

    size_t ndim() const { return ndim_; }
    size_t shape(size_t d) const { return (size_t)shape_[d]; }
    size_t size() const
    {
        size_t n = 1;
        for (size_t d = 0; d < ndim_; ++d)
            n *= shape(d);
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
            offset += (int64_t)(i % shape(d)) * strideBytes_[d];
            i /= shape(d);
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
        // Copied, not dereferenced: an array's data need not be aligned.
        if (single_)
        {
            float v;
            std::memcpy(&v, data_ + offsetBytes, sizeof v);
            return v;
        }
        double v;
        std::memcpy(&v, data_ + offsetBytes, sizeof v);
        return v;
    }

    nb::object converted_; // a list's values as an array
    Py_buffer buffer_{};
    bool hasBuffer_ = false;
    AnyArray fallback_;
    std::vector<Py_ssize_t> fallbackShape_, fallbackStrides_;
    const char* data_ = nullptr;
    bool single_ = false;
    size_t ndim_ = 0;
    const Py_ssize_t* shape_ = nullptr;
    const Py_ssize_t* strideBytes_ = nullptr;
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
tripose::ArgumentMatrix readCameraMatrix(const ArrayView& a, const std::string& name)
{
    if (a.ndim() != 2 || a.shape(0) != 3 || a.shape(1) != 3)
        raiseValue(name + " must have shape (3, 3), got " + a.shapeText());
    return copyMatrix(a, name, 3, 3);
}

tripose::ArgumentMatrix readCameraMatrix(nb::handle object, const std::string& name)
{
    return readCameraMatrix(ArrayView(object, name), name);
}

//! Distortion coefficients: a vector (OpenCV's 4, 5, 8, 12 or 14, checked by the core).
tripose::ArgumentMatrix readDistortion(nb::handle object, const std::string& name)
{
    const ArrayView a(object, name);
    if (a.ndim() > 2 || (a.ndim() == 2 && a.shape(0) != 1 && a.shape(1) != 1))
        raiseValue(name + " must be a vector of 4, 5, 8, 12 or 14 coefficients, got shape " + a.shapeText());
    return copyMatrix(a, name, 1, (int)a.size());
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

} // namespace

bool isSequence(nb::handle object)
{
    return nb::isinstance<nb::list>(object) || nb::isinstance<nb::tuple>(object);
}

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
            args.cameraMatrices.push_back(readCameraMatrix(a, "K"));
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

/** Made by numpy.empty and filled through the array's fields: exporting a C++ buffer as an ndarray
through nanobind costs several times as much, which a small estimate's result (a few 3x3 and
3-vectors) notices (doc/studies/speed.md, "The Python package beside the C++ API").
*/
nb::object newArray(std::initializer_list<size_t> shape, const double* values)
{
    // Looked up once and kept for the life of the process (never released: the interpreter may be
    // finalised before static destructors run).
    static const nb::handle numpyEmpty = nb::object(nb::module_::import_("numpy").attr("empty")).release();
    size_t n = 1;
    nb::object dims = nb::steal(PyTuple_New((Py_ssize_t)shape.size()));
    if (!dims.is_valid())
        throw nb::python_error();
    Py_ssize_t d = 0;
    for (size_t s : shape)
    {
        PyTuple_SET_ITEM(dims.ptr(), d++, PyLong_FromSize_t(s));
        n *= s;
    }
    nb::object array = numpyEmpty(dims);
    // numpy.empty gives a new C-contiguous float64 array: its data is written through its fields.
    std::memcpy(reinterpret_cast<NumpyArrayHead*>(array.ptr())->data, values, n * sizeof(double));
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

} // namespace array_conversions
