# Included at the end of OpenCV's project() call by scripts/build_opencv_intree.sh
# (CMAKE_PROJECT_OpenCV_INCLUDE) when OpenCV's own modules are compiled without optimization: once
# every target exists, tripose's library and its tests get TRIPOSE_INTREE_OPTIMIZATION back. The
# option comes after the build type's flags on the command line, so it is the one that counts.
cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL tripose_set_optimization)

function(tripose_set_optimization)
  foreach(target opencv_tripose opencv_test_tripose opencv_perf_tripose)
    if(TARGET ${target})
      target_compile_options(${target} PRIVATE ${TRIPOSE_INTREE_OPTIMIZATION})
    endif()
  endforeach()
endfunction()
