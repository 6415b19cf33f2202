# Builds modules/tripose outside an OpenCV tree, with the same source layout that
# ocv_define_module() expects: src/ (globbed recursively, so src/generated/ is included),
# test/ and perf/ (compiled against the thin ts shim in cmake/ts_shim).

set(TRIPOSE_TS_SHIM_DIR "${CMAKE_CURRENT_LIST_DIR}/ts_shim")

function(tripose_add_module_targets)
  set(module_dir "${CMAKE_CURRENT_SOURCE_DIR}")
  file(GLOB_RECURSE lib_sources CONFIGURE_DEPENDS "${module_dir}/src/*.cpp")
  add_library(opencv_tripose ${lib_sources})
  add_library(tripose::tripose ALIAS opencv_tripose)
  set_target_properties(opencv_tripose PROPERTIES
    EXPORT_NAME tripose
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
    POSITION_INDEPENDENT_CODE ON)
  target_include_directories(opencv_tripose
    PUBLIC
      $<BUILD_INTERFACE:${module_dir}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE
      ${module_dir}/src)
  target_link_libraries(opencv_tripose
    PUBLIC opencv_core
    # Eigen is header-only: a build-time dependency that installed consumers need not find.
    PRIVATE opencv_imgproc opencv_calib3d $<BUILD_INTERFACE:Eigen3::Eigen>)
  target_compile_options(opencv_tripose PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wno-unused-parameter>)

  if(TRIPOSE_BUILD_TESTS)
    file(GLOB test_sources CONFIGURE_DEPENDS "${module_dir}/test/*.cpp")
    add_executable(opencv_test_tripose ${test_sources})
    tripose_link_ts_shim(opencv_test_tripose)
    add_test(NAME opencv_test_tripose COMMAND opencv_test_tripose)
    set_tests_properties(opencv_test_tripose PROPERTIES
      ENVIRONMENT "OPENCV_TEST_DATA_PATH=${PROJECT_SOURCE_DIR}/test/data")
  endif()

  if(TRIPOSE_BUILD_PERF_TESTS)
    file(GLOB perf_sources CONFIGURE_DEPENDS "${module_dir}/perf/*.cpp")
    add_executable(opencv_perf_tripose ${perf_sources})
    tripose_link_ts_shim(opencv_perf_tripose)
  endif()
endfunction()

function(tripose_link_ts_shim target)
  # Tests reach private headers by relative paths ("../src/..."), as they must inside OpenCV.
  target_include_directories(${target} PRIVATE "${TRIPOSE_TS_SHIM_DIR}")
  target_link_libraries(${target} PRIVATE opencv_tripose opencv_core opencv_imgproc opencv_calib3d
    Eigen3::Eigen GTest::gtest)
  target_compile_definitions(${target} PRIVATE
    TRIPOSE_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/test/data")
endfunction()
