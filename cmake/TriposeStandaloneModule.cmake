# Builds modules/tripose outside an OpenCV tree, with the same source layout that
# ocv_define_module() expects: src/ (globbed recursively, so src/core/ and src/core/generated/ are included),
# test/ and perf/ (compiled against the thin ts shim in cmake/ts_shim). Also builds the support
# library of modules/tripose/support (scene generator, VGG reader, pose error), which the tests,
# perf tests, samples, benchmarks and evaluation link and which is not installed.

set(TRIPOSE_TS_SHIM_DIR "${CMAKE_CURRENT_LIST_DIR}/ts_shim")

function(tripose_add_module_targets)
  set(module_dir "${CMAKE_CURRENT_SOURCE_DIR}")
  # The algorithms build as the OpenCV-free core (src/core, its own CMake project); the module is
  # the adapter around it: the entry points (src/*.cpp) and their OpenCV conversions (src/opencv).
  add_subdirectory("${module_dir}/src/core" "${CMAKE_CURRENT_BINARY_DIR}/core")
  file(GLOB adapter_sources CONFIGURE_DEPENDS "${module_dir}/src/*.cpp" "${module_dir}/src/opencv/*.cpp")
  add_library(opencv_tripose ${adapter_sources} $<TARGET_OBJECTS:tripose_core>)
  add_library(tripose::tripose ALIAS opencv_tripose)
  set_target_properties(opencv_tripose PROPERTIES
    EXPORT_NAME tripose
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
    POSITION_INDEPENDENT_CODE ON
    # As OpenCV builds modules: only what carries CV_EXPORTS (the public API) leaves the library.
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_include_directories(opencv_tripose
    PUBLIC
      $<BUILD_INTERFACE:${module_dir}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE
      ${module_dir}/src)
  target_link_libraries(opencv_tripose
    PUBLIC opencv_core
    # Eigen is header-only: a build-time dependency that installed consumers need not find.
    PRIVATE opencv_calib3d $<BUILD_INTERFACE:Eigen3::Eigen>)
  target_compile_options(opencv_tripose PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wno-unused-parameter>)

  tripose_add_support_library("${module_dir}/support")

  if(TRIPOSE_BUILD_TESTS)
    file(GLOB test_sources CONFIGURE_DEPENDS "${module_dir}/test/*.cpp")
    add_executable(opencv_test_tripose ${test_sources})
    tripose_add_test_target(opencv_test_tripose)
    add_test(NAME opencv_test_tripose COMMAND opencv_test_tripose)
    set_tests_properties(opencv_test_tripose PROPERTIES
      ENVIRONMENT "OPENCV_TEST_DATA_PATH=${PROJECT_SOURCE_DIR}/test/data")
  endif()

  if(TRIPOSE_BUILD_PERF_TESTS)
    file(GLOB perf_sources CONFIGURE_DEPENDS "${module_dir}/perf/*.cpp")
    add_executable(opencv_perf_tripose ${perf_sources})
    tripose_add_test_target(opencv_perf_tripose)
  endif()
endfunction()

# tripose_support: built only when a target that links it is (EXCLUDE_FROM_ALL), and never installed.
# It calls nothing of the module: the ground truth of a test must not go through the code under test.
function(tripose_add_support_library support_dir)
  file(GLOB support_sources CONFIGURE_DEPENDS "${support_dir}/src/*.cpp")
  add_library(tripose_support STATIC EXCLUDE_FROM_ALL ${support_sources})
  target_include_directories(tripose_support PUBLIC "${support_dir}/include")
  target_link_libraries(tripose_support PUBLIC opencv_core PRIVATE opencv_calib3d)
  target_compile_options(tripose_support PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wno-unused-parameter>)
endfunction()

# The accuracy and perf tests: the ts shim, the module, its support library and, with
# TRIPOSE_UNITY_TESTS, their files compiled eight to a batch.
function(tripose_add_test_target target)
  if(TRIPOSE_UNITY_TESTS)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
  tripose_link_ts_shim(${target})
endfunction()

function(tripose_link_ts_shim target)
  # Tests reach private headers by relative paths ("../src/..."), as they must inside OpenCV.
  target_include_directories(${target} PRIVATE "${TRIPOSE_TS_SHIM_DIR}")
  target_link_libraries(${target} PRIVATE opencv_tripose tripose_support opencv_core opencv_calib3d
    Eigen3::Eigen GTest::gtest)
  target_compile_definitions(${target} PRIVATE
    TRIPOSE_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/test/data")
endfunction()
